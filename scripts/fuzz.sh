#!/usr/bin/env bash
# Longer fuzzing: every fuzz target as a libFuzzer program (clang, with
# AddressSanitizer and UndefinedBehaviorSanitizer) in build-fuzz/, each run
# for SECONDS from the seed corpus. New inputs that reach new code collect in
# build-fuzz/found/TARGET; a crash leaves crash-* / timeout-* / oom-* files in
# the current folder, to be replayed with `build-fuzz/fuzz/fuzz_TARGET FILE`.
#
#   scripts/fuzz.sh [SECONDS (default 60)] [TARGET...]   e.g. scripts/fuzz.sh 600 rawlog
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(histogram rangefinder_ini robot_ini experiment_ini world route rawlog)

missing=()
for p in clang libclang-rt-14-dev libmrpt-dev libopencv-dev libopencv-contrib-dev zlib1g-dev cmake; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOMNIRANGE_FUZZ=ON \
  -DOMNIRANGE_SANITIZE=address,undefined -DOMNIRANGE_BUILD_TESTS=OFF -DOMNIRANGE_BUILD_BENCHMARKS=OFF
cmake --build build-fuzz -j2 --target "${targets[@]/#/fuzz_}"

# fuzz/AllocationLimit.cpp turns an allocation over 1 GiB into bad_alloc;
# libFuzzer's own malloc limit is set above that.
export ASAN_OPTIONS="allocator_may_return_null=1:max_allocation_size_mb=2048"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/found/$t"
  echo "== fuzz_$t for $seconds s"
  status=0
  "build-fuzz/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -malloc_limit_mb=4096 \
    -print_final_stats=1 "build-fuzz/found/$t" "build-fuzz/fuzz/corpus/$t" >"build-fuzz/fuzz_$t.log" 2>&1 || status=$?
  grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|==[0-9]+==ERROR|SUMMARY)" "build-fuzz/fuzz_$t.log" || true
  [ $status -eq 0 ] || { echo "fuzz_$t found a problem: build-fuzz/fuzz_$t.log"; exit 1; }
done
