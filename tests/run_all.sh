#!/bin/sh
# Runs each test binary given, shows its failures and its summary, and ends
# with the total over all of them: "N passed, N failed".  Exits non-zero if
# any test failed or any binary crashed (a sanitizer report aborts it).
# The binaries run TEST_JOBS at a time (default: the processor count; each
# suite is one thread but for its thread-pool tests), their reports shown
# in the order given.
# sh run_all.sh --one <binary> <dir>: one binary, its output and status to
# <dir>/<name>.out and <dir>/<name>.status (how the pool below runs each)
if [ "$1" = --one ]; then
    name=$(basename "$2")
    ASAN_OPTIONS=abort_on_error=0:detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "$2" > "$3/$name.out" 2>&1
    echo $? > "$3/$name.status"
    exit 0
fi
JOBS=${TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
passed=0; failed=0; crashed=0
start=$(date +%s)
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
# the sanitizer builds run slowest: they start first, so that no core
# is left alone with one at the end
{ printf '%s\n' "$@" | grep asan; printf '%s\n' "$@" | grep -v asan; } |
    xargs -P "$JOBS" -I{} sh "$0" --one {} "$tmp"
for bin in "$@"; do
    name=$(basename "$bin")
    out=$(cat "$tmp/$name.out" 2>/dev/null)
    status=$(cat "$tmp/$name.status" 2>/dev/null || echo "not run")
    last=$(printf '%s\n' "$out" | tail -n 1)
    p=$(printf '%s\n' "$last" | sed -n 's/^\([0-9][0-9]*\) passed, \([0-9][0-9]*\) failed$/\1/p')
    f=$(printf '%s\n' "$last" | sed -n 's/^\([0-9][0-9]*\) passed, \([0-9][0-9]*\) failed$/\2/p')
    if [ -z "$p" ]; then
        printf '%s\n' "$out"
        printf '%-34s CRASHED (exit %s)\n' "$name" "$status"
        crashed=$((crashed + 1)); failed=$((failed + 1))
        continue
    fi
    printf '%s\n' "$out" | grep -E '^(not ok|  FAIL)' || true
    printf '%-34s %s\n' "$name" "$last"
    passed=$((passed + p)); failed=$((failed + f))
    if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
        printf '%-34s exited %s with no failed test\n' "$name" "$status"
        failed=$((failed + 1))
    fi
done
echo "configurations: $#, $JOBS at a time, crashed: $crashed, time: $(( $(date +%s) - start )) s"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
