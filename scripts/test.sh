#!/usr/bin/env bash
# Runs every test: the release build (warnings as errors) with all tests,
# an optimised build under AddressSanitizer and UBSan with the unit and
# the quick command-line tests (the "slow" ones, whole suites of sessions,
# run in the release pass), and each fuzzer (fuzz/) for a few seconds in a
# clang build of the libraries they need.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DAFFORD_WERROR=ON
cmake --build build -j "$jobs"

cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAFFORD_WERROR=ON \
      -DAFFORD_SANITIZE=ON -DAFFORD_BENCH=OFF
cmake --build build-asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -LE slow

ctest --test-dir build --output-on-failure -j "$jobs"

# libFuzzer comes with Debian's clang-14 (scripts/install.sh); without it
# the fuzzers are skipped, saying so.
if ! command -v clang++-14 >/dev/null || ! echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' |
     clang++-14 -x c++ -fsanitize=fuzzer -o /dev/null - 2>/dev/null; then
  echo "test.sh: fuzzers SKIPPED: clang++-14 with libFuzzer not found (scripts/install.sh installs it)" >&2
  exit 0
fi
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAFFORD_FUZZ=ON
cmake --build build-fuzz -j "$jobs"
ctest --test-dir build-fuzz --output-on-failure -j "$jobs" -L fuzz
