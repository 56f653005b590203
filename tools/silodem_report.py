#!/usr/bin/python3
"""Figures and an HTML report of one silodem silo run.

Usage: silodem_report.py [--check-labels] RUN_DIR

Reads RUN_DIR/summary.json (required), fill.csv, outlet.csv, probe_*.csv and
measured.csv (all optional). Writes RUN_DIR/figures/*.png and RUN_DIR/report.html
and prints the paths it wrote. A missing optional file skips its figures (the
report says "not recorded"). Exit 0 on success, 2 if RUN_DIR or its summary.json
is unusable, 3 with --check-labels if an axis label lacks a unit.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

import silodem_plots as sp  # noqa: E402

MAX_SNAPSHOTS = 8


def status_suffix(run):
    """' (flow stopped)' / ' (incomplete run)' for figure titles, else ''."""
    notes = []
    if run.summary.get("flow_stopped") is True:
        notes.append("FLOW STOPPED")
    if run.summary.get("complete") is False:
        notes.append("INCOMPLETE RUN")
    return " \u2014 " + ", ".join(notes) if notes else ""


# ---- outlet figures -------------------------------------------------------------------------


def fig_rate_cumulative(run):
    """Rate per bin (steps), cumulative mass on a second axis, filled mass, measured rate."""
    out = run.outlet()
    fig, ax = sp.new_figure()
    ax.plot(*sp.step_xy(out["t_start"], out["t_end"], out["rate"]), color="C0",
            label="mass flow rate (per bin)")
    meas = run.measured_or_none()
    if meas is not None and meas["rate"] is not None:
        ax.plot(meas["t"], meas["rate"], "o", mfc="none", color="k", label="measured")
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel(sp.RATE_LABEL, color="C0")
    ax.set_ylim(bottom=0)
    twin = ax.twinx()
    twin.plot(*sp.cumulative_xy(out["t_start"], out["t_end"], out["cumulative"]), color="C1",
              label="discharged mass (cumulative)")
    filled = run.value("filled_mass_kg")
    if sp.finite(filled):
        twin.axhline(filled, color="C1", ls="--", lw=1,
                     label="filled mass {}".format(sp.fmt(filled, "kg")))
    twin.set_ylabel(sp.MASS_LABEL, color="C1")
    twin.set_ylim(bottom=0)
    sp.set_title(ax, run.case, "mass flow rate and discharged mass" + status_suffix(run))
    sp.legend_below(fig, *sp.axes_handles(ax, twin), ncol=2)
    return fig


def fig_calorific(run):
    """Outlet calorific value per bin, each coal's heating value, inventory mean, measured."""
    out = run.outlet()
    fig, ax = sp.new_figure()
    ax.plot(*sp.step_xy(out["t_start"], out["t_end"], out["calorific"]), color="k", lw=1.6,
            label="outlet (per bin)")
    for i, (name, q) in enumerate(run.coals):
        if sp.finite(q):
            ax.axhline(q, color=sp.coal_color(i), ls="--", lw=1.2,
                       label="{} {}".format(name, sp.fmt(q, "kcal/kg")))
    inventory = run.value("inventory_calorific_kcal_kg")
    if sp.finite(inventory):
        ax.axhline(inventory, color="0.4", ls="-.", lw=1.2,
                   label="inventory mean {}".format(sp.fmt(inventory, "kcal/kg")))
    meas = run.measured_or_none()
    if meas is not None and meas["calorific"] is not None:
        ax.plot(meas["t"], meas["calorific"], "s", mfc="none", color="C3", label="measured")
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel(sp.CALORIFIC_LABEL)
    sp.set_title(ax, run.case, "calorific value of the discharged coal")
    sp.legend_below(fig, *ax.get_legend_handles_labels())
    return fig


def fig_fractions(run):
    """Stacked mass fraction of each coal per outlet bin (%)."""
    out = run.outlet()
    if not out["fractions"]:
        raise sp.DataError("outlet.csv has no fraction_ columns")
    fig, ax = sp.new_figure()
    width = out["t_end"] - out["t_start"]
    bottom = np.zeros(len(width))
    for i, (name, frac) in enumerate(out["fractions"]):
        share = np.nan_to_num(frac) * 100.0
        ax.bar(out["t_start"], share, width=width, bottom=bottom, align="edge",
               color=sp.coal_color(i), label=name, linewidth=0)
        bottom += share
    ax.set_ylim(0, 100)
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel("mass fraction of the discharged coal (%)")
    sp.set_title(ax, run.case, "composition of the discharged coal per bin")
    sp.legend_below(fig, *ax.get_legend_handles_labels(), ncol=min(len(out["fractions"]), 4))
    return fig


# ---- slab snapshots -------------------------------------------------------------------------


def read_slab(run):
    """probe_slab.csv as a dict of arrays."""
    _, rows = run.table("probe_slab.csv")
    keys = ("t_s", "coal", "x_m", "z_m", "vz_m_s", "radius_m")
    return {k: sp.column(rows, k) for k in keys}


def snapshot_times(times, limit=MAX_SNAPSHOTS):
    """The distinct snapshot times, evenly thinned to at most `limit`."""
    distinct = np.unique(times[np.isfinite(times)])
    if len(distinct) > limit:
        pick = np.unique(np.round(np.linspace(0, len(distinct) - 1, limit)).astype(int))
        distinct = distinct[pick]
    return distinct


def slab_extent(run, slab):
    """(xmin, xmax, zmin, zmax) covering the silo outline and the particles."""
    r = np.nan_to_num(slab["radius_m"])
    xs = [np.nanmin(slab["x_m"] - r), np.nanmax(slab["x_m"] + r)]
    zs = [np.nanmin(slab["z_m"] - r), np.nanmax(slab["z_m"] + r)]
    outline = sp.silo_outline(run.summary)
    if outline is not None:
        xs += [np.nanmin(outline[0]), np.nanmax(outline[0])]
        zs += [0.0, np.nanmax(outline[1])]
        zs[0] = max(zs[0], -0.3 * np.nanmax(outline[1]))  # falling particles far below
    pad = 0.03 * max(max(xs) - min(xs), max(zs) - min(zs))
    return min(xs) - pad, max(xs) + pad, min(zs) - pad, max(zs) + pad


def time_titles(times):
    """Panel titles 't = 1.0 s', with more decimals if one decimal would not tell them apart."""
    for decimals in (1, 2, 3, 4, 6):
        titles = {t: "t = {:.{}f} s".format(t, decimals) for t in times}
        if len(set(titles.values())) == len(times):
            break
    return titles


def snapshot_grid(run, slab, times, side_width):
    """Figure, panel axes and the side axes (legend / colorbar) for the snapshot panels.

    side_width: width of the side column in inches."""
    n = len(times)
    ncols = n if n <= 4 else int(np.ceil(n / 2))
    nrows = 1 if n <= 4 else 2
    x0, x1, z0, z1 = slab_extent(run, slab)
    panel_w = min(2.4, 10.0 / ncols)
    # drawing area = panel minus tick labels and axis labels; then the equal-aspect height
    panel_h = min(max((panel_w - 0.7) * (z1 - z0) / (x1 - x0), 1.0) + 0.9, 9.0 / nrows)
    fig = plt.figure(figsize=(ncols * panel_w + side_width + 0.4, nrows * panel_h + 0.8),
                     dpi=sp.DPI)
    grid = fig.add_gridspec(nrows, ncols + 1,
                            width_ratios=[1] * ncols + [side_width / panel_w])
    axes = [fig.add_subplot(grid[k // ncols, k % ncols]) for k in range(n)]
    side = fig.add_subplot(grid[:, ncols])
    titles = time_titles(times)
    for ax, t in zip(axes, times):
        ax.set_xlim(x0, x1)
        ax.set_ylim(z0, z1)
        ax.set_aspect("equal", adjustable="box")
        ax.set_title(titles[t], fontsize=10)
        ax.set_xlabel("x (m)", fontsize=9)
        ax.set_ylabel("z (m)", fontsize=9)
        ax.tick_params(labelsize=8)
        outline = sp.silo_outline(run.summary)
        if outline is not None:
            ax.plot(*outline, color="k", lw=1)
    return fig, axes, side


def draw_particles(ax, slab, rows, colors):
    """Circles of true radius at (x, z), one face colour per particle."""
    size = 2.0 * slab["radius_m"][rows]
    circles = EllipseCollection(size, size, np.zeros(len(size)), units="xy",
                                offsets=np.column_stack([slab["x_m"][rows], slab["z_m"][rows]]),
                                transOffset=ax.transData, facecolors=colors,
                                edgecolors="none")
    ax.add_collection(circles)


def fig_snapshots_coal(run):
    """Slab snapshots coloured by coal."""
    slab = read_slab(run)
    times = snapshot_times(slab["t_s"])
    if len(times) == 0:
        raise sp.DataError("probe_slab.csv has no snapshot times")
    fig, axes, side = snapshot_grid(run, slab, times, side_width=1.6)
    coal = np.nan_to_num(slab["coal"], nan=-1).astype(int)
    for ax, t in zip(axes, times):
        rows = np.nonzero(slab["t_s"] == t)[0]
        draw_particles(ax, slab, rows, [sp.coal_color(c) for c in coal[rows]])
    ids = sorted(set(coal[coal >= 0]))
    handles = [Line2D([], [], ls="none", marker="o", ms=9, color=sp.coal_color(c))
               for c in ids]
    side.axis("off")
    sp.mark_role(side, "legend")
    side.legend(handles, [run.coal_name(c) for c in ids], loc="center left", fontsize=9,
                title="coal", frameon=False)
    fig.suptitle("{}\nparticles in the axial slab by coal".format(run.case), fontsize=11)
    fig.tight_layout()
    return fig


def fig_snapshots_velocity(run):
    """Slab snapshots coloured by vertical velocity (diverging, symmetric about 0)."""
    slab = read_slab(run)
    times = snapshot_times(slab["t_s"])
    if len(times) == 0:
        raise sp.DataError("probe_slab.csv has no snapshot times")
    fig, axes, side = snapshot_grid(run, slab, times, side_width=0.25)
    shown = np.isin(slab["t_s"], times)
    vz = slab["vz_m_s"]
    # Colour limits from the particles still in the silo (z >= 0): those falling below the
    # outlet are much faster and would wash the flow pattern out.
    speeds = np.abs(vz[shown & np.isfinite(vz) & (slab["z_m"] >= 0)])
    limit = float(np.percentile(speeds, 98)) if speeds.size else 0.0
    limit = limit if limit > 0 else 1e-3
    norm = Normalize(-limit, limit)
    cmap = plt.get_cmap("RdBu_r")
    for ax, t in zip(axes, times):
        rows = np.nonzero(slab["t_s"] == t)[0]
        draw_particles(ax, slab, rows, cmap(norm(np.nan_to_num(vz[rows]))))
    mappable = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
    bar = fig.colorbar(mappable, cax=side, extend="both")
    bar.set_label("vertical velocity v_z (m/s)")
    sp.mark_role(side, "colorbar")
    fig.suptitle("{}\nparticles in the axial slab by vertical velocity".format(run.case),
                 fontsize=11)
    fig.tight_layout()
    return fig


# ---- probe time series ----------------------------------------------------------------------


def fig_velocity_profiles(run):
    """Time-averaged v_z across the width, one line per height."""
    _, rows = run.table("probe_velocity_profile.csv")
    col = {k: sp.column(rows, k) for k in
           ("height_m", "x_m", "vz_mean_m_s", "vz_std_m_s", "t_from_s", "t_to_s")}
    windows = sorted(set(zip(col["t_from_s"], col["t_to_s"])))
    groups = sorted(set(zip(col["t_from_s"], col["t_to_s"], col["height_m"])))
    fig, ax = sp.new_figure()
    colors = plt.get_cmap("viridis")(np.linspace(0, 0.9, max(len(groups), 1)))
    for color, (a, b, h) in zip(colors, groups):
        sel = (col["t_from_s"] == a) & (col["t_to_s"] == b) & (col["height_m"] == h)
        order = np.argsort(col["x_m"][sel])
        x, v, s = (col[k][sel][order] for k in ("x_m", "vz_mean_m_s", "vz_std_m_s"))
        label = "z = {:.2f} m".format(h)
        if len(windows) > 1:
            label += ", t = {:.3g}\u2013{:.3g} s".format(a, b)
        if not np.any(np.isfinite(v)):
            label += " (no particles)"
        ax.plot(x, v, marker=".", color=color, label=label)
        ax.fill_between(x, v - s, v + s, color=color, alpha=0.12, lw=0)
    ax.axhline(0, color="0.5", lw=0.8)
    ax.set_xlabel("x, across the silo (m)")
    ax.set_ylabel("mean vertical velocity v_z (m/s)")
    window = ("t = {:.3g}\u2013{:.3g} s".format(*windows[0]) if len(windows) == 1
              else "several time windows")
    sp.set_title(ax, run.case, "time-averaged vertical velocity ({}), band \u00b1 1 std"
                 .format(window))
    sp.legend_below(fig, *ax.get_legend_handles_labels(), ncol=4)
    return fig


def time_series(run, name, columns):
    """Time and the requested columns of a probe time-series file."""
    _, rows = run.table(name)
    return sp.column(rows, "t_s"), [sp.column(rows, c) for c in columns]


def simple_series(run, t, y, ylabel, subject, color="C0"):
    """A one-line time-series figure."""
    fig, ax = sp.new_figure()
    ax.plot(t, y, color=color)
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel(ylabel)
    sp.set_title(ax, run.case, subject)
    return fig, ax


def fig_adhesion(run):
    """Share of adhered particles (%): held by a partner particle's cohesive force."""
    t, (share,) = time_series(run, "probe_adhesion.csv", ["adhered_share"])
    fig, ax = simple_series(run, t, share * 100.0, "adhered particles (%)",
                            "particles held by cohesion (partner force above the threshold)")
    ax.set_ylim(bottom=0)
    fig.tight_layout()
    return fig


def fig_cohesion_force(run):
    """Mean and maximum cohesive contact force (log scale when they span decades)."""
    t, (mean, peak) = time_series(run, "probe_cohesion_force.csv",
                                  ["mean_cohesive_force_n", "max_cohesive_force_n"])
    fig, ax = sp.new_figure()
    ax.plot(t, mean, color="C0", label="mean over the particles in the hopper")
    ax.plot(t, peak, color="C3", lw=1, label="largest")
    positive = np.concatenate([mean, peak])
    positive = positive[np.isfinite(positive) & (positive > 0)]
    if positive.size and positive.max() > 30 * positive.min():
        ax.set_yscale("log")
    ax.set_xlabel(sp.TIME_LABEL)
    ax.set_ylabel("cohesive force on a particle (N)")
    sp.set_title(ax, run.case, "cohesive force per particle (sum over its contacts)")
    sp.legend_below(fig, *ax.get_legend_handles_labels(), ncol=2)
    return fig


def fig_level(run):
    """Fill level on the centre line, with the cone and silo tops for reference."""
    t, (level,) = time_series(run, "probe_level.csv", ["level_m"])
    fig, ax = simple_series(run, t, level, "fill level on the axis (m)", "fill level")
    ax.lines[0].set_label("level")
    silo = run.summary.get("silo") if isinstance(run.summary.get("silo"), dict) else {}
    cone = sp.num(silo.get("cone_height_m"))
    cyl = sp.num(silo.get("cylinder_height_m"))
    if sp.finite(cone):
        ax.axhline(cone, color="0.5", ls="--", lw=1, label="top of the cone")
        if sp.finite(cyl):
            ax.axhline(cone + cyl, color="0.5", ls=":", lw=1, label="top of the silo")
    ax.set_ylim(bottom=0)
    sp.legend_below(fig, *ax.get_legend_handles_labels())
    return fig


def fig_coordination(run):
    """Mean coordination number."""
    t, (coord,) = time_series(run, "probe_coordination.csv", ["mean_coordination"])
    fig, ax = simple_series(run, t, coord, "mean coordination number (contacts/particle)",
                            "mean coordination number")
    ax.set_ylim(bottom=0)
    fig.tight_layout()
    return fig


FIGURES = [
    ("rate_cumulative.png", fig_rate_cumulative,
     "Outlet mass flow rate per bin and cumulative discharged mass (dashed: filled mass)."),
    ("calorific.png", fig_calorific,
     "Calorific value of the coal leaving per bin, against each coal and the inventory mean."),
    ("fractions.png", fig_fractions, "Mass share of each coal in the outflow per bin."),
    ("snapshots_coal.png", fig_snapshots_coal,
     "Particles in a thin slab through the axis, coloured by coal."),
    ("snapshots_velocity.png", fig_snapshots_velocity,
     "Particles in a thin slab through the axis, coloured by vertical velocity (blue: down)."),
    ("velocity_profiles.png", fig_velocity_profiles,
     "Time-averaged vertical velocity across the silo at several heights."),
    ("adhesion.png", fig_adhesion, "Share of particles in the hopper held by a partner particle's cohesive force above the threshold."),
    ("cohesion_force.png", fig_cohesion_force, "Cohesive force on a particle (sum of the cohesive forces of its contacts with particles and walls): mean over the particles in the hopper, and the largest."),
    ("level.png", fig_level, "Height of the top of the bed on the silo axis."),
    ("coordination.png", fig_coordination, "Mean number of contacts per particle."),
]


def make_figures(run, fig_dir, records):
    """Draw every figure it can; returns [(name, caption, written path or None, note)]."""
    results = []
    for name, builder, caption in FIGURES:
        path = os.path.join(fig_dir, name)
        try:
            fig = builder(run)
        except (sp.NotRecorded, sp.DataError) as e:
            if os.path.exists(path):
                os.remove(path)  # a stale figure of an earlier report
            results.append((name, caption, None, sp.skip_note(e)))
            continue
        sp.save_figure(fig, path, records)
        results.append((name, caption, path, ""))
    return results


# ---- HTML report ----------------------------------------------------------------------------


def alerts_html(run):
    """Prominent notes: incomplete run, stopped flow, silo not emptied."""
    s = run.summary
    parts = []
    if s.get("complete") is False:
        parts.append('<p class="alert">Run incomplete: {}</p>'.format(
            sp.esc(s.get("error") or "no error text")))
    if s.get("flow_stopped") is True:
        parts.append('<p class="alert">Flow stopped: the silo did not empty ({}).</p>'.format(
            sp.esc(s.get("end") or "")))
    elif s.get("end") and s.get("end") != "emptied":
        parts.append('<p class="notice">End of the discharge: {}.</p>'.format(sp.esc(s["end"])))
    return "\n".join(parts)


def yes_no(value):
    """'yes' / 'no' / em dash for a JSON boolean."""
    return {True: "yes", False: "no"}.get(value, "\u2014")


def summary_html(run):
    """The summary table."""
    v, s = run.value, run.summary
    rows = [
        ("case", run.case),
        ("filled mass", sp.fmt(v("filled_mass_kg"), "kg")),
        ("particles filled", sp.fmt(v("particles_filled"), "", 10)),
        ("discharged mass", sp.fmt(v("discharged_mass_kg"), "kg")),
        ("remaining mass", sp.fmt(v("remaining_mass_kg"), "kg")),
        ("lost mass", sp.fmt(v("lost_mass_kg"), "kg")),
        ("discharge time", sp.fmt(v("discharge_time_s"), "s")),
        ("mean rate", sp.fmt(v("mean_rate_kg_s"), "kg/s")),
        ("flow stopped", yes_no(s.get("flow_stopped"))),
        ("end", s.get("end") or "\u2014"),
        ("complete", yes_no(s.get("complete"))),
        ("coarse-graining ratio k", sp.fmt(v("k"))),
        ("time step dt", sp.fmt(v("time_step_s"), "s")),
        ("threads", sp.fmt(v("threads"), "", 6)),
        ("wall time", sp.fmt(v("wall_time_s"), "s")),
        ("inventory calorific value", sp.fmt(v("inventory_calorific_kcal_kg"), "kcal/kg")),
        ("outlet calorific value", sp.fmt(v("outlet_mean_calorific_kcal_kg"), "kcal/kg")),
    ]
    if s.get("error"):
        rows.append(("error", s["error"]))
    return "<h2>Summary</h2>\n" + sp.html_table(["quantity", "value"], rows, numeric=(1,))


def fill_html(run):
    """The fill report table (fill.csv) and the fill warnings."""
    parts = ["<h2>Fill</h2>"]
    try:
        header, rows = run.table("fill.csv")
        cells = [[cell_text(row.get(h, "")) for h in header] for row in rows]
        numeric = tuple(i for i, h in enumerate(header) if h not in ("segment", "coal", "settled"))
        parts.append(sp.html_table(header, cells, numeric=numeric))
    except (sp.NotRecorded, sp.DataError) as e:
        parts.append('<p class="missing">Fill report: {}.</p>'.format(sp.esc(sp.skip_note(e))))
    warnings = run.summary.get("fill_warnings") or []
    if warnings:
        items = "".join("<li>{}</li>".format(sp.esc(w)) for w in warnings)
        parts.append('<p class="notice">Fill warnings:</p><ul>{}</ul>'.format(items))
    else:
        parts.append("<p>Fill warnings: none.</p>")
    return "\n".join(parts)


def cell_text(cell):
    """A CSV cell for the HTML table: numbers to 4 significant digits."""
    try:
        return sp.fmt(float(cell)) if cell.strip() else "\u2014"
    except ValueError:
        return cell


def measured_html(run):
    """Relative errors against measured outlet data (silodem's and this tool's)."""
    reported = run.summary.get("measured")
    reported = reported if isinstance(reported, dict) else None
    own = sp.measured_errors(run)
    if reported is None and own is None:
        return ""
    rows = []
    for key, label in (("rate", "mass flow rate"), ("calorific", "calorific value")):
        for stat in ("max", "mean"):
            sim_value = sp.num(reported.get("{}_{}_rel_error".format(key, stat))) if reported \
                else None
            mine = own.get(key) if own else None
            points = [reported.get(key + "_points") if reported else None,
                      mine["points"] if mine else None]
            rows.append((label, stat, pct(sim_value), pct(mine[stat] if mine else None),
                         " / ".join("\u2014" if n is None else str(n) for n in points)))
    head = "<h2>Measured data</h2>\n"
    if reported:
        head += "<p>File {}, {} points (from summary.json).</p>\n".format(
            sp.esc(reported.get("file", "measured.csv")), sp.esc(reported.get("points", "?")))
    note = ("<p>Relative error |sim \u2212 meas| / |meas| against the simulated bin containing "
            "each measured time; \u2014 = not measured or not recorded.</p>")
    table = sp.html_table(["quantity", "statistic", "relative error (silodem)",
                           "relative error (recomputed)",
                           "points compared (silodem / recomputed)"], rows,
                          numeric=(2, 3, 4))
    return head + table + note


def pct(value):
    """A fraction as a percentage text."""
    return sp.fmt(100.0 * value, "%", 3) if sp.finite(value) else "\u2014"


def figures_html(results):
    """Each figure with its caption, or a 'not recorded' line."""
    parts = ["<h2>Figures</h2>"]
    for name, caption, path, note in results:
        if path:
            parts.append(sp.html_figure("figures/" + name, caption))
        else:
            parts.append('<p class="missing">{}: {}</p>'.format(sp.esc(name), sp.esc(note)))
    return "\n".join(parts)


def write_report(run, results):
    """RUN_DIR/report.html; returns its path."""
    body = "\n".join(p for p in (alerts_html(run), summary_html(run), fill_html(run),
                                 measured_html(run), figures_html(results)) if p)
    path = os.path.join(run.dir, "report.html")
    sp.write_text(path, sp.html_page("silodem report: " + run.case, body))
    return path


def main(argv=None):
    """Command line entry point; returns the exit code."""
    parser = argparse.ArgumentParser(description="Figures and HTML report of a silodem run.")
    parser.add_argument("run_dir", metavar="RUN_DIR")
    parser.add_argument("--check-labels", action="store_true",
                        help="print the axis labels of every figure (LABELS lines); exit 3 if "
                             "one lacks a unit")
    args = parser.parse_args(argv)
    try:
        run = sp.Run(args.run_dir)
        fig_dir = os.path.join(args.run_dir, "figures")
        os.makedirs(fig_dir, exist_ok=True)
    except (sp.RunError, OSError) as e:
        print("silodem_report: error: {}".format(e), file=sys.stderr)
        return 2
    records = []
    results = make_figures(run, fig_dir, records)
    for _, _, path, _ in results:
        if path:
            print(path)
    print(write_report(run, results))
    if args.check_labels:
        problems = sp.print_label_check(records)
        for p in problems:
            print("silodem_report: label without unit: " + p, file=sys.stderr)
        return 3 if problems else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
