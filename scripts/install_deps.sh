#!/usr/bin/env bash
# Installs every build, test and plotting dependency of flume from Debian 12 packages.
# Safe to run again: it installs only what is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build git   # compiler and build
  libtomlplusplus-dev                     # case files
  libcli11-dev                            # command line
  libfmt-dev                              # formatting
  nlohmann-json3-dev                      # summary.json, results.json
  libgtest-dev                            # tests
  libbenchmark-dev                        # benchmarks
  python3 python3-matplotlib              # validation plots
  clang-format                            # formatting check
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install_deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install_deps: done"
