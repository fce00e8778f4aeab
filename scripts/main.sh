#!/usr/bin/env bash
# The main job on the embedded default: set up, then run the rangefinder on
# one 1024x768 frame with the paper's parameters and print its speed.
# (It grows into the full experiment as the simulator and apps land.)
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
build/tests/benchmarks/omnirange_bench_rangefinder \
  --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
