#!/usr/bin/env bash
# Opens a rawlog in MRPT's RawLogViewer under Xvfb, selects its second
# object and saves a screenshot: the check behind docs/img/rawlogviewer-omniscan.png.
#   scripts/rawlogviewer-screenshot.sh RAWLOG OUT.png
# Needs Debian's xvfb, xdotool, x11-apps and imagemagick.
set -euo pipefail
rawlog=$(realpath "$1"); out=$(realpath -m "$2")
plugin=$(realpath "$(dirname "$0")/../build/plugin/libomnirange.so")
. "$(dirname "$0")/xvfb.sh"
viewer=""
start_xvfb 1600x1000x24
trap 'kill $xvfb $viewer 2>/dev/null || true' EXIT
# MRPT 2.5.8 finds external images only when started from the rawlog's folder.
(cd "$(dirname "$rawlog")" && RawLogViewer -l "$plugin" "$(basename "$rawlog")" </dev/null >/dev/null 2>&1) & viewer=$!
sleep 6
for w in $(xdotool search --name "Tip of the Day" 2>/dev/null); do xdotool windowclose "$w" || true; done
main=$(xdotool search --name "RawlogViewer - Part of the MRPT project" | head -1)
xdotool windowsize "$main" 1580 980
sleep 2
xdotool mousemove 150 309 click 1   # the tree row of object [11], an OMNISCAN of the stock rawlogs
sleep 2
xwd -root -silent | /usr/bin/convert xwd:- "$out"
echo "screenshot: $out"
