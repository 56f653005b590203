#!/usr/bin/env bash
# The committed study files and the cases they run still load: every study in studies/ and
# studies/shear/ passes `silodem study --dry-run` (its base found, every run's case with its --set
# values checked), and every case file there (the frozen bases, the shear-test cases) passes
# `silodem check`. A renamed key or a moved base makes a study that the docs cite unrunnable;
# this says which.
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
studies=0
cases=0
for f in "$src"/studies/*.toml "$src"/studies/shear/*.toml "$src"/studies/bases/*.toml; do
  if grep -q '^base *=' "$f"; then
    studies=$((studies + 1))
    "$bin" study "$f" --out "$work/$(basename "$f" .toml)" --dry-run > "$work/out.log" 2>&1 ||
      { echo "FAIL: study --dry-run $f: $(tail -1 "$work/out.log")"; fail=1; }
  else
    cases=$((cases + 1))
    "$bin" check "$f" > "$work/out.log" 2>&1 ||
      { echo "FAIL: check $f: $(tail -1 "$work/out.log")"; fail=1; }
  fi
done
# Fewer files than committed means the globs found nothing (studies/ moved): not a pass.
[ "$studies" -ge 20 ] || { echo "FAIL: only $studies study files found"; fail=1; }
[ "$cases" -ge 4 ] || { echo "FAIL: only $cases case files found"; fail=1; }
echo "$studies studies, $cases cases"
exit $fail
