#!/usr/bin/env bash
# End-to-end test of `silodem bench` on the small silo: the JSON the issue names, the fill
# cache (made, reused, keyed on the case), the exported bed against the case's own numbers, and
# a clear refusal of a case without a silo. The case is the demo as it was before issue 16 item 5
# (10% of Eq. 13-14), whose bed flows freely once the valve opens, so that --flowing 0.3 has
# removed particles; the shipped demo only trickles at first.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
bad() { printf 'FAIL: %s\n' "$*"; fail=1; }

case_file="$src/studies/bases/small-silo-10pct.toml"
"$bin" bench "$case_file" --threads 1 --steps 20 --json --cache "$work/cache" \
  --export-bed "$work/bed" > "$work/first.json" || bad "first bench exited $?"
"$bin" bench "$case_file" --threads 1 --steps 20 --json --cache "$work/cache" \
  > "$work/second.json" || bad "second bench exited $?"
"$bin" bench "$case_file" --threads 1 --steps 20 --json --cache "$work/cache" \
  --set "coarse_graining.k=4" > "$work/k4.json" || bad "k = 4 bench exited $?"
"$bin" bench "$case_file" --threads 1 --steps 20 --json --cache "$work/cache" \
  --set "simulation.reorder_every=5" > "$work/sorted.json" || bad "sorted bench exited $?"
"$bin" check "$case_file" --json > "$work/check.json" || bad "check exited $?"

python3 - "$work" <<'PY' || fail=1
import csv, json, math, os, sys
w = sys.argv[1]
first, second, k4, srt = (json.load(open(os.path.join(w, f + ".json")))
                          for f in ("first", "second", "k4", "sorted"))
check = json.load(open(os.path.join(w, "check.json")))
need = ["particles", "steps", "threads", "particle_steps_per_s", "discharge_particle_steps_per_s",
        "neighbor_rebuilds", "contacts_per_particle", "peak_rss_bytes"]
for key in need:
    assert key in first, f"missing {key}"
assert first["steps"] == 20 and first["threads"] == 1, first
assert first["particle_steps_per_s"] > 0 and first["discharge_particle_steps_per_s"] > 0
# A settled cohesive bed of spheres: coordination between 3 (isostatic frictional packing) and 8.
assert 3.0 < first["contacts_per_particle"] < 8.0, first["contacts_per_particle"]
assert first["peak_rss_bytes"] > first["rss_at_start_bytes"] > 0
# The cache: the first run fills, the second loads the same bed, another k is another bed.
assert first["fill_cached"] is False and second["fill_cached"] is True, (first, second)
assert second["particles"] == first["particles"] and second["cache"] == first["cache"]
assert k4["fill_cached"] is False and k4["cache"] != first["cache"]
# A speed-only key (the Morton reorder) times the same cached bed.
assert srt["fill_cached"] is True and srt["cache"] == first["cache"], srt
assert srt["particles"] == first["particles"]
assert os.path.exists(first["cache"]) and os.path.exists(k4["cache"])
# k = 4 particles are (4/3)^3 heavier: about (3/4)^3 as many fill the same silo mass.
ratio = k4["particles"] / first["particles"]
assert abs(ratio / (3 / 4) ** 3 - 1) < 0.1, ratio
# The exported bed: one row per particle, each coal's CG mass and diameter as `check` derives them.
rows = list(csv.DictReader(open(os.path.join(w, "bed", "bed.csv"))))
assert len(rows) == first["particles"], (len(rows), first["particles"])
bed = json.load(open(os.path.join(w, "bed", "bed.json")))
assert bed["particles"] == len(rows)
for row in rows:
    m = check["materials"][int(row["coal"])]
    assert abs(2 * float(row["radius_m"]) / m["cg_diameter_m"] - 1) < 1e-12, row
    assert abs(float(row["mass_kg"]) / m["cg_mass_kg"] - 1) < 1e-12, row
    assert 0.0 <= float(row["z_m"]) < bed["silo"]["cone_height_m"] + bed["silo"]["cylinder_height_m"]
assert abs(bed["time_step_s"] / check["time_step_s"] - 1) < 1e-12
PY

# A damaged cache is reported with the way out, and --refill replaces it.
cache_file=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["cache"])' "$work/first.json")
printf 'not a fill' > "$cache_file"
"$bin" bench "$case_file" --threads 1 --steps 5 --json --cache "$work/cache" \
  > /dev/null 2> "$work/damaged.txt"
code=$?
[ "$code" -ne 0 ] || bad "a damaged cache was accepted"
grep -q -- "--refill" "$work/damaged.txt" || bad "the damaged-cache error does not say --refill: $(cat "$work/damaged.txt")"
"$bin" bench "$case_file" --threads 1 --steps 5 --json --cache "$work/cache" --refill \
  > "$work/refilled.json" || bad "--refill exited $?"
grep -q '"fill_cached" : false' "$work/refilled.json" || bad "--refill did not fill again"

# --flowing (issue 19): the bed discharged to 0.3 s, cached, and timed there. The second call
# loads the same flowing bed. At 0.3 s some coal has left (about 0.3 kg at the case's 1.1 kg/s),
# so the flowing bed holds fewer particles than the settled one; its rebuilds are counted.
"$bin" bench "$case_file" --threads 1 --steps 20 --json --cache "$work/cache" --flowing 0.3 \
  > "$work/flow1.json" || bad "bench --flowing exited $?"
"$bin" bench "$case_file" --threads 1 --steps 20 --json --cache "$work/cache" --flowing 0.3 \
  > "$work/flow2.json" || bad "second bench --flowing exited $?"
python3 - "$work" <<'PY' || fail=1
import json, os, sys
w = sys.argv[1]
a, b = (json.load(open(os.path.join(w, f))) for f in ("flow1.json", "flow2.json"))
for key in ["flowing_particle_steps_per_s", "flowing_particles", "flowing_neighbor_rebuilds",
            "flowing_list_pairs_per_particle", "flowing_time_s", "flowing_cached"]:
    assert key in a, f"bench --flowing: missing {key}"
assert a["flowing_cached"] is False and b["flowing_cached"] is True, (a, b)
assert a["flowing_cache"] == b["flowing_cache"] and os.path.exists(a["flowing_cache"])
assert b["flowing_particles"] == a["flowing_particles"], (a, b)
assert 0.3 <= a["flowing_time_s"] < 0.3 + 1e-3, a["flowing_time_s"]
assert 0 < a["flowing_particles"] < a["particles"], (a["flowing_particles"], a["particles"])
assert a["flowing_particle_steps_per_s"] > 0 and a["flowing_steps"] == 20
assert a["flowing_neighbor_rebuilds"] >= 0
# One thread: the slowest thread's time in the pair loop is the mean (0 if nothing was timed).
assert a["flowing_pair_loop_imbalance"] == 1.0 and a["pair_loop_imbalance"] == 1.0, a
PY
# The per-particle skin (simulation.skin_floor, speed only) keeps the cached beds and lists
# fewer pairs in the flowing bed once the list has been rebuilt (a rebuild every 50-60 steps).
for f in 1 0.25; do
  "$bin" bench "$case_file" --threads 1 --steps 200 --json --cache "$work/cache" --flowing 0.3 \
    --set simulation.skin_floor=$f > "$work/floor$f.json" || bad "bench --flowing, skin_floor $f: exit $?"
done
python3 - "$work" <<'PY' || fail=1
import json, os, sys
w = sys.argv[1]
a, b = (json.load(open(os.path.join(w, f))) for f in ("floor1.json", "floor0.25.json"))
assert a["flowing_cached"] and b["flowing_cached"] and b["fill_cached"], (a, b)
assert a["flowing_neighbor_rebuilds"] >= 1, a
pa, pb = a["flowing_list_pairs_per_particle"], b["flowing_list_pairs_per_particle"]
assert 0 < pb < 0.95 * pa, (pa, pb)
PY
# A time after the silo has emptied is refused with the reason.
"$bin" bench "$case_file" --threads 1 --steps 5 --cache "$work/cache" --flowing 50 \
  > /dev/null 2> "$work/flow_late.txt"
[ $? -eq 3 ] && grep -q "before --flowing 50 s" "$work/flow_late.txt" ||
  bad "--flowing after the end: $(cat "$work/flow_late.txt")"

# A generic case (no silo) is refused with exit code 2 and one line naming the file.
"$bin" bench "$src/tests/data/base.toml" --steps 5 --cache "$work/cache" \
  > "$work/out.txt" 2> "$work/err.txt"
code=$?
[ "$code" -eq 2 ] || bad "a case without [silo]: exit $code, expected 2"
[ "$(wc -l < "$work/err.txt")" -eq 1 ] || bad "a case without [silo]: not one line: $(cat "$work/err.txt")"
grep -q "base.toml" "$work/err.txt" || bad "the error does not name the file"

[ "$fail" -eq 0 ] && echo "e2e_bench: all checks passed"
exit "$fail"
