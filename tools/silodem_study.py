#!/usr/bin/python3
"""Figures and report.html of a silodem study directory.

Usage: silodem_study.py STUDY_DIR

Reads STUDY_DIR/study.json (the varied keys, the window) and STUDY_DIR/study.csv
(one row per run, written by `silodem study`), and the outlet.csv of each
finished run under STUDY_DIR/runs/. Writes STUDY_DIR/figures/:
  <metric>_vs_<key>.png   each metric against each varied key: the seeds as
                          dots (crosses: the flow stopped), their mean with the
                          seeds' standard deviation, one line per combination
                          of the other varied keys;
  outlet_rate.png, outlet_cumulative.png, outlet_calorific.png
                          the outlet curves of every finished run overlaid, one
                          colour per grid point (its seeds share it);
and STUDY_DIR/report.html with a table per grid point and per run and all
figures. Prints the paths it wrote. Exit 0 on success, 2 if the directory is
not a study directory.
"""

import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

import silodem_plots as sp  # noqa: E402

METRICS = [
    ("discharged_fraction", "discharged fraction of the filled mass (-)"),
    ("mean_rate_kg_s", "mean discharge rate (kg/s)"),
    ("window_rate_kg_s", "mean rate in the window (kg/s)"),
    ("discharge_time_s", "discharge time (s)"),
    ("outlet_mean_calorific_kcal_kg", "outlet mean calorific value (kcal/kg)"),
    ("wall_time_s", "wall time of the run (s)"),
]


class UsageError(Exception):
    """A directory that is not a study directory."""


def load(study_dir):
    """(meta, rows) of a study directory."""
    try:
        with open(os.path.join(study_dir, "study.json"), encoding="utf-8") as f:
            meta = json.load(f)
        with open(os.path.join(study_dir, "study.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
    except (OSError, ValueError) as e:
        raise UsageError("not a study directory ({})".format(e)) from None
    if not isinstance(meta.get("vary"), list):
        raise UsageError("study.json has no list 'vary'")
    return meta, rows


number = sp.cell_number


def order(values, numeric):
    """The distinct values of a varied key, in a plotting order."""
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    if numeric:
        seen.sort(key=number)
    return seen


def point_key(row, keys):
    """The grid point of a row: its varied keys' values."""
    return tuple(row[k] for k in keys)


def point_label(keys, values):
    """'a=1, b=2' of a grid point (or of the keys other than the x axis)."""
    return ", ".join("{}={}".format(k, v) for k, v in zip(keys, values)) or "all runs"


def style(i):
    """Colour and marker of the i-th series."""
    return {"color": plt.get_cmap("tab10")(i % 10),
            "ls": ["-", "--", "-.", ":"][(i // 10) % 4]}


def mean_std(values):
    """(mean, standard deviation) of the finite values; NaN if none."""
    xs = [v for v in values if math.isfinite(v)]
    if not xs:
        return math.nan, math.nan
    m = sum(xs) / len(xs)
    s = math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) if len(xs) > 1 else 0.0
    return m, s


def fig_metric(meta, rows, metric, ylabel, key):
    """One metric against one varied key."""
    keys, numeric = meta["vary"], dict(zip(meta["vary"], meta.get("vary_numeric", [])))
    others = [k for k in keys if k != key]
    xs = order([r[key] for r in rows], numeric.get(key, False))
    pos = {v: (number(v) if numeric.get(key) else i) for i, v in enumerate(xs)}
    series = order([point_key(r, others) for r in rows], False)
    fig, ax = sp.new_figure()
    # Series side by side: a small shift (a factor on a log axis) so their seeds do not overlap.
    values = [number(v) for v in xs] if numeric.get(key) else []
    log_x = bool(values) and min(values) > 0 and max(values) / min(values) >= 8
    width = 0.0
    if numeric.get(key) and len(xs) > 1 and not log_x:
        width = 0.004 * (values[-1] - values[0])
    for si, s in enumerate(series):
        st = style(si)
        mx, my, me = [], [], []
        shift = si - (len(series) - 1) / 2
        offset = shift * width
        for x in xs:
            group = [r for r in rows if r[key] == x and point_key(r, others) == s
                     and r["state"] == "finished"]
            vals = [number(r[metric]) for r in group]
            for r, v in zip(group, vals):
                if math.isfinite(v):
                    stopped = r.get("flow_stopped") == "true"
                    ax.plot(pos[x] * (1 + 0.01 * shift) if log_x else pos[x] + offset, v, "x" if stopped else "o", ms=5 if stopped else 3,
                            color=st["color"], alpha=0.8)
            m, sd = mean_std(vals)
            if math.isfinite(m):
                mx.append(pos[x] * (1 + 0.01 * shift) if log_x else pos[x] + offset)
                my.append(m)
                me.append(sd)
        if mx:
            ax.errorbar(mx, my, yerr=me, color=st["color"], ls=st["ls"], capsize=3,
                        label=point_label(others, s))
    if log_x:
        ax.set_xscale("log")
        ax.set_xticks(values)
        ax.set_xticklabels(xs)
        ax.minorticks_off()
    if not numeric.get(key):
        ax.set_xticks(range(len(xs)))
        ax.set_xticklabels(xs, rotation=20 if len(xs) > 4 else 0)
    ax.set_xlabel("{} (case-file units)".format(key))
    ax.set_ylabel(ylabel)
    if metric != "outlet_mean_calorific_kcal_kg":
        ax.set_ylim(bottom=0)
    sp.set_title(ax, meta.get("title") or "study", "{} against {}".format(metric, key))
    handles, labels = ax.get_legend_handles_labels()
    handles += [Line2D([], [], color="0.3", marker="o", ls="none", ms=3),
                Line2D([], [], color="0.3", marker="x", ls="none", ms=5)]
    labels += ["one seed", "one seed, flow stopped (arched)"]
    sp.legend_below(fig, handles, labels, ncol=2)
    return fig


def finished_runs(study_dir, rows, keys):
    """[(point, run)] of the finished runs with an outlet.csv."""
    got = []
    for r in rows:
        if r["state"] != "finished":
            continue
        try:
            run = sp.Run(os.path.join(study_dir, "runs", r["run"]))
            got.append((point_key(r, keys), run, run.outlet()))
        except (sp.RunError, sp.NotRecorded, sp.DataError):
            continue
    return got


def fig_outlet(meta, data, which):
    """Outlet curves of every finished run, one colour per grid point."""
    keys = meta["vary"]
    points = order([p for p, _, _ in data], False)
    fig, ax = sp.new_figure()
    for p, run, out in data:
        st = style(points.index(p))
        if which == "cumulative":
            xy = sp.cumulative_xy(out["t_start"], out["t_end"], out["cumulative"])
        else:
            xy = sp.step_xy(out["t_start"], out["t_end"], out[which])
        ax.plot(*xy, color=st["color"], ls=st["ls"], lw=1, alpha=0.85)
    ylabel = {"rate": sp.RATE_LABEL, "cumulative": sp.MASS_LABEL,
              "calorific": sp.CALORIFIC_LABEL}[which]
    subject = {"rate": "outlet mass flow rate per bin", "cumulative": "cumulative discharged mass",
               "calorific": "calorific value of the discharged coal"}[which]
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel(ylabel)
    if which != "calorific":
        ax.set_ylim(bottom=0)
    sp.set_title(ax, meta.get("title") or "study", subject + " (every run; seeds share a colour)")
    handles = [Line2D([], [], **style(i)) for i in range(len(points))]
    labels = [point_label(keys, p) for p in points]
    if len(handles) > 24:
        handles, labels = handles[:24], labels[:24]
        handles.append(Line2D([], [], color="none"))
        labels.append("... ({} points in all)".format(len(points)))
    sp.legend_below(fig, handles, labels, ncol=2)
    return fig


def point_rows(meta, rows):
    """One table row per grid point: seeds, arched seeds, each metric's mean +- std."""
    keys = meta["vary"]
    out = []
    for p in order([point_key(r, keys) for r in rows], False):
        group = [r for r in rows if point_key(r, keys) == p]
        done = [r for r in group if r["state"] == "finished"]
        stopped = sum(r.get("flow_stopped") == "true" for r in done)
        cells = list(p) + ["{}/{}".format(len(done), len(group)), str(stopped)]
        for metric, _ in METRICS[:5]:
            m, s = mean_std([number(r[metric]) for r in done])
            cells.append("" if not math.isfinite(m) else
                         "{:.4g} \u00b1 {:.2g}".format(m, s) if len(done) > 1 else
                         "{:.4g}".format(m))
        out.append(cells)
    return out


def write_html(study_dir, meta, rows, figures):
    """STUDY_DIR/report.html; returns its path."""
    keys = meta["vary"]
    win = meta.get("window_s") or [0, 0]
    parts = ["<p>Base case: {}<br>Study file: {}<br>{} runs; window for the windowed rate: "
             "{}</p>".format(sp.esc(meta.get("base", "")), sp.esc(meta.get("study_file", "")),
                             len(rows),
                             sp.esc("{} to {} s after the valve opened".format(*win))
                             if win[1] > win[0] else "none")]
    headers = keys + ["runs finished", "flow stopped"] + [m for m, _ in METRICS[:5]]
    parts += ["<h2>Grid points (mean \u00b1 standard deviation over the seeds)</h2>",
              sp.html_table(headers, point_rows(meta, rows),
                            numeric=tuple(range(len(keys), len(headers))))]
    failed = [r["run"] for r in rows if r["state"] == "failed"]
    if failed:
        parts.append('<p class="alert">A guard stopped {} run(s) (left out of the means and '
                     'figures; see logs/): {}</p>'.format(len(failed), sp.esc(", ".join(failed))))
    stopped = [r["run"] for r in rows if r.get("flow_stopped") == "true"]
    if stopped:
        parts.append('<p class="alert">Flow stopped (arched) in {} of {} runs.</p>'.format(
            len(stopped), len(rows)))
    cols = ["run"] + keys + ["seed", "state", "end", "discharged_mass_kg", "discharge_time_s",
                             "mean_rate_kg_s", "window_rate_kg_s", "wall_time_s"]
    parts += ["<h2>Runs</h2>",
              sp.html_table(cols, [[r.get(c, "") for c in cols] for r in rows],
                            numeric=tuple(range(len(keys) + 4, len(cols))))]
    parts.append("<h2>Figures</h2>")
    parts += [sp.html_figure("figures/" + name, caption) for name, caption in figures]
    path = os.path.join(study_dir, "report.html")
    sp.write_text(path, sp.html_page("silodem study: {}".format(meta.get("title") or study_dir),
                                     "\n".join(parts)))
    return path


def main(argv=None):
    """Command line entry point; returns the exit code."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    study_dir = argv[0]
    try:
        meta, rows = load(study_dir)
    except UsageError as e:
        print("silodem_study: error: {}".format(e), file=sys.stderr)
        return 2
    fig_dir = os.path.join(study_dir, "figures")
    os.makedirs(fig_dir, exist_ok=True)
    records, figures = [], []
    win = meta.get("window_s") or [0, 0]
    for metric, ylabel in METRICS:
        if metric == "window_rate_kg_s" and not win[1] > win[0]:
            continue
        for key in meta["vary"]:
            name = "{}_vs_{}.png".format(metric, key)
            sp.save_figure(fig_metric(meta, rows, metric, ylabel, key),
                           os.path.join(fig_dir, name), records)
            figures.append((name, "{} against {}: dots are seeds (crosses: flow stopped), "
                                  "lines the seeds' mean \u00b1 standard deviation.".format(
                                      metric, key)))
            print(os.path.join(fig_dir, name))
    data = finished_runs(study_dir, rows, meta["vary"])
    for which in ("rate", "cumulative", "calorific"):
        name = "outlet_{}.png".format(which)
        sp.save_figure(fig_outlet(meta, data, which), os.path.join(fig_dir, name), records)
        figures.append((name, "Outlet {} of every finished run.".format(which)))
        print(os.path.join(fig_dir, name))
    print(write_html(study_dir, meta, rows, figures))
    problems = sp.label_problems(records)
    for p in problems:
        print("silodem_study: label without unit: " + p, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
