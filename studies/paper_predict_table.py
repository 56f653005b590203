"""Issue 16 c, the predictions: one row per paper-silo run of any scenario, and k = 4 against k = 3.

For each run directory (summary.json, outlet.csv and fill.csv, committed under validation/runs/ or
a live run's directory; a run still going is read from outlet_so_far.csv and progress.json and
marked "unfinished") prints:
  - scenario, k, the filled and discharged mass, the discharge time, the mean rate and how the
    run ended; the time by which 95% of the fill was out (interpolated in the 1 s bins), which a
    slow drip of the last few per cent does not move;
  - the bottom coal (the coal of segment H1 in fill.csv): its mass in the fill, and the time by
    which 95% of it had left (end of its 1 s bin);
  - the outlet calorific value (Eq. 17, outlet.csv's 1 s bins): in the first bin, the first time
    it crosses the midpoint of the two coals' values (interpolated between bin centres), and the
    mass-weighted mean over the run against the inventory's (the fill's) mean;
  - for L3-I2 only, the differences from the experiment (PHYSICS.md 7: 30.2 kg, 90 s, 0.335
    kg/s): the paper measured no other scenario's numbers.
Then, for each scenario with one finished run at k = 3 and one at k = 4 (the paper's Fig. 5
check that the scale factor does not change the answer), the ratios k = 4 / k = 3 of the
discharge time, the mean rate, the 95%-of-the-fill time and the midpoint-crossing time.
Usage: /usr/bin/python3 studies/paper_predict_table.py RUN_DIR [RUN_DIR ...]
"""
import csv
import json
import pathlib
import sys

EXP_MASS, EXP_TIME, EXP_RATE = 30.2, 90.0, 0.335  # PHYSICS.md 7 (the paper, section 4.1.3)


def read_run(run):
    run = pathlib.Path(run)
    summary = json.load(open(run / "summary.json"))
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
    bottom = h1[0]["coal"]
    coal_mass = {}
    for s in fill:
        coal_mass[s["coal"]] = coal_mass.get(s["coal"], 0.0) + float(s["mass_kg"])
    if finished:
        heating = {c["name"]: float(c["heating_value_kcal_kg"]) for c in summary["coals"]}
    else:
        heating = None
    return dict(run=run, summary=summary, finished=finished, bins=bins, bottom=bottom, coal_mass=coal_mass,
                heating=heating)


def heating_values(r, others):
    """The coals' heating values: the run's summary, or a finished run's of the same list."""
    if r["heating"]:
        return r["heating"]
    for o in others:
        if o["heating"] and set(o["heating"]) >= set(r["coal_mass"]):
            return o["heating"]
    # An unfinished run alone: Eq. 17 inverted on a bin of one coal only.
    h = {}
    for b in r["bins"]:
        for c in r["coal_mass"]:
            if float(b[f"fraction_{c}"] or 0) == 1.0 and b["calorific_kcal_kg"]:
                h[c] = float(b["calorific_kcal_kg"])
    return h if len(h) == len(r["coal_mass"]) else None


def midpoint_crossing(bins, heating):
    """First time the outlet value crosses the midpoint of the two coals' values (bin centres)."""
    if heating is None or len(heating) != 2:
        return float("nan")
    mid = sum(heating.values()) / 2
    pts = [(0.5 * (float(b["t_start_s"]) + float(b["t_end_s"])), float(b["calorific_kcal_kg"]))
           for b in bins if float(b["mass_kg"]) > 0 and b["calorific_kcal_kg"]]
    if not pts:
        return float("nan")
    first_side = pts[0][1] > mid
    for (t0, q0), (t1, q1) in zip(pts, pts[1:]):
        if (q1 > mid) != first_side:
            return t0 + (t1 - t0) * (q0 - mid) / (q0 - q1)
    return float("nan")


def fill_out(bins, fraction, filled):
    """Time at which the cumulative outflow reaches fraction of the filled mass (linear in the bin)."""
    acc = 0.0
    for b in bins:
        m = float(b["mass_kg"])
        if m > 0 and acc + m >= fraction * filled:
            t0, t1 = float(b["t_start_s"]), float(b["t_end_s"])
            return t0 + (t1 - t0) * (fraction * filled - acc) / m
        acc += m
    return float("nan")


def bottom_out(bins, bottom):
    """Time (end of the 1 s bin) by which 95% of the bottom coal that left had left."""
    masses = [float(b["mass_kg"]) * float(b[f"fraction_{bottom}"] or 0) for b in bins]
    total, acc = sum(masses), 0.0
    for b, m in zip(bins, masses):
        acc += m
        if total > 0 and acc >= 0.95 * total:
            return float(b["t_end_s"])
    return float("nan")


def row(r, others):
    s, bins = r["summary"], r["bins"]
    heating = heating_values(r, others)
    out = float(s["discharged_mass_kg"]) if r["finished"] else sum(float(b["mass_kg"]) for b in bins)
    filled = sum(r["coal_mass"].values())
    if r["finished"]:
        time, end = float(s["discharge_time_s"]), s["end"]
    else:
        progress = json.load(open(r["run"] / "progress.json"))
        time, end = float(progress["t_s"]), f"unfinished at {float(progress['t_s']):.1f} s"
    rate = out / time if time > 0 else float("nan")
    q = [(float(b["mass_kg"]), float(b["calorific_kcal_kg"])) for b in bins if b["calorific_kcal_kg"]]
    q_mean = sum(m * v for m, v in q) / sum(m for m, _ in q) if q else float("nan")
    q_inv = (sum(m * heating[c] for c, m in r["coal_mass"].items()) / filled) if heating else float("nan")
    mid = midpoint_crossing(bins, heating)
    t95 = fill_out(bins, 0.95, filled)
    k = s.get("k")
    if k is None:
        k = float(json.load(open(r["run"] / "check.json")).get("k", float("nan")))
    text = (
        f"{r['run']}: {s['scenario']}, k = {float(k):g}: {out:.2f} of {filled:.2f} kg in {time:.1f} s, "
        f"{rate:.4f} kg/s, {end}; 95% of the fill " +
        (f"out at {t95:.1f} s" if t95 == t95 else f"{'never' if r['finished'] else 'not yet'} out ({out / filled:.1%})") +
        f"; bottom {r['bottom']} ({r['coal_mass'][r['bottom']]:.2f} kg) 95% "
        f"{'out' if r['finished'] else 'of what is out so far'} by {bottom_out(bins, r['bottom']):.0f} s; outlet kcal/kg: first bin {q[0][1]:.0f}, "
        f"midpoint crossed at " + (f"{mid:.1f} s" if mid == mid else "-") +
        f", mean {q_mean:.0f} (inventory {q_inv:.0f})"
    )
    if s["scenario"] == "L3-I2" and r["finished"]:
        text += (f"; against the experiment {out / EXP_MASS - 1:+.1%}, {time / EXP_TIME - 1:+.1%}, "
                 f"{rate / EXP_RATE - 1:+.1%}")
    return text, dict(scenario=s["scenario"], k=float(k), time=time, rate=rate, mid=mid, t95=t95,
                      finished=r["finished"])


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
        if any(len(v) > 1 for v in by_k.values()):
            print(f"{scenario}: several finished runs at one k: no k = 4 / k = 3 ratio")
        elif by_k[3.0] and by_k[4.0]:
            a, b = by_k[3.0][0], by_k[4.0][0]
            def ratio(key):
                return f"{b[key] / a[key]:.3f}" if a[key] == a[key] and b[key] == b[key] else "-"
            print(f"{scenario}: k = 4 / k = 3: discharge time {ratio('time')}, mean rate {ratio('rate')}, "
                  f"95% of the fill out {ratio('t95')}, midpoint crossing {ratio('mid')}")


if __name__ == "__main__":
    main(sys.argv[1:])
