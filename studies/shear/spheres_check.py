#!/usr/bin/env python3
"""Issue 17, must-show 2: checks of the shear cell on monodisperse spheres (stdlib only).

usage: spheres_check.py OUT   (OUT as written by studies/shear/spheres_check.sh)

Reads OUT/<config>_seed=<n>/shear_test.json for the configs base, box, stiff, f1, f2, takes the
mean over the seeds found, prints a table and the checks, writes OUT/checks.csv, and exits 1 if a
check fails, else 2 if a config has no finished run (its checks are written as not run), and 2
without checks if base has no run, the cells do not fit together or the runs mix first
pre-shears (fixed ones of two strains, or fixed ones and ones run to steady state). The optional
configs f4 (F = 0.60 N) and box2 (a third cell size), if OUT holds them, are reported beside the
checks, not checked: whether C grows in proportion to the force from f2 to f4, and whether phi
settles with the cell's size.
The cell sizes are read from the runs, not assumed: stiff, f1, f2 and f4 must be in base's cell and
box in another (spheres_check.sh's layout since 2026-12-06 is base 14 x 11 diameters, box 18 x 14,
box2 10 x 8; validation/shear/peak-ratio/spheres/ holds the runs of the layout before, base 10 x 8,
box 14 x 11, box2 18 x 14).
The tolerances are issue 17's. The steady friction is reported, not compared with the DEM
literature (see the comment at PRESHEAR_KPA).
"""
import csv
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shear_summary  # noqa: E402

PRESHEAR_KPA = 9.0
# The DEM literature's steady (critical-state) tau / sigma for such spheres is reported beside one
# published value, not checked against a band: the one 3D DEM value that could be read here is
# 0.38 for freely rotating, polydisperse spheres with mu_p >= 0.3 sheared between rough blocks
# (Latham, Abe & Mora 2005, "Macroscopic friction response of rotational and non-rotational
# lattice solid gouge models in 2D and 3D", abstract; docs/validation.md 5.1). One value is not a
# band, so it is printed, not checked.
LITERATURE_STEADY_RATIO = 0.38
FORCES_N = {"f1": 0.15, "f2": 0.30, "f4": 0.60}
CONFIGS = ["base", "box", "stiff", "f1", "f2"]
OPTIONAL = ["f4", "box2"]


def collect(out):
    runs = {c: [] for c in CONFIGS + OPTIONAL}
    for name in sorted(os.listdir(out)):
        config, _, seed = name.partition("_seed=")
        path = os.path.join(out, name)
        if config in runs and os.path.exists(os.path.join(path, "shear_test.json")):
            for r in shear_summary.rows(path):
                r["seed"] = int(seed)
                runs[config].append(r)
    return runs


def failure_points(out, config):
    """Mean failure shear stress (kPa) at each target normal stress over the seeds of config.

    Each point's tau is scaled to its target normal stress, tau x sigma_target / sigma: the cell's
    servo holds the mean normal stress, not the stress at the failure point (on average 9-16%
    above it at the peak of tau / sigma for dry spheres, docs/validation/shear-cell.md 5.1). Exact for a locus
    through the origin (the dry spheres); for f1 and f2 the failure points' sigma is on the target
    within 3% on average, so the scaling moves their cohesive part by about that much."""
    taus = {}
    for name in sorted(os.listdir(out)):
        c, _, _ = name.partition("_seed=")
        path = os.path.join(out, name, "points.csv")
        if c != config or not os.path.exists(path):
            continue
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if row["kind"] == "failure":
                    target = float(row["sigma_target_kpa"])
                    taus.setdefault(target, []).append(
                        float(row["tau_kpa"]) * target / float(row["sigma_kpa"]))
    return {sigma: statistics.fmean(t) for sigma, t in taus.items()}


def print_failure_ratios(name, pts, ref_name, ref_pts):
    """Print the failure tau of one config over another's at each common target stress."""
    common = sorted(set(ref_pts) & set(pts))
    if common:
        print(f"failure tau of {name} over {ref_name} at sigma = "
              + ", ".join(f"{s:g}" for s in common) + " kPa: "
              + ", ".join(f"{pts[s] / ref_pts[s]:.3f}" for s in common)
              + " (reported, not checked)")


def mean_sd(values):
    if not values:
        return math.nan, math.nan
    return statistics.fmean(values), (statistics.stdev(values) if len(values) > 1 else math.nan)


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    out = argv[1]
    runs = collect(out)
    missing = [c for c in CONFIGS if not runs[c]]
    if "base" in missing:
        print(f"spheres_check: no finished run of base in {out}", file=sys.stderr)
        return 2
    procedures = sorted({r["first_preshear"] for rs in runs.values() for r in rs})
    if len(procedures) > 1:
        print(f"spheres_check: the runs in {out} mix first pre-shears {procedures} (fixed: before "
              "2026-12-07; add seeds to such a folder with SHEAR_ARGS=\"--preshear-max-strain "
              "0.5\")", file=sys.stderr)
        return 2
    cells = {}
    for c, rs in runs.items():
        widths = sorted({round(r["cell_width_d"], 3) for r in rs})
        if len(widths) > 1:
            print(f"spheres_check: the runs of {c} in {out} are in cells {widths} diameters wide, "
                  "not one", file=sys.stderr)
            return 2
        if widths:
            cells[c] = widths[0]
    for c in ("stiff", "f1", "f2", "f4"):
        if c in cells and cells[c] != cells["base"]:
            print(f"spheres_check: {c} is in a {cells[c]:g}-diameter cell, base in a "
                  f"{cells['base']:g}: they must share the cell (runs of two layouts in {out}?)",
                  file=sys.stderr)
            return 2
    if cells.get("box") == cells["base"]:
        print(f"spheres_check: box and base are both {cells['base']:g} diameters wide: the box check "
              "needs two cell sizes", file=sys.stderr)
        return 2
    stats = {}
    print("config  cell (d)  seeds  C (kPa)        phi (deg)      steady tau/sigma   bulk density")
    for c in [c for c in CONFIGS + OPTIONAL if runs[c]]:
        rs = runs[c]
        s = {k: mean_sd([r[k] for r in rs])
             for k in ("cohesion_kpa", "friction_angle_deg", "steady_ratio", "bulk_density_kg_m3")}
        s["n"] = len(rs)
        stats[c] = s
        print(f"{c:6}  {cells[c]:8g}  {len(rs):5}  {s['cohesion_kpa'][0]:6.3f} +-{s['cohesion_kpa'][1]:5.3f}  "
              f"{s['friction_angle_deg'][0]:5.2f} +-{s['friction_angle_deg'][1]:4.2f}  "
              f"{s['steady_ratio'][0]:6.4f} +-{s['steady_ratio'][1]:6.4f}   "
              f"{s['bulk_density_kg_m3'][0]:7.1f}")

    checks = []

    def check(name, value, low, high, note, needs=()):
        """One check; written as not run (pass "-") when a config it needs has no run."""
        if any(c in missing for c in needs):
            checks.append({"check": name, "value": "not run", "low": f"{low:.4g}",
                           "high": f"{high:.4g}", "pass": "-", "note": note})
            return
        v = value()
        checks.append({"check": name, "value": f"{v:.4g}", "low": f"{low:.4g}",
                       "high": f"{high:.4g}", "pass": int(low <= v <= high), "note": note})

    base_phi = stats["base"]["friction_angle_deg"][0]
    base_ratio = stats["base"]["steady_ratio"][0]
    for c in ("base", "box", "stiff"):
        check(f"{c}: C / pre-shear stress", lambda c=c: stats[c]["cohesion_kpa"][0] / PRESHEAR_KPA,
              -0.03, 0.03, "issue 17: |C| below 3% of the pre-shear stress", (c,))
    for c in ("box", "stiff"):
        check(f"{c} / base: phi", lambda c=c: stats[c]["friction_angle_deg"][0] / base_phi, 0.95,
              1.05, "issue 17: the same within 5%", (c,))
        check(f"{c} / base: steady tau/sigma", lambda c=c: stats[c]["steady_ratio"][0] / base_ratio,
              0.95, 1.05, "issue 17: the same within 5%", (c,))
    ratio = (stats["f2"]["cohesion_kpa"][0] / stats["f1"]["cohesion_kpa"][0]
             if "f1" in stats and "f2" in stats else math.nan)
    check("C(f2) / C(f1) over F2 / F1", lambda: ratio / (FORCES_N["f2"] / FORCES_N["f1"]), 0.9, 1.1,
          "issue 17: C proportional to the force within 10%", ("f1", "f2"))

    # Supplementary, not issue 17's wording: the cohesive part of the strength, i.e. the mean over
    # the failure stresses of tau(f) - tau(base), should double with the force as well. Unlike the
    # intercept of a free-slope fit, it does not trade strength between C and phi.
    base_pts, f1_pts, f2_pts = (failure_points(out, c) for c in ("base", "f1", "f2"))
    sigmas = sorted(set(base_pts) & set(f1_pts) & set(f2_pts))
    if sigmas:
        excess = {c: statistics.fmean(pts[s] - base_pts[s] for s in sigmas)
                  for c, pts in (("f1", f1_pts), ("f2", f2_pts))}
        print(f"cohesive excess over base, mean over {len(sigmas)} failure stresses: "
              f"f1 {excess['f1']:.3f} kPa, f2 {excess['f2']:.3f} kPa")
        check("excess(f2) / excess(f1) over F2 / F1",
              lambda: excess["f2"] / excess["f1"] / (FORCES_N["f2"] / FORCES_N["f1"]), 0.9, 1.1,
              "supplementary: the strength above the dry spheres' grows with the force, "
              "proportional within 10%")
    else:
        check("excess(f2) / excess(f1) over F2 / F1", lambda: math.nan, 0.9, 1.1,
              "supplementary: the strength above the dry spheres' grows with the force, "
              "proportional within 10%", ("f1", "f2"))
    # Reported, not checked: the failure stresses themselves of the larger box and of 10x k_n
    # against the base cell's, stress by stress (what the fitted C and phi summarise).
    for c in ("box", "stiff"):
        if c in stats:
            print_failure_ratios(c, failure_points(out, c), "base", base_pts)
    # Reported, not checked: the optional configs.
    if all(c in stats for c in ("f1", "f2", "f4")):
        c_ratio = stats["f4"]["cohesion_kpa"][0] / stats["f2"]["cohesion_kpa"][0]
        print(f"C(f4) / C(f2) over F4 / F2: {c_ratio / (FORCES_N['f4'] / FORCES_N['f2']):.3f} "
              f"(C(f2) / C(f1) over F2 / F1: {ratio / (FORCES_N['f2'] / FORCES_N['f1']):.3f}; "
              f"phi f1 {stats['f1']['friction_angle_deg'][0]:.2f}, f2 "
              f"{stats['f2']['friction_angle_deg'][0]:.2f}, f4 {stats['f4']['friction_angle_deg'][0]:.2f} "
              "deg) (reported, not checked)")
        f4_pts = failure_points(out, "f4")
        common = sorted(set(base_pts) & set(f2_pts) & set(f4_pts))
        if common:
            e2 = statistics.fmean(f2_pts[s] - base_pts[s] for s in common)
            e4 = statistics.fmean(f4_pts[s] - base_pts[s] for s in common)
            print(f"cohesive excess over base: f4 {e4:.3f} kPa; excess(f4) / excess(f2) over F4 / F2: "
                  f"{e4 / e2 / (FORCES_N['f4'] / FORCES_N['f2']):.3f} (reported, not checked)")
    if "box2" in stats and "box" in stats:
        print(f"cells: base {cells['base']:g}, box {cells['box']:g}, box2 {cells['box2']:g} diameters; "
              f"phi box2 / box: {stats['box2']['friction_angle_deg'][0] / stats['box']['friction_angle_deg'][0]:.3f}, "
              f"box2 / base: {stats['box2']['friction_angle_deg'][0] / base_phi:.3f}; steady tau/sigma "
              f"box2 / box: {stats['box2']['steady_ratio'][0] / stats['box']['steady_ratio'][0]:.3f}, "
              f"box2 / base: {stats['box2']['steady_ratio'][0] / base_ratio:.3f} (reported, not checked)")
        print_failure_ratios("box2", failure_points(out, "box2"), "box", failure_points(out, "box"))
    print(f"steady tau/sigma against the one published 3D DEM value "
          f"({LITERATURE_STEADY_RATIO}, Latham et al. 2005): base "
          f"{base_ratio / LITERATURE_STEADY_RATIO:.3f}"
          + (f", box {stats['box']['steady_ratio'][0] / LITERATURE_STEADY_RATIO:.3f}" if "box" in stats else "")
          + " (reported, not checked)")

    with open(os.path.join(out, "checks.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(checks[0]))
        w.writeheader()
        w.writerows(checks)
    failed = 0
    for ch in checks:
        verdict = "NOT RUN" if ch["pass"] == "-" else ("pass" if ch["pass"] else "FAIL")
        print(f"{verdict}  {ch['check']}: {ch['value']} in [{ch['low']}, {ch['high']}]  ({ch['note']})")
        failed += 1 if ch["pass"] == 0 else 0
    if failed:
        return 1
    if missing:
        print(f"spheres_check: no finished run for {', '.join(missing)} in {out}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
