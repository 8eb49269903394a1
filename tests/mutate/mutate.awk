# The mutants file's reader (POSIX awk), used by tests/mutate/run.sh.
#   awk -v mode=list -f mutate.awk mutants.txt
#       prints "name<TAB>config" for each mutant, or fails on a malformed file
#   awk -v mode=apply -v name=NAME -v out=FILE -f mutate.awk mutants.txt ga2d_physics.h
#       writes the header with NAME's "from" lines replaced by its "to" lines
#       to FILE; fails unless the "from" lines occur exactly once, as whole
#       consecutive lines (so a mutant whose text rotted away is noticed).
function fail(msg) { print "mutants.txt:" FNR ": " msg > "/dev/stderr"; bad = 1; exit 2 }
FNR == NR {
    if ($0 ~ /^@@ mutant /) {
        if (state != "") fail("mutant " cur " has no @@ end")
        cur = $3; state = "head"
        if (cur == "" || NF != 3) fail("a mutant needs one name: @@ mutant NAME")
        if (cur in seen) fail("mutant " cur " is listed twice")
        seen[cur] = 1; order[++count] = cur; config[cur] = "float"; nfrom[cur] = 0; nto[cur] = 0
        next
    }
    if (state == "") {
        if ($0 ~ /^@@/) fail("unexpected " $0 " outside a mutant")
        next                                   # comments between mutants
    }
    if ($0 ~ /^@@ config /) { if (state != "head") fail("@@ config before @@ from"); config[cur] = $3; next }
    if ($0 == "@@ from") { if (state != "head") fail("@@ from twice"); state = "from"; next }
    if ($0 == "@@ to") { if (state != "from") fail("@@ to without @@ from"); state = "to"; next }
    if ($0 == "@@ end") {
        if (state != "to") fail("@@ end without @@ to")
        if (nfrom[cur] == 0) fail("mutant " cur " has no from lines")
        state = ""; next
    }
    if ($0 ~ /^@@/) fail("unknown line " $0)
    if (state == "from") from[cur, ++nfrom[cur]] = $0
    else if (state == "to") to[cur, ++nto[cur]] = $0
    # lines after the name and before @@ from say what the mutant breaks
    next
}
{ line[++n] = $0 }
END {
    if (bad) exit 2
    if (state != "") { print "mutants.txt: mutant " cur " has no @@ end" > "/dev/stderr"; exit 2 }
    if (mode == "list") {
        for (i = 1; i <= count; ++i) print order[i] "\t" config[order[i]]
        exit 0
    }
    if (!(name in seen)) { print "no mutant named " name > "/dev/stderr"; exit 2 }
    k = nfrom[name]; hits = 0
    for (i = 1; i + k - 1 <= n; ++i) {
        for (j = 1; j <= k && line[i + j - 1] == from[name, j]; ++j) continue
        if (j > k) { ++hits; at = i }
    }
    if (hits != 1) {
        print "mutant " name ": its from text occurs " hits " times in the header (must be exactly once)" > "/dev/stderr"
        exit 3
    }
    for (i = 1; i < at; ++i) print line[i] > out
    for (j = 1; j <= nto[name]; ++j) print to[name, j] > out
    for (i = at + k; i <= n; ++i) print line[i] > out
    close(out)
}
