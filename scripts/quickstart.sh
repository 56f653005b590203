#!/usr/bin/env bash
# Quick start: install what is missing, build, run the default case into runs/<timestamp>/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
cmake --preset release > /dev/null
cmake --build --preset release -j"$(nproc)"
out="runs/default-$(date +%Y%m%d-%H%M%S)"
./build/release/silodem check cases/default.toml
rc=0
./build/release/silodem run cases/default.toml --out "$out" || rc=$?
# Exit 4: the flow stopped (no outflow for stall_time) or max_time came, with every file written;
# the default case sits close to where its outlet arches (docs/validation/flow-or-arch.md 4.7).
if [ $rc -eq 4 ]; then
  echo "the run ended before the silo emptied (flow stopped or max_time; exit 4); results in $out"
elif [ $rc -ne 0 ]; then
  exit $rc
else
  echo "results in $out"
fi
