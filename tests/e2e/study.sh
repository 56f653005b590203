#!/usr/bin/env bash
# End-to-end (issue 16): `silodem study` runs 3 values x 2 seeds of a shortened small-silo case to
# the end. Killed with SIGKILL in a run's discharge, then in a run's fill, then stopped with
# SIGTERM, and started again each time, it leaves the finished runs alone, resumes the one killed
# in its discharge from its checkpoint (with the same result as an uninterrupted run), continues
# the one killed in its fill (from its fill checkpoint, or from the start if it had none yet), and
# ends; no child outlives a killed study. It writes study.csv
# with one row per run and the metric columns, the figures and report.html.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
fail=0
bad() { printf 'FAIL: %s\n' "$*"; fail=1; }

cat > "$work/study.toml" <<TOML
title = "e2e study: outlet size"
base = "$src/tests/data/small_silo.toml"
seeds = [1, 2]
# A narrower outlet and finer steps make each discharge last a few seconds, long enough to be
# killed in the middle; frequent checkpoints make the kill land after one.
set = ["simulation.steps_per_collision=60", "simulation.checkpoint_interval=0.02",
       "discharge.max_time=4"]
window = [0.2, 0.6]
[[vary]]
key = "silo.outlet_diameter_mm"
name = "outlet"
values = [30.0, 34.0, 38.0]
TOML

# Bad input is refused before anything runs: an unknown case key in a value list.
sed 's/key = "silo.outlet_diameter_mm"/key = "silo.outlet_diamter_mm"/' "$work/study.toml" > "$work/bad.toml"
"$bin" study "$work/bad.toml" --out "$work/bad" > /dev/null 2> "$work/bad.err"
rc=$?
[ $rc -eq 2 ] || bad "a study with an unknown key exited $rc, expected 2"
grep -q "outlet_diamter_mm" "$work/bad.err" || bad "the error does not name the key: $(cat "$work/bad.err")"
[ -e "$work/bad/runs" ] && bad "a refused study started runs"

# --dry-run lists the six runs and writes nothing.
"$bin" study "$work/study.toml" --out "$work/s" --dry-run > "$work/dry.txt" 2>&1 || bad "--dry-run exited $?"
[ "$(grep -c "silo.outlet_diameter_mm=" "$work/dry.txt")" -eq 6 ] || bad "--dry-run: $(cat "$work/dry.txt")"
[ -e "$work/s" ] && bad "--dry-run wrote $work/s"

# 1. Start, and kill the study (SIGKILL) as soon as its third run is in its discharge.
"$bin" study "$work/study.toml" --out "$work/s" --threads 1 --jobs 1 > "$work/s1.log" 2>&1 &
pid=$!
third="$work/s/runs/outlet=34.0_seed=1"
fourth="$work/s/runs/outlet=34.0_seed=2"
for _ in $(seq 1 4800); do  # fill.csv: the fill is done; the discharge's checkpoint follows
  [ -f "$third/fill.csv" ] && sleep 0.3 && break
  sleep 0.05
done
[ -f "$third/fill.csv" ] || bad "the third run never reached its discharge: $(tail -3 "$work/s1.log")"
{ kill -9 $pid; wait $pid; } 2>/dev/null
sleep 0.5
pgrep -f -- "--out $work/s/runs/" > /dev/null && bad "a child run outlived the killed study"
grep -q '"complete" : true' "$work/s/runs/outlet=30.0_seed=1/summary.json" ||
  bad "the first run was not finished before the kill"
grep -q '"complete" : false' "$third/summary.json" || bad "the third run finished before the kill"
# What the finished runs look like now: no later start may touch them.
stat -c '%Y %i' "$work/s/runs/outlet=30.0_seed="{1,2}/summary.json > "$work/before.txt"

# 2. Start again, and kill it while the fourth run is in its fill.
"$bin" study "$work/study.toml" --out "$work/s" --threads 1 --jobs 1 > "$work/s2.log" 2>&1 &
pid=$!
for _ in $(seq 1 4800); do
  [ -f "$fourth/summary.json" ] && [ ! -f "$fourth/fill.csv" ] && break
  sleep 0.05
done
{ kill -9 $pid; wait $pid; } 2>/dev/null
sleep 0.5
[ -f "$fourth/summary.json" ] && [ ! -f "$fourth/fill.csv" ] ||
  bad "the fourth run was not caught in its fill"
grep -q '"complete" : true' "$third/summary.json" || bad "the third run was not resumed to its end"

# 3. Start again with two runs side by side; SIGTERM stops it with the children checkpointed.
# The signal goes once a child of this start has written a checkpoint (one newer than the mark):
# the fourth run may have left one from its fill, and a SIGTERM sent before the study has set
# its handler ends it with the default 143.
touch "$work/mark3"
sleep 0.05
"$bin" study "$work/study.toml" --out "$work/s" --threads 2 --jobs 2 > "$work/s3.log" 2>&1 &
pid=$!
for _ in $(seq 1 4800); do
  [ -n "$(find "$work/s/runs" -name checkpoint.bin -newer "$work/mark3" 2> /dev/null)" ] && break
  sleep 0.05
done
kill -TERM $pid
wait $pid
rc=$?
[ $rc -eq 130 ] || bad "a study stopped by SIGTERM exited $rc, expected 130"
grep -q "study interrupted" "$work/s3.log" || bad "no message on SIGTERM: $(tail -2 "$work/s3.log")"
grep -l '"end" : "interrupted' "$work/s/runs/"*/summary.json > /dev/null ||
  bad "no run says it was interrupted after the SIGTERM"
ls "$work/s/runs/"*/progress.json > /dev/null 2>&1 ||
  bad "no interrupted run left its progress.json (where it stopped)"
"$bin" study "$work/study.toml" --out "$work/s" --status > "$work/status3.txt" 2>&1 ||
  bad "--status exited $?"
grep -Eq "resumable +(discharge t = [0-9.]+ s, [0-9.]+ kg out|fill)" "$work/status3.txt" &&
  grep -q "nothing is running in" "$work/status3.txt" ||
  bad "--status of the interrupted study: $(cat "$work/status3.txt")"

# 4. Start again: it ends.
"$bin" study "$work/study.toml" --out "$work/s" --threads 2 --jobs 2 > "$work/s4.log" 2>&1 ||
  bad "the continued study exited $?: $(tail -3 "$work/s4.log")"
stat -c '%Y %i' "$work/s/runs/outlet=30.0_seed="{1,2}/summary.json > "$work/after.txt"
cmp -s "$work/before.txt" "$work/after.txt" || bad "a continued study redid a finished run"
grep -q "resumed at t = " "$work/s/logs/outlet=34.0_seed=1.log" ||
  bad "the run killed in its discharge was not resumed from its checkpoint"
[ "$(grep -c '^filled ' "$work/s/logs/outlet=34.0_seed=2.log")" -ge 1 ] &&
  [ "$(grep -c 'resumed at t = ' "$work/s/logs/outlet=34.0_seed=2.log")" -le 1 ] ||
  bad "the run killed in its fill: $(cat "$work/s/logs/outlet=34.0_seed=2.log" | grep -v discharge | tail -5)"
grep -q "runs done" "$work/s4.log" || bad "no progress line"
# Runs finished before this start give the mean run time at once: the first line has an ETA.
grep -m1 "runs done" "$work/s4.log" | grep -q "ETA [0-9][0-9]* s" ||
  bad "the continued study's first progress line has no ETA: $(grep -m1 "runs done" "$work/s4.log")"
if ls "$work/s/runs/"*/progress.json > /dev/null 2>&1; then bad "a finished run kept its progress.json"; fi
"$bin" study "$work/study.toml" --out "$work/s" --status > "$work/status4.txt" 2>&1
[ "$(grep -c "finished  .*: [0-9.]* kg out in" "$work/status4.txt")" -eq 6 ] &&
  grep -q "^6 of 6 runs done" "$work/status4.txt" || bad "--status of the finished study: $(cat "$work/status4.txt")"
# The same directory under a study whose fixed settings changed: every run is a mismatch, none done.
sed 's/discharge.max_time=4/discharge.max_time=5/' "$work/study.toml" > "$work/changed.toml"
"$bin" study "$work/changed.toml" --out "$work/s" --status > "$work/status5.txt" 2>&1
[ "$(grep -c "  mismatch  " "$work/status5.txt")" -eq 6 ] &&
  grep -q "^0 of 6 runs done" "$work/status5.txt" || bad "--status after the study changed: $(cat "$work/status5.txt")"

# The killed and resumed run equals the same run made at once.
"$bin" run "$src/tests/data/small_silo.toml" --out "$work/ref" --threads 1 --no-report \
  --set simulation.steps_per_collision=60 --set simulation.checkpoint_interval=0.02 \
  --set discharge.max_time=4 --set silo.outlet_diameter_mm=34.0 --set simulation.seed=1 \
  > /dev/null 2>&1 || bad "reference run exited $?"
for f in outlet.csv fill.csv final_state.bin; do
  cmp -s "$work/ref/$f" "$third/$f" || bad "the killed and resumed run's $f differs from an uninterrupted run"
done

python3 - "$work/s" <<'PY' || fail=1
import csv, json, os, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(d, "study.csv"))))
assert len(rows) == 6, f"study.csv has {len(rows)} rows, expected 6"
for col in ["run", "outlet", "seed", "state", "discharged_mass_kg", "discharge_time_s",
            "mean_rate_kg_s", "window_rate_kg_s", "flow_stopped", "end",
            "outlet_mean_calorific_kcal_kg", "wall_time_s"]:
    assert col in rows[0], f"study.csv lacks {col}"
assert sorted((r["outlet"], r["seed"]) for r in rows) == sorted(
    (o, s) for o in ["30.0", "34.0", "38.0"] for s in ["1", "2"]), rows
for r in rows:
    assert r["state"] == "finished", r
    s = json.load(open(os.path.join(d, "runs", r["run"], "summary.json")))
    assert abs(float(r["discharged_mass_kg"]) - s["discharged_mass_kg"]) <= 1e-12 * s["discharged_mass_kg"], r
    assert r["flow_stopped"] == ("true" if s["flow_stopped"] else "false"), r
    # The window rate is the outlet.csv mass inside [0.2, 0.6] s over 0.4 s (bins of 0.1 s).
    out = list(csv.DictReader(open(os.path.join(d, "runs", r["run"], "outlet.csv"))))
    m = sum(float(b["mass_kg"] or 0) for b in out
            if float(b["t_start_s"]) >= 0.2 - 1e-9 and float(b["t_end_s"]) <= 0.6 + 1e-9)
    end = min(0.6, s["discharge_time_s"]) if s["end"] == "emptied" else 0.6
    if end >= 0.6:
        assert abs(float(r["window_rate_kg_s"]) - m / 0.4) <= 1e-9 + 1e-9 * m, (r, m)
# Beverloo: a wider outlet discharges faster (W ~ (D - k d)^2.5: 30 -> 38 mm is +70%).
rate = {o: sum(float(r["window_rate_kg_s"]) for r in rows if r["outlet"] == o) / 2
        for o in ["30.0", "38.0"]}
assert rate["38.0"] > 1.3 * rate["30.0"], rate
for f in ["report.html", "figures/mean_rate_kg_s_vs_outlet.png",
          "figures/window_rate_kg_s_vs_outlet.png", "figures/discharged_fraction_vs_outlet.png",
          "figures/outlet_rate.png", "figures/outlet_cumulative.png",
          "figures/outlet_calorific.png"]:
    p = os.path.join(d, f)
    assert os.path.isfile(p) and os.path.getsize(p) > 0, f"missing {f}"
html = open(os.path.join(d, "report.html")).read()
assert "figures/mean_rate_kg_s_vs_outlet.png" in html and "outlet=38.0_seed=2" in html
PY

# Another start finds every run finished and starts none.
"$bin" study "$work/study.toml" --out "$work/s" --threads 1 > "$work/s5.log" 2>&1 || bad "fifth start exited $?"
grep -q "6 runs finished" "$work/s5.log" || bad "fifth start: $(tail -2 "$work/s5.log")"
# The base case with a comment added is the same case: the finished study goes on. A changed value
# in it is refused.
{ cat "$src/tests/data/small_silo.toml"; echo "# a comment added after the runs"; } > "$work/base.toml"
sed "s|^base = .*|base = \"$work/base.toml\"|" "$work/study.toml" > "$work/study-base.toml"
"$bin" study "$work/study-base.toml" --out "$work/s" --threads 1 > "$work/s6.log" 2>&1 ||
  bad "a base case with a comment added was refused: $(tail -2 "$work/s6.log")"
grep -q "6 runs finished" "$work/s6.log" || bad "comment added: $(tail -2 "$work/s6.log")"
cp "$work/base.toml" "$work/base-comment.toml"
sed -i 's/restitution = 0.3 }/restitution = 0.35 }/' "$work/base.toml"
cmp -s "$work/base.toml" "$work/base-comment.toml" && bad "the test did not change a value in the base case"
"$bin" study "$work/study-base.toml" --out "$work/s" --threads 1 > /dev/null 2> "$work/s6.err"
[ $? -eq 2 ] && grep -q "another case" "$work/s6.err" || bad "a changed base case was not refused: $(cat "$work/s6.err")"
# A changed fixed setting is refused: it would mix two cases in one study.
sed -i 's/discharge.max_time=4/discharge.max_time=5/' "$work/study.toml"
"$bin" study "$work/study.toml" --out "$work/s" --threads 1 > /dev/null 2> "$work/s4.err"
[ $? -eq 2 ] && grep -q "use a new --out" "$work/s4.err" || bad "a changed study was not refused: $(cat "$work/s4.err")"
exit $fail
