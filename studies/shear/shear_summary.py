#!/usr/bin/env python3
"""Rows of a table from shear-test run directories (stdlib only).

usage: shear_summary.py DIR [DIR ...]   prints, per coal of each DIR/shear_test.json: C, phi, the
steady tau/sigma of the first pre-shear (mean of the series beyond a strain of 0.25), f_c,
sigma_1, ffc, bulk density and wall time, as CSV on stdout.
"""
import csv
import json
import math
import os
import sys


def steady_ratio(series_path, from_strain=0.25):
    """Mean tau / mean sigma of the first pre-shear beyond from_strain (nan if absent)."""
    taus, sigmas = [], []
    with open(series_path, newline="") as f:
        for row in csv.DictReader(f):
            if row["phase"] == "preshear" and row["point"] == "0" and float(row["strain"]) > from_strain:
                taus.append(float(row["tau_kpa"]))
                sigmas.append(float(row["sigma_kpa"]))
    if not taus:
        return math.nan
    return (sum(taus) / len(taus)) / (sum(sigmas) / len(sigmas))


def rows(run_dir):
    with open(os.path.join(run_dir, "shear_test.json")) as f:
        doc = json.load(f)
    for c in doc["coals"]:
        series = os.path.join(run_dir, f"series_{c['coal']}.csv")
        yield {
            "run": os.path.basename(os.path.normpath(run_dir)),
            "coal": c["coal"],
            "cohesion_kpa": c["cohesion_kpa"],
            "friction_angle_deg": c["friction_angle_deg"],
            "preshear_kpa": c["preshear_kpa"][0],
            "steady_ratio": steady_ratio(series) if os.path.exists(series) else math.nan,
            "unconfined_yield_kpa": c["unconfined_yield_kpa"],
            "major_consolidation_kpa": c["major_consolidation_kpa"],
            "ffc": c["ffc"],
            "bulk_density_kg_m3": c["bulk_density_kg_m3"],
            "particles": c["cell"]["particles"],
            "wall_time_s": c["cell"]["wall_time_s"],
        }


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    out = None
    for d in argv[1:]:
        for r in rows(d):
            if out is None:
                out = csv.DictWriter(sys.stdout, fieldnames=list(r))
                out.writeheader()
            out.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
