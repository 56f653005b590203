#!/usr/bin/env bash
# Issue 17: every committed shear test (validation/shear/<dir>/, each holding shear_test.json and
# its series) evaluated again with one failure criterion, running nothing:
# `silodem shear-test --refit DIR --failure CRITERION --out OUT/<dir>`. Then
# studies/shear/spheres_check.py on OUT/spheres. validation/shear/peak-ratio/ is this script's
# output with the default criterion, with each refit's series (a copy of its source's) replaced
# by a relative link to the source.
# Usage: bash studies/shear/refit_all.sh OUT [SILODEM] [CRITERION]
set -euo pipefail
out=${1:?usage: refit_all.sh OUT [SILODEM] [CRITERION]}
here=$(cd "$(dirname "$0")/../.." && pwd)
silodem=${2:-$here/build/release/silodem}
criterion=${3:-peak-ratio}
out=$(realpath -m "$out")  # before the cd below
cd "$here/validation/shear"
find . -name shear_test.json -not -path "./peak-ratio/*" | sort | while read -r f; do
  d=${f%/shear_test.json}
  d=${d#./}
  mkdir -p "$out/$(dirname "$d")"
  "$silodem" shear-test --refit "$d" --failure "$criterion" --out "$out/$d" > /dev/null
  echo "refit: $d"
done
/usr/bin/python3 "$here/studies/shear/spheres_check.py" "$out/spheres" || true
