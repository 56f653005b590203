#!/usr/bin/env python3
"""Why a cohesive run's outlet rate falls as the paper's silo empties (issue 16, flow-or-arch.md 4.5).

usage: /usr/bin/python3 studies/paper_decline_figure.py RUN_DIR OTHER_OUTLET_CSV OUT.png

RUN_DIR is a run directory with its probes (outlet.csv, check.json, case.toml and overrides.txt,
probe_coordination.csv,
probe_slab.csv: the probe files are too large to commit, so this needs the run directory itself);
OTHER_OUTLET_CSV is a second run's outlet.csv drawn for comparison. Prints the numbers and draws
four panels:
  (a) the 1 s outlet rate of both runs;
  (b) the rate of each all-Longwanggou 1 s bin against the mass left in the silo;
  (c) RUN_DIR's outflow from the silo's particle count (probe_coordination.csv, every probe
      sample) in 0.5 s blocks per 10 s window: the mean rate, the rate of the flowing blocks and
      the share of blocks "dripping" below 0.1 kg/s (from 20 s on, counted at Longwanggou's
      parcel mass: L3-I2's Indonesian is out by then);
  (d) the mean net normal load k_n delta - F of the contacts between slab particles
      (probe_slab.csv: |y| below the slab half-width), over F, by height above the outlet, at the
      slab's snapshots from 20 s on. delta from the stored positions and radii; F the coal pair's
      moisture force (check.json's cohesion_force_cg_n times the case's factor, the mean of the
      two coals' for a mixed pair; cohesion_exponent 3 and the particle-particle slot). Contacts
      with particles outside the slab, with walls, and the dashpot are left out, so this samples
      the contact loads rather than summing them. Assumes an overlap-only constant moisture force
      and a linear normal spring, as in the run it was written for.
"""
import json
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def case_with_overrides(run):
    """The run's case.toml with its overrides.txt (KEY=VALUE lines, as --set) applied."""
    case = tomllib.load(open(f"{run}/case.toml", "rb"))
    for line in open(f"{run}/overrides.txt"):
        if "=" not in line:
            continue
        key, value = line.strip().split("=", 1)
        *path, last = key.split(".")
        node = case
        for part in path:
            node = node.setdefault(part, {})
        node[last] = tomllib.loads(f"v = {value}")["v"]
    return case


def read_csv(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def outlet(path):
    o = read_csv(path)
    width = o["t_end_s"] - o["t_start_s"]
    return o, np.where(width > 0, o["mass_kg"] / np.where(width > 0, width, 1), 0.0)


def main(argv):
    if len(argv) != 4:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    run, other, out_png = argv[1], argv[2], argv[3]
    check = json.load(open(f"{run}/check.json"))
    case = case_with_overrides(run)
    pp = case["contact"]["particle_particle"]
    factor = pp["cohesion"]["factor"]
    k_n = pp["normal"]["stiffness"]
    force = np.array([m["cohesion_force_cg_n"] * factor for m in check["materials"]])
    filled = sum(s["mass_kg"] for s in check["fill_plan"])

    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    ax = ax.ravel()
    for path, label, colour in ((f"{run}/outlet.csv", "this run", "C0"), (other, "comparison run", "C1")):
        o, rate = outlet(path)
        ax[0].step(o["t_start_s"], rate, where="post", color=colour, label=f"{label} ({path.split('/')[-2]})")
        lw = np.nan_to_num(o["fraction_Longwanggou"]) > 0.99
        left = filled - o["cumulative_kg"] + o["mass_kg"]
        ax[1].plot(left[lw], rate[lw], ".-", color=colour, label=label)
        # rate and its 1 s scatter over windows of the mass left, all-Longwanggou bins
        for hi, lo in ((25, 19), (19, 13), (13, 6.7), (6.7, 2)):
            q = lw & (left <= hi) & (left > lo)
            if q.sum() > 2:
                print(f"{label}: {hi}-{lo} kg left: {rate[q].mean():.3f} kg/s, 1 s bins' CV {rate[q].std() / rate[q].mean():.2f}")
    ax[0].set(xlabel="t (s)", ylabel="outflow (kg/s)", title="(a) outlet rate, 1 s bins")
    ax[0].legend(fontsize=7)
    ax[1].invert_xaxis()
    ax[1].set(xlabel="mass left in the silo (kg)", ylabel="rate (kg/s)",
              title="(b) all-Longwanggou 1 s bins against the mass left")
    ax[1].legend(fontsize=7)

    # (c) outflow from the particle count; the parcel mass of the coal that is flowing then
    co = read_csv(f"{run}/probe_coordination.csv")
    lw_mass = next(m["cg_mass_kg"] for m in check["materials"] if m["name"] == "Longwanggou")
    edges = np.arange(20.0, co["t_s"][-1], 0.5)
    count = np.interp(edges, co["t_s"], co["particles"])
    blocks = -np.diff(count) * lw_mass / 0.5  # kg/s; all Longwanggou after the Indonesian is out
    mids, mean, flowing, dripping = [], [], [], []
    for a in np.arange(20.0, edges[-1], 10.0):
        x = blocks[(edges[:-1] >= a) & (edges[:-1] < a + 10)]
        if len(x) < 4:
            continue
        mids.append(a + 5), mean.append(x.mean()), dripping.append(np.mean(x < 0.1))
        flowing.append(x[x >= 0.1].mean() if np.any(x >= 0.1) else 0.0)
        print(f"{a:5.0f}-{a + 10:.0f} s: mean {x.mean():.3f} kg/s, flowing blocks {flowing[-1]:.3f} kg/s, dripping {dripping[-1]:.2f}")
    ax[2].plot(mids, mean, "o-", label="mean rate (kg/s)")
    ax[2].plot(mids, flowing, "s-", label="rate of the flowing 0.5 s blocks (kg/s)")
    ax[2].plot(mids, dripping, "^-", label="share of 0.5 s blocks below 0.1 kg/s")
    ax[2].set(xlabel="t (s)", title="(c) this run: flowing and dripping, from the particle count")
    ax[2].legend(fontsize=7)

    # (d) net normal load of slab-slab contacts over the pair's moisture force
    sl = read_csv(f"{run}/probe_slab.csv")
    # the slab's coal column is the index into check.json's materials
    bands = [(0.0, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.3), (0.3, 0.4)]
    times = [t for t in np.unique(sl["t_s"]) if t >= 19.9]
    loads = np.full((len(times), len(bands)), np.nan)
    for n, t in enumerate(times):
        s = sl["t_s"] == t
        x = np.c_[sl["x_m"][s], sl["y_m"][s], sl["z_m"][s]]
        r, c = sl["radius_m"][s], sl["coal"][s].astype(int)
        gap = r[:, None] + r[None, :] - np.sqrt(((x[:, None, :] - x[None, :, :]) ** 2).sum(-1))
        i, j = np.where(np.triu(gap > 0, 1))
        pull = 0.5 * (force[c[i]] + force[c[j]])
        ratio = (k_n * gap[i, j] - pull) / pull
        zc = 0.5 * (x[i, 2] + x[j, 2])
        for b, (lo, hi) in enumerate(bands):
            q = (zc >= lo) & (zc < hi)
            if q.sum() > 5:
                loads[n, b] = ratio[q].mean()
        low = (zc >= 0) & (zc < 0.1)
        print(f"t = {t:.0f} s: net load / F by band {np.round(loads[n], 2).tolist()}; "
              f"0-100 mm: {ratio[low].mean():.2f} +- {ratio[low].std() / np.sqrt(low.sum()):.2f} "
              f"(n = {low.sum()}), in tension {np.mean(ratio[low] < 0):.2f}")
    for b, (lo, hi) in enumerate(bands):
        ax[3].plot(times, loads[:, b], "o-", label=f"z {lo * 1e3:.0f}-{hi * 1e3:.0f} mm")
    ax[3].axhline(0, color="k", lw=0.5)
    ax[3].set(xlabel="t (s)", ylabel="mean (k_n delta - F) / F, slab contacts",
              title="(d) this run: net contact load over the moisture force")
    ax[3].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out_png, dpi=100)
    print(f"wrote {out_png}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
