#!/usr/bin/env bash
# The main job on built-in defaults: installs what is missing, builds, lists
# the registry and writes 256 points of every sampler to out/ (seconds), then
# runs `stratum report`: the lecture reproduced in report/index.html (every
# section's figures and measurements, ≤ 10 minutes on 2 cores; docs/report.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release -DSTRATUM_UNIT_TESTS=OFF  # the job runs no gtests: not built (as in run-tests.sh)
bash scripts/demo.sh build/release/bin/stratum out
build/release/bin/stratum report -o report
