#!/usr/bin/env bash
# The main job, a newcomer's first run: set up (packages, build), then the
# paper's two worlds, the maze and the factory, end to end (simulate, learn
# and train, scan, accuracy against the laser and the truth, maps with true
# poses, icp-slam and the odometry-guarded matcher, a report each), and a
# summary on the terminal. About two minutes after set-up on 2 cores.
# Every other world: scripts/benchmark.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/run-suite.sh main
echo "reports: results/maze/report.md, results/factory/report.md"
