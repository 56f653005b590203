#!/usr/bin/env bash
# Quick start: install what is missing, build, run the default case into runs/<timestamp>/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
cmake --preset release > /dev/null
cmake --build --preset release -j"$(nproc)"
out="runs/default-$(date +%Y%m%d-%H%M%S)"
./build/release/silodem check cases/default.toml
./build/release/silodem run cases/default.toml --out "$out"
echo "results in $out"
