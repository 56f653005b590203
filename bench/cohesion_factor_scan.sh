#!/usr/bin/env bash
# Which fraction of the paper's cohesive force (Eq. 13-14) gives the measured outlet rate? Runs
# the paper's silo (cases/paper/L3-I2.toml, or CASE) at k = 4 and k_n = 1e4 N/m for each
# `cohesion.factor` in FACTORS, each for the first T s of discharge (or until the flow stops for
# 2 s), and prints per factor: the mean rate while the bottom coal leaves (bins with >= 90% of
# it), the mean rate over the whole run, the mass out, and whether it stopped; then the factors at
# which each of the two rates crosses the experiment's 0.335 kg/s (PHYSICS.md 7; a mean over its
# whole 90 s discharge), by linear interpolation between the two runs that bracket it
# (docs/validation.md 2.3).
# Long: about 25 minutes per factor at T = 8 s on 2 idle cores. Not part of the test suite.
#
#   FACTORS="0.1 0.2 0.3 0.5 1" T=8 THREADS=2 bash bench/cohesion_factor_scan.sh [SILODEM] [CASE] [OUTDIR]
#
# Runs go to OUTDIR/<case>-k4-kn1e4-T<T>-factor-<f>; a complete one is reused, an interrupted one
# resumed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$root/build/release/silodem}
case_file=${2:-$root/cases/paper/L3-I2.toml}
out=${3:-cohesion-factor-runs}
factors=${FACTORS:-0.1 0.2 0.3 0.5 1}
t_max=${T:-8}
threads=${THREADS:-2}
target=${TARGET_RATE:-0.335}
[ -x "$bin" ] || { echo "no silodem binary at $bin" >&2; exit 2; }
[ -f "$case_file" ] || { echo "no case file $case_file" >&2; exit 2; }
mkdir -p "$out"
py=/usr/bin/python3; [ -x "$py" ] || py=python3
# One directory per case, duration and factor, so that a scan with other settings never reuses
# these runs.
tag="$(basename "$case_file" .toml)-k4-kn1e4-T$t_max"
names=()

for f in $factors; do
  name="$tag-factor-$f"
  names+=("$name")
  [ -f "$out/$name/summary.json" ] && grep -q '"complete" : true' "$out/$name/summary.json" && continue
  if [ -f "$out/$name/checkpoint.bin" ]; then  # interrupted earlier: continue it
    "$bin" run --resume "$out/$name" --threads "$threads" > "$out/$name.resume.log" 2>&1 ||
      echo "$name: resume failed, see $out/$name.resume.log" >&2
    continue
  fi
  rm -rf "${out:?}/$name"
  "$bin" run "$case_file" --out "$out/$name" --threads "$threads" --no-report \
    --set coarse_graining.k=4 \
    --set contact.particle_particle.normal.stiffness=1e4 \
    --set contact.particle_wall.normal.stiffness=1e4 \
    --set contact.particle_particle.cohesion.factor="$f" \
    --set contact.particle_wall.cohesion.factor="$f" \
    --set discharge.max_time="$t_max" --set discharge.stall_time=2 \
    --set probes.every=2000 > "$out/$name.log" 2>&1 ||
    echo "$name: exit $?, see $out/$name.log" >&2
done

"$py" - "$out" "$target" "${names[@]}" <<'PY'
import csv, json, os, sys
out, target, names = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
rows = []
for name in names:
    d = os.path.join(out, name)
    factor = float(name.rsplit("-factor-", 1)[1])
    try:
        s = json.load(open(os.path.join(d, "summary.json")))
    except (OSError, ValueError):
        print(f"factor {factor:g}: no summary.json (the run failed early; see {d}.log)")
        continue
    if not s.get("complete"):
        print(f"factor {factor:g}: incomplete run (end: {s.get('end')}), left out")
        continue
    bottom = None
    oc = os.path.join(d, "outlet.csv")
    if os.path.exists(oc):
        bins = list(csv.DictReader(open(oc)))
        coal = [k for k in bins[0] if k.startswith("fraction_")] if bins else []
        # The bottom coal is the one that leaves first.
        first = next((b for b in bins if float(b["mass_kg"]) > 0), None)
        if first and coal:
            bc = max(coal, key=lambda k: float(first[k]))
            sel = [b for b in bins if float(b["mass_kg"]) > 0 and float(b[bc]) >= 0.9]
            dt = sum(float(b["t_end_s"]) - float(b["t_start_s"]) for b in sel)
            if dt > 0:
                bottom = sum(float(b["mass_kg"]) for b in sel) / dt
    rows.append((factor, bottom, s.get("mean_rate_kg_s"), s.get("discharged_mass_kg"),
                 s.get("flow_stopped"), s.get("end"), s.get("wall_time_s")))
rows.sort()
print("| factor | bottom-coal rate (kg/s) | mean rate (kg/s) | out (kg) | flow stopped | end | wall (s) |")
print("|---|---|---|---|---|---|---|")
for r in rows:
    fmt = lambda v, p: "-" if v is None else f"{v:.{p}f}"
    print(f"| {r[0]:g} | {fmt(r[1], 3)} | {fmt(r[2], 3)} | {fmt(r[3], 3)} | {r[4]} | {r[5]} | {fmt(r[6], 0)} |")
def crossing(col, label):
    # A run that stopped flowing has rate 0 there; a run without such bins is left out.
    pts = [(r[0], 0.0 if r[4] else r[col]) for r in rows if r[4] or r[col] is not None]
    for (f0, q0), (f1, q1) in zip(pts, pts[1:]):
        if (q0 - target) * (q1 - target) <= 0 and q0 != q1:
            f = f0 + (target - q0) * (f1 - f0) / (q1 - q0)
            print(f"{label} = {target} kg/s at factor {f:.3f} (linear between {f0:g} and {f1:g})")
            return
    print(f"{label}: no two runs bracket {target} kg/s")
crossing(1, "bottom-coal rate")
crossing(2, "mean rate over the run")
PY
