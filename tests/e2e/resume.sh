#!/usr/bin/env bash
# End-to-end (issues 5 and 18): a run killed with SIGKILL in the middle of its discharge, or in its
# fill, and resumed gives outlet.csv, fill.csv, lost.csv, the probe CSVs and the final state bit for
# bit equal to an uninterrupted run, also when the checkpoints come by wall-clock time; SIGINT
# stops a run within a second with a checkpoint and a message (in the fill too), and it resumes;
# a changed case file is refused on resume unless --force.
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

# Waits until DIR/fill.csv exists (the fill is done, the discharge begins), then a little longer.
wait_for_discharge() {
  for _ in $(seq 1 3600); do
    [ -f "$1/fill.csv" ] && { sleep "$2"; return 0; }
    sleep 0.1
  done
  return 1
}
# Waits until the fill has written a checkpoint (checkpoint.bin before fill.csv).
wait_for_fill_checkpoint() {
  for _ in $(seq 1 3600); do
    [ -f "$1/fill.csv" ] && return 1
    [ -f "$1/checkpoint.bin" ] && return 0
    sleep 0.05
  done
  return 1
}

# Waits until DIR/outlet_so_far.csv (rewritten at every checkpoint) reaches T s of discharge.
wait_for_outlet_time() {
  for _ in $(seq 1 12000); do
    [ -f "$1/outlet.csv" ] && return 1
    awk -F, -v t="$2" 'END { exit !(NR > 1 && $2 >= t) }' "$1/outlet_so_far.csv" 2> /dev/null &&
      return 0
    sleep 0.05
  done
  return 1
}

# Starts run NAME with the given arguments, kills it with SIGKILL 2 s into its discharge (or, with
# kill_at=T, once its checkpoints have reached T s of discharge), and resumes it to the end.
kill_and_resume() {
  local name=$1; shift
  "$bin" run "$case" --out "$work/$name" "$@" > "$work/$name.log" 2>&1 &
  local pid=$!
  if [ -n "${kill_at:-}" ]; then
    wait_for_outlet_time "$work/$name" "$kill_at" || bad "run $name never reached $kill_at s of discharge"
  else
    wait_for_discharge "$work/$name" 2 || bad "run $name never reached its discharge"
  fi
  kill -9 $pid
  wait $pid 2>/dev/null
  [ -f "$work/$name/outlet.csv" ] && bad "run $name finished before it was killed (make it longer)"
  grep -q '"complete" : false' "$work/$name/summary.json" ||
    bad "a killed run's summary.json must say complete: false"
  ls "$work/$name"/probe_*.csv > /dev/null 2>&1 && bad "a killed run left probe CSVs that look complete"
  cp "$work/$name/outlet_so_far.csv" "$work/$name.outlet_so_far.csv" 2> /dev/null ||
    bad "a killed run left no outlet_so_far.csv (the outlet bins up to its last checkpoint)"
  "$bin" run --resume "$work/$name" > "$work/${name}2.log" 2>&1 ||
    bad "resume of $name exited $?: $(tail -2 "$work/${name}2.log")"
}

"$bin" run "$case" --out "$work/a" "${args[@]}" > "$work/a.log" 2>&1 || bad "reference run exited $?"

# SIGKILL in the middle (the discharge lasts about 0.7 s), then --resume.
kill_at=0.4 kill_and_resume b "${args[@]}"
t_resumed=$(sed -n 's/.*resumed at t = \([0-9.]*\) s.*/\1/p' "$work/b2.log")
awk -v t="${t_resumed:-0}" 'BEGIN { exit !(t > 0) }' ||
  bad "b resumed at t = 0 (no periodic checkpoint?): $(grep resumed "$work/b2.log")"
for f in outlet.csv fill.csv lost.csv final_state.bin probe_slab.csv probe_velocity_profile.csv \
         probe_adhesion.csv probe_cohesion_force.csv probe_level.csv probe_coordination.csv; do
  cmp -s "$work/a/$f" "$work/b/$f" || bad "killed + resumed run: $f differs from the uninterrupted run"
done
grep -q '"complete" : true' "$work/b/summary.json" || bad "resumed run: summary.json not complete"
[ ! -e "$work/b/outlet_so_far.csv" ] || bad "a complete run keeps outlet_so_far.csv"
# The killed run's outlet_so_far.csv ends where its resume began (the last checkpoint; or the one
# before, 0.01 s earlier, if the kill fell between writing the checkpoint and this file), and its
# bins are the uninterrupted run's, except the last few, whose particles were still falling to the
# sink (30 mm: about 0.08 s from rest) and are booked when they reach it: those may hold less,
# never more.
awk -F, -v t="${t_resumed:-0}" '
  NR == FNR { if (FNR > 1) ref[FNR] = $3; refcum[FNR] = $5; next }
  FNR == 1 { next }
  { end = $2; rows[FNR] = $0 }
  END {
    if (end < t - 0.0105 || end > t + 0.0005) { print "ends at " end " s, resumed at " t " s"; exit 1 }
    compared = 0
    for (r in rows) {
      split(rows[r], c, ",")
      if (c[5] > refcum[r] + 1e-12) { print "bin " c[1] " s: cumulative " c[5] " > " refcum[r]; exit 1 }
      if (c[2] <= end - 0.15) {
        if (c[3] != ref[r]) { print "bin " c[1] " s: " c[3] " kg, uninterrupted " ref[r]; exit 1 }
        compared++
      }
    }
    if (compared < 2) { print "only " compared " whole bins before the kill"; exit 1 }
  }' "$work/a/outlet.csv" "$work/b.outlet_so_far.csv" > "$work/partial.err" ||
  bad "outlet_so_far.csv of the killed run: $(cat "$work/partial.err")"
[ ! -e "$work/b/checkpoint.bin" ] || bad "a complete run keeps no checkpoint"
"$bin" run --resume "$work/b" > /dev/null 2> "$work/b3.err"
[ $? -eq 2 ] && grep -q "nothing to resume" "$work/b3.err" || bad "resuming a complete run: $(cat "$work/b3.err")"

# SIGKILL during the fill (issue 18, item 3): the fill's checkpoint resumes it, and the run ends
# bit for bit as the uninterrupted one, fill.csv included.
"$bin" run "$case" --out "$work/f" "${args[@]}" > "$work/f.log" 2>&1 &
pid=$!
wait_for_fill_checkpoint "$work/f" || bad "run f wrote no checkpoint during its fill"
sleep 0.3
kill -9 $pid
wait $pid 2>/dev/null
[ -f "$work/f/fill.csv" ] && bad "run f finished its fill before it was killed (make it longer)"
"$bin" run --resume "$work/f" > "$work/f2.log" 2>&1 || bad "resume of f exited $?: $(tail -2 "$work/f2.log")"
grep -q "resumed the fill in segment H" "$work/f2.log" || bad "f did not resume its fill: $(head -3 "$work/f2.log")"
for f in fill.csv outlet.csv lost.csv final_state.bin probe_level.csv probe_coordination.csv; do
  cmp -s "$work/a/$f" "$work/f/$f" || bad "killed in the fill + resumed: $f differs from the uninterrupted run"
done
# SIGINT during the fill: a checkpoint and a message, exit 130.
"$bin" run "$case" --out "$work/g" "${args[@]}" > "$work/g.log" 2>&1 &
pid=$!
wait_for_fill_checkpoint "$work/g" || bad "run g wrote no checkpoint during its fill"
kill -INT $pid
wait $pid
rc=$?
[ $rc -eq 130 ] || bad "SIGINT in the fill: exit code $rc, expected 130"
grep -q "interrupted during the fill; checkpoint written" "$work/g.log" || bad "SIGINT in the fill: $(tail -2 "$work/g.log")"
"$bin" bench --from "$work/g" --steps 5 > /dev/null 2> "$work/g_from.err"
[ $? -eq 2 ] && grep -q "stopped during its fill" "$work/g_from.err" || bad "bench --from a fill: $(cat "$work/g_from.err")"

# A truncated checkpoint, and one of another format version, are refused with one line (exit 2).
cp -r "$work/g" "$work/t"
truncate -s -100 "$work/t/checkpoint.bin"
"$bin" run --resume "$work/t" > /dev/null 2> "$work/t.err"
[ $? -eq 2 ] && [ "$(wc -l < "$work/t.err")" -eq 1 ] && grep -q "truncated" "$work/t.err" ||
  bad "truncated checkpoint: $(cat "$work/t.err")"
cp "$work/g/checkpoint.bin" "$work/t/checkpoint.bin"
printf '\x07' | dd of="$work/t/checkpoint.bin" bs=1 seek=8 conv=notrunc 2> /dev/null  # version 7
"$bin" run --resume "$work/t" > /dev/null 2> "$work/t.err"
[ $? -eq 2 ] && [ "$(wc -l < "$work/t.err")" -eq 1 ] && grep -q "format version 7" "$work/t.err" ||
  bad "checkpoint of another version: $(cat "$work/t.err")"

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
