#!/usr/bin/env bash
# Regenerates the datasets from the stock worlds with the stock robot.
#   scripts/make-datasets.sh           the full routes, into rawlogs/full/
#   scripts/make-datasets.sh samples   the small committed samples, into rawlogs/
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/apps/omnirange-sim ] || ./scripts/setup.sh

mode=${1:-full}
case "$mode" in
  full)    out=rawlogs/full; frames=0; suffix=""; format=png ;;
  samples) out=rawlogs; frames=20; suffix="-sample"; format=jpg ;;   # JPEG keeps them small
  *) echo "make-datasets: unknown mode '$mode' (full or samples)" >&2; exit 2 ;;
esac
mkdir -p "$out"
for world in factory maze campus; do
  [ -f "worlds/$world.world" ] || continue
  echo "== $world"
  build/apps/omnirange-sim -w "worlds/$world.world" -r "worlds/$world.route" \
    -c ini/robot-omnip2dx.ini -o "$out/$world$suffix.rawlog" -n "$frames" -f "$format"
done
