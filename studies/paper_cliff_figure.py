"""Issue 16 c: the paper's silo (L3-I2, k = 4) over the cohesion factor, from the committed runs.

Reads every outlet.csv under validation/calibration/paper-k4/x=<f>_seed=<s>/ and
validation/studies/paper-cliff/factor=<f>_seed=<s>/ and draws (left) the mean rate over the first
12 s against the factor, seeds as dots, with the experiment's 0.335 kg/s and the calibration's 10%
band, and (right) the rate in 1 s bins of every run. Prints one line per run.
Usage: /usr/bin/python3 studies/paper_cliff_figure.py [OUT.png]
"""
import csv
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
SOURCES = [ROOT / "validation/calibration/paper-k4", ROOT / "validation/studies/paper-cliff"]
TARGET, TOL, WINDOW = 0.335, 0.10, 12.0  # PHYSICS.md 7; studies/paper_silo_calibrate.sh


def runs():
    for src in SOURCES:
        for d in sorted(src.glob("*_seed=*")):
            m = re.match(r"(?:x|factor)=([0-9.]+)_seed=(\d+)", d.name)
            rows = list(csv.DictReader(open(d / "outlet.csv")))
            bins = [(float(r["t_start_s"]), float(r["rate_kg_s"] or 0.0)) for r in rows]
            out = sum(float(r["mass_kg"] or 0.0) for r in rows if float(r["t_start_s"]) < WINDOW)
            yield float(m.group(1)), int(m.group(2)), out / WINDOW, bins


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs/figures/study/paper-k4-cliff.png"
    data = list(runs())
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    a.axhspan(TARGET * (1 - TOL), TARGET * (1 + TOL), color="0.85", label="experiment +-10%")
    a.axhline(TARGET, color="k", lw=1)
    for f, s, rate, bins in data:
        print(f"factor {f:.3f} seed {s}: {rate:.3f} kg/s over 0-{WINDOW:.0f} s")
        a.plot(f, rate, "o", color="C0")
        b.step([t for t, _ in bins], [r for _, r in bins], where="post", label=f"{f:g}, seed {s}")
    factors = sorted({f for f, *_ in data})
    means = [sum(r for g, _, r, _ in data if g == f) / sum(1 for g, *_ in data if g == f) for f in factors]
    a.plot(factors, means, "-", color="C0", label="mean of the seeds")
    a.set_xlabel("cohesion factor (both slots, both coals)")
    a.set_ylabel(f"mean rate over 0-{WINDOW:.0f} s (kg/s)")
    a.set_title("L3-I2, k = 4, k_n = 1e4 N/m")
    a.set_ylim(bottom=0)
    a.legend(fontsize=8)
    b.axhline(TARGET, color="k", lw=1)
    b.set_xlabel("time after the valve opens (s)")
    b.set_ylabel("rate in 1 s bins (kg/s)")
    b.set_xlim(0, WINDOW)
    b.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
