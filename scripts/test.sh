#!/usr/bin/env bash
# Runs every test: the release build (warnings as errors) with all its
# tests; then one clang build under AddressSanitizer and UBSan with the
# unit and the quick command-line tests (the "slow" ones, whole suites of
# sessions, run in the release pass) and each fuzzer (fuzz/) for a few
# seconds, all on the same instrumented libraries. Line tables only, for
# the sanitizers' stack traces: full debug information doubled the build.
# docs/performance.md gives what each step costs.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DAFFORD_WERROR=ON -DAFFORD_UNITY=ON
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"

sanitized=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DAFFORD_BENCH=OFF -DAFFORD_WERROR=ON -DAFFORD_UNITY=ON)
# libFuzzer comes with Debian's clang-14 (scripts/install.sh); without it
# the same tree is built by the default compiler without the fuzzers,
# saying so.
if command -v clang++-14 >/dev/null && echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' |
     clang++-14 -x c++ -fsanitize=fuzzer -o /dev/null - 2>/dev/null; then
  export CC=clang-14 CXX=clang++-14
  sanitized+=(-DAFFORD_FUZZ=ON -DFUZZ_SECONDS=5 "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG")
else
  echo "test.sh: fuzzers SKIPPED: clang++-14 with libFuzzer not found (scripts/install.sh installs it)" >&2
  sanitized+=(-DAFFORD_SANITIZE=ON "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
fi
cmake -S . -B build-asan -G Ninja "${sanitized[@]}"
cmake --build build-asan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -LE slow
