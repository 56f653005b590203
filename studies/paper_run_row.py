"""Issue 16 c: one row of flow-or-arch.md 4.5's table of paper-silo runs, from a run's files.

For each run directory given (summary.json and outlet.csv, committed under validation/runs/ or a
live run's directory once it has finished) prints:
  - discharged mass, discharge time and mean rate (summary.json), with their differences from the
    experiment (PHYSICS.md 7: 30.2 kg in 90 s, 0.335 kg/s);
  - the time by which 95% of the Indonesian that left had left (end of its 1 s bin; also used by
    paper_calibration_curve.py);
  - the Longwanggou's 5% and 95% times of its outflow (interpolated inside the 1 s bins) and its
    mean rate between them (90% of its outflow over that span);
  - the mean rates over 20-40, 40-60 and 60-80 s from the cumulative mass (a window the run did
    not reach is cut at its discharge time and marked);
  - when the experiment's 30.2 kg were out (interpolated), or "never";
  - for a run whose flow stopped, the mass left in the silo and its share of the fill.
Usage: /usr/bin/python3 studies/paper_run_row.py RUN_DIR [RUN_DIR ...]
"""
import csv
import json
import pathlib
import sys

EXP_MASS, EXP_TIME, EXP_RATE = 30.2, 90.0, 0.335  # PHYSICS.md 7 (the paper, section 4.1.3)
TOP, BOTTOM = "Longwanggou", "Indonesian"  # L3-I2: the Indonesian fills the bottom segments


def read_bins(path):
    bins = []
    for b in csv.DictReader(open(path)):
        bins.append(
            dict(
                t0=float(b["t_start_s"]),
                t1=float(b["t_end_s"]),
                mass=float(b["mass_kg"]),
                cum=float(b["cumulative_kg"]),
                top=float(b[f"fraction_{TOP}"] or 0),
                bottom=float(b[f"fraction_{BOTTOM}"] or 0),
            )
        )
    if not bins:
        raise SystemExit(f"error: {path} has no bins")
    return bins


def bottom_out(bins):
    """Time (end of the 1 s bin) by which 95% of the bottom coal that left had left."""
    masses = [b["mass"] * b["bottom"] for b in bins]
    total, acc = sum(masses), 0.0
    for b, m in zip(bins, masses):
        acc += m
        if acc >= 0.95 * total:
            return b["t1"]
    return float("nan")


def time_when(bins, masses, target):
    """First time at which the running sum of masses (one per bin) reaches target, linear in the bin."""
    acc = 0.0
    for b, m in zip(bins, masses):
        if m > 0 and acc + m >= target:
            return b["t0"] + (b["t1"] - b["t0"]) * (target - acc) / m
        acc += m
    return float("nan")


def cumulative_at(bins, t):
    """Discharged mass at time t (linear inside the bin holding t; the total after the last bin)."""
    before = 0.0
    for b in bins:
        if t <= b["t0"]:
            return before
        if t < b["t1"]:
            return before + b["mass"] * (t - b["t0"]) / (b["t1"] - b["t0"])
        before = b["cum"]
    return before


def row(run):
    run = pathlib.Path(run)
    summary = json.load(open(run / "summary.json"))
    bins = read_bins(run / "outlet.csv")
    d = summary["discharge"] if "discharge" in summary else summary
    mass, time = float(d["discharged_mass_kg"]), float(d["discharge_time_s"])
    rate = mass / time
    out_by = bottom_out(bins)
    top = [b["mass"] * b["top"] for b in bins]
    t5, t95 = time_when(bins, top, 0.05 * sum(top)), time_when(bins, top, 0.95 * sum(top))
    windows = []
    for a, z in ((20, 40), (40, 60), (60, 80)):
        if time <= a:
            windows.append("-")
            continue
        end = min(z, time)
        w = (cumulative_at(bins, end) - cumulative_at(bins, a)) / (end - a)
        windows.append(f"{w:.2f}" + (f" (to {time:.1f} s)" if end < z else ""))
    t_exp = time_when(bins, [b["mass"] for b in bins], EXP_MASS)
    return (
        f"{run}: {mass:.2f} kg ({mass / EXP_MASS - 1:+.1%}), {time:.1f} s ({time / EXP_TIME - 1:+.1%}), "
        f"{rate:.4f} kg/s ({rate / EXP_RATE - 1:+.1%}); {BOTTOM} 95% out by {out_by:.0f} s; "
        f"{TOP} 5-95% of its outflow {t5:.0f}-{t95:.0f} s, {0.9 * sum(top) / (t95 - t5):.2f} kg/s; "
        f"20-40, 40-60, 60-80 s: {', '.join(windows)} kg/s; "
        f"{EXP_MASS} kg out at " + (f"{t_exp:.1f} s" if t_exp == t_exp else "never") + stopped(d)
    )


def stopped(d):
    """'; flow stopped with M kg (F of the fill) left' for a run whose flow stopped, else ''."""
    if d.get("flow_stopped") is not True:
        return ""
    left, filled = float(d["remaining_mass_kg"]), float(d["filled_mass_kg"])
    return f"; flow stopped with {left:.2f} kg ({left / filled:.1%} of the fill) left"


def main(argv):
    if not argv:
        raise SystemExit(__doc__.strip().splitlines()[-1])
    for run in argv:
        print(row(run))


if __name__ == "__main__":
    main(sys.argv[1:])
