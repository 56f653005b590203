#!/usr/bin/env bash
# End-to-end: `silodem run` on a small silo case writes outlet.csv, fill.csv and summary.json
# with a closed mass ledger; --set overrides; a malformed scenario is refused before any output.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
bad() { printf 'FAIL: %s\n' "$*"; fail=1; }
case=$src/tests/data/small_silo.toml

"$bin" run "$case" --out "$work/run" > "$work/out.txt" 2> "$work/err.txt" || bad "run exited $?: $(tail -3 "$work/err.txt")"
for f in outlet.csv fill.csv summary.json case.toml check.json; do
  [ -f "$work/run/$f" ] || bad "missing $f"
done
python3 - "$work/run" <<'PY' || fail=1
import csv, json, sys, os
d = sys.argv[1]
s = json.load(open(os.path.join(d, "summary.json")))
for k in ["filled_mass_kg", "discharged_mass_kg", "remaining_mass_kg", "lost_mass_kg",
          "discharge_time_s", "mean_rate_kg_s", "flow_stopped", "particles_filled", "k",
          "time_step_s", "wall_time_s", "complete"]:
    assert k in s, f"summary.json lacks {k}"
assert s["complete"] is True and s["flow_stopped"] is False, s
ledger = s["filled_mass_kg"] - (s["remaining_mass_kg"] + s["discharged_mass_kg"] + s["lost_mass_kg"])
assert abs(ledger) < 1e-12, ledger
assert s["discharged_mass_kg"] >= 0.995 * s["filled_mass_kg"], s
rows = list(csv.DictReader(open(os.path.join(d, "outlet.csv"))))
need = ["t_start_s", "t_end_s", "mass_kg", "rate_kg_s", "cumulative_kg", "fraction_Longwanggou",
        "fraction_Indonesian", "calorific_kcal_kg"]
assert all(k in rows[0] for k in need), rows[0].keys()
assert abs(float(rows[-1]["cumulative_kg"]) - s["discharged_mass_kg"]) < 1e-9
# Eq. 17 in every bin with mass
for r in rows:
    if float(r["mass_kg"]) > 0:
        x = float(r["fraction_Longwanggou"])
        assert abs(float(r["calorific_kcal_kg"]) - (3108 + 1680 * x)) < 1e-6, r
fill = list(csv.DictReader(open(os.path.join(d, "fill.csv"))))
assert [r["coal"] for r in fill] == ["Indonesian", "Longwanggou"], fill
assert [r["segment"] for r in fill] == ["H1", "H2"], fill
print("silo e2e ok:", s["discharged_mass_kg"], "kg in", s["discharge_time_s"], "s")
PY

# --set reaches the case, and a malformed scenario is an input error before any output.
"$bin" check "$case" --set fill.scenario=I2 | grep -q "H2  Indonesian" || bad "--set fill.scenario not applied"
"$bin" run "$case" --out "$work/bad" --set fill.scenario=L1-X1 > /dev/null 2> "$work/bad.err"
[ $? -eq 2 ] || bad "unknown coal symbol: expected exit 2"
grep -q "no coal has the symbol" "$work/bad.err" || bad "message: $(cat "$work/bad.err")"
"$bin" run "$case" --out "$work/bad2" --set fill.scenario=L1I1 > /dev/null 2> "$work/bad2.err"
[ $? -eq 2 ] || bad "malformed scenario: expected exit 2"
grep -q "fill.scenario" "$work/bad2.err" || bad "message names the key: $(cat "$work/bad2.err")"
[ ! -e "$work/bad" ] && [ ! -e "$work/bad2" ] || bad "output directory left behind"
[ $fail -eq 0 ] && echo "e2e silo ok"
exit $fail
