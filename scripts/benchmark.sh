#!/usr/bin/env bash
# The full suite: every experiment of ini/suite.txt (the paper's worlds, the
# hard ones, the held-out rooms, the hyperbolic mirror), as many at once as
# the machine has cores; about 15 minutes on 2 cores after set-up. Writes
# results/suite-summary.md and .csv. With --docs it then copies the CSV to
# docs/results/suite.csv and makes the tables of docs/results.md and
# README.md again from it.
set -euo pipefail
cd "$(dirname "$0")/.."
docs=false
[ "${1:-}" = "--docs" ] && docs=true
./scripts/setup.sh
./scripts/run-suite.sh -o results/suite-summary
if $docs; then
  mkdir -p docs/results
  cp results/suite-summary.csv docs/results/suite.csv
  build/apps/omnirange-summary --csv docs/results/suite.csv --fill docs/results.md --fill README.md
fi
