#!/usr/bin/env python3
"""One material's shear tests at two coarse-graining factors, point by point (stdlib only).

usage: compare_k.py COAL "A_DIR [A_DIR ...]" "B_DIR [B_DIR ...]"

Each DIR is a finished `silodem shear-test` directory (points.csv, shear_test.json) holding COAL;
A and B are the seeds of the two sets (e.g. k = 3 and k = 4), each a space-separated list. Prints,
for each target normal stress, the mean measured sigma and failure tau of each set with the
standard error of the mean over its seeds, and B's mean tau over A's; then each set's mean C and
phi with the seeds' standard deviation and the mean of the fits' own standard errors. This
compares the tested strength without the straight line's extrapolation to sigma = 0
(docs/validation/shear-cell.md 5.2, 5.7).
"""
import csv
import json
import math
import os
import statistics
import sys


def failure_points(run_dir, coal):
    """{target sigma (kPa): (sigma, tau)} of COAL's failure points in one test."""
    with open(os.path.join(run_dir, "points.csv"), newline="") as f:
        return {
            float(r["sigma_target_kpa"]): (float(r["sigma_kpa"]), float(r["tau_kpa"]))
            for r in csv.DictReader(f)
            if r["coal"] == coal and r["kind"] == "failure"
        }


def fit(run_dir, coal):
    with open(os.path.join(run_dir, "shear_test.json")) as f:
        (c,) = [c for c in json.load(f)["coals"] if c["coal"] == coal]
    return c


def mean_se(values):
    m = statistics.mean(values)
    se = statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else math.nan
    return m, se


def main(argv):
    if len(argv) != 4:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    coal, sets = argv[1], [argv[2].split(), argv[3].split()]
    points = [[failure_points(d, coal) for d in dirs] for dirs in sets]
    if any(not p for ps in points for p in ps):
        print(f"a directory holds no failure points of {coal}", file=sys.stderr)
        return 1
    targets = sorted(points[0][0], reverse=True)
    print("target_kpa,a_sigma,a_tau,a_tau_se,b_sigma,b_tau,b_tau_se,b_over_a")
    for t in targets:
        row = []
        for ps in points:
            sig = statistics.mean(p[t][0] for p in ps)
            tau, se = mean_se([p[t][1] for p in ps])
            row.append((sig, tau, se))
        (sa, ta, ea), (sb, tb, eb) = row
        print(f"{t:g},{sa:.3f},{ta:.3f},{ea:.3f},{sb:.3f},{tb:.3f},{eb:.3f},{tb / ta:.3f}")
    for name, dirs in zip("ab", sets):
        fits = [fit(d, coal) for d in dirs]
        c = [f["cohesion_kpa"] for f in fits]
        phi = [f["friction_angle_deg"] for f in fits]
        se_c = [f.get("cohesion_stderr_kpa") for f in fits]
        se_c = [x for x in se_c if x is not None]
        sd = (lambda v: statistics.stdev(v) if len(v) > 1 else math.nan)
        print(f"{name}: {len(dirs)} seeds, C {statistics.mean(c):.3f} kPa (seeds' sd {sd(c):.3f}; "
              f"fits' mean standard error {statistics.mean(se_c) if se_c else math.nan:.3f}), "
              f"phi {statistics.mean(phi):.2f} deg (sd {sd(phi):.2f})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
