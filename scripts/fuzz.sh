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
# Two things MRPT does with a corrupt rawlog end a libFuzzer run and cannot be
# changed here (docs/robustness.md): it decodes a JPEG stored inside the
# rawlog with libjpeg's default error handler, which calls exit(); and it
# grows containers element by element to a length read from the file, past
# libFuzzer's memory limit (the apps cap their address space and report it).
# The rawlog target therefore runs in fork mode and goes on past them; each
# input it kept is replayed, and only other kinds fail this script.
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/found/$t" "build-fuzz/artifacts/$t"
  rm -f "build-fuzz/artifacts/$t"/*
  echo "== fuzz_$t for $seconds s"
  extra=()
  [ "$t" = rawlog ] && extra=(-fork=1 -ignore_crashes=1)
  status=0
  "build-fuzz/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -malloc_limit_mb=4096 \
    -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t/" "${extra[@]}" \
    "build-fuzz/found/$t" "build-fuzz/fuzz/corpus/$t" >"build-fuzz/fuzz_$t.log" 2>&1 || status=$?
  grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|==[0-9]+==ERROR|SUMMARY)|#[0-9]+: .*exec/s" \
    "build-fuzz/fuzz_$t.log" | tail -3 || true
  jpeg=0; length=0; other=0
  for a in "build-fuzz/artifacts/$t"/*; do
    [ -e "$a" ] || continue
    replay=$("build-fuzz/fuzz/fuzz_$t" -rss_limit_mb=4096 -malloc_limit_mb=4096 "$a" 2>&1 || true)
    if grep -q "libjpeg" <<<"$replay"; then jpeg=$((jpeg + 1))
    elif grep -q "out-of-memory" <<<"$replay" && grep -q "mrpt::" <<<"$replay"; then length=$((length + 1))
    else other=$((other + 1)); echo "problem: $a"; fi
  done
  echo "inputs kept: $jpeg ended in libjpeg's exit(), $length grew an MRPT container past the memory limit, $other other"
  if [ "$t" != rawlog ] && [ $status -ne 0 ]; then echo "fuzz_$t found a problem: build-fuzz/fuzz_$t.log"; exit 1; fi
  [ $other -eq 0 ] || { echo "fuzz_$t found a problem: build-fuzz/fuzz_$t.log"; exit 1; }
done
