#!/usr/bin/env bash
# The main job on the embedded default: set up, then run the two experiments
# that reproduce the paper (simulate -> train -> scan -> accuracy -> maps ->
# icp-slam -> report). Reports go to results/maze/ and results/factory/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
for experiment in maze factory; do
  echo "== experiment: $experiment"
  build/apps/omnirange-experiment "ini/$experiment.ini"
done
echo "reports: results/maze/report.md results/factory/report.md"
