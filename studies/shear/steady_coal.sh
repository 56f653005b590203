#!/usr/bin/env bash
# Issue 17, must-show 3 with the steady first pre-shear (docs/validation/shear-cell.md 5.9): the
# set of 5.6-5.7 (lambda 0.190: k1 1e5, k2 5e5, kc 2.5e4 N/m in both slots, luding-epsd.toml)
# in the default 14 x 11 cell, with the first pre-shear run until steady (the default since
# 2026-12-07; the flags are written out so that an older binary refuses the run), both coals,
# k = 3 and 4, seeds 1..SEEDS. Runs go to OUT/k=<k>/kc=2.5e4_<coal>_seed=<n>/, the layout of
# validation/shear/steady/ (copy its runs into OUT to go on from them). Resumable: a run whose
# shear_test.json exists is skipped, one with a shear_checkpoint.bin (killed or stopped) goes on
# from it (--resume; its log is appended to). JOBS runs
# side by side (environment, default 1), one thread each. Then the means per coal and k, and
# each coal's k = 4 failure stresses over its k = 3 ones:
#   /usr/bin/python3 studies/shear/shear_summary.py OUT/k=4/* OUT/k=3/*
#   /usr/bin/python3 studies/shear/compare_k.py COAL "OUT/k=3/kc=2.5e4_COAL_seed=*" "OUT/k=4/..."
# Cost: about 50 min of one core a test at k = 4 (the steady pre-shear ran 1.6 of strain in 5.9),
# more at k = 3.
# Usage: bash studies/shear/steady_coal.sh OUT [SILODEM] [SEEDS] [KS] [COALS] [VARIANT]
# KS default "4 3", COALS default "Longwanggou Indonesian"; the order of the loops is seed, k,
# coal, so that the first seeds of every coal and k come first. VARIANT, NAME:KEY=VALUE[,KEY=VALUE
# ...], adds --set KEY=VALUE for each pair to every test and puts them in
# OUT/k=<k>/kc=2.5e4_NAME_<coal>_seed=<n>/, e.g. Indonesian's own rolling friction of 5.7 (fitted
# to its measured friction angle):
#   bash studies/shear/steady_coal.sh OUT SILODEM 3 4 Indonesian \
#     roll0.8:contact.particle_particle.coal.Indonesian.rolling.friction=0.8
# or its own sliding and rolling friction together:
#   bash studies/shear/steady_coal.sh OUT SILODEM 1 4 Indonesian \
#     slide0.9roll1.2:contact.particle_particle.coal.Indonesian.tangential.friction=0.9,contact.particle_particle.coal.Indonesian.rolling.friction=1.2
set -euo pipefail
out=${1:?usage: steady_coal.sh OUT [SILODEM] [SEEDS] [KS] [COALS] [VARIANT]}
here=$(cd "$(dirname "$0")/../.." && pwd)
silodem=${2:-$here/build/release/silodem}
seeds=${3:-3}
read -r -a ks <<<"${4:-4 3}"
read -r -a coals <<<"${5:-Longwanggou Indonesian}"
variant=${6:-}
tag=kc=2.5e4_
extra=()
if [[ -n $variant ]]; then
  [[ $variant == ?*:?*=* ]] || { echo "VARIANT must be NAME:KEY=VALUE[,KEY=VALUE...], not '$variant'" >&2; exit 2; }
  tag=kc=2.5e4_${variant%%:*}_
  IFS=, read -r -a pairs <<<"${variant#*:}"
  for pair in "${pairs[@]}"; do
    [[ $pair == ?*=?* ]] || { echo "VARIANT pair must be KEY=VALUE, not '$pair' in '$variant'" >&2; exit 2; }
    extra+=(--set "$pair")
  done
fi
jobs_max=${JOBS:-1}
mkdir -p "$out"

common=(--width 14 --height 11 --preshear-strain 0.5 --preshear-max-strain 2)
for slot in particle_particle particle_wall; do
  common+=(--set "contact.$slot.normal.stiffness=1e5"
    --set "contact.$slot.normal.unloading_stiffness=5e5"
    --set "contact.$slot.normal.adhesion_stiffness=2.5e4")
done

run_one() {
  local seed=$1 k=$2 coal=$3
  local dir=$out/k=$k/${tag}${coal}_seed=$seed
  [[ -f $dir/shear_test.json ]] && return 0
  mkdir -p "$out/k=$k"
  local resume=()
  if [[ -f $dir/shear_checkpoint.bin ]]; then resume=(--resume); else rm -rf "$dir" "$dir.log"; fi
  echo "$(date -u +%FT%TZ) start $coal k = $k seed $seed ${resume[*]}"
  "$silodem" shear-test "$here/studies/shear/luding-epsd.toml" --coal "$coal" --seed "$seed" \
    --threads 1 --out "$dir" "${common[@]}" --set "coarse_graining.k=$k" "${extra[@]}" "${resume[@]}" >>"$dir.log" 2>&1 ||
    { echo "failed: $coal k = $k seed $seed (see $dir.log)"; return 1; }
  [[ -f $dir/shear_test.json ]] || { echo "failed: $coal k = $k seed $seed wrote no shear_test.json"; return 1; }
  echo "$(date -u +%FT%TZ) done $coal k = $k seed $seed"
}

running=0
for seed in $(seq 1 "$seeds"); do
  for k in "${ks[@]}"; do
    for coal in "${coals[@]}"; do
      run_one "$seed" "$k" "$coal" &
      running=$((running + 1))
      if [ "$running" -ge "$jobs_max" ]; then wait -n || true; running=$((running - 1)); fi
    done
  done
done
wait || true
