#!/usr/bin/python3
"""The figure of a silodem calibration: the metric against the parameter.

Usage: silodem_calibrate.py CALIBRATION_DIR

Reads CALIBRATION_DIR/calibration.json (metric, target, tolerance, keys) and
CALIBRATION_DIR/calibration.csv (every run of every evaluation, written by
`silodem calibrate`). Writes CALIBRATION_DIR/calibration.png: each seed as a
dot (a cross where the flow stopped), each evaluation's mean with its standard
error, the order of the evaluations, and the target with its tolerance band.
Prints the path. Exit 0 on success, 2 if the directory is not a calibration.
"""

import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import silodem_plots as sp  # noqa: E402

UNITS = {"discharged_mass_kg": "kg", "discharge_time_s": "s", "mean_rate_kg_s": "kg/s",
         "window_rate_kg_s": "kg/s", "discharged_fraction": "-",
         "outlet_mean_calorific_kcal_kg": "kcal/kg"}


number = sp.cell_number


def main(argv=None):
    """Command line entry point; returns the exit code."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print("usage: silodem_calibrate.py CALIBRATION_DIR", file=sys.stderr)
        return 2
    d = argv[0]
    try:
        with open(os.path.join(d, "calibration.json"), encoding="utf-8") as f:
            meta = json.load(f)
        with open(os.path.join(d, "calibration.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
    except (OSError, ValueError) as e:
        print("silodem_calibrate: error: not a calibration directory ({})".format(e),
              file=sys.stderr)
        return 2
    metric, target, tol = meta["metric"], float(meta["target"]), float(meta["tolerance"])
    fig, ax = sp.new_figure()
    band = tol * abs(target)
    ax.axhspan(target - band, target + band, color="0.85")
    ax.axhline(target, color="0.4", lw=1)
    finite = [number(r["value"]) for r in rows if math.isfinite(number(r["value"]))]
    top = max(finite + [target + band]) * 1.1 if finite else target * 2
    evals = {}
    for r in rows:
        e = int(r["evaluation"])
        x, v = number(r["x"]), number(r["value"])
        evals.setdefault(e, (x, number(r["mean"]), number(r["standard_error"])))
        stopped = r.get("flow_stopped") == "true"
        if math.isnan(v):
            continue
        ax.plot(x, min(v, top), "x" if stopped else "o", color="C0", ms=9 if stopped else 3,
                alpha=0.9, zorder=5)
    for e, (x, m, se) in sorted(evals.items()):
        if math.isfinite(m):
            ax.errorbar(x, m, yerr=se if math.isfinite(se) else 0, fmt="s", color="C3", ms=5,
                        capsize=3)
            ax.annotate(str(e), (x, m), textcoords="offset points", xytext=(5, 5), fontsize=8)
    keys = ", ".join(meta.get("params", []))
    ax.set_xlabel("{} (case-file units)".format(keys))
    ax.set_ylabel("{} ({})".format(metric, UNITS.get(metric, "-")))
    ax.set_ylim(bottom=0, top=top)
    sp.set_title(ax, "calibration of {}".format(keys),
                 "{} = {:.4g} \u00b1 {:g}% (numbers: order of evaluation)".format(metric, target,
                                                                           100 * tol))
    handles = [Patch(color="0.85"), Line2D([], [], color="C0", marker="o", ls="none", ms=3),
               Line2D([], [], color="C0", marker="x", ls="none", ms=6),
               Line2D([], [], color="C3", marker="s", ls="none", ms=5)]
    labels = ["target \u00b1 tolerance", "one seed", "one seed, flow stopped (rate 0)",
              "evaluation: mean \u00b1 standard error"]
    sp.legend_below(fig, handles, labels, ncol=2)
    path = os.path.join(d, "calibration.png")
    sp.save_figure(fig, path, [])
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
