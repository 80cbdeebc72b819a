#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release); further
# arguments go to the configure step (e.g. -DSTRATUM_UNIT_TESTS=OFF).
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
shift || true
cmake --preset "$preset" "$@" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
