#!/usr/bin/env bash
# Configures and builds flume into build/ (Release) or, with --sanitize, build-sanitize/
# (AddressSanitizer + UndefinedBehaviorSanitizer).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--sanitize" ]; then
  # Build type None: the sanitizer flags of CMakeLists.txt alone (-O1 -g1).
  cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=None -DFLUME_SANITIZE=ON \
    -DFLUME_BUILD_BENCH=OFF >/dev/null
  cmake --build build-sanitize
else
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build
fi
