#!/usr/bin/env bash
# scripts/run-suite.sh runs the main group's two experiments through GNU
# parallel, a job each, two at a time: one line per experiment as it ends,
# the summary of both, and the same figures as omnirange-experiment run by
# hand on the same ini and frames.
#   run_suite_test.sh SOURCE_DIR BUILD_APPS_DIR WORK_DIR
set -euo pipefail
source_dir=$1; apps=$2; work=$3
rm -rf "$work"; mkdir -p "$work"
"$source_dir/scripts/run-suite.sh" -j 2 -r "$work/results" -n 30 main >"$work/out.txt" 2>&1 || {
  cat "$work/out.txt"; echo "FAIL: run-suite.sh exited non-zero"; exit 1; }
for name in maze factory; do
  grep -Eq "^\[[12]/2\] $name done " "$work/out.txt" || { cat "$work/out.txt"; echo "FAIL: no line for $name"; exit 1; }
  [ -f "$work/results/$name/metrics.ini" ] || { echo "FAIL: no report for $name"; exit 1; }
done
rows=$(cut -d, -f1 "$work/results/main-summary.csv" | tail -n +2 | xargs)
[ "$rows" = "maze factory" ] || { echo "FAIL: summary rows '$rows'"; exit 1; }
# By hand: the same figures (the run's clock aside).
"$apps/omnirange-experiment" -q "$source_dir/ini/maze.ini" -n 30 -o "$work/by_hand" </dev/null
if ! diff <(grep -v '^seconds' "$work/results/maze/metrics.ini") <(grep -v '^seconds' "$work/by_hand/metrics.ini"); then
  echo "FAIL: the suite's maze figures differ from a run by hand"; exit 1
fi
echo "PASS"
