#!/usr/bin/env bash
# The main job on the embedded default: set up, then run the two experiments
# that reproduce the paper, the two hard worlds, the rooms held out (each until its first run) and the factory
# through a hyperbolic mirror
# (simulate -> train -> scan
# -> accuracy against the laser and the truth -> maps -> icp-slam -> report).
# Reports go to results/NAME/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
for experiment in maze factory office warehouse lab hallway library classroom canteen kitchen garage shop livingroom meetingroom reception studio nursery bakery workshop gym clinic gallery hotel laundry pharmacy bookshop factory-hyperbolic; do
  echo "== experiment: $experiment"
  build/apps/omnirange-experiment "ini/$experiment.ini"
done
echo "reports: results/{maze,factory,office,warehouse,lab,hallway,library,classroom,canteen,kitchen,garage,shop,livingroom,meetingroom,reception,studio,nursery,bakery,workshop,gym,clinic,gallery,hotel,laundry,pharmacy,bookshop,factory-hyperbolic}/report.md"
