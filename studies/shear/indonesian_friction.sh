#!/usr/bin/env bash
# Issue 17, item 4 (per-coal fit): does more contact friction steepen Indonesian's yield locus?
# Lambda 0.190 (k1 1e5, k2 5e5, kc 2.5e4 N/m in both slots, docs/validation/shear-cell.md 5.6-5.7)
# gives both coals about the same locus, while the measured ones differ (Longwanggou 0.67 kPa,
# 33.4 deg; Indonesian 0.68 kPa, 37.2 deg): Indonesian comes out at phi 31-35 deg and C 0.8-1.1
# kPa. Per-coal values ([contact.particle_particle.coal.Indonesian], docs/config.md) let
# Indonesian's own contacts carry more friction. Variants, Indonesian only, k = K, seeds 1..SEEDS:
#   roll0.8    epsd rolling friction 0.8 (the set's 0.5)
#   slide0.9   sliding friction 0.9 (the set's 0.6)
# The set itself at k = 4 is validation/shear/luding-k4-stiff10-seeds/ (seeds 1-3), at k = 3
# luding-k3-stiff10/kc=2.5e4_* (seed 1) and luding-k3-stiff10-seeds/ (seeds 2-3); roll0.8 and
# slide0.9 at k = 4 are luding-k4-stiff10-indonesian-friction/ (docs/validation/shear-cell.md
# 5.7). Compare point by point with studies/shear/compare_k.py Indonesian "SET DIRS" "VARIANT DIRS".
# Resumable: a run whose shear_test.json exists (at the same k) is skipped. One run at a time, one thread.
# Cost: about 15 min of one core a test at k = 4.
# Usage: bash studies/shear/indonesian_friction.sh OUT [SILODEM] [SEEDS] [VARIANTS] [K]
# VARIANTS: a space-separated list of the names above (default: both). K: the coarse-graining
# factor (default 4; at k = 3 a test takes 17-42 min).
set -euo pipefail
out=${1:?usage: indonesian_friction.sh OUT [SILODEM] [SEEDS] [VARIANTS] [K]}
here=$(cd "$(dirname "$0")/../.." && pwd)
silodem=${2:-$here/build/release/silodem}
seeds=${3:-3}
read -r -a names <<<"${4:-roll0.8 slide0.9}"
k=${5:-4}
mkdir -p "$out"

# The 10 x 8 cell of the sets it is compared with (the default cell before 2026-12-06).
set_args=(--width 10 --height 8 --set "coarse_graining.k=$k")
for slot in particle_particle particle_wall; do
  set_args+=(--set "contact.$slot.normal.stiffness=1e5"
    --set "contact.$slot.normal.unloading_stiffness=5e5"
    --set "contact.$slot.normal.adhesion_stiffness=2.5e4")
done
declare -A variant=(
  [roll0.8]="contact.particle_particle.coal.Indonesian.rolling.friction=0.8"
  [slide0.9]="contact.particle_particle.coal.Indonesian.tangential.friction=0.9"
)
for seed in $(seq 1 "$seeds"); do
  for name in "${names[@]}"; do
    [[ -n ${variant[$name]+set} ]] || { echo "unknown variant '$name' (roll0.8, slide0.9)" >&2; exit 2; }
    dir=$out/${name}_Indonesian_seed=$seed
    if [[ -f $dir/shear_test.json ]]; then
      # Folder names carry no k: a finished run at another k must not pass for this one.
      done_k=$(/usr/bin/python3 -c 'import json, sys; print(float(json.load(open(sys.argv[1]))["k"]))' \
        "$dir/shear_test.json")
      [[ $done_k == "$(/usr/bin/python3 -c "print(float($k))")" ]] ||
        { echo "$dir was run at k = $done_k, not $k: give another OUT" >&2; exit 2; }
      continue
    fi
    resume=()  # a killed or stopped test goes on from its checkpoint
    if [[ -f $dir/shear_checkpoint.bin ]]; then resume=(--resume); else rm -rf "$dir" "$dir.log"; fi
    echo "$(date -u +%FT%TZ) $name seed $seed ${resume[*]}"
    "$silodem" shear-test "$here/studies/shear/luding-epsd.toml" --coal Indonesian --seed "$seed" \
      --threads 1 --out "$dir" "${set_args[@]}" --set "${variant[$name]}" "${resume[@]}" >>"$dir.log" 2>&1
  done
done
