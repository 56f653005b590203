#!/usr/bin/env bash
# silodem against LIGGGHTS 3.8.0 on the same settled silo bed (README.md beside this file).
# Installs Debian's liggghts if it is missing, builds silodem, and runs liggghts_bench.py with the
# given arguments (default: the paper's L3-I2 at k = 3, dry, 2000 steps). Not part of CI.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
if ! command -v liggghts > /dev/null; then
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y liggghts
fi
cmake -S "$root" --preset release > /dev/null
cmake --build --preset release -j"$(nproc)" --target silodem > /dev/null
cd "$root"
exec /usr/bin/python3 "$here/liggghts_bench.py" --silodem "$root/build/release/silodem" "$@"
