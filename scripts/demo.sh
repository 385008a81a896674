#!/usr/bin/env bash
# Quick start, command 1: set up, build, and wind a real reel from cases/.
#   bash scripts/demo.sh [SCENE]     (default: cases/newsprint-rider.yaml)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
scene="${1:-cases/newsprint-rider.yaml}"
name="$(basename "$scene" .yaml)"
./build/reelsim run "$scene" -o "build/$name.h5"
echo "demo: wrote build/$name.h5 (inspect with: h5dump -H build/$name.h5)"
