#!/usr/bin/env bash
# Issue 17, must-show 2: the shear cell against what is known of simple spheres. Monodisperse
# spheres, sliding friction 0.5, no rolling resistance (studies/shear/spheres-mu0.5.toml), the FT-4
# procedure at 9 kPa pre-shear, sheared at an inertial number of 5e-3 at the lowest stress (quasi-static:
# mu(I) of Jop et al. 2006 with I0 = 0.28 adds about 0.005 to tau / sigma there):
#   base   the default cell, 14 d wide and 11 d high since 2026-12-06 (2920 particles),
#          k_n = 3e4 N/m (stiffness number k_n / (sigma d) = 556 at 9 kPa)
#   box    18 d wide, 14 d high (about 2x base's particles)
#   stiff  k_n = 3e5 N/m (10x), base's cell
#   f1/f2  the constant-force law (cohesion "overlap-only") at F = 0.15 and 0.30 N (Bond number
#          F / (m g) 54 and 108, as the paper's 54-72 at k = 3; F / d^2 = 4.2 and 8.3 kPa), base's cell
#   f4     the same at F = 0.60 N (Bond number 216, F / d^2 = 16.7 kPa): does C grow in proportion
#          to the force once the bonds outweigh the stresses of the test?
#   box2   10 d wide, 8 d high (1146 particles), the default cell before 2026-12-06
# (validation/shear/peak-ratio/spheres/ holds runs of the layout before 2026-12-06: base 10 x 8,
# box 14 x 11, box2 18 x 14, the others in the 10 x 8 cell; spheres_check.py reads each run's cell
# and refuses runs of the two layouts mixed.)
# with SEEDS seeds each (default 3). CONFIGS (environment) names the configs to run, default
# "base f1 f2 box stiff" (issue 17's checks); f4 and box2 are run on request and reported beside
# them. Then studies/shear/spheres_check.py compares the seeds' means with the tolerances of issue
# 17 and writes OUT/checks.csv; exit 1 if a check fails, else 2 if a config has no finished run.
# Resumable: a run whose shear_test.json exists is skipped. JOBS runs side by side (environment,
# default 2), one thread each. SHEAR_ARGS (environment) is added to every run: e.g.
# "--preshear-max-strain 0.5" adds seeds to a folder of runs made with the fixed first pre-shear
# of before 2026-12-07 (both committed folders; spheres_check.py refuses the two procedures mixed).
# Cost (with the fixed first pre-shear of 0.5; one that runs to steady state can add up to 55%):
# about 3 min of one core per run in the 10 x 8 cell (box2); base, f1, f2 and f4 about 2.5x
# that, box about 5x, stiff about 3x base.
# Usage: bash studies/shear/spheres_check.sh OUT [SILODEM] [SEEDS]
set -euo pipefail
out=${1:?usage: spheres_check.sh OUT [SILODEM] [SEEDS]}
here=$(cd "$(dirname "$0")/../.." && pwd)
silodem=${2:-$here/build/release/silodem}
seeds=${3:-3}
jobs_max=${JOBS:-2}
case_file=$here/studies/shear/spheres-mu0.5.toml
mkdir -p "$out"

# The default cell, written out so that a binary with another default cannot change the layout.
cell="--width 14 --height 11"
declare -A extra=(
  [base]="$cell"
  [box]="--width 18 --height 14"
  [stiff]="$cell --set contact.particle_particle.normal.stiffness=3e5 --set contact.particle_wall.normal.stiffness=3e5"
  [f1]="$cell --set contact.particle_particle.cohesion.law=overlap-only --set coal[0].cohesion_force_n=0.15"
  [f2]="$cell --set contact.particle_particle.cohesion.law=overlap-only --set coal[0].cohesion_force_n=0.30"
  [f4]="$cell --set contact.particle_particle.cohesion.law=overlap-only --set coal[0].cohesion_force_n=0.60"
  [box2]="--width 10 --height 8"
)
read -r -a configs <<<"${CONFIGS:-base f1 f2 box stiff}"
read -r -a shear_args <<<"${SHEAR_ARGS:-}"
for name in "${configs[@]}"; do
  [[ -n ${extra[$name]+set} ]] || { echo "unknown config '$name' (base box stiff f1 f2 f4 box2)" >&2; exit 2; }
done
jobs=()
for s in $(seq 1 "$seeds"); do
  for name in "${configs[@]}"; do jobs+=("$name:$s"); done
done

run_one() {
  local name=${1%%:*} seed=${1##*:}
  local dir=$out/${name}_seed=$seed
  [ -f "$dir/shear_test.json" ] && return 0
  local resume=()  # a killed or stopped test goes on from its checkpoint
  if [ -f "$dir/shear_checkpoint.bin" ]; then resume=(--resume); else rm -rf "$dir" "$out/${name}_seed=$seed.log"; fi
  # shellcheck disable=SC2086
  "$silodem" shear-test "$case_file" --out "$dir" --threads 1 --seed "$seed" --inertial-number 5e-3 ${extra[$name]} ${shear_args[@]+"${shear_args[@]}"} ${resume[@]+"${resume[@]}"} \
    >> "$out/${name}_seed=$seed.log" 2>&1 || { echo "failed: $name seed $seed (see $out/${name}_seed=$seed.log)"; return 1; }
  echo "done: $name seed $seed"
}

running=0
for j in "${jobs[@]}"; do
  run_one "$j" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs_max" ]; then wait -n || true; running=$((running - 1)); fi
done
wait || true
exec /usr/bin/python3 "$here/studies/shear/spheres_check.py" "$out"
