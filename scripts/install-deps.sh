#!/usr/bin/env bash
# Installs the Debian 12 packages stratum needs, when missing (run as root).
# With --test, also what only the tests need: headless Chromium and Selenium
# to open the report page, clang and its libFuzzer runtime for the fuzz
# targets (docs/fuzzing.md), clang-format and clang-tidy for the layout and
# lint checks (.clang-format, .clang-tidy).
set -euo pipefail
packages=(cmake ninja-build g++ git libboost-dev libboost-math-dev libtbb-dev libfmt-dev nlohmann-json3-dev
  libcli11-dev libgtest-dev libbenchmark-dev python3-dev python3-numpy python3-scipy python3-pybind11
  pybind11-dev python3-pytest python3-matplotlib libembree-dev libopenimageio-dev
  libpng-dev libopenexr-dev libopenmpi-dev openmpi-bin libkissfft-dev)
if [ "${1:-}" = --test ]; then packages+=(chromium chromium-driver python3-selenium python3-dask clang libclang-rt-14-dev clang-format clang-tidy); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
