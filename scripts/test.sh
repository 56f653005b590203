#!/usr/bin/env bash
# Builds (warnings as errors) and runs the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release > /dev/null
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)"
