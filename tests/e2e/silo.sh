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

# Measured outlet data (issue 4): one rate and one calorific value, drawn and compared.
printf 't_s,rate_kg_s,calorific_kcal_kg\n0.05,0.5,\n0.15,,3500\n' > "$work/measured.csv"
"$bin" run "$case" --out "$work/run" --set output.vtk_interval=0.05 --set probes.every=100 \
  --set "output.measured=\"$work/measured.csv\"" > "$work/out.txt" 2> "$work/err.txt" || bad "run exited $?: $(tail -3 "$work/err.txt")"
for f in outlet.csv fill.csv lost.csv summary.json case.toml check.json report.html measured.csv \
         particles.pvd silo.vtp vtk/particles_000000.vtp; do
  [ -f "$work/run/$f" ] || bad "missing $f"
done
# Probes and figures of every run (issue 4).
for p in slab velocity_profile adhesion cohesion_force level coordination; do
  [ -s "$work/run/probe_$p.csv" ] || bad "missing probe_$p.csv"
done
for f in rate_cumulative calorific fractions snapshots_coal snapshots_velocity velocity_profiles \
         adhesion cohesion_force level coordination; do
  [ -s "$work/run/figures/$f.png" ] || bad "missing figures/$f.png"
  grep -q "figures/$f.png" "$work/run/report.html" || bad "report.html does not show $f.png"
done
# The fill table (a dozen columns) scrolls inside its box instead of running off the page.
grep -A1 '<div class="table-wrap"><table>' "$work/run/report.html" | grep -q "segment\|coal" ||
  bad "report.html's fill table is not in a scrolling box"
grep -q "\.table-wrap { overflow-x: auto" "$work/run/report.html" || bad "report.html lacks the table box style"
ls "$work/run"/*.partial "$work/run"/vtk/*.partial > /dev/null 2>&1 && bad "a .partial file was left behind"
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
# lost.csv: one row per lost particle, their masses the ledger's lost mass.
lost = list(csv.DictReader(open(os.path.join(d, "lost.csv"))))
assert len(lost) == s["particles_lost"], (len(lost), s["particles_lost"])
assert abs(sum(float(r["mass_kg"]) for r in lost) - s["lost_mass_kg"]) < 1e-12, lost
reasons = ("outside_wall", "above_silo", "below_outside_outlet")
assert all(r["reason"] in reasons for r in lost), lost
assert isinstance(s["particles_round_rim"], int), s
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
# The measured data's errors, recomputed here from outlet.csv (same rule: the bin holding t).
m = s["measured"]
assert m["points"] == 2 and m["rate_points"] == 1 and m["calorific_points"] == 1, m
def bin_at(t):
    return next(r for r in rows if float(r["t_start_s"]) <= t < float(r["t_end_s"]))
err_rate = abs(float(bin_at(0.05)["rate_kg_s"]) - 0.5) / 0.5
err_cal = abs(float(bin_at(0.15)["calorific_kcal_kg"]) - 3500) / 3500
assert abs(m["rate_max_rel_error"] - err_rate) < 1e-12, (m, err_rate)
assert abs(m["calorific_mean_rel_error"] - err_cal) < 1e-12, (m, err_cal)
# Probes: the level falls as the silo empties; the flow-pattern snapshot at t = 0 exists.
lv = [r for r in csv.DictReader(open(os.path.join(d, "probe_level.csv"))) if r["level_m"]]
assert float(lv[0]["t_s"]) == 0 and float(lv[-1]["level_m"]) < float(lv[0]["level_m"]), lv[-1]
slab = list(csv.DictReader(open(os.path.join(d, "probe_slab.csv"))))
assert any(float(r["t_s"]) == 0 for r in slab)
assert s["vtk_frames"] >= 2, s["vtk_frames"]
print("silo e2e ok:", s["discharged_mass_kg"], "kg in", s["discharge_time_s"], "s")
PY

# Probes and ParaView frames only observe: the same run without them gives the same outlet.csv.
"$bin" run "$case" --out "$work/plain" --no-report --set probes.every=0 > /dev/null 2>&1 || bad "plain run exited $?"
cmp -s "$work/run/outlet.csv" "$work/plain/outlet.csv" || bad "probes changed outlet.csv"
[ ! -e "$work/plain/report.html" ] && [ ! -e "$work/plain/probe_level.csv" ] || bad "--no-report / probes.every = 0 not honoured"

# A guard trips in the middle of the discharge (issue 5: particles fall far below the outlet, faster
# than the bound, which the fill never reaches): exit 3, a diagnostic, the outputs so far
# and the last good checkpoint kept, summary.json marked incomplete.
"$bin" run "$case" --out "$work/guard" --no-report --set simulation.max_speed=2 --set discharge.sink_depth_mm=1000 \
  --set simulation.checkpoint_interval=0.02 > /dev/null 2> "$work/guard.err"
[ $? -eq 3 ] || bad "speed guard: expected exit 3"
grep -q "speed guard at step .* particle .* above the bound 2 m/s; likely cause" "$work/guard.err" \
  || bad "speed guard message: $(cat "$work/guard.err")"
for f in fill.csv outlet.csv checkpoint.bin probe_level.csv summary.json; do
  [ -s "$work/guard/$f" ] || bad "speed guard: $f not kept"
done
grep -q '"complete" : false' "$work/guard/summary.json" && grep -q 'speed guard' "$work/guard/summary.json" \
  || bad "speed guard: summary.json not marked incomplete with the error"
# Remove the cause and continue from the last good checkpoint (--force: the case changed).
grep -v max_speed "$work/guard/overrides.txt" > "$work/guard/o.txt" && mv "$work/guard/o.txt" "$work/guard/overrides.txt"
"$bin" run --resume "$work/guard" --no-report > /dev/null 2>&1
[ $? -eq 2 ] || bad "resume of a changed case without --force: expected exit 2"
"$bin" run --resume "$work/guard" --force --no-report > /dev/null 2> "$work/guard2.err" \
  || bad "resume after the guard (--force) exited $?: $(tail -2 "$work/guard2.err")"
grep -q '"complete" : true' "$work/guard/summary.json" || bad "resumed guard run not complete"

# A dry run of the same case, then `compare` overlays both (issue 4, Fig. 7 style).
"$bin" run "$case" --out "$work/dry" --set contact.particle_particle.cohesion.law=none \
  --set contact.particle_wall.cohesion.law=none > /dev/null 2> "$work/dry.err" || bad "dry run exited $?: $(tail -3 "$work/dry.err")"
"$bin" compare "$work/run" "$work/dry" --out "$work/cmp" --labels "cohesive,dry" > /dev/null 2> "$work/cmp.err" || bad "compare exited $?: $(cat "$work/cmp.err")"
for f in compare_rate.png compare_cumulative.png compare_calorific.png compare.html; do
  [ -s "$work/cmp/$f" ] || bad "compare: missing $f"
done
grep -q "dry" "$work/cmp/compare.html" || bad "compare.html lacks the labels"
"$bin" compare "$work/run" --out "$work/cmp1" > /dev/null 2>&1
[ $? -eq 2 ] || bad "compare with one run: expected exit 2"
# `report` remakes the figures of an existing run.
rm -rf "$work/dry/figures" "$work/dry/report.html"
"$bin" report "$work/dry" > /dev/null || bad "report exited $?"
[ -s "$work/dry/report.html" ] && [ -s "$work/dry/figures/rate_cumulative.png" ] || bad "report did not remake the figures"

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
