#!/usr/bin/env bash
# End-to-end (issue 16): `silodem calibrate` recovers a known answer. The target is the mean
# discharge rate of one small-silo run with a 37 mm outlet (seed 1; not the bracket's midpoint,
# so the first bisection step does not land on it); calibrating the outlet diameter in the
# bracket [20, 60] mm must find 37 mm. Tolerance of the answer: the search stops when the rate is
# within 3% of the target; by Beverloo (W ~ (D - 1.5 d)^2.5, d = 5 mm) 3% of W is 1.2% of
# D - 1.5 d, 0.4 mm, and the scatter of the rate between nearby outlets (about 5%, a new fill
# each) adds 0.6 mm: a found D within 1.5 mm of 37 is right. The 20 mm end (D/d = 4) arches:
# a stopped flow is an evaluation with rate 0, not an error. Killed and restarted, the search
# reuses its finished evaluations.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
fail=0
bad() { printf 'FAIL: %s\n' "$*"; fail=1; }
case=$src/tests/data/small_silo.toml
fixed=(--set discharge.max_time=3)

"$bin" run "$case" --out "$work/truth" --threads 1 --no-report "${fixed[@]}" \
  --set silo.outlet_diameter_mm=37.0 --set simulation.seed=1 > /dev/null 2>&1 || bad "truth run exited $?"
target=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['mean_rate_kg_s'])" "$work/truth/summary.json")

args=(calibrate "$case" --param silo.outlet_diameter_mm --target "mean_rate_kg_s=$target"
      --bracket 20,60 --seeds 1 --tolerance 0.03 --threads 2 --jobs 2 --out "$work/cal" "${fixed[@]}")
# Killed during its first evaluations, then started again.
"$bin" "${args[@]}" > "$work/c1.log" 2>&1 &
pid=$!
for _ in $(seq 1 4800); do
  ls "$work/cal/runs/"*/checkpoint.bin > /dev/null 2>&1 && break
  sleep 0.05
done
ls "$work/cal/runs/"*/checkpoint.bin > /dev/null 2>&1 || bad "no evaluation wrote a checkpoint"
{ kill -9 $pid; wait $pid; } 2>/dev/null
sleep 0.5
pgrep -f -- "--out $work/cal/runs/" > /dev/null && bad "a run outlived the killed calibration"
"$bin" "${args[@]}" > "$work/c2.log" 2>&1
rc=$?
[ $rc -eq 0 ] || bad "calibrate exited $rc: $(tail -3 "$work/c2.log")"
python3 - "$work/cal" "$target" <<'PY' || fail=1
import csv, os, re, sys
d, target = sys.argv[1], float(sys.argv[2])
rows = list(csv.DictReader(open(os.path.join(d, "calibration.csv"))))
assert rows, "calibration.csv is empty"
by_x = {}
for r in rows:
    by_x.setdefault(float(r["x"]), []).append(r)
assert 20.0 in by_x and 60.0 in by_x, sorted(by_x)
assert by_x[20.0][0]["flow_stopped"] == "true", "the 20 mm end did not arch: " + str(by_x[20.0][0])
assert float(by_x[20.0][0]["value"]) == 0.0, "an arched evaluation must count as rate 0"
text = open(os.path.join(d, "calibrated.toml")).read()
assert text.startswith("# Calibrated by `silodem calibrate`"), text[:200]
m = re.search(r"outlet_diameter_mm = ([0-9.e+-]+)", text)
assert m, "calibrated.toml has no outlet_diameter_mm"
found = float(m.group(1))
assert abs(found - 37.0) <= 1.5, f"found {found} mm, the answer is 37 mm"
assert len(by_x) >= 4, f"{len(by_x)} evaluations: the search did not search"
val = [float(r["mean"]) for r in rows if float(r["x"]) == found][0]
assert abs(val - target) <= 0.03 * target, (val, target)
assert os.path.getsize(os.path.join(d, "calibration.png")) > 0
PY
# The run killed in its discharge was resumed, not started again.
grep -l "resumed at t = " "$work/cal/logs/"*.log > /dev/null || bad "the restarted search resumed no run"
# Every run directory of the search has a finished run (none was left half done).
for r in "$work/cal/runs/"*; do
  grep -q '"complete" : true' "$r/summary.json" || bad "$r is not finished"
done
# The calibrated case runs as it is.
"$bin" check "$work/cal/calibrated.toml" > /dev/null 2>&1 || bad "calibrated.toml does not check"
# The search continued from a copy of its case at another path, with a comment added (a frozen
# base): the same case by content, so it is accepted and no evaluation is made again. A copy with
# another value is refused.
runs_before=$(ls "$work/cal/runs" | wc -l)
{ echo "# a frozen copy of the case"; cat "$case"; } > "$work/copy.toml"
copy_args=("${args[@]}")
copy_args[1]=$work/copy.toml
"$bin" "${copy_args[@]}" > "$work/c4.log" 2>&1 || bad "the search from a copy of its case: $(tail -3 "$work/c4.log")"
[ "$(ls "$work/cal/runs" | wc -l)" -eq "$runs_before" ] || bad "the search from a copy made new evaluations"
grep -q "^case=$work/copy.toml$" "$work/cal/search.txt" || bad "search.txt does not record the case path"
sed 's/^title = .*/title = "another case"/' "$case" > "$work/other.toml"
copy_args[1]=$work/other.toml
cp "$work/cal/search.txt" "$work/search.before"
"$bin" "${copy_args[@]}" > /dev/null 2> "$work/c5.err"
[ $? -eq 2 ] && grep -q "holds another case" "$work/c5.err" || bad "a search from another case: $(cat "$work/c5.err")"
cmp -s "$work/cal/search.txt" "$work/search.before" || bad "a refused search rewrote search.txt"
# Another search in the same directory is refused.
"$bin" calibrate "$case" --param silo.outlet_diameter_mm --target mean_rate_kg_s=1 --bracket 20,60 \
  --out "$work/cal" > /dev/null 2> "$work/c3.err"
[ $? -eq 2 ] && grep -q "use a new --out" "$work/c3.err" || bad "a second search in one DIR: $(cat "$work/c3.err")"
# A target outside what the bracket gives is reported, with the evaluations kept.
"$bin" calibrate "$case" --param silo.outlet_diameter_mm --target mean_rate_kg_s=100 \
  --bracket 36,44 --threads 2 --jobs 2 --out "$work/nb" "${fixed[@]}" > /dev/null 2> "$work/nb.err"
[ $? -eq 4 ] && grep -q "not bracketed" "$work/nb.err" || bad "unbracketed target: $(cat "$work/nb.err")"
[ -f "$work/nb/calibrated.toml" ] && bad "an unbracketed search wrote calibrated.toml"
exit $fail
