#!/bin/sh
# make test-browser: the pyramid demo's animated SVG, rendered by headless
# Chromium at two moments (0.5 s and 8 s of its 11 s loop).  Checks that the
# pictures differ, that the top box is drawn where the simulation put it
# (its world position mapped through the SVG's viewBox), awake (orange) at
# first and asleep (grey) later, with nothing above it.  Not part of
# make test: it needs Debian's chromium and imagemagick.
set -eu
CHROME=$(command -v chromium || command -v chromium-browser || true)
[ -n "$CHROME" ] || { echo "test-browser needs a browser: apt-get install chromium"; exit 1; }
CONVERT=/usr/bin/convert
[ -x "$CONVERT" ] || { echo "test-browser needs imagemagick: apt-get install imagemagick"; exit 1; }
svg=build/pyramid.svg
[ -f "$svg" ] || { echo "run make demo first"; exit 1; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT

shot() { # virtual milliseconds, output png
    "$CHROME" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$profile" --hide-scrollbars --window-size=640,640 \
        --virtual-time-budget="$1" --screenshot="$2" "file://$PWD/$svg" >/dev/null 2>&1
    [ -s "$2" ] || { echo "no screenshot from chromium"; exit 1; }
}
shot 500 build/browser_0500ms.png
shot 8000 build/browser_8000ms.png

# world -> pixel: svg (x, -y), then viewBox (vx vy vw vh) onto 640 x 640
set -- $(sed -n 's/.*viewBox="\([^"]*\)".*/\1/p' "$svg" | head -n 1)
vx=$1 vy=$2 vw=$3 vh=$4
# the top box starts at (0, 19.5); the tests bound its drift to 3 cm, far
# inside its 0.5 m half-width, so its centre pixel is the box's
px=$(awk -v x=0 -v vx="$vx" -v vw="$vw" 'BEGIN { printf "%d", (x - vx) * 640 / vw }')
py=$(awk -v y=19.5 -v vy="$vy" -v vh="$vh" 'BEGIN { printf "%d", (-y - vy) * 640 / vh }')
above=$(awk -v y=21.0 -v vy="$vy" -v vh="$vh" 'BEGIN { printf "%d", (-y - vy) * 640 / vh }')
pixel() { "$CONVERT" "$1" -format "%[hex:p{$2,$3}]" info: | cut -c1-6 | tr 'A-F' 'a-f'; }
near() { # hex colours within 24 per channel
    awk -v a="$1" -v b="$2" 'function h(s, i) { return index("0123456789abcdef", substr(s, i, 1)) - 1 }
        function c(s, k) { return h(s, 2 * k + 1) * 16 + h(s, 2 * k + 2) }
        BEGIN { for (k = 0; k < 3; ++k) { d = c(a, k) - c(b, k); if (d > 24 || d < -24) exit 1 } }'
}
early=$(pixel build/browser_0500ms.png "$px" "$py")
late=$(pixel build/browser_8000ms.png "$px" "$py")
sky=$(pixel build/browser_8000ms.png "$px" "$above")
diff=$(compare -metric AE build/browser_0500ms.png build/browser_8000ms.png null: 2>&1 || true)
echo "top box at pixel ($px, $py): #$early at 0.5 s, #$late at 8 s; above it #$sky; $diff pixels differ"
fail=0
near "$early" e59e4c || { echo "FAIL: the top box is not awake (orange) at 0.5 s"; fail=1; }
near "$late" 9e9e9e || { echo "FAIL: the top box is not asleep (grey) at 8 s"; fail=1; }
near "$sky" fbfbf8 || { echo "FAIL: something is drawn above the top box"; fail=1; }
[ "${diff%% *}" -gt 0 ] 2>/dev/null || { echo "FAIL: the two moments look the same"; fail=1; }
[ $fail -eq 0 ] && echo "browser check passed: build/browser_0500ms.png, build/browser_8000ms.png"
exit $fail
