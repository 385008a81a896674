#!/usr/bin/env bash
# Quick start, command 2: set up, build, and pass the whole test suite (ctest).
# .ci/run runs exactly this. Three passes:
#   1. the normal build (build/): every test, plus the unit tests again under valgrind;
#   2. an AddressSanitizer + UBSan build (build-asan/): every test, any report fails it;
#   3. the scene loader and the HDF5 reader fuzzed with libFuzzer, 60 s between them
#      (build-fuzz/, clang; scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
echo "reelsim test.sh: the three passes take about 15-20 minutes on 2 cores (setup.sh's first"
echo "build longer); a failure stops it at once"
bash scripts/setup.sh
echo "== tests (build/) =="
(cd build && ctest --output-on-failure -j "$(nproc)" | tee ctest-summary.log)

echo "== tests under AddressSanitizer + UBSan (build-asan/) =="
# built for the baseline x86-64 (REELSIM_SIMD off), as the portable build is: its functions
# compiled for both AVX2 and the baseline (src/util/vector_clones.h) run here too
RS_BUILD_DIR=build-asan RS_BUILD_TYPE=Debug \
  RS_CMAKE_ARGS="-DREELSIM_SANITIZE=ON -DREELSIM_BENCH=OFF -DREELSIM_SIMD=OFF" \
  bash scripts/setup.sh
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
(cd build-asan && ctest --output-on-failure -j "$(nproc)" | tee ctest-summary.log)

echo "== fuzzing the scene loader and the HDF5 reader (build-fuzz/) =="
bash scripts/fuzz.sh "${RS_FUZZ_SECONDS:-60}"

# One closing line for both ctest passes (a failure above has already stopped the script).
total=0
for log in build/ctest-summary.log build-asan/ctest-summary.log; do
  n=$(sed -n 's/.*tests passed, 0 tests failed out of \([0-9]*\).*/\1/p' "$log")
  total=$((total + ${n:-0}))
done
echo "tests: $total passed, 0 failed"
