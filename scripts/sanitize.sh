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

# A corrupt length field in a rawlog makes MRPT allocate before it reads:
# ASan then returns null (bad_alloc, reported as an error) instead of aborting.
export ASAN_OPTIONS="allocator_may_return_null=1:max_allocation_size_mb=2048:detect_leaks=1:suppressions=$PWD/scripts/sanitize-suppressions.txt"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitize-suppressions.txt"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# rawlog-grabber is not built with ASan and cannot load the instrumented
# plugin (the ASan runtime must come first); the normal build runs that test.
ctest --test-dir build-asan --output-on-failure -j2 -E "RawlogGrabberRunsTheSensorPlugin" "$@"
