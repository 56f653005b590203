#!/usr/bin/env python3
"""Does a smoother failure point shrink the scatter of the fitted C? (stdlib only)

usage: estimator_check.py COAL DIR [DIR ...]

Each DIR is a finished `silodem shear-test` directory holding series_<COAL>.csv (one row per
strain step of 0.005). For each DIR, the failure point of each shear to failure is taken in
several ways from the recorded series, and the straight line tau = C + sigma tan(phi) is fitted
through the five points as the test itself does (scenario/yield_locus.hpp):
  wN      the N-row centred moving means of sigma and tau (cut short at the shear's ends) where
          tau / sigma peaks: w3 is the test's own `peak-ratio` and gives its stored C and phi;
          wider windows average more of the cell's swings
  meanA   the mean sigma and tau over the shear from row A on (no peak at all: the mean
          mobilised strength of the whole shear)
  w3pre   w3's tau times the test's mean pre-shear tau / sigma over that of the pre-shear before
          the point (points.csv): the pre-shear normalisation of ring shear testing, which takes
          the spread of the pre-shears as the sample's and removes it from the failure points
Prints, per estimator, each DIR's C (kPa), phi (deg) and the fit's standard error of C, then the
mean and the standard deviation over the DIRs (docs/validation/shear-cell.md 5.7).
"""
import csv
import math
import os
import statistics
import sys

ESTIMATORS = ["w3", "w5", "w9", "w15", "mean0", "mean10", "mean25", "w3pre"]


def shears(run_dir, coal):
    """[(sigma, tau) rows] of each shear to failure, in the order of the test."""
    by_point = {}
    with open(os.path.join(run_dir, f"series_{coal}.csv"), newline="") as f:
        for r in csv.DictReader(f):
            if r["phase"] == "shear":
                by_point.setdefault(int(r["point"]), []).append(
                    (float(r["sigma_kpa"]), float(r["tau_kpa"])))
    return [by_point[p] for p in sorted(by_point)]


def preshear_ratios(run_dir, coal):
    """tau / sigma of each pre-shear before a shear to failure, in the order of the test."""
    by_point = {}
    with open(os.path.join(run_dir, "points.csv"), newline="") as f:
        for r in csv.DictReader(f):
            if r["coal"] == coal and r["kind"] == "preshear":
                by_point[int(r["point"])] = float(r["tau_kpa"]) / float(r["sigma_kpa"])
    return [by_point[p] for p in sorted(by_point)]


def normalised(points, ratios):
    """Each failure tau times the mean pre-shear ratio over the ratio of its own pre-shear."""
    mean = statistics.fmean(ratios)
    return [(s, t * mean / r) for (s, t), r in zip(points, ratios)]


def failure(rows, est):
    if est.startswith("w"):
        h = int(est[1:]) // 2  # centred windows, cut short at the ends as pick_failure's
        windows = [(statistics.fmean(s for s, _ in rows[max(0, i - h):i + h + 1]),
                    statistics.fmean(t for _, t in rows[max(0, i - h):i + h + 1]))
                   for i in range(len(rows))]
        return max((p for p in windows if p[0] > 0), key=lambda p: p[1] / p[0])
    rest = rows[int(est[4:]):]
    return statistics.fmean(s for s, _ in rest), statistics.fmean(t for _, t in rest)


def fit(points):
    """C (kPa), phi (deg), se(C) (kPa) of the least-squares line, as yield_locus.hpp."""
    s = [p[0] for p in points]
    t = [p[1] for p in points]
    n = len(points)
    slope, c = statistics.linear_regression(s, t)
    sse = sum((ti - c - slope * si) ** 2 for si, ti in zip(s, t))
    sxx = sum((si - statistics.fmean(s)) ** 2 for si in s)
    se_c = math.sqrt(sse / (n - 2)) * math.sqrt(1 / n + statistics.fmean(s) ** 2 / sxx)
    return c, math.degrees(math.atan(slope)), se_c


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    coal, dirs = argv[1], argv[2:]
    tests = [shears(d, coal) for d in dirs]
    ratios = [preshear_ratios(d, coal) for d in dirs]
    for est in ESTIMATORS:
        if est == "w3pre":
            fits = [fit(normalised([failure(rows, "w3") for rows in test], r))
                    for test, r in zip(tests, ratios)]
        else:
            fits = [fit([failure(rows, est) for rows in test]) for test in tests]
        cs = [f[0] for f in fits]
        phis = [f[1] for f in fits]
        sd = statistics.stdev(cs) if len(cs) > 1 else math.nan
        print(f"{est:7s} C {' '.join(f'{c:5.2f}' for c in cs)}  mean {statistics.fmean(cs):.2f}"
              f" sd {sd:.2f} | phi {' '.join(f'{p:4.1f}' for p in phis)} mean"
              f" {statistics.fmean(phis):.1f} | se(C) {' '.join(f'{f[2]:.2f}' for f in fits)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
