#!/usr/bin/env bash
# The README's picture: an omnicam image of the factory with its scan drawn
# on it (omnirange-tuner under Xvfb, the learned parameters and colour model
# of results/factory), beside the map the guarded matcher built from the
# omnicam's scans (results/factory/maps_guarded.png's last panel).
#   [FRAME=N] scripts/readme-picture.sh [OUT.png]    (after ./scripts/main.sh)
# Needs Debian's xvfb, xdotool, x11-apps and imagemagick.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"; apps="$src/build/apps"; run="$src/results/factory"
out=$(realpath -m "${1:-$src/docs/img/readme.png}")
work=$(mktemp -d)
. "$src/scripts/xvfb.sh"
tuner=""; xvfb=""
trap 'kill $tuner $xvfb 2>/dev/null || true; rm -rf "$work"' EXIT
start_xvfb 1600x1000x24
"$apps/omnirange-tuner" -i "$run/dataset/factory.rawlog" -c "$run/learned.ini" -H "$run/floor.hist" -f "${FRAME:-40}" \
  </dev/null >/dev/null 2>&1 & tuner=$!
win=$(timeout 30 xdotool search --sync --onlyvisible --name "omnirange-tuner" | head -1)
sleep 4
eval "$(xdotool getwindowgeometry --shell "$win")"
xwd -root -silent | /usr/bin/convert xwd:- -crop "${WIDTH}x${HEIGHT}+${X}+${Y}" +repage "$work/window.png"
# The image panel (its top left, 768 x 576), cropped to the mirror's disc.
/usr/bin/convert "$work/window.png" -crop 430x430+173+73 +repage -resize 376x376 "$work/omni.png"
/usr/bin/convert "$run/maps_guarded.png" -crop 500x376+1000+0 +repage "$work/map.png"
/usr/bin/convert "$work/omni.png" "$work/map.png" -background white -splice 8x0 +append "$out"
echo "picture: $out"
