"""Issue 16 c: the paper's silo (L3-I2) run to empty, from the committed runs.

Reads every outlet.csv under validation/runs/paper-empty-k4/<case>/ (factor 0.111, the 12 s
calibration), validation/runs/paper-recal-k4/factor=<f>_seed=<s>/ (the recalibration on the
whole-discharge mean), validation/runs/paper-rumpf-k4/factor=<f>_seed=<s>/ (one factor on Eq. 14
at the DEM packing's porosity, 35 s runs), validation/runs/paper-rumpf-empty-k4/factor=<f>_seed=<s>/
(the same, run to empty), validation/runs/paper-rumpf-recal-k4/factor=<f>_seed=<s>/ (its
recalibration on runs to empty), validation/runs/paper-rumpf-k3/factor=<f>_seed=<s>/ (that force at
k = 3, alpha 2) and validation/runs/paper-k3/scenario=L3-I2_seed=<s>/
(k = 3 with the calibrated force), and draws (left) the cumulative discharged mass against time with the
experiment's end point (30.2 kg at 90 s, PHYSICS.md 7) and its mean rate as a dashed line (the
paper gives the experiment's rate only as that mean), (middle) the rate in 1 s bins, and (right)
the outlet calorific value in 1 s bins. Prints one line per run: mass, time, mean rate, their ratios to the
experiment's and whether all three are inside issue 16's band (5%, 10%, 10%).
Usage: /usr/bin/python3 studies/paper_empty_figure.py [OUT.png]
"""
import csv
import json
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXP_MASS, EXP_TIME = 30.2, 90.0  # PHYSICS.md 7 (the paper, section 4.1.3)


# (folder under validation/runs/, label of each factor=<f>_seed=<s> run, "{f}" and "{s}" filled in)
FACTOR_RUNS = [
    ("paper-recal-k4", "{f}, seed {s}"),
    ("paper-rumpf-k4", "{f} on rumpf_porosity 0.38, seed {s} (35 s)"),
    ("paper-rumpf-empty-k4", "{f} on rumpf_porosity 0.38, seed {s}, to empty"),
    ("paper-rumpf-recal-k4", "{f} on rumpf_porosity 0.38, seed {s}, to empty"),
    ("paper-rumpf-mid-k4", "{f} on rumpf_porosity 0.38, seed {s}, to empty"),
    ("paper-rumpf-mid-seeds-k4", "{f} on rumpf_porosity 0.38, seed {s}, to empty, per-particle skin"),
    ("paper-rumpf-k3", "{f} under alpha 2 at k = 3, rumpf_porosity 0.38, seed {s}"),
]


def runs():
    d = ROOT / "validation/runs/paper-empty-k4/L3-I2"
    if (d / "outlet.csv").exists():
        yield "0.111 (12 s calibration), seed 1", d
    for folder, label in FACTOR_RUNS:
        for d in sorted((ROOT / "validation/runs" / folder).glob("factor=*_seed=*/")):
            m = re.match(r"factor=([0-9.]+)_seed=(\d+)", d.name)
            if m and (d / "outlet.csv").exists():
                yield label.format(f=f"{float(m.group(1)):g}", s=m.group(2)), d
    for d in sorted((ROOT / "validation/runs/paper-k3").glob("scenario=L3-I2_seed=*/")):
        if (d / "outlet.csv").exists():
            yield "0.54 at k = 3, alpha 2 (the force of 0.135 at k = 4)", d


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs/figures/study/paper-k4-empty.png"
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(14, 4.2))
    a.plot([0, EXP_TIME], [0, EXP_MASS], "k--", lw=1, label="experiment's mean rate (0.335 kg/s)")
    a.plot([EXP_TIME], [EXP_MASS], "ks", label="experiment: 30.2 kg in 90 s")
    b.axhline(EXP_MASS / EXP_TIME, color="k", ls="--", lw=1)
    found = list(runs())
    colours = plt.cm.tab20(range(len(found)))  # one colour a run (the default cycle has ten)
    for (label, d), colour in zip(found, colours):
        rows = list(csv.DictReader(open(d / "outlet.csv")))
        s = json.load(open(d / "summary.json"))
        t = [float(r["t_end_s"]) for r in rows]
        a.plot([0] + t, [0] + [float(r["cumulative_kg"]) for r in rows], label=f"factor {label}",
               color=colour)
        b.step([float(r["t_start_s"]) for r in rows], [float(r["rate_kg_s"] or 0) for r in rows],
               where="post", color=colour)
        cal = [(float(r["t_start_s"]) + 0.5, float(r["calorific_kcal_kg"])) for r in rows
               if r["calorific_kcal_kg"] not in ("", "nan")]
        c.plot([x for x, _ in cal], [y for _, y in cal], ".-", ms=3, color=colour)
        mass, time, rate = s["discharged_mass_kg"], s["discharge_time_s"], s["mean_rate_kg_s"]
        # Issue 16 must-show 4: mass within 5%, time and mean rate within 10% of the experiment.
        band = [abs(mass / EXP_MASS - 1) <= 0.05, abs(time / EXP_TIME - 1) <= 0.10,
                abs(rate / (EXP_MASS / EXP_TIME) - 1) <= 0.10]
        print(f"factor {label}: {mass:.3f} kg in {time:.1f} s, {rate:.3f} kg/s, end {s['end']}; "
              f"against the experiment {mass / EXP_MASS:.3f}, {time / EXP_TIME:.3f}, "
              f"{rate / (EXP_MASS / EXP_TIME):.3f}: " +
              ("stopped by its time limit, no band" if s["end"] == "time limit" else
               f"{'inside' if all(band) else 'outside'} the 5/10/10% band"))
    a.set_xlabel("time after the valve opens (s)")
    a.set_ylabel("discharged mass (kg)")
    a.set_title("L3-I2, k_n = 1e4 N/m, one factor (k = 4 unless said)")
    a.legend(fontsize=7)
    b.set_xlabel("time after the valve opens (s)")
    b.set_ylabel("rate in 1 s bins (kg/s)")
    b.set_ylim(bottom=0)
    c.set_xlabel("time after the valve opens (s)")
    c.set_ylabel("outlet calorific value, 1 s bins (kcal/kg)")
    for ax in (a, b, c):
        ax.set_xlim(left=0)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
