#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer (GCC)
# in build-asan/ and runs the test suite there. Any sanitizer report fails the
# test that caused it (-fno-sanitize-recover). Takes about ten times the normal
# build and a few times the normal test run; not part of .ci/run.
#
#   scripts/sanitize.sh [extra ctest arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh >/dev/null

cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOMNIRANGE_SANITIZE=address,undefined \
  -DOMNIRANGE_BUILD_BENCHMARKS=OFF
cmake --build build-asan -j2

# malloc may fail (the fuzz targets' allocation limit relies on it, and the
# apps report a failed allocation as an error).
export ASAN_OPTIONS="allocator_may_return_null=1:detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitize-suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# rawlog-grabber is not built with ASan and cannot load the instrumented
# plugin (the ASan runtime must come first); the normal build runs that test.
ctest --test-dir build-asan --output-on-failure -j2 -E "RawlogGrabberRunsTheSensorPlugin" "$@"
