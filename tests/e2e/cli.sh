#!/usr/bin/env bash
# End-to-end tests of the command line: check --json, run, and bad input (exit code 2, one line,
# no output directory left behind).
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
say() { printf '%s\n' "$*"; }
bad() { say "FAIL: $*"; fail=1; }

# 1. check --json on the default case: the fields the issue names, as numbers. With the paper's
# force as printed (Eq. 13-15: Eq. 15's porosity, alpha = 3) they are VERIFICATION.md's; as
# shipped (rumpf_porosity 0.38, alpha = 2) Eq. 14 and Eq. 13 give them from the same sigma_t.
"$bin" check "$src/cases/default.toml" --json --set coarse_graining.rumpf_porosity=0 \
  --set coarse_graining.cohesion_exponent=3 > "$work/check.json" || bad "check --json exited $?"
"$bin" check "$src/cases/default.toml" --json > "$work/shipped.json" || bad "check --json exited $?"
# The force each contact kind gets: factor x pair rule of F_L,cg, factor x wall_factor x F_L,cg.
"$bin" check "$src/cases/default.toml" --json --set contact.particle_particle.cohesion.factor=0.5 \
  --set contact.particle_particle.cohesion.pair_rule=min --set contact.particle_wall.cohesion.factor=2 \
  --set contact.particle_wall.cohesion.wall_factor=0.25 > "$work/applied.json" || bad "check --json exited $?"
"$bin" check "$src/cases/default.toml" --set contact.particle_particle.cohesion.factor=0.5 \
  > "$work/applied.txt" || bad "check exited $?"
python_ok=$(command -v python3 || true)
[ -n "$python_ok" ] || bad "python3 is missing: the check --json values are not tested"
if [ -n "$python_ok" ]; then
  python3 - "$work/check.json" "$work/shipped.json" "$work/applied.json" "$work/applied.txt" <<'PY' || fail=1
import json, sys
d = json.load(open(sys.argv[1]))
need = ["name", "porosity", "tensile_strength_pa", "cohesion_force_n", "cohesion_force_cg_n",
        "cg_diameter_m", "cg_mass_kg", "bond_number", "restitution_cg", "restitution_policy",
        "damping_normal", "collision_time_s"]
for m in d["materials"]:
    missing = [k for k in need if k not in m]
    assert not missing, f"missing {missing}"
assert isinstance(d["warnings"], list)
L = d["materials"][0]
# T-U1/T-U2 through the CLI (VERIFICATION.md 1.1-1.2, k = 3)
def near(a, b, tol): assert abs(a / b - 1) < tol, (a, b)
near(L["porosity"], 0.5472, 1e-3)
near(L["tensile_strength_pa"], 1016.1, 1e-3)
near(L["cohesion_force_n"], 9.627e-3, 1e-3)
near(L["cohesion_force_cg_n"], 0.2599, 1e-3)
near(L["bond_number"], 54.49, 1e-3)
near(L["cg_diameter_m"], 8.4e-3, 1e-9)
near(d["materials"][1]["cohesion_force_cg_n"], 0.4171, 1e-3)
near(d["k"], 3.0, 1e-12)
near(d["time_step_s"], d["collision_time_min_s"] / 50, 1e-9)
# As shipped: F_L = d_sv^2 sigma_t eps / (1 - eps) with eps = 0.38 (Eq. 14), F_L,cg = k^2 F_L.
shipped = json.load(open(sys.argv[2]))
near(shipped["cohesion_exponent"], 2.0, 1e-12)
for m, d_sv in zip(shipped["materials"], [2.8e-3, 3.2e-3]):
    f = d_sv**2 * m["tensile_strength_pa"] * 0.38 / 0.62
    near(m["cohesion_force_n"], f, 1e-6)
    near(m["cohesion_force_cg_n"], 9 * f, 1e-6)
near(shipped["materials"][0]["tensile_strength_pa"], 1016.1, 1e-3)
near(shipped["materials"][0]["cohesion_force_n"], 4.8826e-3, 1e-3)
# The applied force per contact kind, with the factors and rules set on the command line.
a = json.load(open(sys.argv[3]))
fl, fi = (m["cohesion_force_cg_n"] for m in a["materials"])
rows = {(r["section"], tuple(r["coals"])): r["force_n"] for r in a["cohesion_applied"]}
want = {("particle_particle", ("Longwanggou", "Longwanggou")): 0.5 * fl,
        ("particle_particle", ("Longwanggou", "Indonesian")): 0.5 * min(fl, fi),
        ("particle_particle", ("Indonesian", "Indonesian")): 0.5 * fi,
        ("particle_wall", ("Longwanggou",)): 2 * 0.25 * fl,
        ("particle_wall", ("Indonesian",)): 2 * 0.25 * fi}
assert set(rows) == set(want), sorted(rows)
for key, f in want.items():
    near(rows[key], f, 1e-9)
text = open(sys.argv[4]).read()
assert "moisture force per contact, as applied" in text, text
assert "pair Longwanggou-Indonesian" in text and f"{0.25 * (fl + fi):.4e} N" in text, text
print("check --json ok")
PY
fi

# 2. A tiny run writes the trajectory and a complete summary.
cat > "$work/drop.toml" <<EOF2
[simulation]
end_time = 0.05
[[coal]]
name = "glass"
diameter_mm = 10
true_density_kg_m3 = 2500
cohesion_force_n = 0
[contact.particle_particle]
normal = { law = "linear_spring_dashpot", stiffness = 1e5, restitution = 0.5 }
[contact.particle_wall]
normal = { law = "linear_spring_dashpot", stiffness = 1e5, restitution = 0.5 }
[[particle]]
coal = "glass"
position = [0.0, 0.0, 1.0]
[output]
every = 10
EOF2
"$bin" run "$work/drop.toml" --out "$work/drop" > /dev/null 2>&1 || bad "run exited $?"
[ -f "$work/drop/trajectory.csv" ] || bad "no trajectory.csv"
python3 -c 'import json,sys; sys.exit(0 if json.load(open(sys.argv[1]))["complete"] is True else 1)' \
  "$work/drop/summary.json" || bad "summary not complete"
# free fall: z(t) = 1 - g t^2 / 2 in the last row
python3 - "$work/drop/trajectory.csv" <<'PY' || fail=1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
t, z = float(rows[-1]["t_s"]), float(rows[-1]["z_m"])
assert abs(z - (1 - 9.81 * t * t / 2)) < 1e-9, (t, z)
assert abs(t - 0.05) < 1e-4, t
PY
# An existing non-empty directory is never overwritten.
"$bin" run "$work/drop.toml" --out "$work/drop" > /dev/null 2> "$work/err.txt"
[ $? -eq 2 ] || bad "existing out dir: expected exit 2"
grep -q "not empty" "$work/err.txt" || bad "existing out dir: message"

# 3. Bad input: exit 2, one line naming key and file:line, no output directory.
base=$src/tests/data/base.toml
try_bad() {  # name, sed expression, expected key, expected line
  local name=$1 expr=$2 key=$3
  sed "$expr" "$base" > "$work/$name.toml"
  local line
  line=$(grep -n -m1 "$4" "$work/$name.toml" | cut -d: -f1)
  "$bin" run "$work/$name.toml" --out "$work/out_$name" > /dev/null 2> "$work/$name.err"
  local code=$?
  [ $code -eq 2 ] || bad "$name: exit code $code, expected 2"
  [ "$(wc -l < "$work/$name.err")" -eq 1 ] || bad "$name: expected one line, got: $(cat "$work/$name.err")"
  grep -q "$key" "$work/$name.err" || bad "$name: key $key not named: $(cat "$work/$name.err")"
  grep -q "$name.toml:$line" "$work/$name.err" || bad "$name: line $line not named: $(cat "$work/$name.err")"
  [ ! -e "$work/out_$name" ] || bad "$name: output directory left behind"
}
try_bad unknown 's/moisture_percent/moisture_pecent/' "did you mean 'moisture_percent'" moisture_pecent
try_bad negative 's/diameter_mm = 2.8/diameter_mm = -2.8/' "coal\[0\].diameter_mm" "diameter_mm = -2.8"
try_bad moisture 's/moisture_percent = 8.8/moisture_percent = 100/' "moisture_percent" "moisture_percent = 100"
try_bad bulk 's/bulk_density_kg_m3 = 778/bulk_density_kg_m3 = 2000/' "bulk_density_kg_m3" "bulk_density_kg_m3 = 2000"
try_bad kless 's/^k = 3/k = 0.9/' "coarse_graining.k" "^k = 0.9"
try_bad overlap 's/position = \[0.02, 0.0, 0.01\]/position = [0.001, 0.0, 0.01]/' "particle\[1\].position" "position = \[0.001"
try_bad missing 's/^true_density_kg_m3 = 1567$//' "true_density_kg_m3" '^\[\[coal\]\]'
try_bad dt 's/^end_time = 0.01/end_time = 0.01\ntime_step = 1e-4/' "simulation.time_step" "time_step = 1e-4"

# 4. docs/config.md is generated from the schema and must be current.
"$bin" config-docs | diff -q - "$src/docs/config.md" > /dev/null ||
  bad "docs/config.md is stale: run 'silodem config-docs > docs/config.md'"

[ $fail -eq 0 ] && say "e2e ok"
exit $fail
