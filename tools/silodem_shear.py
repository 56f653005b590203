#!/usr/bin/python3
"""The figures of a silodem shear test: the yield locus with its two Mohr circles, and the
shear and normal stresses through the test.

Usage: silodem_shear.py [--quiet] SHEAR_DIR

Reads SHEAR_DIR/shear_test.json and SHEAR_DIR/series_<coal>.csv (written by `silodem
shear-test`). Writes, per coal, SHEAR_DIR/figures/yield_locus_<coal>.png (the failure points,
the pre-shear points, the fitted locus, the Mohr circle of the unconfined yield strength through
the origin and the one of the major consolidation stress through the pre-shear point, and the
measured locus tau = C + sigma tan(phi) of the coal) and SHEAR_DIR/figures/shear_series_<coal>.png.
Prints each path (not with --quiet). Exit 0 on success, 2 if the directory is not a shear test.
"""

import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np  # noqa: E402

import silodem_plots as sp  # noqa: E402


def safe(name):
    return re.sub(r"[^A-Za-z0-9-]", "_", name)


def circle(ax, centre_radius, **kw):
    c, r = centre_radius
    a = np.linspace(0.0, math.pi, 181)
    ax.plot(c + r * np.cos(a), r * np.sin(a), **kw)


def locus_figure(doc, r, path, records):
    fig, ax = sp.new_figure((7.0, 5.5))
    pts = np.array(r["yield_locus"], dtype=float)
    pre = np.array(r["preshear_points"], dtype=float)
    c = r["cohesion_kpa"]
    t = math.tan(math.radians(r["friction_angle_deg"]))
    s1 = r["major_consolidation_kpa"]
    xs = np.linspace(0.0, max(s1, doc["preshear_kpa"]) * 1.05, 50)
    ax.plot(xs, c + t * xs, color="C0", label="DEM yield locus: C = {:.3f} kPa, phi = {:.1f} deg"
            .format(c, r["friction_angle_deg"]))
    m = r["measured"]
    ax.plot(xs, m["cohesion_kpa"] + math.tan(math.radians(m["friction_angle_deg"])) * xs,
            color="0.4", linestyle="--",
            label="measured (FT-4): C = {:.2f} kPa, phi = {:.1f} deg"
            .format(m["cohesion_kpa"], m["friction_angle_deg"]))
    if r["unconfined_yield_kpa"] > 0:
        circle(ax, r["mohr_unconfined_kpa"], color="C3",
               label="f_c = {:.3f} kPa".format(r["unconfined_yield_kpa"]))
    circle(ax, r["mohr_consolidation_kpa"], color="C2",
           label="sigma_1 = {:.2f} kPa, ffc = {}".format(
               s1, "inf" if r["ffc"] is None else "{:.2f}".format(r["ffc"])))
    ax.plot(pts[:, 0], pts[:, 1], "o", color="C0", label="failure (peak)")
    ax.plot(pre[:, 0], pre[:, 1], "s", color="C1", mfc="none", label="pre-shear (steady)")
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("normal stress sigma (kPa)")
    ax.set_ylabel("shear stress tau (kPa)")
    sp.set_title(ax, "{}, k = {:g}".format(r["coal"], doc["k"]),
                 "yield locus at {:g} kPa pre-shear".format(doc["preshear_kpa"]))
    h, lab = ax.get_legend_handles_labels()
    sp.legend_below(fig, h, lab, ncol=2)
    sp.save_figure(fig, path, records)


def series_figure(doc, r, csv_path, path, records):
    _, rows = sp.read_rows(csv_path)
    tt = sp.column(rows, "time_s")
    fig, ax = sp.new_figure()
    ax.plot(tt, sp.column(rows, "sigma_kpa"), color="C0", lw=0.8, label="normal stress")
    ax.plot(tt, sp.column(rows, "tau_kpa"), color="C3", lw=0.8, label="shear stress")
    ax.set_xlabel("simulated time (s)")
    ax.set_ylabel("stress on the lid (kPa)")
    sp.set_title(ax, "{}, k = {:g}".format(r["coal"], doc["k"]), "the shear test's stresses")
    h, lab = ax.get_legend_handles_labels()
    sp.legend_below(fig, h, lab)
    sp.save_figure(fig, path, records)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    quiet = "--quiet" in argv
    argv = [a for a in argv if a != "--quiet"]
    if len(argv) != 1:
        print("usage: silodem_shear.py [--quiet] SHEAR_DIR", file=sys.stderr)
        return 2
    d = argv[0]
    try:
        with open(os.path.join(d, "shear_test.json")) as f:
            doc = json.load(f)
        coals = doc["coals"]
    except (OSError, ValueError, KeyError) as e:
        print("silodem_shear.py: {} is not a shear test: {}".format(d, e), file=sys.stderr)
        return 2
    os.makedirs(os.path.join(d, "figures"), exist_ok=True)
    records = []
    for r in coals:
        name = safe(r["coal"])
        p = os.path.join(d, "figures", "yield_locus_{}.png".format(name))
        locus_figure(doc, r, p, records)
        if not quiet:
            print(p)
        s = os.path.join(d, "series_{}.csv".format(name))
        if os.path.exists(s):
            p = os.path.join(d, "figures", "shear_series_{}.png".format(name))
            series_figure(doc, r, s, p, records)
            if not quiet:
                print(p)
    problems = sp.label_problems(records)
    for pr in problems:
        print("silodem_shear.py: " + pr, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
