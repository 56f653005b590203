#!/usr/bin/env bash
# Issue 16, study c: calibrate one cohesion factor, the same for both coals and for particle and
# wall, on the paper's silo (L3-I2 at k = 4, k_n = 1e4 N/m) against the experiment's mean rate,
# 0.335 kg/s (PHYSICS.md 7), taken as the window rate over the first 12 s of discharge. 3 seeds
# per evaluation; the bracket [0.1, 0.13] from docs/validation.md 4.1 and 4.3 (0.1 flows at about
# 0.56 kg/s over 12 s; the small silo at k = 4 arches from 0.125). Resumable: run the same
# command again after a kill or a reboot and it continues from the finished runs.
# Cost: about 1.5-3 h of one core per flowing 12 s run, so several sessions on 2 cores.
# Usage: bash studies/paper_silo_calibrate.sh OUT_DIR [SILODEM]
set -euo pipefail
out=${1:?usage: paper_silo_calibrate.sh OUT_DIR [SILODEM]}
here=$(cd "$(dirname "$0")/.." && pwd)
silodem=${2:-$here/build/release/silodem}
# The base is the paper case as it was when this search ran (the paper's force as printed,
# alpha = 3): studies/bases/paper-L3-I2-eq15.toml.
exec "$silodem" calibrate "$here/studies/bases/paper-L3-I2-eq15.toml" \
  --param contact.particle_particle.cohesion.factor,contact.particle_wall.cohesion.factor \
  --target window_rate_kg_s=0.335 --window 0,12 --bracket 0.1,0.13 --seeds 3 --tolerance 0.1 \
  --out "$out" --threads 2 --jobs 2 \
  --set coarse_graining.k=4 --set contact.particle_particle.normal.stiffness=1e4 \
  --set contact.particle_wall.normal.stiffness=1e4 --set discharge.max_time=12.0 \
  --set probes.every=2000
