#!/bin/sh
# make mutate: plants each bug of tests/mutate/mutants.txt, one at a time,
# in a copy of ga2d_physics.h, builds the test runner against the copy and
# runs the suite up to its first failing test (TEST_FIRST_FAILURE), which
# must come (a test fails, or the runner crashes or hangs).  Prints a table of the mutants and the tests that
# caught them; exits non-zero if any mutant survived, or if a mutant's
# "from" text is not in the header exactly once (the mutant rotted), or if
# a mutated copy does not compile.
#   sh tests/mutate/run.sh [NAME ...]     (every mutant, or those named)
# Runs from the repository root, MUTATE_JOBS mutants at a time (default:
# the processor count; a mutant starts as soon as one ends).  Needs only sh, awk, sed, cmp and a C compiler.
CC=${CC:-gcc}
OPT="-O2 -ffp-contract=off"
WARN="-Wall -Wextra -Wpedantic -Wshadow -Wdouble-promotion"
DIR=tests/mutate
OUT=build/mutate
LIST=$DIR/mutants.txt
# seconds: the whole suite runs in about 17 s here (C99 float, gcc -O2),
# so a mutant that makes it run six times as long is taken to hang
TIMEOUT=${MUTATE_TIMEOUT:-120}
JOBS=${MUTATE_JOBS:-$(nproc 2>/dev/null || echo 2)}
mkdir -p "$OUT" || exit 1

# sh run.sh --one <name> <config>: one mutant (how the pool below runs each)
one=""
if [ "$1" = --one ]; then one=1; shift; fi
if [ -z "$one" ]; then
all=$(awk -v mode=list -f $DIR/mutate.awk $LIST) || exit 1
[ -n "$all" ] || { echo "mutate: $LIST lists no mutant"; exit 1; }
names=$all
if [ $# -gt 0 ]; then
    names=""
    for want in "$@"; do
        row=$(printf '%s\n' "$all" | awk -F '\t' -v n="$want" '$1 == n')
        [ -n "$row" ] || { echo "mutate: no mutant named $want"; exit 1; }
        names="$names$row
"
    done
fi
fi

# The part of the header before the implementation (declarations and
# inline code every test file sees): when a mutant leaves it alone, only
# the file that compiles the runner's implementation (test_main.c) is
# rebuilt.  test_config.c compiles a private GA2D_STATIC copy of the
# library for its checks of the configuration macros; it is built once
# against the real header, like the other files (it tests no physics, and
# building it per mutant would cost a third more time).
api_part() { sed '/^#if defined(GA2D_IMPLEMENTATION)/q' "$1"; }
[ -n "$one" ] || api_part ga2d_physics.h > "$OUT/api.orig"
IMPL_SRC=$(grep -l '^#define GA2D_IMPLEMENTATION' tests/test_*.c | xargs grep -L '^#define GA2D_STATIC')
OTHER_SRC=$(for f in tests/test_*.c; do case " $(echo $IMPL_SRC) " in *" $f "*) ;; *) echo "$f" ;; esac; done)

cflags() { # config -> flags
    case $1 in
    float) echo "-std=c99" ;;
    double) echo "-std=c99 -DGA2D_DOUBLE" ;;
    *) echo "mutate: unknown config $1" >&2; return 1 ;;
    esac
}

# Objects of the test files that do not compile the implementation, built
# once per configuration against the real header (-Werror: they are the
# suite as make test builds it).
base_objects() { # config
    b=$OUT/base-$1
    mkdir -p "$b" && flags=$(cflags "$1") || return 1
    for src in $OTHER_SRC; do
        o=$b/$(basename "$src" .c).o
        fresh=1
        for dep in "$src" ga2d_physics.h tests/*.h tests/fuzz/*.h; do [ "$o" -nt "$dep" ] || fresh=0; done
        [ $fresh = 1 ] && continue
        nice $CC $flags $OPT $WARN -Werror -I. -c "$src" -o "$o" || return 1
    done
}

# Builds the runner against the mutated header in $1/ (config $2): the
# implementation files always, the others only if the API part changed.
build_mutant() { # dir config
    flags=$(cflags "$2") || return 1
    objs=""
    if api_part "$1/ga2d_physics.h" | cmp -s - "$OUT/api.orig"; then
        for src in $OTHER_SRC; do objs="$objs $OUT/base-$2/$(basename "$src" .c).o"; done
        srcs=$IMPL_SRC
    else
        srcs="$IMPL_SRC $OTHER_SRC"
    fi
    for src in $srcs; do
        # -w: a planted bug may leave a variable unused; that is not the point
        nice $CC $flags $OPT -w -I"$1" -I. -c "$src" -o "$1/$(basename "$src" .c).o" || return 1
        objs="$objs $1/$(basename "$src" .c).o"
    done
    nice $CC $objs -o "$1/runner" -lm
}

# One mutant, start to end; its table row goes to $OUT/<name>/row.
one_mutant() { # name config
    d=$OUT/$1
    rm -rf "$d" && mkdir -p "$d" || return 1
    if ! awk -v mode=apply -v name="$1" -v out="$d/ga2d_physics.h" -f $DIR/mutate.awk $LIST ga2d_physics.h 2> "$d/apply.log"; then
        echo "BROKEN	$(cat "$d/apply.log")" > "$d/row"; return
    fi
    if cmp -s "$d/ga2d_physics.h" ga2d_physics.h; then
        echo "BROKEN	its from and to lines are the same" > "$d/row"; return
    fi
    if ! build_mutant "$d" "$2" > "$d/build.log" 2>&1; then
        echo "BROKEN	the mutated header does not build (see $d/build.log)" > "$d/row"; return
    fi
    # the suite runs from the repository root (it reads tests/fuzz/)
    if command -v timeout >/dev/null 2>&1; then
        TEST_FIRST_FAILURE=1 nice timeout "$TIMEOUT" "$d/runner" > "$d/run.log" 2>&1; status=$?
    else
        TEST_FIRST_FAILURE=1 nice "$d/runner" > "$d/run.log" 2>&1; status=$?
    fi
    by=$(sed -n 's/^not ok  \(.*\) ([0-9]* failed checks)$/\1/p' "$d/run.log" |
         awk 'NR <= 3 { printf "%s%s", (NR > 1 ? "; " : ""), $0 } END { if (NR > 3) printf "; and %d more", NR - 3 }')
    if [ "$status" -eq 0 ]; then
        echo "SURVIVED	($(tail -n 1 "$d/run.log"))" > "$d/row"; return
    fi
    if [ -z "$by" ]; then
        if [ "$status" -eq 124 ]; then by="the runner hung (killed after $TIMEOUT s)"
        else by="the runner crashed (exit $status): $(grep -v '^ga2d_physics' "$d/run.log" | tail -n 1)"; fi
    fi
    echo "caught	$by" > "$d/row"
    rm -f "$d"/*.o "$d/runner" # keep the logs, drop the bulk
}

# One mutant's table row, from $OUT/<name>/row.
row_of() { # name config
    if [ -f "$OUT/$1/row" ]; then r=$(cat "$OUT/$1/row"); else r="BROKEN	the mutant's run did not finish"; fi
    printf '%-40s %-7s %-9s %s\n' "$1" "$2" "$(printf '%s' "$r" | cut -f1)" "$(printf '%s' "$r" | cut -f2-)"
}

if [ -n "$one" ]; then
    one_mutant "$1" "$2"
    row_of "$1" "$2" # as each ends; the table below keeps the list's order
    exit 0
fi

start=$(date +%s)
for config in $(printf '%s\n' "$names" | cut -f2 | sort -u); do
    base_objects "$config" || { echo "mutate: the unmutated test files do not build ($config)"; exit 1; }
done
table=$OUT/table.txt
printf '%-40s %-7s %-9s %s\n' MUTANT CONFIG RESULT "CAUGHT BY"
# a pool of JOBS: a mutant starts as soon as one ends
printf '%s\n' "$names" | awk -F '\t' 'NF == 2 { print $1, $2 }' | xargs -P "$JOBS" -n 2 sh "$0" --one
printf '%-40s %-7s %-9s %s\n' MUTANT CONFIG RESULT "CAUGHT BY" > "$table"
printf '%s\n' "$names" | awk -F '\t' 'NF == 2 { print $1, $2 }' | while read -r n c; do row_of "$n" "$c"; done >> "$table"
caught=$(grep -c '^[^ ]*  *[^ ]*  *caught ' "$table")
survived=$(grep -c '^[^ ]*  *[^ ]*  *SURVIVED ' "$table")
broken=$(grep -c '^[^ ]*  *[^ ]*  *BROKEN ' "$table")
grep -E '^[^ ]+ +[^ ]+ +(SURVIVED|BROKEN) ' "$table"
echo "mutate: $caught caught, $survived survived, $broken broken; $JOBS at a time; $(( $(date +%s) - start )) s; the table is in $table"
[ "$survived" -eq 0 ] && [ "$broken" -eq 0 ]
