#!/usr/bin/env bash
# Is the time step converged? Empties studies/bases/small-silo-10pct.toml (the demo before issue
# 16 item 5, whose table docs/validation.md section 3 holds; or CASE) at its stiffness and at
# 10x (and 100x) k_n, dt scaled with t_col, for several seeds, dry and cohesive, and prints the
# discharge time and mean rate of each run and the seed means (docs/validation.md section 3).
# Long: about 35 minutes on one core. Not part of the test suite.
#
#   bash bench/stiffness_convergence.sh [SILODEM] [CASE] [OUTDIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/release/silodem}
case_file=${2:-$root/studies/bases/small-silo-10pct.toml}
out=${3:-stiffness-runs}
mkdir -p "$out"
py=/usr/bin/python3; [ -x "$py" ] || py=python3

run() {  # name, then --set arguments
  local name=$1; shift
  [ -f "$out/$name/summary.json" ] && return 0
  rm -rf "${out:?}/$name"
  "$bin" run "$case_file" --out "$out/$name" --threads 1 --no-report "$@" > "$out/$name.log" 2>&1 || true
}
stiff() { echo "--set contact.particle_particle.normal.stiffness=$1 --set contact.particle_wall.normal.stiffness=$1"; }
dry="--set contact.particle_particle.cohesion.law=none --set contact.particle_wall.cohesion.law=none"

for seed in 1 2 3; do
  for kn in 1e4 1e5; do
    # shellcheck disable=SC2046
    run "cohesive-kn$kn-seed$seed" $(stiff $kn) --set simulation.seed=$seed
    # shellcheck disable=SC2046,SC2086
    run "dry-kn$kn-seed$seed" $(stiff $kn) $dry --set simulation.seed=$seed
  done
done
for seed in 1 2 3; do
  # shellcheck disable=SC2046
  run "cohesive-kn1e6-seed$seed" $(stiff 1e6) --set simulation.seed=$seed
done

"$py" - "$out" <<'PY'
import glob, json, os, re, statistics, sys
out = sys.argv[1]
rows = {}
for f in sorted(glob.glob(os.path.join(out, "*", "summary.json"))):
    name = os.path.basename(os.path.dirname(f))
    m = re.match(r"(cohesive|dry)-kn([0-9e]+)-seed(\d+)", name)
    s = json.load(open(f))
    rows.setdefault((m.group(1), float(m.group(2))), []).append(
        (int(m.group(3)), s["discharge_time_s"], s["mean_rate_kg_s"], s["lost_mass_kg"],
         s["wall_time_s"], s.get("flow_stopped")))
print("| material | k_n (N/m) | seeds | discharge time (s) | mean rate (kg/s) | rate: seed mean +- sd | vs k_n = 1e4 | wall (s) |")
print("|---|---|---|---|---|---|---|---|")
base = {}
for (mat, kn), rs in sorted(rows.items()):
    rs.sort()
    rates = [r[2] for r in rs]
    mean = statistics.mean(rates)
    sd = statistics.stdev(rates) if len(rates) > 1 else float("nan")
    if kn == 1e4:
        base[mat] = mean
    rel = f"{100 * (mean / base[mat] - 1):+.1f}%" if mat in base else ""
    print(f"| {mat} | {kn:.0e} | {','.join(str(r[0]) for r in rs)} | "
          f"{' / '.join(f'{r[1]:.3f}' for r in rs)} | {' / '.join(f'{r[2]:.4f}' for r in rs)} | "
          f"{mean:.4f} +- {100 * sd / mean:.1f}% | {rel} | {' / '.join(f'{r[4]:.0f}' for r in rs)} |")
PY
