#!/usr/bin/env bash
# Frames/s of omnirange-scan on 1024x768 JPEG rawlogs on 1 and 2 threads:
# decoding alone, the whole image and only the box the scan reads
# (--decode-only, --whole-images), and scanning; checks that the scans of
# both decodes are the same, byte for byte.
#   tests/benchmarks/bench_scan.sh [FRAMES] [RUNS] [--fill FILE]   (after scripts/setup.sh)
# Each figure is the median of RUNS whole-process runs (wall-clock time).
# With --fill, the block between "<!-- bench_scan -->" and "<!-- end bench_scan -->"
# in FILE (docs/results.md) is made again from the table printed.
set -euo pipefail
cd "$(dirname "$0")/../.."
frames=${1:-200}; runs=${2:-5}; fill=""
[ "${3:-}" = "--fill" ] && fill=${4:?--fill needs a file}
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
common=(-i "$work/factory.rawlog" -c ini/factory.ini -H "$work/f.hist")
box=$("$apps/omnirange-scan" "${common[@]}" -o "$work/x.rawlog" --decode-only 2>&1 </dev/null |
  sed -n 's/.*the scan reads a \([0-9x]*\) box of the \([0-9x]*\) image (\([0-9.]*\) %).*/\1 box of \2, \3 %/p')
"$apps/omnirange-scan" -q "${common[@]}" -o "$work/region.rawlog" </dev/null
"$apps/omnirange-scan" -q "${common[@]}" -o "$work/whole.rawlog" --whole-images </dev/null
cmp -s "$work/region.rawlog" "$work/whole.rawlog" && same=yes || same=NO

fps() { echo "$frames / $1" | bc -l; }
table="| threads | decode whole | decode the box | scan (box) | scan / whole decode |
|---|---|---|---|---|"
for j in 1 2; do
  t_whole=$(timeit "$apps/omnirange-scan" -q "${common[@]}" -j "$j" -o "$work/x.rawlog" --decode-only --whole-images)
  t_box=$(timeit "$apps/omnirange-scan" -q "${common[@]}" -j "$j" -o "$work/x.rawlog" --decode-only)
  t_scan=$(timeit "$apps/omnirange-scan" -q "${common[@]}" -j "$j" -o "$work/scanned.rawlog")
  table+=$(printf '\n| %d | %.0f frames/s | %.0f frames/s | %.0f frames/s | %.2f |' "$j" \
    "$(fps "$t_whole")" "$(fps "$t_box")" "$(fps "$t_scan")" "$(echo "$t_whole / $t_scan" | bc -l)")
done
table+=$(printf '\n\n%d JPEG frames of the factory, median of %d runs; the scan reads a %s; scans of the box and of the whole image the same byte for byte: %s.' \
  "$frames" "$runs" "$box" "$same")
echo "$table"
if [ -n "$fill" ]; then
  grep -q '^<!-- bench_scan -->$' "$fill" && grep -q '^<!-- end bench_scan -->$' "$fill" ||
    { echo "bench_scan.sh: no '<!-- bench_scan -->' ... '<!-- end bench_scan -->' block in '$fill'" >&2; exit 1; }
  printf '%s\n' "$table" > "$work/table"
  awk -v t="$work/table" '
    /^<!-- bench_scan -->$/ {print; while ((getline l < t) > 0) print l; skip=1; next}
    /^<!-- end bench_scan -->$/ {skip=0}
    !skip' "$fill" > "$work/filled"
  cat "$work/filled" > "$fill"
fi
[ "$same" = yes ]
