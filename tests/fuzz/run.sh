#!/bin/sh
# make fuzz's runner (tests/fuzz/fuzz.mk sets the environment): runs each
# harness named, FUZZ_JOBS at a time (default: the processor count; every
# harness is one process on one core), then prints one summary line per
# harness in the order named.  Exits non-zero if any harness found a crash
# or a violated invariant.  A fixed campaign (FUZZ_FIXED non-empty) runs
# a set number of inputs from FUZZ_SEED on a fresh corpus: the inputs do
# not depend on the time taken, so running harnesses side by side changes
# none of them.
#   FUZZ_DIR=build/fuzz FUZZ_FIXED=1 FUZZ_SEED=1 sh tests/fuzz/run.sh world polygon_double
# Other settings: FUZZ_SECONDS (a timed run), FUZZ_NORAND (a command prefix
# that turns address randomization off), FUZZ_RUNS_<kind> (inputs per
# harness of that kind in a fixed campaign).
DIR=${FUZZ_DIR:-build/fuzz}
JOBS=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}
SECS=${FUZZ_SECONDS:-60}

# One harness, start to end; its summary line goes to $DIR/<harness>.line,
# its exit status to $DIR/<harness>.status.
one_harness() { # harness
    h=$1; kind=${h%_double}; corpus=$DIR/corpus/$h; log=$DIR/$h.log
    if [ -n "$FUZZ_FIXED" ]; then
        corpus=$DIR/fixed-corpus/$h; rm -rf "$corpus"
        runs=$(eval echo "\${FUZZ_RUNS_$kind:-}")
        [ -n "$runs" ] || { echo "fuzz: no FUZZ_RUNS_$kind set" > "$log"; echo 1 > "$DIR/$h.status"; return; }
        limit="-runs=$runs -seed=${FUZZ_SEED:-1} -reload=0"; run=$FUZZ_NORAND
    else
        limit="-max_total_time=$SECS"; run=""
    fi
    mkdir -p "$corpus" "tests/fuzz/seeds/$kind" "tests/fuzz/regress/$kind"
    # shellcheck disable=SC2086 # $run and $limit are word lists
    $run "./$DIR/fuzz_$h" $limit -timeout=20 -max_len=4096 -print_final_stats=1 \
        -artifact_prefix="$DIR/$h-" "$corpus" "tests/fuzz/seeds/$kind" "tests/fuzz/regress/$kind" \
        > "$log" 2>&1
    rc=$?
    done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -n 1)
    if [ $rc -ne 0 ] || [ -z "$done_line" ]; then
        printf 'fuzz %-16s FAILED (exit %s): see %s and %s-crash-*\n' "$h" "$rc" "$log" "$DIR/$h" > "$DIR/$h.line"
        echo 1 > "$DIR/$h.status"; return
    fi
    execs=$(grep -E '^stat::number_of_executed_units:' "$log" | awk '{print $2}')
    field() { printf '%s\n' "$done_line" | sed -n "s/.*$1 \\([^ ]*\\).*/\\1/p"; }
    printf 'fuzz %-16s %10s executions  cov: %-5s ft: %-6s corpus: %-12s %s exec/s\n' \
        "$h" "$execs" "$(field 'cov:')" "$(field ' ft:')" "$(field ' corp:')" "$(field ' exec\/s:')" > "$DIR/$h.line"
    echo 0 > "$DIR/$h.status"
}

# sh run.sh --one <harness>: one harness (how the pool below runs each)
if [ "$1" = --one ]; then one_harness "$2"; exit 0; fi

mkdir -p "$DIR" || exit 1
for h in "$@"; do
    [ -x "$DIR/fuzz_$h" ] || { echo "fuzz: $DIR/fuzz_$h is not built"; exit 1; }
    rm -f "$DIR/$h.line" "$DIR/$h.status"
done
start=$(date +%s)
if [ -n "$FUZZ_FIXED" ]; then what="fixed campaign from seed ${FUZZ_SEED:-1}"; else what="$SECS s per harness"; fi
echo "== fuzz: $# harnesses ($what), $JOBS at a time"
# a pool of JOBS: a harness starts as soon as one ends
printf '%s\n' "$@" | xargs -P "$JOBS" -n 1 sh "$0" --one
status=0
for h in "$@"; do
    [ "$(cat "$DIR/$h.status" 2>/dev/null)" = 0 ] && continue
    status=1; echo "== fuzz $h:"; tail -n 40 "$DIR/$h.log"
done
echo "== fuzz summary ($what, $JOBS at a time, $(( $(date +%s) - start )) s)"
for h in "$@"; do cat "$DIR/$h.line" 2>/dev/null || echo "fuzz $h: the run did not finish"; done
exit $status
