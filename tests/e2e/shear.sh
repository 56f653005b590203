#!/usr/bin/env bash
# End-to-end (issue 17, item 2): `silodem shear-test` on a small cell of frictionless spheres
# writes shear_test.json (the fields the issue names), points.csv, the series and the yield-locus
# figure, and --json prints the same JSON; bad input is refused with exit 2 and one line; a test
# stopped by SIGTERM keeps a checkpoint and --resume finishes it as if never stopped.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
bad() { printf 'FAIL: %s\n' "$*"; fail=1; }
case_file="$src/tests/data/frictionless_spheres.toml"
quick=(--preshear 2 --normal 1.5,1 --width 5 --height 4 --inertial-number 0.01
       --preshear-strain 0.1 --preshear-max-strain 0.2 --represhear-strain 0.05
       --failure-strain 0.05 --threads 1)

"$bin" shear-test "$case_file" --out "$work/st" "${quick[@]}" --json > "$work/out.json" 2> "$work/err.txt"
rc=$?
[ "$rc" = 0 ] || bad "shear-test exited $rc: $(tail -3 "$work/err.txt")"
for f in shear_test.json points.csv series_glass.csv figures/yield_locus_glass.png \
         figures/shear_series_glass.png; do
  [ -s "$work/st/$f" ] || bad "no $f"
done
/usr/bin/python3 - "$work" <<'PY' || fail=1
import csv, json, sys
w = sys.argv[1]
printed = json.load(open(w + "/out.json"))
doc = json.load(open(w + "/st/shear_test.json"))
assert printed == doc, "--json differs from shear_test.json"
assert doc["preshear_kpa"] == 2 and doc["normal_kpa"] == [1.5, 1.0], doc["normal_kpa"]
(r,) = doc["coals"]
for k in ["coal", "cohesion_kpa", "friction_angle_deg", "unconfined_yield_kpa",
          "major_consolidation_kpa", "ffc", "bulk_density_kg_m3", "yield_locus"]:
    assert k in r, "missing " + k
assert r["coal"] == "glass"
assert len(r["yield_locus"]) == 2 and all(len(p) == 2 for p in r["yield_locus"])
# two failure points leave the fit no degree of freedom: no standard error, written as null
assert r["cohesion_stderr_kpa"] is None and r["friction_angle_stderr_deg"] is None, r
# each failure point near its normal stress: the servo lags a dilating sample, most at this
# cell's fast shear (inertial number 0.01), so within 25%
for (s, t), want in zip(r["yield_locus"], [1.5, 1.0]):
    assert abs(s / want - 1) < 0.25, (s, want)
    assert 0 <= t < s, (s, t)
# sigma_1 lies beyond the pre-shear stress (the consolidation circle passes through it)
assert r["major_consolidation_kpa"] > 0.9 * doc["preshear_kpa"], r["major_consolidation_kpa"]
# the bulk density is the solid fraction times the particle density
assert abs(r["bulk_density_kg_m3"] - 2500 * r["solid_fraction"]) < 1e-6 * 2500
assert 0.5 < r["solid_fraction"] < 0.72, r["solid_fraction"]
rows = list(csv.DictReader(open(w + "/st/points.csv")))
assert [x["kind"] for x in rows] == ["preshear", "failure", "preshear", "failure"], rows
series = list(csv.DictReader(open(w + "/st/series_glass.csv")))
phases = {x["phase"] for x in series}
assert {"compress", "consolidate", "preshear", "relax", "shear"} <= phases, phases
# the first pre-shear ran past --preshear-strain to --preshear-max-strain: it cannot be steady
# before two windows of 0.2 of strain, so it goes on (a step of 0.1) to the largest strain and
# says so; the JSON reports the strain it ran, the series' last row of it
assert doc["preshear_min_strain"] == 0.1 and doc["preshear_max_strain"] == 0.2, doc
first = [float(x["strain"]) for x in series if x["phase"] == "preshear" and x["point"] == "0"]
g = r["preshear_strain"]
assert abs(first[-1] - g) < 1e-9, (first[-1], g)
assert 0.2 <= g < 0.2 + 0.011, g
assert not r["preshear_steady"], r
assert r["preshear_steady"] == (not any("first pre-shear was not steady" in w for w in r["warnings"])), r
PY

# --refit evaluates the recorded series again without running. Each failure point must be the
# three-row window (rows of the series' phase "shear") with the largest mean tau / mean sigma
# (peak-ratio, the default) or the largest mean tau (peak-tau), computed here from the series;
# refit with the test's own criterion gives its points again.
"$bin" shear-test --refit "$work/st" --out "$work/rf-ratio" > /dev/null 2> "$work/rf.err" ||
  bad "refit exited $?: $(cat "$work/rf.err")"
"$bin" shear-test --refit "$work/st" --failure peak-tau --out "$work/rf-tau" > /dev/null 2>> "$work/rf.err" ||
  bad "refit --failure peak-tau exited $?: $(cat "$work/rf.err")"
/usr/bin/python3 - "$work" <<'PY' || fail=1
import csv, json, sys
w = sys.argv[1]
rows = {}
for r in csv.DictReader(open(f"{w}/st/series_glass.csv")):
    if r["phase"] == "shear":
        rows.setdefault(int(r["point"]), []).append((float(r["sigma_kpa"]), float(r["tau_kpa"])))
def pick(rs, ratio):
    best = None
    for i in range(len(rs)):
        win = rs[max(0, i - 1):i + 2]
        s = sum(x[0] for x in win) / len(win)
        t = sum(x[1] for x in win) / len(win)
        key = t / s if ratio else t
        if best is None or key > best[0]:
            best = (key, s, t)
    return best[1], best[2]
run, same, tau = (json.load(open(f"{w}/{d}/shear_test.json")) for d in ("st", "rf-ratio", "rf-tau"))
assert run["failure_criterion"] == "peak-ratio" and tau["failure_criterion"] == "peak-tau"
assert run["failure_strain"] == 0.05 and tau["failure_strain"] == 0.05
assert same["refit_from"].endswith("/st"), same["refit_from"]
for doc, ratio in ((run, True), (same, True), (tau, False)):
    for k, (s, t) in enumerate(doc["coals"][0]["yield_locus"], start=1):
        ws, wt = pick(rows[k], ratio)
        assert abs(s - ws) <= 1e-9 * ws and abs(t - wt) <= 1e-9 * abs(wt), (doc["failure_criterion"], k, s, t, ws, wt)
a, b = run["coals"][0], same["coals"][0]
assert abs(a["cohesion_kpa"] - b["cohesion_kpa"]) < 1e-9 and abs(a["friction_angle_deg"] - b["friction_angle_deg"]) < 1e-9
assert a["bulk_density_kg_m3"] == tau["coals"][0]["bulk_density_kg_m3"]
# An older test's JSON without failure_strain: refit with --failure-strain.
old = json.load(open(f"{w}/st/shear_test.json"))
del old["failure_strain"]
json.dump(old, open(f"{w}/st/shear_test.json", "w"))
PY
"$bin" shear-test --refit "$work/st" --failure-strain 0.05 --out "$work/rf-old" > /dev/null 2> "$work/e.txt" ||
  bad "refit of a test without failure_strain: $(cat "$work/e.txt")"
expect_refit_error() {
  local what=$1 needle=$2
  shift 2
  "$bin" shear-test "$@" > /dev/null 2> "$work/e.txt"
  local rc=$?
  [ "$rc" = 2 ] || bad "$what: exit $rc, want 2"
  [ "$(wc -l < "$work/e.txt")" = 1 ] || bad "$what: not one line: $(cat "$work/e.txt")"
  grep -q -- "$needle" "$work/e.txt" || bad "$what: no '$needle' in: $(cat "$work/e.txt")"
}
expect_refit_error "refit past the shear's strain" "reached only" --refit "$work/st" --out "$work/rb1" --failure-strain 0.3
[ -e "$work/rb1" ] && bad "a refused refit left $work/rb1"
expect_refit_error "refit with a case" "no case" "$case_file" --refit "$work/st" --out "$work/rb2"
expect_refit_error "refit with --coal" "excludes" --refit "$work/st" --coal glass --out "$work/rb3"
expect_refit_error "refit of a directory without a test" "shear_test.json" --refit "$work" --out "$work/rb4"
mv "$work/st/series_glass.csv" "$work/series.bak"
expect_refit_error "refit without the series" "series_glass.csv" --refit "$work/st" --out "$work/rb5"
mv "$work/series.bak" "$work/st/series_glass.csv"

# Bad input: exit 2, one line naming the option and the value.
expect_input_error() {
  local what=$1 needle=$2
  shift 2
  "$bin" shear-test "$case_file" "$@" > "$work/o.txt" 2> "$work/e.txt"
  local rc=$?
  [ "$rc" = 2 ] || bad "$what: exit $rc, want 2"
  [ "$(wc -l < "$work/e.txt")" = 1 ] || bad "$what: not one line: $(cat "$work/e.txt")"
  grep -q -- "$needle" "$work/e.txt" || bad "$what: no '$needle' in: $(cat "$work/e.txt")"
}
expect_input_error "normal above pre-shear" "--normal" --out "$work/b1" --normal 12,3
[ -e "$work/b1" ] && [ -n "$(ls -A "$work/b1")" ] && bad "a refused test left files in b1"
expect_input_error "not a number" "'x'" --out "$work/b2" --normal 3,x
expect_input_error "unknown coal" "not a coal of the case" --out "$work/b3" --coal coke
expect_input_error "out not empty" "not empty" --out "$work/st"
expect_input_error "first pre-shear's largest strain below its least" "--preshear-max-strain" \
  --out "$work/b4" --preshear-strain 0.5 --preshear-max-strain 0.4
expect_refit_error "refit with --preshear-max-strain" "excludes" --refit "$work/st" --out "$work/rb6" \
  --preshear-max-strain 1

# Stopped by SIGTERM, a test writes shear_checkpoint.bin and exits 130 without shear_test.json;
# --resume with the same command finishes it with the series and the result of the test never
# stopped (st above: the same options, one thread). The test is frozen (SIGSTOP) as soon as it
# says it is pressing, then sent SIGTERM and let go: it stops at its next checkpoint chance, early
# in the test, however fast the machine.
stop_when() {  # stop_when PID FILE TEXT: SIGTERM to PID once FILE holds TEXT (10 min at most)
  local pid=$1 file=$2 text=$3 seen=0
  for _ in $(seq 1 12000); do
    grep -q "$text" "$file" 2>/dev/null && { seen=1; break; }
    sleep 0.05
  done
  [ "$seen" = 1 ] || bad "no '$text' in $file within 10 min"
  kill -STOP "$pid"
  kill -TERM "$pid"
  kill -CONT "$pid"
}
stopped_test() {  # stopped_test WHAT CASE OUT TEXT: the quick test, stopped at TEXT, exits 130
  local what=$1 case=$2 dir=$3 text=$4 pid rc
  "$bin" shear-test "$case" --out "$dir" "${quick[@]}" 2> "$dir.err" &
  pid=$!
  stop_when "$pid" "$dir.err" "$text"
  wait "$pid"
  rc=$?
  [ "$rc" = 130 ] || bad "$what, SIGTERM: exit $rc, want 130 ($(tail -2 "$dir.err"))"
}
stopped_test "one coal" "$case_file" "$work/int" "pressing"
[ -s "$work/int/shear_checkpoint.bin" ] || bad "SIGTERM: no shear_checkpoint.bin"
[ -e "$work/int/shear_test.json" ] && bad "SIGTERM: an unfinished test wrote shear_test.json"
grep -q -- "--resume" "$work/int.err" || bad "SIGTERM: the message does not say --resume"
expect_input_error "an interrupted test's directory without --resume" "add --resume" \
  --out "$work/int" "${quick[@]}"
expect_input_error "resume with another seed" "another case file" --out "$work/int" "${quick[@]}" \
  --seed 2 --resume
expect_input_error "resume with nothing to resume" "no shear_checkpoint.bin" --out "$work/b5" \
  "${quick[@]}" --resume
cp "$work/int/shear_checkpoint.bin" "$work/ck.bak"
head -c 100 "$work/ck.bak" > "$work/int/shear_checkpoint.bin"
expect_input_error "resume a truncated checkpoint" "shear_checkpoint.bin" --out "$work/int" \
  "${quick[@]}" --resume
cp "$work/ck.bak" "$work/int/shear_checkpoint.bin"
"$bin" shear-test "$case_file" --out "$work/int" "${quick[@]}" --resume > /dev/null 2> "$work/res.err"
rc=$?
[ "$rc" = 0 ] || bad "--resume: exit $rc ($(tail -2 "$work/res.err"))"
grep -q "resumed at" "$work/res.err" || bad "--resume: no 'resumed at' line"
[ -e "$work/int/shear_checkpoint.bin" ] && bad "--resume: the finished test kept its checkpoint"
cmp -s "$work/st/series_glass.csv" "$work/int/series_glass.csv" ||
  bad "--resume: the series differs from the test never stopped"
/usr/bin/python3 - "$work/st" "$work/int" <<'PY' || fail=1
import json, sys
(a,) = json.load(open(f"{sys.argv[1]}/shear_test.json"))["coals"]
(b,) = json.load(open(f"{sys.argv[2]}/shear_test.json"))["coals"]
for k in ("cohesion_kpa", "friction_angle_deg", "yield_locus", "bulk_density_kg_m3", "preshear_points"):
    assert a[k] == b[k], (k, a[k], b[k])
assert a["cell"]["steps"] == b["cell"]["steps"], (a["cell"]["steps"], b["cell"]["steps"])
PY

# The same checkpoint continued with two threads: allowed, and the result says so.
mkdir -p "$work/int2"
cp "$work/ck.bak" "$work/int2/shear_checkpoint.bin"
quick2=("${quick[@]}")
quick2[${#quick2[@]}-1]=2  # --threads 2
"$bin" shear-test "$case_file" --out "$work/int2" "${quick2[@]}" --resume > /dev/null 2> "$work/res2.err"
rc=$?
[ "$rc" = 0 ] || bad "--resume with two threads: exit $rc ($(tail -2 "$work/res2.err"))"
grep -q "with 2 threads where it had 1" "$work/int2/shear_test.json" ||
  bad "--resume with two threads: no warning in shear_test.json"

# A test of two coals stopped in the second keeps the first one's result in its checkpoint:
# resumed, its first coal ("glass", the same as the one-coal case's) is st's test exactly and
# its second is finished too.
two="$src/tests/data/frictionless_spheres_two.toml"
stopped_test "two coals" "$two" "$work/two" "glass2: .*pressing"
"$bin" shear-test "$two" --out "$work/two" "${quick[@]}" --resume > /dev/null 2> "$work/two2.err"
rc=$?
[ "$rc" = 0 ] || bad "two coals, --resume: exit $rc ($(tail -2 "$work/two2.err"))"
grep -q "^glass: " "$work/two2.err" && bad "two coals, --resume: ran the finished coal again"
cmp -s "$work/st/series_glass.csv" "$work/two/series_glass.csv" ||
  bad "two coals: the first coal's series differs from the one-coal test's"
/usr/bin/python3 - "$work/st" "$work/two" <<'PY' || fail=1
import json, sys
(a,) = json.load(open(f"{sys.argv[1]}/shear_test.json"))["coals"]
g, h = json.load(open(f"{sys.argv[2]}/shear_test.json"))["coals"]
assert (g["coal"], h["coal"]) == ("glass", "glass2"), (g["coal"], h["coal"])
for k in ("cohesion_kpa", "friction_angle_deg", "yield_locus", "bulk_density_kg_m3"):
    assert a[k] == g[k], (k, a[k], g[k])
assert len(h["yield_locus"]) == 2 and h["cell"]["steps"] > 0, h
PY
expect_input_error "resume a finished test" "finished test" --out "$work/int" "${quick[@]}" --resume
exit $fail
