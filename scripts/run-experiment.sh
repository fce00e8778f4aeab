#!/usr/bin/env bash
# One experiment of ini/suite.txt, as run-suite.sh hands it to GNU parallel:
#   run-experiment.sh NAME RESULTS_DIR [FRAMES]
# Its report goes to RESULTS_DIR/NAME, its output to RESULTS_DIR/logs/NAME.log
# (with SHOW=1 to the terminal instead); one line says how it ended.
set -uo pipefail
cd "$(dirname "$0")/.."
name=$1; results=$2; frames=${3:-}
args=("ini/$name.ini" -o "$results/$name")
[ -n "$frames" ] && args+=(-n "$frames")
if [ "${SHOW:-0}" = 1 ]; then
  echo "== experiment $name"
  build/apps/omnirange-experiment "${args[@]}" </dev/null
  exit
fi
log=$results/logs/$name.log
build/apps/omnirange-experiment "${args[@]}" </dev/null >"$log" 2>&1
status=$?
if [ $status -eq 0 ]; then echo "$name done"; else echo "$name FAILED: $(tail -1 "$log")"; fi
exit $status
