#!/usr/bin/env bash
# Builds the case reader's fuzzer (fuzz/) with clang + libFuzzer under ASan and UBSan and runs
# it for a bounded time (default 60 s, or the first argument) from the corpus in fuzz/corpus
# and the bundled cases. New inputs it finds go to a scratch copy (build-fuzz/corpus), not into
# the repository; a finding fails the script, and its input is left in build-fuzz/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=None >/dev/null
cmake --build build-fuzz
rm -rf build-fuzz/corpus
mkdir -p build-fuzz/corpus
cp fuzz/corpus/* build-fuzz/corpus/
cd build-fuzz
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ./fuzz_case_reader -max_total_time="$seconds" -max_len=8192 -timeout=10 \
  -dict=../fuzz/case.dict -print_final_stats=1 corpus ../cases 2>&1 | tail -n 25
