#!/bin/sh
# ab_header.sh - the working tree's ga2d_physics.h against the header of an
# earlier commit, on box scenes of scenes.h, in one run, two ways:
#   runs   the two builds of bench_scenes.c (the same driver, built
#          -DBENCH_BOXES_ONLY with the project's flags, so it needs nothing
#          from after shapes) take turns, one whole run each per round, the
#          order swapped every round: per scene and build the median and
#          minimum ms/step over the rounds, and new / old;
#   steps  ab_steps.c steps a world of each build in turn, one step each
#          (ab_world.c built once per header), the first swapped every
#          step, so even a short slow spell of the machine falls on both:
#          the medians over the rounds, and the median of new / old over
#          every pair of steps.
# Both say whether the two builds' accuracy figures are the same bits (ga2d
# is deterministic: a change that keeps a scene's bits gives the same
# figure).
#
#   sh tests/bench/ab_header.sh [COMMIT [ROUNDS [scene ...]]]
#
# COMMIT defaults to 21b9092 (before shapes), ROUNDS to 5, the scenes to
# large_pyramid and many_pyramids.  AB_FULL=1 builds both drivers with every
# scene (rain, mixed_pile, joint_grid too): for a COMMIT with joints; the
# steps measure skips a scene whose bodies come and go (rain, mixed_pile)
# or that has a chain (spinner), and says so.  Run from the repository's top.  Writes
# $AB_DIR (default build/bench/ab): the two headers as built, the
# binaries, ab.csv (runs: round, build, scene, ms/step, figure) and
# steps.txt (steps: every round).
set -eu

COMMIT=${1:-21b9092}
ROUNDS=${2:-5}
[ $# -gt 2 ] && shift 2 || set --
SCENES=${*:-large_pyramid many_pyramids}
DIR=${AB_DIR:-build/bench/ab}
case $DIR in /*) BIN=$DIR ;; *) BIN=./$DIR ;; esac
CC=${CC:-gcc}
OPT="-O2 -g -ffp-contract=off"
WARN="-Wall -Wextra -Wpedantic -Wshadow -Wdouble-promotion -Werror"

[ -f ga2d_physics.h ] && [ -f tests/bench/bench_scenes.c ] || { echo "ab_header.sh: run it from the repository's top" >&2; exit 2; }
mkdir -p "$(dirname "$DIR")"
# one run at a time per folder: two would share the binaries and the CSVs,
# and each would load the machine under the other's clock
mkdir "$DIR.lock" 2>/dev/null || {
    echo "ab_header.sh: $DIR is in use by another run (remove $DIR.lock if none is), or set AB_DIR" >&2
    exit 1
}
trap 'rmdir "$DIR.lock"' EXIT
trap 'exit 130' INT TERM
mkdir -p "$DIR/old" "$DIR/new"
git show "$COMMIT:ga2d_physics.h" > "$DIR/old/ga2d_physics.h"
# the working tree's header as it is now: an edit during the run changes nothing
cp ga2d_physics.h "$DIR/new/ga2d_physics.h"
[ "${AB_FULL:-0}" = 1 ] && ONLY=-DAB_FULL || ONLY=-DBENCH_BOXES_ONLY
for b in old new; do
    # bench_scenes.c includes "ga2d_physics.h": its own folder has none, so -I picks the build's
    $CC -std=c99 $OPT $WARN $ONLY -I"$DIR/$b" tests/bench/bench_scenes.c -o "$DIR/bench_$b" -lm
    $CC -std=c99 $OPT $WARN $ONLY -DAB_SIDE=$b -I"$DIR/$b" -c tests/bench/ab_world.c -o "$DIR/ab_$b.o"
done
$CC -std=c99 $OPT $WARN -c tests/bench/ab_steps.c -o "$DIR/ab_steps.o"
$CC "$DIR/ab_steps.o" "$DIR/ab_old.o" "$DIR/ab_new.o" -o "$DIR/ab_steps" -lm
echo "ab_header: old = $COMMIT:ga2d_physics.h ($(sha1sum < "$DIR/old/ga2d_physics.h" | cut -c1-12)), new = working tree" \
     "($(git rev-parse --short HEAD)$(git diff --quiet HEAD -- ga2d_physics.h || echo ' + edits'), $(sha1sum < "$DIR/new/ga2d_physics.h" | cut -c1-12))"
echo "  $ROUNDS rounds; scenes: $SCENES"
echo "  $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"

echo "round,build,scene,ms_per_step,figure" > "$DIR/ab.csv"
r=1
while [ "$r" -le "$ROUNDS" ]; do
    if [ $((r % 2)) -eq 1 ]; then order="old new"; else order="new old"; fi
    for b in $order; do
        # shellcheck disable=SC2086 # the scene names are words
        BENCH_RUNS=1 "$BIN/bench_$b" "$DIR/run.csv" $SCENES > /dev/null || { echo "ab_header: $b failed" >&2; exit 1; }
        awk -F, -v r="$r" -v b="$b" 'NR > 1 { print r "," b "," $1 "," $3 "," $6 }' "$DIR/run.csv" >> "$DIR/ab.csv"
    done
    printf '  round %d done (%s), load %s\n' "$r" "$order" "$(cut -d' ' -f1 /proc/loadavg)"
    r=$((r + 1))
done

echo
echo "runs: one run of each build per round"
echo "| scene | old ms/step median (min) | new ms/step median (min) | new / old (medians) | figures |"
echo "|---|---|---|---|---|"
for s in $SCENES; do
    stat() { # median and minimum of build $1's times for scene $s
        awk -F, -v b="$1" -v s="$s" '$2 == b && $3 == s { print $4 }' "$DIR/ab.csv" | sort -g |
            awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; print m, v[1] }'
    }
    set -- $(stat old) $(stat new)
    same=$(awk -F, -v s="$s" '$3 == s { print $5 }' "$DIR/ab.csv" | sort -u | wc -l)
    [ "$same" -eq 1 ] && figs="the same bits" || figs="DIFFER"
    awk -v s="$s" -v om="$1" -v ol="$2" -v nm="$3" -v nl="$4" -v f="$figs" \
        'BEGIN { printf "| %s | %.3f (%.3f) | %.3f (%.3f) | %.3f | %s |\n", s, om, ol, nm, nl, nm / om, f }'
done
echo "per-round times: $DIR/ab.csv"

echo
echo "steps: the two builds stepped in turn, $ROUNDS rounds (load $(cut -d' ' -f1 /proc/loadavg))"
# shellcheck disable=SC2086 # the scene names are words
"$BIN/ab_steps" "$ROUNDS" $SCENES > "$DIR/steps.txt" || { cat "$DIR/steps.txt"; echo "ab_header: ab_steps failed" >&2; exit 1; }
sed -n '/^| scene/,$p' "$DIR/steps.txt"
echo "every round: $DIR/steps.txt; load at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
