"""Issue 16 c, must-show 4: the calibration curve of the paper's silo (L3-I2, k = 4, run to empty).

Reads the committed study.csv files of the runs to empty and draws, for each way of turning the
coals' properties into the moisture force, the mean rate and the discharge time against the one
cohesion factor, with issue 16's band around the experiment (PHYSICS.md 7: 30.2 kg in 90 s, 0.335
kg/s; band 10% in time and rate):
  - Eq. 15's porosities (validation/studies/paper-empty-k4, paper-recal-k4: 0.111, 0.125, 0.135);
  - rumpf_porosity 0.38 (validation/studies/paper-rumpf-empty-k4, paper-rumpf-recal-k4,
    paper-rumpf-mid-k4 and, once it has run, paper-rumpf-mid-seeds-k4: 0.30-0.32).
A third panel gives the time by which 95% of the Indonesian (the bottom coal) had left, from each
run's committed outlet.csv, against the paper's "within the first 20 s" (its section 4.2, a statement
about its simulation, not a measurement): the shape of the discharge beside its mean.
Each point is one seed; a run whose flow stopped is drawn hollow; the line joins each factor's mean
over its seeds, marked by a bar where it has several (red if a seed's flow stopped: its time counts
as the time it stopped, so the mean time is a lower bound). Prints every run, each factor's mean
(and the seeds' range where it has several) and, between the two neighbouring factors whose mean
rates bracket 0.335 kg/s (and whose mean times bracket 90 s), the factor found by linear
interpolation: a reading of the means, not a calibrated value (where a factor has one seed, of
that seed).
Usage: /usr/bin/python3 studies/paper_calibration_curve.py [OUT.png]
"""
import csv
import pathlib
import sys

import matplotlib

from paper_run_row import bottom_out, read_bins  # same folder: the table's reading of the phases

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXP_MASS, EXP_TIME, EXP_RATE = 30.2, 90.0, 0.335  # PHYSICS.md 7 (the paper, section 4.1.3)
BAND = 0.10  # issue 16, must-show 4: 10% in discharge time and in mean rate

FAMILIES = [
    ("Eq. 15 porosities, alpha 3", ["paper-empty-k4", "paper-recal-k4"]),
    (
        "rumpf_porosity 0.38, alpha 3",
        ["paper-rumpf-empty-k4", "paper-rumpf-recal-k4", "paper-rumpf-mid-k4", "paper-rumpf-mid-seeds-k4"],
    ),
]


def rows(folders):
    out = []
    for folder in folders:
        path = ROOT / "validation/studies" / folder / "study.csv"
        if not path.exists():  # a study not yet run (or not yet committed)
            continue
        for r in csv.DictReader(open(path)):
            if r["state"] != "finished" or r.get("scenario", "L3-I2") != "L3-I2":
                continue
            factor = float(r["factor"]) if "factor" in r else 0.111  # paper-empty-k4 varies the scenario
            out.append(
                dict(
                    factor=factor,
                    seed=int(r["seed"]),
                    mass=float(r["discharged_mass_kg"]),
                    time=float(r["discharge_time_s"]),
                    rate=float(r["mean_rate_kg_s"]),
                    stopped=r["flow_stopped"] == "true",
                    folder=folder,
                )
            )
            out[-1]["indonesian"] = indonesian_out(run_dir(folder, out[-1]) / "outlet.csv")
    return sorted(out, key=lambda r: (r["factor"], r["seed"]))


def run_dir(folder, r):
    base = ROOT / "validation/runs" / folder
    return base / "L3-I2" if folder == "paper-empty-k4" else base / f"factor={r['factor']:g}_seed={r['seed']}"


def indonesian_out(outlet):
    """Time (end of the 1 s bin) by which 95% of the Indonesian that left had left."""
    return bottom_out(read_bins(outlet))


def means(pts):
    """One point per factor: the mean of its seeds' metrics, and how many seeds it has."""
    out = []
    for f in sorted({p["factor"] for p in pts}):
        group = [p for p in pts if p["factor"] == f]
        m = dict(factor=f, seeds=len(group), stopped=sum(p["stopped"] for p in group))
        for key in ("rate", "time", "indonesian"):
            vals = [p[key] for p in group]
            m[key], m[key + "_range"] = sum(vals) / len(vals), (min(vals), max(vals))
        out.append(m)
    return out


def crossing(points, key, target):
    """Factors where the metric crosses target between neighbouring factors (linear)."""
    found = []
    for a, b in zip(points, points[1:]):
        ya, yb = a[key] - target, b[key] - target
        if a["factor"] != b["factor"] and ya * yb <= 0 and ya != yb:
            found.append(a["factor"] + (b["factor"] - a["factor"]) * ya / (ya - yb))
    return found


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs/figures/study/paper-k4-calibration-curve.png"
    fig, axes = plt.subplots(len(FAMILIES), 3, figsize=(14, 3.6 * len(FAMILIES)), squeeze=False)
    for (name, folders), (ar, at, ai) in zip(FAMILIES, axes):
        pts = rows(folders)
        print(f"{name}:")
        for p in pts:
            inside = abs(p["time"] / EXP_TIME - 1) <= BAND and abs(p["rate"] / EXP_RATE - 1) <= BAND
            print(
                f"  factor {p['factor']:g} seed {p['seed']} ({p['folder']}): {p['mass']:.2f} kg, "
                f"{p['time']:.1f} s ({p['time'] / EXP_TIME - 1:+.1%}), {p['rate']:.4f} kg/s "
                f"({p['rate'] / EXP_RATE - 1:+.1%}), Indonesian 95% out by {p['indonesian']:.0f} s"
                f"{', flow stopped' if p['stopped'] else ''}"
                f"{', inside the band' if inside else ''}"
            )
        avg = means(pts)
        for m in avg:
            if m["seeds"] > 1:
                print(
                    f"  factor {m['factor']:g}, mean of {m['seeds']} seeds: "
                    f"{m['time']:.1f} s ({m['time_range'][0]:.1f}-{m['time_range'][1]:.1f}), "
                    f"{m['rate']:.4f} kg/s ({m['rate_range'][0]:.4f}-{m['rate_range'][1]:.4f}), "
                    f"Indonesian out by {m['indonesian']:.0f} s"
                    + (
                        f"; {m['stopped']} of them stopped with the silo not empty, so the mean time is a "
                        "lower bound and the mean rate an upper bound"
                        if m["stopped"]
                        else ""
                    )
                )
        for key, target, unit in (("rate", EXP_RATE, "kg/s"), ("time", EXP_TIME, "s")):
            xs = crossing(avg, key, target)
            said = ", ".join(f"{x:.4f}" for x in xs) if xs else "not bracketed"
            print(f"  {key} = {target:g} {unit} at factor {said} (linear between the factors' means)")
        for ax, key, target, label in (
            (ar, "rate", EXP_RATE, "mean rate (kg/s)"),
            (at, "time", EXP_TIME, "discharge time (s)"),
        ):
            ax.axhspan(target * (1 - BAND), target * (1 + BAND), color="0.85", label="experiment +-10%")
            ax.axhline(target, color="k", ls="--", lw=1, label=f"experiment ({target:g})")
            ax.plot([m["factor"] for m in avg], [m[key] for m in avg], "-", color="C0", lw=1)
            for m in avg:
                if m["seeds"] > 1:  # the factor's mean; red where a seed's flow stopped (a bound)
                    ax.plot(m["factor"], m[key], "_", ms=14, mew=2, color="C3" if m["stopped"] else "C0")
            for p in pts:
                ax.plot(p["factor"], p[key], "o", color="C0", mfc="none" if p["stopped"] else "C0")
            ax.set_xlabel(f"cohesion factor ({name})")
            ax.set_ylabel(label)
            ax.grid(alpha=0.3)
        ai.axhline(20, color="k", ls=":", lw=1, label="the paper's simulation: within 20 s")
        ai.plot([m["factor"] for m in avg], [m["indonesian"] for m in avg], "-", color="C1", lw=1)
        for p in pts:
            ai.plot(p["factor"], p["indonesian"], "s", color="C1", mfc="none" if p["stopped"] else "C1")
        ai.set_xlabel(f"cohesion factor ({name})")
        ai.set_ylabel("95% of the Indonesian out by (s)")
        ai.grid(alpha=0.3)
        if any(p["stopped"] for p in pts):
            ar.plot([], [], "o", color="C0", mfc="none", label="hollow: the flow stopped (not empty)")
        if any(m["seeds"] > 1 for m in avg):
            ar.plot([], [], "_", ms=14, mew=2, color="C0", label="bar: the factor's mean (red: a seed stopped)")
        ai.legend(fontsize=8)
        ar.legend(fontsize=8)
        several = [f"{m['factor']:g}: {m['seeds']} seeds" for m in avg if m["seeds"] > 1]
        count = "one seed per factor" if not several else "; ".join(several) + ", the others one"
        ar.set_title(f"L3-I2, k = 4, {count} ({name})", fontsize=9, loc="left")
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
