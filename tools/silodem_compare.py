#!/usr/bin/python3
"""Overlay the outlet curves of several silodem runs.

Usage: silodem_compare.py --out OUT_DIR [--labels A,B,...] [--check-labels] RUN_DIR RUN_DIR...

Reads summary.json (required), outlet.csv and measured.csv (optional) of each
RUN_DIR. Writes OUT_DIR/compare_rate.png, compare_cumulative.png,
compare_calorific.png and compare.html, and prints the paths it wrote. OUT_DIR
is created; it must not exist or be empty. Exit 0 on success, 2 on a usage
error or an unusable run directory, 3 with --check-labels if an axis label
lacks a unit.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

import silodem_plots as sp  # noqa: E402

LINESTYLES = ["-", "--", "-.", ":"]


class UsageError(Exception):
    """A command line the tool refuses."""


def run_labels(runs, given):
    """One legend label per run: --labels or 'title, scenario'; clashes get the dir name."""
    if given is not None:
        labels = [s.strip() for s in given.split(",")]
        if len(labels) != len(runs):
            raise UsageError("--labels has {} labels for {} run directories"
                             .format(len(labels), len(runs)))
    else:
        labels = [run.case for run in runs]
    names = [os.path.basename(os.path.normpath(run.dir)) for run in runs]
    unique = disambiguate(labels, names)
    if len(set(unique)) < len(unique):  # the directory names clash too: use the paths
        unique = disambiguate(labels, [run.dir for run in runs])
    return unique


def disambiguate(labels, suffixes):
    """Labels that occur more than once get ' (suffix)' appended."""
    clashing = {lab for lab in labels if labels.count(lab) > 1}
    return ["{} ({})".format(lab, suf) if lab in clashing else lab
            for lab, suf in zip(labels, suffixes)]


def style(i):
    """Colour and line style of the i-th run."""
    return {"color": plt.get_cmap("tab10")(i % 10), "ls": LINESTYLES[(i // 10) % 4]}


def compared(runs):
    """Figure title line naming the compared cases."""
    cases = []
    for run in runs:
        if run.case not in cases:
            cases.append(run.case)
    text = "; ".join(cases)
    if len(text) > 70:
        text = "{} runs of {} cases".format(len(runs), len(cases))
    return "comparison: " + text


def outlets(runs):
    """[(index, outlet arrays)] of the runs that have outlet.csv, and notes for the others."""
    got, notes = [], []
    for i, run in enumerate(runs):
        try:
            got.append((i, run.outlet()))
        except (sp.NotRecorded, sp.DataError) as e:
            notes.append("{}: {}".format(run.dir, sp.skip_note(e)))
    return got, notes


def draw_measured(ax, runs, labels, key):
    """Measured points of each run that has them, in the run's colour."""
    for i, run in enumerate(runs):
        meas = run.measured_or_none()
        if meas is not None and meas[key] is not None:
            ax.plot(meas["t"], meas[key], "o", mfc="none", color=style(i)["color"],
                    label="measured, " + labels[i])


def fig_rate(runs, labels, data):
    """Mass flow rate per bin of every run."""
    fig, ax = sp.new_figure()
    for i, out in data:
        ax.plot(*sp.step_xy(out["t_start"], out["t_end"], out["rate"]), label=labels[i],
                **style(i))
    draw_measured(ax, runs, labels, "rate")
    ax.set_ylim(bottom=0)
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel(sp.RATE_LABEL)
    sp.set_title(ax, compared(runs), "outlet mass flow rate per bin")
    sp.legend_below(fig, *ax.get_legend_handles_labels(), ncol=2)
    return fig


def fig_cumulative(runs, labels, data):
    """Cumulative discharged mass of every run; dotted: each run's filled mass."""
    fig, ax = sp.new_figure()
    for i, out in data:
        ax.plot(*sp.cumulative_xy(out["t_start"], out["t_end"], out["cumulative"]),
                label=labels[i], **style(i))
        filled = runs[i].value("filled_mass_kg")
        if sp.finite(filled):
            ax.axhline(filled, color=style(i)["color"], ls=":", lw=1)
    ax.set_ylim(bottom=0)
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel(sp.MASS_LABEL)
    sp.set_title(ax, compared(runs), "cumulative discharged mass")
    handles, names = ax.get_legend_handles_labels()
    handles.append(Line2D([], [], color="0.3", ls=":", lw=1))
    names.append("filled mass of each run")
    sp.legend_below(fig, handles, names, ncol=2)
    return fig


def fig_calorific(runs, labels, data):
    """Outlet calorific value per bin of every run, with each coal's heating value."""
    fig, ax = sp.new_figure()
    for i, out in data:
        ax.plot(*sp.step_xy(out["t_start"], out["t_end"], out["calorific"]), label=labels[i],
                **style(i))
    draw_measured(ax, runs, labels, "calorific")
    seen = set()
    for run in runs:
        for name, q in run.coals:
            if sp.finite(q) and (name, q) not in seen:
                seen.add((name, q))
                ax.axhline(q, color="0.55", ls=(0, (1, 3)) if len(seen) % 2 else "--", lw=1,
                           label="{} {}".format(name, sp.fmt(q, "kcal/kg")))
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel(sp.CALORIFIC_LABEL)
    sp.set_title(ax, compared(runs), "calorific value of the discharged coal")
    sp.legend_below(fig, *ax.get_legend_handles_labels(), ncol=2)
    return fig


FIGURES = [
    ("compare_rate.png", fig_rate, "Outlet mass flow rate per bin (circles: measured)."),
    ("compare_cumulative.png", fig_cumulative,
     "Cumulative discharged mass (dotted: filled mass of each run)."),
    ("compare_calorific.png", fig_calorific,
     "Calorific value of the coal leaving per bin (grey: heating value of each coal)."),
]


def summary_rows(runs, labels):
    """One table row per run."""
    rows = []
    for run, label in zip(runs, labels):
        v, s = run.value, run.summary
        status = "yes" if s.get("flow_stopped") is True else "no"
        if s.get("complete") is False:
            status += " (incomplete run)"
        rows.append([label, s.get("scenario") or "\u2014", sp.fmt(v("filled_mass_kg")),
                     sp.fmt(v("discharged_mass_kg")), sp.fmt(v("discharge_time_s")),
                     sp.fmt(v("mean_rate_kg_s")), status, run.dir])
    return rows


def write_html(out_dir, runs, labels, notes):
    """OUT_DIR/compare.html; returns its path."""
    headers = ["label", "scenario", "filled (kg)", "discharged (kg)", "discharge time (s)",
               "mean rate (kg/s)", "flow stopped", "run directory"]
    parts = ["<h2>Runs</h2>", sp.html_table(headers, summary_rows(runs, labels),
                                            numeric=(2, 3, 4, 5))]
    stopped = [lab for run, lab in zip(runs, labels) if run.summary.get("flow_stopped") is True]
    if stopped:
        parts.append('<p class="alert">Flow stopped in: {}</p>'.format(
            sp.esc("; ".join(stopped))))
    for note in notes:
        parts.append('<p class="missing">{}</p>'.format(sp.esc(note)))
    parts.append("<h2>Figures</h2>")
    parts += [sp.html_figure(name, caption) for name, _, caption in FIGURES]
    path = os.path.join(out_dir, "compare.html")
    sp.write_text(path, sp.html_page("silodem comparison of {} runs".format(len(runs)),
                                     "\n".join(parts)))
    return path


def prepare_out_dir(out_dir):
    """Create OUT_DIR; refuse an existing non-empty one."""
    if os.path.exists(out_dir) and (not os.path.isdir(out_dir) or os.listdir(out_dir)):
        raise UsageError("output directory exists and is not empty: {}".format(out_dir))
    os.makedirs(out_dir, exist_ok=True)


def parse_args(argv):
    """The command line."""
    parser = argparse.ArgumentParser(description="Overlay the outlet curves of silodem runs.")
    parser.add_argument("--out", required=True, metavar="OUT_DIR")
    parser.add_argument("--labels", metavar="A,B,...", help="legend labels, one per run")
    parser.add_argument("--check-labels", action="store_true",
                        help="print the axis labels of every figure (LABELS lines); exit 3 if "
                             "one lacks a unit")
    parser.add_argument("run_dirs", nargs="*", metavar="RUN_DIR")
    return parser.parse_args(argv)


def main(argv=None):
    """Command line entry point; returns the exit code."""
    args = parse_args(argv)
    try:
        if len(args.run_dirs) < 2:
            raise UsageError("need at least 2 run directories, got {}".format(len(args.run_dirs)))
        runs = [sp.Run(d) for d in args.run_dirs]
        labels = run_labels(runs, args.labels)
        prepare_out_dir(args.out)
    except (UsageError, sp.RunError, OSError) as e:
        print("silodem_compare: error: {}".format(e), file=sys.stderr)
        return 2
    data, notes = outlets(runs)
    records = []
    for name, builder, _ in FIGURES:
        path = os.path.join(args.out, name)
        sp.save_figure(builder(runs, labels, data), path, records)
        print(path)
    print(write_html(args.out, runs, labels, notes))
    if args.check_labels:
        problems = sp.print_label_check(records)
        for p in problems:
            print("silodem_compare: label without unit: " + p, file=sys.stderr)
        return 3 if problems else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
