#!/usr/bin/env bash
# omnirange-tuner on the factory sample at frame 5 (histogram trained on the
# sample, the ini's parameters), under Xvfb on a 1280x720 screen: the picture
# in docs/tuner.md.
#   scripts/tuner-screenshot.sh OUT.png
# Needs Debian's xvfb, xdotool, x11-apps and imagemagick, and a build in build/.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"; apps="$src/build/apps"; out=$(realpath -m "$1")
work=$(mktemp -d)
"$apps/omnirange-train" -q -i "$src/rawlogs/factory-sample.rawlog" -c "$src/ini/factory.ini" -o "$work/f.hist"
. "$src/scripts/xvfb.sh"
tuner=""; xvfb=""
trap 'kill $tuner $xvfb 2>/dev/null || true; rm -rf "$work"' EXIT
start_xvfb 1280x720x24
"$apps/omnirange-tuner" -i "$src/rawlogs/factory-sample.rawlog" -c "$src/ini/factory.ini" -H "$work/f.hist" -f 5 \
  </dev/null >/dev/null 2>&1 & tuner=$!
win=$(timeout 30 xdotool search --sync --onlyvisible --name "omnirange-tuner" | head -1)
sleep 3
xdotool mousemove 1279 719  # no tooltip in the picture
sleep 1
eval "$(xdotool getwindowgeometry --shell "$win")"
xwd -root -silent | /usr/bin/convert xwd:- -crop "${WIDTH}x${HEIGHT}+${X}+${Y}" +repage "$out"
echo "screenshot: $out (${WIDTH}x${HEIGHT})"
