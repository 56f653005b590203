"""Issue 16 c, the predictions: one row per paper-silo run of any scenario, and k = 4 against k = 3.

For each run directory prints one row. A finished run is read from summary.json, outlet.csv and
fill.csv (a run directory, or its small files committed under validation/runs/); a run still
going from outlet_so_far.csv, progress.json, fill.csv and check.json, which is also what a
committed `unfinished/` folder holds (given it or the run directory above it; the coals' heating
values from its case.toml, from another run given beside it, or solved from its own outlet bins,
each a mix of the two coals); such rows say "unfinished" and their times are "so far".
A row gives:
  - scenario (summary.json's; without one, the fill's layers from the top, each coal by its
    initial, e.g. I2-L3), k, the filled and discharged mass, the discharge time, the mean rate
    and how the run ended;
  - the time by which 95% of the fill was out (interpolated in the 1 s bins of outlet.csv), or
    that it never was; it falls inside a slow tail when the tail holds more than 5% of the fill;
  - the bottom coal (the coal of segment H1 in fill.csv): its mass in the fill, and the time
    (end of its 1 s bin) by which 95% of the bottom coal that left had left;
  - the outlet calorific value (Eq. 17, outlet.csv's 1 s bins): in the first bin, the first time
    it crosses the midpoint of the two coals' values (interpolated between bin centres), and the
    mass-weighted mean over the run against the inventory's (the fill's) mean;
  - for L3-I2 only, the differences from the experiment (PHYSICS.md 7: 30.2 kg, 90 s, 0.335
    kg/s): the paper measured no other scenario's numbers.
Then, for each scenario with finished runs at k = 3 and at k = 4 (the paper's Fig. 5 check that
the scale factor does not change the answer), the ratios k = 4 / k = 3 of the means over each
k's runs (seeds) of the discharge time, the mean rate, the 95%-of-the-fill time ("-" if a run
never got there) and the midpoint-crossing time, with how each run ended (a ratio of runs that
ended differently compares different things).
Usage: /usr/bin/python3 studies/paper_predict_table.py RUN_DIR [RUN_DIR ...]
"""
import csv
import json
import math
import pathlib
import sys
import tomllib

EXP_MASS, EXP_TIME, EXP_RATE = 30.2, 90.0, 0.335  # PHYSICS.md 7 (the paper, section 4.1.3)
NAN = float("nan")


def load_json(path):
    if not path.exists():
        raise SystemExit(f"error: {path} is missing")
    return json.load(open(path))


def layers(fill):
    """The scenario name of a fill, from the top: runs of one coal, each as its initial and count."""
    order = sorted(fill, key=lambda s: int(s["segment"].lstrip("H")), reverse=True)
    parts = []
    for s in order:
        if parts and parts[-1][0] == s["coal"]:
            parts[-1][1] += 1
        else:
            parts.append([s["coal"], 1])
    return "-".join(f"{coal[0]}{n}" for coal, n in parts)


def read_run(run):
    run = pathlib.Path(run)
    if not (run / "summary.json").exists() and (run / "unfinished").is_dir():
        run = run / "unfinished"  # a committed run directory that holds only its unfinished state
    summary = json.load(open(run / "summary.json")) if (run / "summary.json").exists() else {}
    finished = summary.get("complete") is True
    outlet = run / ("outlet.csv" if finished else "outlet_so_far.csv")
    if not outlet.exists():
        raise SystemExit(f"error: {outlet} is missing")
    bins = list(csv.DictReader(open(outlet)))
    if not bins:
        raise SystemExit(f"error: {outlet} has no bins")
    fill = list(csv.DictReader(open(run / "fill.csv")))
    h1 = [s for s in fill if s["segment"] == "H1"]
    if not h1:
        raise SystemExit(f"error: {run / 'fill.csv'} has no segment H1")
    coal_mass = {}
    for s in fill:
        coal_mass[s["coal"]] = coal_mass.get(s["coal"], 0.0) + float(s["mass_kg"])
    if finished:
        heating = {c["name"]: float(c["heating_value_kcal_kg"]) for c in summary["coals"]}
        k, time, end = float(summary["k"]), float(summary["discharge_time_s"]), summary["end"]
        out = float(summary["discharged_mass_kg"])
        inventory = float(summary["inventory_calorific_kcal_kg"])
    else:
        check = load_json(run / "check.json")
        progress = load_json(run / "progress.json")
        heating = None
        if (run / "case.toml").exists():  # a live run's directory has its case
            with open(run / "case.toml", "rb") as f:
                heating = {c["name"]: float(c["heating_value_kcal_kg"]) for c in tomllib.load(f)["coal"]}
        k, time = float(check["k"]), float(bins[-1]["t_end_s"])
        end = f"unfinished (outflow read to {time:.1f} s, the run at {float(progress['t_s']):.1f} s)"
        out = sum(float(b["mass_kg"]) for b in bins)
        inventory = float(check.get("inventory_calorific_kcal_kg", NAN))
    return dict(run=run, scenario=summary.get("scenario") or layers(fill), finished=finished, bins=bins,
                bottom=h1[0]["coal"], coal_mass=coal_mass, heating=heating, k=k, time=time, end=end,
                out=out, inventory=inventory)


def heating_values(r, others):
    """The coals' heating values: the run's summary or case, another run's of the same coals, or
    solved from the run's own outlet bins, each a mix of the two (a committed unfinished/ folder
    has no case)."""
    if r["heating"]:
        return r["heating"]
    for o in others:
        if o["heating"] and set(o["heating"]) >= set(r["coal_mass"]):
            return o["heating"]
    coals = sorted(r["coal_mass"])
    if len(coals) != 2:
        return None
    # each bin's value is x_a H_a + x_b H_b: the least-squares H over the bins (normal equations)
    saa = sab = sbb = saq = sbq = 0.0
    for b in r["bins"]:
        if float(b["mass_kg"]) <= 0 or not b["calorific_kcal_kg"]:
            continue
        xa, xb = (float(b.get(f"fraction_{c}") or 0.0) for c in coals)
        q = float(b["calorific_kcal_kg"])
        saa, sab, sbb, saq, sbq = saa + xa * xa, sab + xa * xb, sbb + xb * xb, saq + xa * q, sbq + xb * q
    det = saa * sbb - sab * sab
    if det <= 1e-9 * max(saa * sbb, 1e-300):
        return None  # every bin holds the coals in one ratio (or one coal only): not determined
    return {coals[0]: (sbb * saq - sab * sbq) / det, coals[1]: (saa * sbq - sab * saq) / det}


def midpoint_crossing(bins, heating):
    """First time the outlet value crosses the midpoint of the two coals' values (bin centres)."""
    if heating is None or len(heating) != 2:
        return NAN
    mid = sum(heating.values()) / 2
    pts = [(0.5 * (float(b["t_start_s"]) + float(b["t_end_s"])), float(b["calorific_kcal_kg"]))
           for b in bins if float(b["mass_kg"]) > 0 and b["calorific_kcal_kg"]]
    if not pts:
        return NAN
    first_side = pts[0][1] > mid
    for (t0, q0), (t1, q1) in zip(pts, pts[1:]):
        if (q1 > mid) != first_side:
            return t0 + (t1 - t0) * (q0 - mid) / (q0 - q1)
    return NAN


def fill_out(bins, fraction, filled):
    """Time at which the cumulative outflow reaches fraction of the filled mass (linear in the bin)."""
    acc = 0.0
    for b in bins:
        m = float(b["mass_kg"])
        if m > 0 and acc + m >= fraction * filled:
            t0, t1 = float(b["t_start_s"]), float(b["t_end_s"])
            return t0 + (t1 - t0) * (fraction * filled - acc) / m
        acc += m
    return NAN


def bottom_out(bins, bottom):
    """Time (end of the 1 s bin) by which 95% of the bottom coal that left had left."""
    masses = [float(b["mass_kg"]) * float(b[f"fraction_{bottom}"] or 0) for b in bins]
    total, acc = sum(masses), 0.0
    for b, m in zip(bins, masses):
        acc += m
        if total > 0 and acc >= 0.95 * total:
            return float(b["t_end_s"])
    return NAN


def fmt_time(t, missing):
    return f"{t:.1f} s" if not math.isnan(t) else missing


def row(r, others):
    bins, out, time = r["bins"], r["out"], r["time"]
    heating = heating_values(r, others)
    filled = sum(r["coal_mass"].values())
    rate = out / time if time > 0 else NAN
    q = [(float(b["mass_kg"]), float(b["calorific_kcal_kg"])) for b in bins
         if float(b["mass_kg"]) > 0 and b["calorific_kcal_kg"]]
    q_mean = sum(m * v for m, v in q) / sum(m for m, _ in q) if q else NAN
    mid = midpoint_crossing(bins, heating)
    t95 = fill_out(bins, 0.95, filled)
    so_far = "" if r["finished"] else " so far"
    t_bottom = bottom_out(bins, r["bottom"])
    text = (
        f"{r['run']}: {r['scenario']}, k = {r['k']:g}: {out:.2f} of {filled:.2f} kg in {time:.1f} s, "
        f"{rate:.4f} kg/s, {r['end']}; 95% of the fill " +
        (f"out at {t95:.1f} s" if not math.isnan(t95) else
         f"{'never' if r['finished'] else 'not yet'} out ({out / filled:.1%})") +
        f"; bottom {r['bottom']} ({r['coal_mass'][r['bottom']]:.2f} kg): 95% of what left{so_far} out by "
        + (f"{t_bottom:.0f} s" if not math.isnan(t_bottom) else "-") +
        "; outlet kcal/kg: first bin " + (f"{q[0][1]:.0f}" if q else "-") +
        ", midpoint crossed at " + fmt_time(mid, "-" if r["finished"] else "- (not yet)") +
        f", mean{so_far} {q_mean:.0f} (inventory {r['inventory']:.0f})"
    )
    if r["scenario"] == "L3-I2" and r["finished"]:
        text += (f"; against the experiment {out / EXP_MASS - 1:+.1%}, {time / EXP_TIME - 1:+.1%}, "
                 f"{rate / EXP_RATE - 1:+.1%}")
    return text, dict(scenario=r["scenario"], k=r["k"], time=time, rate=rate, mid=mid, t95=t95,
                      finished=r["finished"], end=r["end"])


def mean_of(runs, key):
    """The mean of one value over a k's runs; nan if any run lacks it (e.g. never 95% out)."""
    values = [v[key] for v in runs]
    return NAN if any(math.isnan(x) for x in values) else sum(values) / len(values)


def ratio_line(scenario, a, b):
    """k = 4 / k = 3 of the means over each k's finished runs (a: k = 3's, b: k = 4's)."""
    def ratio(key):
        x, y = mean_of(a, key), mean_of(b, key)
        return f"{y / x:.3f}" if not (math.isnan(x) or math.isnan(y)) else "-"
    ends = "; ".join(f"k = {k}: {', '.join(v['end'] for v in runs)}" for k, runs in ((3, a), (4, b)))
    return (f"{scenario}: k = 4 / k = 3 ({len(b)} / {len(a)} runs, their means): discharge time {ratio('time')}, "
            f"mean rate {ratio('rate')}, 95% of the fill out {ratio('t95')}, midpoint crossing "
            f"{ratio('mid')} ({ends})")


def main(argv):
    if not argv:
        raise SystemExit(__doc__.strip().splitlines()[-1])
    runs = [read_run(a) for a in argv]
    rows = []
    for r in runs:
        text, values = row(r, runs)
        print(text)
        rows.append(values)
    for scenario in sorted({v["scenario"] for v in rows}):
        done = [v for v in rows if v["scenario"] == scenario and v["finished"]]
        by_k = {k: [v for v in done if v["k"] == k] for k in (3.0, 4.0)}
        if by_k[3.0] and by_k[4.0]:
            print(ratio_line(scenario, by_k[3.0], by_k[4.0]))

if __name__ == "__main__":
    main(sys.argv[1:])
