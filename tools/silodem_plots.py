"""Shared reading, plotting and HTML helpers of the silodem post-processing tools.

Reads the files of a silodem run directory (summary.json, fill.csv, outlet.csv,
probe_*.csv, measured.csv); writes nothing itself. silodem_report.py and
silodem_compare.py import it to build figures (PNG) and HTML pages.

Conventions: times are seconds since the valve opened, z = 0 is the outlet
plane, the silo axis is x = y = 0. Empty CSV cells are read as NaN and drawn
as gaps.
"""

import csv
import html
import json
import math
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)
import numpy as np  # noqa: E402

FIGSIZE = (8.0, 5.0)
DPI = 120
TIME_LABEL = "time since valve opening (s)"
RATE_LABEL = "mass flow rate (kg/s)"
MASS_LABEL = "discharged mass (kg)"
CALORIFIC_LABEL = "calorific value (kcal/kg)"

# A unit is a non-empty text in (...) or [...], e.g. "(kg/s)", "[%]".
_UNIT = re.compile(r"\([^()]*\S[^()]*\)|\[[^\[\]]*\S[^\[\]]*\]")


class RunError(Exception):
    """A run directory that cannot be reported at all (no readable summary.json)."""


class NotRecorded(Exception):
    """An optional file of the run directory is missing."""


class DataError(Exception):
    """An optional file exists but cannot be used (malformed, no rows)."""


# ---- numbers and text -----------------------------------------------------------------------


def num(value):
    """A JSON value as a float; None for absent, null, booleans, text that is no number.

    The C++ side writes NaN as the string "NaN" (toml++ JSON formatter)."""
    if value is None or isinstance(value, bool):
        return None
    if isinstance(value, (int, float)):
        return float(value)
    try:
        return float(str(value).strip())
    except ValueError:
        return None


def cell_number(cell):
    """A CSV cell as a float: NaN if empty or not a number ('inf' stays infinite)."""
    try:
        return float(cell)
    except (TypeError, ValueError):
        return math.nan


def finite(value):
    """True for a finite number."""
    return value is not None and isinstance(value, (int, float)) and math.isfinite(value)


def fmt(value, unit="", digits=4):
    """A number with `digits` significant digits and its unit; an em dash if unknown."""
    if not finite(value):
        return "\u2014"
    text = "{:.{}g}".format(value, digits)
    return text + (" " + unit if unit else "")


def has_unit(label):
    """True if an axis label names a unit in parentheses or brackets."""
    return bool(label) and bool(_UNIT.search(label))


# ---- reading --------------------------------------------------------------------------------


def load_summary(run_dir):
    """summary.json as a dict; RunError if the directory or the file is unusable."""
    if not os.path.isdir(run_dir):
        raise RunError("not a readable directory: {}".format(run_dir))
    path = os.path.join(run_dir, "summary.json")
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except FileNotFoundError:
        raise RunError("no summary.json in {}".format(run_dir)) from None
    except (OSError, ValueError) as e:
        raise RunError("cannot read {}: {}".format(path, e)) from None
    if not isinstance(data, dict):
        raise RunError("{} is not a JSON object".format(path))
    return data


def read_rows(path):
    """The rows of a CSV file as dicts (header keys); NotRecorded / DataError."""
    name = os.path.basename(path)
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
            header = reader.fieldnames or []
    except FileNotFoundError:
        raise NotRecorded(name) from None
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise DataError("{}: {}".format(name, e)) from None
    if not header:
        raise DataError("{}: no header".format(name))
    if not rows:
        raise DataError("{}: no data rows".format(name))
    return header, rows


def column(rows, name, required=True):
    """A numeric column as a float array; empty or non-numeric cells are NaN."""
    if required and name not in rows[0]:
        raise DataError("column {} missing".format(name))
    out = np.full(len(rows), np.nan)
    for i, row in enumerate(rows):
        cell = (row.get(name) or "").strip()
        if cell:
            try:
                out[i] = float(cell)
            except ValueError:
                pass
    return out


def case_title(summary, run_dir=""):
    """The case name: summary title (or case file / directory name), plus the scenario."""
    title = str(summary.get("title") or "").strip()
    if not title:
        case = str(summary.get("case") or "").strip()
        title = os.path.splitext(os.path.basename(case))[0] if case else ""
    if not title:
        title = os.path.basename(os.path.normpath(run_dir)) or "silodem run"
    scenario = str(summary.get("scenario") or "").strip()
    title = title + ", " + scenario if scenario and scenario not in title else title
    k = summary.get("k")
    if isinstance(k, (int, float)) and "k = {:g}".format(k) not in title:
        title += " (run at k = {:g})".format(k)  # e.g. --set coarse_graining.k=4
    return title


def coal_list(summary):
    """[(name, heating value or None)] in coal-id order, from summary `coals`."""
    out = []
    for i, coal in enumerate(summary.get("coals") or []):
        if not isinstance(coal, dict):
            continue
        name = str(coal.get("name") or "coal {}".format(i))
        out.append((name, num(coal.get("heating_value_kcal_kg"))))
    return out


class Run:
    """A run directory: its summary and lazily read, cached data files."""

    def __init__(self, run_dir):
        self.dir = run_dir
        self.summary = load_summary(run_dir)
        self.case = case_title(self.summary, run_dir)
        self.coals = coal_list(self.summary)
        self._cache = {}

    def value(self, key):
        """A numeric summary value (None if absent or not a number)."""
        return num(self.summary.get(key))

    def table(self, name):
        """(header, rows) of a CSV file of the run; NotRecorded / DataError."""
        if name not in self._cache:
            try:
                self._cache[name] = read_rows(os.path.join(self.dir, name))
            except (NotRecorded, DataError) as e:
                self._cache[name] = e
        got = self._cache[name]
        if isinstance(got, Exception):
            raise got
        return got

    def coal_name(self, index):
        """The name of coal id `index`."""
        if 0 <= index < len(self.coals):
            return self.coals[index][0]
        return "coal {}".format(index)

    def outlet(self):
        """outlet.csv as arrays: t_start, t_end, mass, rate, cumulative, calorific, fractions."""
        header, rows = self.table("outlet.csv")
        data = {key: column(rows, col) for key, col in (
            ("t_start", "t_start_s"), ("t_end", "t_end_s"), ("mass", "mass_kg"),
            ("rate", "rate_kg_s"), ("cumulative", "cumulative_kg"),
            ("calorific", "calorific_kcal_kg"))}
        data["fractions"] = [(col[len("fraction_"):], column(rows, col))
                             for col in header if col.startswith("fraction_")]
        return data

    def measured(self):
        """measured.csv as {"t": array, "rate": array or None, "calorific": array or None}."""
        _, rows = self.table("measured.csv")
        t = column(rows, "t_s")
        rate = measured_column(rows, "rate_kg_s")
        cal = measured_column(rows, "calorific_kcal_kg")
        if rate is None and cal is None:
            raise DataError("measured.csv: neither rate_kg_s nor calorific_kcal_kg")
        return {"t": t, "rate": rate, "calorific": cal}

    def measured_or_none(self):
        """measured() or None when there is no usable measured.csv."""
        try:
            return self.measured()
        except (NotRecorded, DataError):
            return None


def measured_column(rows, name):
    """A measured column, or None if it is absent or has no value at all."""
    if name not in rows[0]:
        return None
    values = column(rows, name)
    return values if np.isfinite(values).any() else None


def skip_note(error):
    """The report text for a figure that could not be drawn."""
    if isinstance(error, NotRecorded):
        return "not recorded ({} missing)".format(error)
    return "not drawn: {}".format(error)


# ---- measured data --------------------------------------------------------------------------


def relative_errors(t_start, t_end, simulated, t_meas, measured):
    """{"max", "mean", "points"} of |sim - meas| / |meas| over the measured points, or None.

    A point at time t is compared with the bin t_start <= t < t_end; points outside
    the simulated range, with an empty simulated bin, or with meas = 0 are skipped."""
    errors = []
    for t, m in zip(t_meas, measured):
        if not (math.isfinite(t) and math.isfinite(m)) or m == 0:
            continue
        hit = np.nonzero((t_start <= t) & (t < t_end))[0]
        if hit.size == 0 or not math.isfinite(simulated[hit[0]]):
            continue
        errors.append(abs(simulated[hit[0]] - m) / abs(m))
    if not errors:
        return None
    return {"max": max(errors), "mean": sum(errors) / len(errors), "points": len(errors)}


def measured_errors(run):
    """The tool's own relative errors {"rate": ..., "calorific": ...} (None entries if absent)."""
    meas = run.measured_or_none()
    if meas is None:
        return None
    try:
        out = run.outlet()
    except (NotRecorded, DataError):
        return None
    result = {}
    for key in ("rate", "calorific"):
        result[key] = None if meas[key] is None else relative_errors(
            out["t_start"], out["t_end"], out[key], meas["t"], meas[key])
    return result


# ---- geometry -------------------------------------------------------------------------------


def silo_outline(summary):
    """(x, z) arrays of both silo walls (NaN-separated), or None without `silo`."""
    silo = summary.get("silo")
    if not isinstance(silo, dict):
        return None
    d_out = num(silo.get("outlet_diameter_m"))
    h_cone = num(silo.get("cone_height_m"))
    d_cyl = num(silo.get("cylinder_diameter_m"))
    h_cyl = num(silo.get("cylinder_height_m"))
    if not all(finite(v) for v in (d_out, h_cone, d_cyl, h_cyl)):
        return None
    top = h_cone + h_cyl
    xr = [d_cyl / 2, d_cyl / 2, d_out / 2]
    zr = [top, h_cone, 0.0]
    x = np.array([-v for v in xr] + [np.nan] + xr)
    z = np.array(zr + [np.nan] + zr)
    return x, z


# ---- plotting -------------------------------------------------------------------------------


def coal_color(index):
    """A fixed colour per coal id (the same in every figure)."""
    return plt.get_cmap("tab10")(index % 10)


def new_figure(size=FIGSIZE):
    """A figure with one axes."""
    fig, ax = plt.subplots(figsize=size, dpi=DPI)
    return fig, ax


def step_xy(t_start, t_end, values):
    """Polyline of per-bin values as steps; a NaN value (or a hole between bins) is a gap."""
    xs, ys = [], []
    for i, (a, b, v) in enumerate(zip(t_start, t_end, values)):
        if i and t_start[i] != t_end[i - 1]:
            xs.append(np.nan)
            ys.append(np.nan)
        xs += [a, b]
        ys += [v, v]
    return np.array(xs, dtype=float), np.array(ys, dtype=float)


def cumulative_xy(t_start, t_end, cumulative):
    """Cumulative mass as a line through (first bin start, 0) and each bin end."""
    if len(t_start) == 0:
        return np.array([]), np.array([])
    return (np.concatenate([[t_start[0]], t_end]), np.concatenate([[0.0], cumulative]))


def set_title(ax, case, subject):
    """Axes title: the case on the first line, the subject on the second."""
    ax.set_title("{}\n{}".format(case, subject), fontsize=11)


def legend_below(fig, handles, labels, ncol=None, top_rect=1.0):
    """A figure legend under the axes, never covering data; applies tight_layout."""
    if not handles:
        fig.tight_layout()
        return
    ncol = ncol or min(len(handles), 3)
    rows = math.ceil(len(handles) / ncol)
    height_in = fig.get_size_inches()[1]
    bottom = min(0.5, (0.12 + 0.24 * rows) / height_in)
    fig.tight_layout(rect=(0, bottom, 1, top_rect))
    fig.legend(handles, labels, loc="lower center", ncol=ncol, fontsize=9,
               frameon=False, bbox_to_anchor=(0.5, 0.01))


def axes_handles(*axes):
    """Legend handles and labels of several axes (e.g. an axes and its twin)."""
    handles, labels = [], []
    for ax in axes:
        h, l = ax.get_legend_handles_labels()
        handles += h
        labels += l
    return handles, labels


def mark_role(ax, role):
    """Tag an axes as 'colorbar' or 'legend' for the label check."""
    ax._silodem_role = role


def _effective_label(ax, which):
    """The label a reader sees for ax's x or y axis (a hidden twin axis uses its sibling's)."""
    axis = ax.xaxis if which == "x" else ax.yaxis
    label = axis.get_label_text()
    if axis.get_visible() and label:
        return label
    shared = ax.get_shared_x_axes() if which == "x" else ax.get_shared_y_axes()
    for other in shared.get_siblings(ax):
        other_axis = other.xaxis if which == "x" else other.yaxis
        if other is not ax and other_axis.get_visible() and other_axis.get_label_text():
            return other_axis.get_label_text()
    return label


def axes_labels(fig, name):
    """[(figure name, axes, xlabel, ylabel)] for every axes of fig.

    Legend-only axes are left out. A colorbar has xlabel None and its label as ylabel."""
    records = []
    for i, ax in enumerate(fig.axes):
        role = getattr(ax, "_silodem_role", "")
        if role == "legend":
            continue
        if role == "colorbar":
            label = ax.get_ylabel() or ax.get_xlabel()
            records.append((name, "colorbar {}".format(i), None, label))
            continue
        title = ax.get_title().replace("\n", " / ") or "axes {}".format(i)
        records.append((name, title, _effective_label(ax, "x"), _effective_label(ax, "y")))
    return records


def label_problems(records):
    """Text of each record whose labels lack a unit (empty list: all fine)."""
    problems = []
    for name, axes, xlabel, ylabel in records:
        is_colorbar = axes.startswith("colorbar")
        if not (is_colorbar and xlabel is None) and not has_unit(xlabel):
            problems.append("{} [{}]: x label {!r} has no unit".format(name, axes, xlabel))
        if not has_unit(ylabel):
            problems.append("{} [{}]: y label {!r} has no unit".format(name, axes, ylabel))
    return problems


def save_figure(fig, path, records):
    """Write fig as PNG, append its label records, close it."""
    records.extend(axes_labels(fig, os.path.basename(path)))
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def print_label_check(records):
    """--check-labels: print every record as a JSON line, return the problems."""
    for rec in records:
        print("LABELS " + json.dumps(
            {"figure": rec[0], "axes": rec[1], "xlabel": rec[2], "ylabel": rec[3]}))
    return label_problems(records)


# ---- HTML -----------------------------------------------------------------------------------

CSS = """
body { font-family: sans-serif; margin: 2em auto; max-width: 1100px; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 1.6em; }
.table-wrap { overflow-x: auto; max-width: 100%; margin: 0.5em 0; }
table { border-collapse: collapse; font-size: 0.92em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: left; }
th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.alert { border: 2px solid #b00; background: #fee; padding: 0.6em 1em; font-weight: bold; }
.notice { border: 1px solid #c90; background: #ffe; padding: 0.6em 1em; }
figure { margin: 1.5em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.95em; color: #444; }
.missing { color: #777; font-style: italic; }
"""


def esc(value):
    """HTML-escaped text of any value."""
    return html.escape(str(value), quote=True)


def html_table(headers, rows, numeric=()):
    """An HTML table; cells are escaped; columns whose index is in `numeric` align right. It sits
    in a box that scrolls sideways, so a table wider than the page (fill.csv has a dozen columns)
    does not run off it."""
    out = ['<div class="table-wrap"><table>', "<tr>" + "".join("<th>{}</th>".format(esc(h)) for h in headers) + "</tr>"]
    for row in rows:
        cells = []
        for i, cell in enumerate(row):
            cls = ' class="num"' if i in numeric else ""
            cells.append("<td{}>{}</td>".format(cls, esc(cell)))
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</table></div>")
    return "\n".join(out)


def html_page(title, body):
    """A self-contained HTML page (inline CSS, no scripts, no external resources)."""
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<title>{}</title>\n<style>{}</style>\n</head>\n<body>\n<h1>{}</h1>\n{}\n"
            "</body>\n</html>\n").format(esc(title), CSS, esc(title), body)


def html_figure(src, caption):
    """An <img> with a one-line caption (src relative to the page)."""
    return ('<figure><img src="{}" alt="{}"><figcaption>{}</figcaption></figure>'
            .format(esc(src), esc(caption), esc(caption)))


def write_text(path, text):
    """Write a text file (UTF-8)."""
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
