#!/bin/sh
# Runs each test binary given, shows its failures and its summary, and ends
# with the total over all of them: "N passed, N failed".  Exits non-zero if
# any test failed or any binary crashed (a sanitizer report aborts it).
passed=0; failed=0; crashed=0
start=$(date +%s)
for bin in "$@"; do
    name=$(basename "$bin")
    out=$(ASAN_OPTIONS=abort_on_error=0:detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "$bin" 2>&1)
    status=$?
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
echo "configurations: $#, crashed: $crashed, time: $(( $(date +%s) - start )) s"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
