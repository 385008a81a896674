#!/usr/bin/env bash
# Quick start, command 2: set up, build, and pass the whole test suite (ctest).
# .ci/run runs exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)"
