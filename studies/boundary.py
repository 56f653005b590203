#!/usr/bin/python3
"""Where the small silo flows and where it arches, in dimensionless terms (issue 16, study b).

Usage: boundary.py --out OUT_DIR --dry DRY_STUDY_DIR [--dry ...] STUDY_DIR [STUDY_DIR ...]

Reads each STUDY_DIR/study.csv (written by `silodem study`) and, per run, check.json
(F_L,cg and d_cg of each coal, k, alpha), fill.csv (the settled bulk density of the bottom
segment H1) and summary.json (outlet diameter, cone). Groups the runs by grid point (all
varied keys but the seed) and classifies each point: "flows" (every seed emptied), "arches"
(every seed's flow stopped) or "mixed". For the coal at the outlet (segment H1) it computes:

  D / d_cg                  outlet diameter over the coarse-grained diameter;
  Bo_cg = F / (m_cg g)      the cohesive force F = factor x F_L,cg over the parcel's weight;
  Pi = <f> / F              the mean contact force from the stress at the outlet over F, with
                            <f> = 0.873 d_cg^2 sigma_1 (VERIFICATION.md 1.7) and Jenike's
                            stress in a stable arch sigma_1 = rho_b g D / H(theta),
                            H = 2 + theta / 60 (theta: the cone's half angle in degrees), with
                            rho_b the DEM bed's own settled bulk density of H1;
  rate / dry                the mean discharge rate (a stopped flow counts 0) over the dry
                            rate of the same outlet and k (from the --dry studies).

Writes OUT_DIR/boundary.csv (one row per grid point) and OUT_DIR/boundary.png (Pi against
D / d_cg, marked by class), and prints a markdown table.
"""

import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))

import silodem_plots as sp  # noqa: E402

G = 9.81


def runs_of(study_dir):
    """The rows of a study.csv that finished, with their run directory."""
    with open(os.path.join(study_dir, "study.csv"), newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(study_dir, "study.json"), encoding="utf-8") as f:
        meta = json.load(f)
    out = []
    for r in rows:
        if r["state"] != "finished":
            continue
        r["_dir"] = os.path.join(study_dir, "runs", r["run"])
        r["_point"] = tuple((k, r[k]) for k in meta["vary"])
        r["_study"] = os.path.basename(os.path.normpath(study_dir))
        out.append(r)
    return out


def run_numbers(run_dir):
    """Outlet D, cone half angle, and the bottom coal's d_cg, m_cg, F_L,cg, rho_b (H1)."""
    check = json.load(open(os.path.join(run_dir, "check.json"), encoding="utf-8"))
    summary = json.load(open(os.path.join(run_dir, "summary.json"), encoding="utf-8"))
    with open(os.path.join(run_dir, "fill.csv"), newline="", encoding="utf-8") as f:
        fill = list(csv.DictReader(f))
    h1 = [s for s in fill if s["segment"] == "H1"][0]
    coal = [m for m in check["materials"] if m["name"] == h1["coal"]][0]
    silo = summary["silo"]
    d_out = silo["outlet_diameter_m"]
    theta = math.degrees(math.atan((silo["cylinder_diameter_m"] - d_out) / 2 /
                                   silo["cone_height_m"]))
    return {"D": d_out, "theta": theta, "coal": h1["coal"], "d_cg": coal["cg_diameter_m"],
            "m_cg": coal["cg_mass_kg"], "F_cg": coal["cohesion_force_cg_n"],
            "rho_b": float(h1["bulk_density_kg_m3"]), "k": check["k"],
            "alpha": check["cohesion_exponent"]}


def factor_of(run_dir):
    """The particle-particle cohesion factor of a run (from its overrides, else its case)."""
    path = os.path.join(run_dir, "overrides.txt")
    if not os.path.exists(path):
        return math.nan
    lines = open(path, encoding="utf-8").read().splitlines()
    for line in lines:
        if line.startswith("contact.particle_particle.coal.") and ".cohesion.factor=" in line:
            raise SystemExit(f"{path}: '{line}': a per-coal cohesion factor is not supported "
                             "here (Bo_cg and Pi take one factor for every coal)")
    for line in lines:
        if line.startswith("contact.particle_particle.cohesion.factor="):
            return float(line.split("=", 1)[1])
    return math.nan


def mean(xs):
    """Mean of a non-empty list (NaN if empty)."""
    return sum(xs) / len(xs) if xs else math.nan


def main(argv=None):
    """Command line entry point."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--dry", action="append", default=[])
    ap.add_argument("studies", nargs="+")
    a = ap.parse_args(argv)
    dry = {}
    for d in a.dry:
        for r in runs_of(d):
            n = run_numbers(r["_dir"])
            dry.setdefault((round(n["D"], 6), n["k"]), []).append(float(r["mean_rate_kg_s"]))
    points = {}
    for d in a.studies:
        for r in runs_of(d):
            points.setdefault((r["_study"],) + r["_point"], []).append(r)
    rows = []
    for key, group in points.items():
        n = run_numbers(group[0]["_dir"])
        factor = factor_of(group[0]["_dir"])
        force = factor * n["F_cg"]
        sigma1 = n["rho_b"] * G * n["D"] / (2 + n["theta"] / 60)
        f_mean = 0.873 * n["d_cg"] ** 2 * sigma1
        stopped = sum(r["flow_stopped"] == "true" for r in group)
        emptied = sum(r["end"] == "emptied" for r in group)
        cls = "arches" if stopped == len(group) else "flows" if emptied == len(group) else "mixed"
        rates = [0.0 if r["flow_stopped"] == "true" else float(r["mean_rate_kg_s"]) for r in group]
        dry_rate = mean(dry.get((round(n["D"], 6), n["k"]), []))
        rows.append({
            "study": key[0], "point": " ".join("{}={}".format(k, v) for k, v in key[1:]),
            "k": n["k"], "alpha": n["alpha"], "factor": factor, "outlet_mm": 1e3 * n["D"],
            "coal_at_outlet": n["coal"], "D_over_dcg": n["D"] / n["d_cg"],
            "Bo_cg": force / (n["m_cg"] * G) if force > 0 else 0.0,
            "Pi": f_mean / force if force > 0 else math.inf, "seeds": len(group),
            "stopped": stopped, "class": cls, "rate_kg_s": mean(rates),
            "rate_over_dry": mean(rates) / dry_rate if dry_rate > 0 else math.nan,
            "rate_min": min(rates), "rate_max": max(rates)})
    rows.sort(key=lambda r: (r["study"], r["outlet_mm"], r["k"], r["alpha"], r["factor"]))
    os.makedirs(a.out, exist_ok=True)
    cols = list(rows[0].keys())
    with open(os.path.join(a.out, "boundary.csv"), "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, cols)
        w.writeheader()
        w.writerows(rows)
    fig, ax = sp.new_figure()
    marks = {"flows": ("o", "C0"), "mixed": ("s", "C1"), "arches": ("x", "C3")}
    for cls, (m, c) in marks.items():
        sel = [r for r in rows if r["class"] == cls and math.isfinite(r["Pi"])]
        ax.scatter([r["D_over_dcg"] for r in sel], [r["Pi"] for r in sel], marker=m, color=c,
                   label=cls, s=36)
    ax.set_yscale("log")
    ax.set_xlabel("outlet diameter / coarse-grained diameter D / d_cg (-)")
    ax.set_ylabel("Pi = <f> / F_coh (-)")
    sp.set_title(ax, "small silo: flow and arching",
                 "mean contact force from the arch stress over the cohesive force")
    sp.legend_below(fig, *ax.get_legend_handles_labels(), ncol=3)
    fig.savefig(os.path.join(a.out, "boundary.png"), dpi=sp.DPI)
    # The collapse: rate / dry against Pi, one series per (outlet, k, alpha).
    fig, ax = sp.new_figure()
    series = sorted({(r["outlet_mm"], r["k"], r["alpha"]) for r in rows})
    for i, (d_mm, k, alpha) in enumerate(series):
        sel = sorted((r for r in rows if (r["outlet_mm"], r["k"], r["alpha"]) == (d_mm, k, alpha)
                      and math.isfinite(r["Pi"])), key=lambda r: r["Pi"])
        ax.plot([r["Pi"] for r in sel], [r["rate_over_dry"] for r in sel],
                marker="osD^v<>"[i % 7], color="C{}".format(i % 10), ls="-", lw=1,
                label="D = {:.0f} mm, k = {:.0f}, alpha = {:.0f} (D/d_cg = {:.2f})".format(
                    d_mm, k, alpha, sel[0]["D_over_dcg"] if sel else math.nan))
    ax.set_xscale("log")
    ax.set_ylim(bottom=0)
    ax.set_xlabel("Pi = <f> / F_coh (-)")
    ax.set_ylabel("mean rate / dry rate (-)")
    sp.set_title(ax, "small silo: does the rate collapse onto Pi?",
                 "stopped flows count as rate 0; each point the mean of its seeds")
    sp.legend_below(fig, *ax.get_legend_handles_labels(), ncol=1)
    fig.savefig(os.path.join(a.out, "collapse.png"), dpi=sp.DPI)
    # Keys varied besides outlet, k, alpha and factor (e.g. a switch) get a column of their own.
    extra = sorted({kv.split("=", 1)[0] for r in rows for kv in r["point"].split()} -
                   {"outlet", "k", "alpha", "factor"})
    print("| " + " | ".join(extra + ["outlet (mm)", "k", "alpha", "factor", "D/d_cg", "Bo_cg",
                                      "Pi", "seeds stopped", "class",
                                      "rate / dry (min-max kg/s)"]) + " |")
    print("|" + "---|" * (len(extra) + 10))
    for r in rows:
        kv = dict(x.split("=", 1) for x in r["point"].split())
        print("| " + "".join("{} | ".format(kv.get(e, "")) for e in extra) +
              "{:.0f} | {:.0f} | {:.0f} | {:g} | {:.2f} | {:.1f} | {:.3f} | {}/{} | {} | "
              "{:.2f} ({:.3f}-{:.3f}) |".format(
                  r["outlet_mm"], r["k"], r["alpha"], r["factor"], r["D_over_dcg"], r["Bo_cg"],
                  r["Pi"], r["stopped"], r["seeds"], r["class"], r["rate_over_dry"],
                  r["rate_min"], r["rate_max"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
