#!/usr/bin/env bash
# Installs the dependencies, builds flume and runs the whole test suite: the GoogleTest suite
# (Release), the same suite under AddressSanitizer + UndefinedBehaviorSanitizer, the formatting
# check, and the quick validation set beside the case reader's fuzzer for a minute.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh

# The test suites run one test at a time: each test already uses both cores through OpenMP.
echo "== build (Release) and tests"
bash scripts/build.sh
ctest --test-dir build --output-on-failure

# Under the sanitizers each level is one process (tests/CMakeLists.txt), and the `settling`
# tests are left out (still tanks run for thousands of steps, 60-110 s each there, 13 of the
# suite's 14 minutes): their code paths run there in the short tests, their physics in the
# Release suite above. The suite takes about 2.5 minutes.
echo "== build with AddressSanitizer + UndefinedBehaviorSanitizer, and tests"
bash scripts/build.sh --sanitize
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure --label-exclude settling

echo "== formatting (clang-format)"
files=$(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find src tests bench -name '*.[ch]pp')
clang-format --dry-run --Werror $files

# The fuzzer (one process, one core) runs beside the quick validation (two one-thread cases at
# a time) rather than before it: its minute then costs CI little wall time of its own. Its
# output is printed once both have ended; either failing fails the script.
echo "== fuzzing the case reader and --set (libFuzzer, ASan + UBSan, 60 s), beside the quick validation"
bash scripts/fuzz.sh 60 >build/fuzz.log 2>&1 &
fuzz_pid=$!

# Two cases at once, one thread each: the quick set's coarse runs gain nothing from a second
# thread (README, `--jobs`).
echo "== quick validation (flume validate --quick --jobs 2)"
validate_status=0
./build/flume validate --quick --jobs 2 --out build/validation-quick || validate_status=$?
fuzz_status=0
wait "$fuzz_pid" || fuzz_status=$?
echo "== the fuzzer's output"
cat build/fuzz.log
[ "$fuzz_status" -eq 0 ] || echo "FAILED: the fuzzer (scripts/fuzz.sh, exit status $fuzz_status)"
[ "$validate_status" -eq 0 ] || echo "FAILED: the quick validation (exit status $validate_status)"
[ "$fuzz_status" -eq 0 ] && [ "$validate_status" -eq 0 ]
