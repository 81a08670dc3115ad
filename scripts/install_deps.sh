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
  libhdf5-dev                             # checkpoints
  libgtest-dev                            # tests
  libbenchmark-dev                        # benchmarks
  python3 python3-matplotlib              # validation plots
  python3-h5py python3-vtk9               # tests: the outputs read by h5py and VTK's own readers
  clang-format                            # formatting check
  clang-14 libfuzzer-14-dev               # the case reader's fuzzer (fuzz/)
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
