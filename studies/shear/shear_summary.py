#!/usr/bin/env python3
"""Rows of a table from shear-test run directories (stdlib only).

usage: shear_summary.py DIR [DIR ...]   prints, per coal of each DIR/shear_test.json: C, phi (each
with the fit's standard error), the
steady tau/sigma of the first pre-shear (mean of the series beyond a strain of 0.25 and over at
most its last 0.3: the first pre-shear was 0.5 long before 2026-12-07 and now runs until steady),
f_c,
sigma_1, ffc, bulk density and wall time, as CSV on stdout; and, for the paper's two coals, each
failure shear stress over the measured yield locus C + sigma tan(phi) at the same normal stress
(Table 1 of the paper, PHYSICS.md: Longwanggou 0.67 kPa, 33.4 deg; Indonesian 0.68 kPa, 37.2 deg),
as its min, mean and max: a check of the tested points that does not extrapolate to sigma = 0.
"""
import csv
import json
import math
import os
import sys


def first_preshear_rows(series_path):
    """(strain, tau, sigma) of each row of the first pre-shear ([] if the series is absent)."""
    if not os.path.exists(series_path):
        return []
    with open(series_path, newline="") as f:
        return [(float(r["strain"]), float(r["tau_kpa"]), float(r["sigma_kpa"]))
                for r in csv.DictReader(f) if r["phase"] == "preshear" and r["point"] == "0"]


def steady_ratio(rows, from_strain=0.25, last_strain=0.3):
    """Mean tau / mean sigma of the first pre-shear's rows beyond from_strain, over at most its
    last last_strain (nan if none)."""
    if not rows:
        return math.nan
    end = rows[-1][0]
    kept = [(t, s) for g, t, s in rows if g > max(from_strain, end - last_strain)]
    if not kept:
        return math.nan
    return (sum(t for t, _ in kept) / len(kept)) / (sum(s for _, s in kept) / len(kept))


def first_preshear(doc, rows):
    """The first pre-shear's procedure: "fixed G" (to the strain G: every test before 2026-12-07,
    whose JSON has no preshear_max_strain; G from the series' rows, to 0.1) or "steady G0-G1" (on
    until steady, from the strain G0 to at most G1)."""
    lo, hi = doc.get("preshear_min_strain"), doc.get("preshear_max_strain")
    if lo is not None and hi is not None:
        return f"steady {lo:g}-{hi:g}" if hi > lo else f"fixed {lo:g}"
    end = rows[-1][0] if rows else math.nan
    return f"fixed {round(end, 1):g}"


MEASURED_LOCUS = {"Longwanggou": (0.67, 33.4), "Indonesian": (0.68, 37.2)}  # kPa, deg (Table 1)


def locus_ratios(coal, yield_locus):
    """Failure tau over the measured locus at each tested sigma ([] for a coal not in Table 1)."""
    if coal not in MEASURED_LOCUS:
        return []
    c, phi = MEASURED_LOCUS[coal]
    return [tau / (c + sigma * math.tan(math.radians(phi))) for sigma, tau in yield_locus]


def number_or_nan(x):
    return math.nan if x is None else x


def rows(run_dir):
    with open(os.path.join(run_dir, "shear_test.json")) as f:
        doc = json.load(f)
    for c in doc["coals"]:
        series = os.path.join(run_dir, f"series_{c['coal']}.csv")
        first = first_preshear_rows(series)
        ratios = locus_ratios(c["coal"], c["yield_locus"]) or [math.nan]
        yield {
            "run": os.path.basename(os.path.normpath(run_dir)),
            "coal": c["coal"],
            "cohesion_kpa": c["cohesion_kpa"],
            "friction_angle_deg": c["friction_angle_deg"],
            # the fit's standard errors (shear_test.json since 2026-12-05; nan before, or null
            # with two failure points)
            "cohesion_stderr_kpa": number_or_nan(c.get("cohesion_stderr_kpa")),
            "friction_angle_stderr_deg": number_or_nan(c.get("friction_angle_stderr_deg")),
            "preshear_kpa": c["preshear_kpa"][0],
            "steady_ratio": steady_ratio(first),
            "unconfined_yield_kpa": c["unconfined_yield_kpa"],
            "major_consolidation_kpa": c["major_consolidation_kpa"],
            "ffc": c["ffc"],
            "bulk_density_kg_m3": c["bulk_density_kg_m3"],
            "locus_ratio_min": min(ratios),
            "locus_ratio_mean": sum(ratios) / len(ratios),
            "locus_ratio_max": max(ratios),
            "particles": c["cell"]["particles"],
            "cell_width_d": c["cell"]["width_mm"] / c["cell"]["mean_cg_diameter_mm"],
            "first_preshear": first_preshear(doc, first),
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
