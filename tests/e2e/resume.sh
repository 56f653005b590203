#!/usr/bin/env bash
# End-to-end (issue 5): a run killed with SIGKILL in the middle of its discharge and resumed gives
# outlet.csv, fill.csv, lost.csv, the probe CSVs and the final state bit for bit equal to an
# uninterrupted run, also when the checkpoints come by wall-clock time; SIGINT stops a run within
# a second with a checkpoint and a message, and it resumes; a changed case file is refused on
# resume unless --force.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
fail=0
bad() { printf 'FAIL: %s\n' "$*"; fail=1; }
case=$src/tests/data/small_silo.toml
# Finer steps and a narrower outlet make the discharge last long enough (several seconds) to be
# hit in the middle.
args=(--threads 1 --no-report --set simulation.steps_per_collision=100 --set silo.outlet_diameter_mm=32
      --set simulation.checkpoint_interval=0.01 --set probes.every=200)

# Waits until DIR/checkpoint.bin exists (the discharge has begun), then a little longer.
wait_for_discharge() {
  for _ in $(seq 1 600); do
    [ -f "$1/checkpoint.bin" ] && { sleep "$2"; return 0; }
    sleep 0.1
  done
  return 1
}

# Starts run NAME with the given arguments, kills it with SIGKILL 2 s into its discharge, and
# resumes it to the end.
kill_and_resume() {
  local name=$1; shift
  "$bin" run "$case" --out "$work/$name" "$@" > "$work/$name.log" 2>&1 &
  local pid=$!
  wait_for_discharge "$work/$name" 2 || bad "run $name never reached its discharge"
  kill -9 $pid
  wait $pid 2>/dev/null
  [ -f "$work/$name/outlet.csv" ] && bad "run $name finished before it was killed (make it longer)"
  grep -q '"complete" : false' "$work/$name/summary.json" ||
    bad "a killed run's summary.json must say complete: false"
  ls "$work/$name"/probe_*.csv > /dev/null 2>&1 && bad "a killed run left probe CSVs that look complete"
  "$bin" run --resume "$work/$name" > "$work/${name}2.log" 2>&1 ||
    bad "resume of $name exited $?: $(tail -2 "$work/${name}2.log")"
}

"$bin" run "$case" --out "$work/a" "${args[@]}" > "$work/a.log" 2>&1 || bad "reference run exited $?"

# SIGKILL in the middle, then --resume.
kill_and_resume b "${args[@]}"
t_resumed=$(sed -n 's/.*resumed at t = \([0-9.]*\) s.*/\1/p' "$work/b2.log")
awk -v t="${t_resumed:-0}" 'BEGIN { exit !(t > 0) }' ||
  bad "b resumed at t = 0 (no periodic checkpoint?): $(grep resumed "$work/b2.log")"
for f in outlet.csv fill.csv lost.csv final_state.bin probe_slab.csv probe_velocity_profile.csv \
         probe_adhesion.csv probe_cohesion_force.csv probe_level.csv probe_coordination.csv; do
  cmp -s "$work/a/$f" "$work/b/$f" || bad "killed + resumed run: $f differs from the uninterrupted run"
done
grep -q '"complete" : true' "$work/b/summary.json" || bad "resumed run: summary.json not complete"
[ ! -e "$work/b/checkpoint.bin" ] || bad "a complete run keeps no checkpoint"
"$bin" run --resume "$work/b" > /dev/null 2> "$work/b3.err"
[ $? -eq 2 ] && grep -q "nothing to resume" "$work/b3.err" || bad "resuming a complete run: $(cat "$work/b3.err")"

# Checkpoints by wall-clock time alone (none by simulated time): a SIGKILL 2 s into the discharge
# resumes from after t = 0, and the checkpoints, taken at steps that depend on the machine's
# speed, leave the result bit for bit unchanged.
kill_and_resume e "${args[@]}" --set simulation.checkpoint_interval=0 \
  --set simulation.checkpoint_wall_interval=0.3
t_resumed=$(sed -n 's/.*resumed at t = \([0-9.]*\) s.*/\1/p' "$work/e2.log")
awk -v t="${t_resumed:-0}" 'BEGIN { exit !(t > 0) }' ||
  bad "e resumed at t = 0: no checkpoint by wall time: $(grep resumed "$work/e2.log")"
for f in outlet.csv lost.csv final_state.bin probe_slab.csv; do
  cmp -s "$work/a/$f" "$work/e/$f" || bad "checkpoints by wall time: $f differs from the uninterrupted run"
done

# SIGINT: exits within a second with a message and a checkpoint; resumes to the same result.
"$bin" run "$case" --out "$work/c" "${args[@]}" > "$work/c.log" 2>&1 &
pid=$!
wait_for_discharge "$work/c" 1 || bad "run c never reached its discharge"
t0=$(date +%s.%N)
kill -INT $pid
wait $pid
rc=$?
t1=$(date +%s.%N)
[ $rc -eq 130 ] || bad "SIGINT: exit code $rc, expected 130"
python3 -c "import sys; d = $t1 - $t0; sys.exit(0 if d < 1.0 else 1)" || bad "SIGINT: took more than 1 s to stop"
grep -q "checkpoint written; continue with: silodem run --resume" "$work/c.log" || bad "SIGINT: no message: $(tail -2 "$work/c.log")"
[ -f "$work/c/checkpoint.bin" ] || bad "SIGINT: no checkpoint"
grep -q '"end" : "interrupted"' "$work/c/summary.json" || bad "SIGINT: summary.json does not say interrupted"
# bench --from times steps of the interrupted discharge from its checkpoint (the state the resume
# below starts from) and leaves the directory as it was.
before=$(cd "$work/c" && ls -l --time-style=+%s.%N && md5sum ./*)
"$bin" bench --from "$work/c" --steps 40 --threads 1 --json > "$work/from.json" 2> "$work/from.err" ||
  bad "bench --from exited $?: $(cat "$work/from.err")"
after=$(cd "$work/c" && ls -l --time-style=+%s.%N && md5sum ./*)
[ "$before" = "$after" ] || bad "bench --from changed the run directory"
"$bin" bench --from "$work/a" --steps 5 > /dev/null 2> "$work/from_done.err"
[ $? -eq 2 ] && grep -q -- "--from.*nothing to resume" "$work/from_done.err" ||
  bad "bench --from a complete run: $(cat "$work/from_done.err")"
"$bin" bench "$case" --from "$work/c" --steps 5 > /dev/null 2>&1
[ $? -eq 2 ] || bad "bench --from with a case file too was not refused"
# A changed case is refused, then accepted with --force... but first resume it unchanged.
cp -r "$work/c" "$work/d"
echo "# edited" >> "$work/d/case.toml"
"$bin" run --resume "$work/d" > /dev/null 2> "$work/d.err"
[ $? -eq 2 ] && grep -q "changed since the checkpoint" "$work/d.err" || bad "changed case: $(cat "$work/d.err")"
"$bin" bench --from "$work/d" --steps 5 > /dev/null 2> "$work/d_from.err"
[ $? -eq 2 ] && grep -q -- "--from.*changed since the checkpoint.*--set" "$work/d_from.err" &&
  ! grep -q -- "--force" "$work/d_from.err" || bad "bench --from a changed case: $(cat "$work/d_from.err")"
"$bin" run --resume "$work/d" --force > "$work/d.log" 2>&1 &
pid=$!
for _ in $(seq 1 100); do grep -q "resumed at" "$work/d.log" && break; sleep 0.1; done
grep -q "resumed at" "$work/d.log" || bad "--force did not resume: $(cat "$work/d.log")"
kill -9 $pid
wait $pid 2>/dev/null
"$bin" run --resume "$work/c" > "$work/c2.log" 2>&1 || bad "resume of c exited $?"
for f in outlet.csv lost.csv final_state.bin probe_slab.csv probe_velocity_profile.csv; do
  cmp -s "$work/a/$f" "$work/c/$f" || bad "interrupted + resumed run: $f differs"
done
# What bench --from started from is what the resume started from.
python3 - "$work/from.json" "$work/c2.log" <<'PY' || bad "bench --from: see above"
import json, re, sys
b = json.load(open(sys.argv[1]))
m = re.search(r"resumed at t = ([0-9.]+) s after the valve opened \((\d+) particles", open(sys.argv[2]).read())
assert m, "no 'resumed at' line"
assert b["steps"] == 40 and b["threads"] == 1, b
assert f'{b["discharge_time_start_s"]:.3f}' == m.group(1), (b["discharge_time_start_s"], m.group(1))
assert b["particles_start"] == int(m.group(2)), (b["particles_start"], m.group(2))
assert 0 < b["particles_end"] <= b["particles_start"], b
assert b["discharge_particle_steps_per_s"] > 0 and b["wall_s_per_simulated_s"] > 0, b
for key in ("neighbor_rebuilds", "list_pairs_per_particle", "contacts_per_particle",
            "stepping_peak_rss_bytes"):
    assert key in b, key
PY

[ $fail -eq 0 ] && echo "e2e resume ok"
exit $fail
