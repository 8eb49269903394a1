#!/bin/sh
# make mutate: plants each bug of tests/mutate/mutants.txt, one at a time,
# in a copy of ga2d_physics.h, builds the test runner against the copy and
# runs the whole suite, which must fail (a test fails, or the runner
# crashes or hangs).  Prints a table of the mutants and the tests that
# caught them; exits non-zero if any mutant survived, or if a mutant's
# "from" text is not in the header exactly once (the mutant rotted), or if
# a mutated copy does not compile.
#   sh tests/mutate/run.sh [NAME ...]     (every mutant, or those named)
# Runs from the repository root, MUTATE_JOBS mutants at a time (default:
# the processor count).  Needs only sh, awk, sed, cmp and a C compiler.
CC=${CC:-gcc}
OPT="-O2 -ffp-contract=off"
WARN="-Wall -Wextra -Wpedantic -Wshadow -Wdouble-promotion"
DIR=tests/mutate
OUT=build/mutate
LIST=$DIR/mutants.txt
TIMEOUT=${MUTATE_TIMEOUT:-600} # seconds; the whole suite runs in well under a minute
JOBS=${MUTATE_JOBS:-$(nproc 2>/dev/null || echo 2)}
mkdir -p "$OUT" || exit 1

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

# The part of the header before the implementation (declarations and
# inline code every test file sees): when a mutant leaves it alone, only
# the file that compiles the runner's implementation (test_main.c) is
# rebuilt.  test_config.c compiles a private GA2D_STATIC copy of the
# library for its checks of the configuration macros; it is built once
# against the real header, like the other files (it tests no physics, and
# building it per mutant would cost a third more time).
api_part() { sed '/^#if defined(GA2D_IMPLEMENTATION)/q' "$1"; }
api_part ga2d_physics.h > "$OUT/api.orig"
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
        nice timeout "$TIMEOUT" "$d/runner" > "$d/run.log" 2>&1; status=$?
    else
        nice "$d/runner" > "$d/run.log" 2>&1; status=$?
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

start=$(date +%s)
for config in $(printf '%s\n' "$names" | cut -f2 | sort -u); do
    base_objects "$config" || { echo "mutate: the unmutated test files do not build ($config)"; exit 1; }
done
table=$OUT/table.txt
printf '%-40s %-7s %-9s %s\n' MUTANT CONFIG RESULT "CAUGHT BY" | tee "$table"
batch=""
flush() {
    wait
    for n in $batch; do
        c=$(printf '%s\n' "$names" | awk -F '\t' -v n="$n" '$1 == n { print $2 }')
        if [ -f "$OUT/$n/row" ]; then r=$(cat "$OUT/$n/row"); else r="BROKEN	the mutant's run did not finish"; fi
        printf '%-40s %-7s %-9s %s\n' "$n" "$c" "$(printf '%s' "$r" | cut -f1)" "$(printf '%s' "$r" | cut -f2-)" | tee -a "$table"
    done
    batch=""
}
running=0
tab=$(printf '\t')
for line in $(printf '%s\n' "$names" | tr "$tab" ':'); do
    name=${line%%:*}
    config=${line#*:}
    one_mutant "$name" "$config" &
    batch="$batch $name"
    running=$((running + 1))
    if [ "$running" -ge "$JOBS" ]; then flush; running=0; fi
done
flush
caught=$(grep -c '^[^ ]*  *[^ ]*  *caught ' "$table")
survived=$(grep -c '^[^ ]*  *[^ ]*  *SURVIVED ' "$table")
broken=$(grep -c '^[^ ]*  *[^ ]*  *BROKEN ' "$table")
echo "mutate: $caught caught, $survived survived, $broken broken; $(( $(date +%s) - start )) s; the table is in $table"
[ "$survived" -eq 0 ] && [ "$broken" -eq 0 ]
