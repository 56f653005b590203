#!/usr/bin/env bash
# Fuzzes the case-file loader with libFuzzer (clang 14, ASan + UBSan) for SECONDS (default 60).
# Seed corpus: the project's own case files. tests/fuzz/regressions/ holds inputs that once
# crashed it (fixed since); they are replayed first and must pass.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
cmake --preset fuzz > /dev/null
cmake --build --preset fuzz -j"$(nproc)"
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp cases/*.toml cases/paper/*.toml tests/data/*.toml "$corpus"/
export ASAN_OPTIONS=detect_leaks=1
if compgen -G "tests/fuzz/regressions/*" > /dev/null; then
  ./build/fuzz/fuzz_case_loader tests/fuzz/regressions/*
fi
./build/fuzz/fuzz_case_loader -max_total_time="$seconds" -max_len=8192 -timeout=10 \
  -print_final_stats=1 "$corpus"
