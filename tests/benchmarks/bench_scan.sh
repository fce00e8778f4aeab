#!/usr/bin/env bash
# Frames/s of omnirange-scan on 1024x768 JPEG rawlogs with 2 threads, beside
# the frames/s of only reading and decoding the same images (--decode-only).
#   tests/benchmarks/bench_scan.sh [FRAMES] [RUNS]     (after scripts/setup.sh)
# Each figure is the median of RUNS whole-process runs (wall-clock time).
set -euo pipefail
cd "$(dirname "$0")/../.."
frames=${1:-200}; runs=${2:-5}
apps=build/apps
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT

"$apps/omnirange-sim" -q -w worlds/factory.world -r worlds/factory.route -c ini/robot-omnip2dx.ini \
  -f jpg -n "$frames" -o "$work/factory.rawlog"
"$apps/omnirange-train" -q -i "$work/factory.rawlog" -c ini/factory.ini -o "$work/f.hist" --every 4

median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
timeit() {  # prints the median wall time in seconds of "$@" over $runs runs
  for _ in $(seq "$runs"); do
    s=$(date +%s.%N); "$@" >/dev/null; e=$(date +%s.%N)
    echo "$e - $s" | bc -l
  done | median
}
common=(-q -i "$work/factory.rawlog" -c ini/factory.ini -H "$work/f.hist" -j 2)
t_decode=$(timeit "$apps/omnirange-scan" "${common[@]}" -o "$work/x.rawlog" --decode-only)
t_scan=$(timeit "$apps/omnirange-scan" "${common[@]}" -o "$work/scanned.rawlog")
printf 'frames: %d JPEG 1024x768, 2 threads, median of %d runs\n' "$frames" "$runs"
printf 'decode only : %.2f s  %6.1f frames/s\n' "$t_decode" "$(echo "$frames / $t_decode" | bc -l)"
printf 'scan        : %.2f s  %6.1f frames/s\n' "$t_scan" "$(echo "$frames / $t_scan" | bc -l)"
printf 'scan / decode-only throughput: %.1f %%\n' "$(echo "100 * $t_decode / $t_scan" | bc -l)"
