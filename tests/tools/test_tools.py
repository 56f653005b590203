#!/usr/bin/python3
"""Tests of tools/silodem_report.py, silodem_compare.py, silodem_study.py, silodem_calibrate.py,
and of studies/paper_predict_table.py.

Run: /usr/bin/python3 tests/tools/test_tools.py
Builds synthetic run directories (known data) in a temporary directory, runs
both scripts as subprocesses and checks their PNGs, HTML, axis labels (every
label names a unit), exit codes, and the measured-data relative errors.
Writes only inside the temporary directory.
"""

import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.normpath(os.path.join(HERE, "..", "..", "tools"))
REPORT = os.path.join(TOOLS, "silodem_report.py")
COMPARE = os.path.join(TOOLS, "silodem_compare.py")
STUDY = os.path.join(TOOLS, "silodem_study.py")
CALIBRATE = os.path.join(TOOLS, "silodem_calibrate.py")
PREDICT_TABLE = os.path.normpath(os.path.join(HERE, "..", "..", "studies", "paper_predict_table.py"))
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
sys.path.insert(0, TOOLS)

import silodem_plots as sp  # noqa: E402

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
REPORT_FIGURES = ["rate_cumulative.png", "calorific.png", "fractions.png", "snapshots_coal.png",
                  "snapshots_velocity.png", "velocity_profiles.png", "adhesion.png",
                  "cohesion_force.png", "level.png", "coordination.png"]
PROBE_FILES = ["probe_slab.csv", "probe_velocity_profile.csv", "probe_adhesion.csv",
               "probe_cohesion_force.csv", "probe_level.csv", "probe_coordination.csv"]
COMPARE_FIGURES = ["compare_rate.png", "compare_cumulative.png", "compare_calorific.png"]
# Independent of the tool's own check: a non-empty text in (...) or [...].
UNIT = re.compile(r"\(\s*[^()\s][^()]*\)|\[\s*[^\[\]\s][^\[\]]*\]")

COALS = [("Longwanggou", 4788.0), ("Indonesian", 3900.0)]
SILO = {"outlet_diameter_m": 0.06, "cone_height_m": 0.19, "cylinder_diameter_m": 0.3,
        "cylinder_height_m": 0.45}
BIN = 1.0  # s, outlet bin width
RATES = [0.40, 0.42, 0.38, 0.36, 0.30, 0.20, 0.0, 0.10]  # kg/s per bin; bin 6 is empty


# ---- synthetic run directory ----------------------------------------------------------------


def write_csv(path, header, rows):
    """A CSV file; None cells are written empty."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for row in rows:
            w.writerow(["" if c is None else c for c in row])


def summary(title, scenario, **extra):
    """A summary.json dict with known numbers."""
    out = {
        "title": title, "scenario": scenario, "complete": True, "error": "",
        "filled_mass_kg": 31.38, "discharged_mass_kg": 2.16, "remaining_mass_kg": 29.21,
        "lost_mass_kg": 0.01, "discharge_time_s": 8.0, "mean_rate_kg_s": 0.27,
        "flow_stopped": False, "end": "emptied", "particles_filled": 26787, "k": 4.0,
        "time_step_s": 1.87e-05, "wall_time_s": 731.9, "threads": 2,
        "outlet_mean_calorific_kcal_kg": 4422.0, "inventory_calorific_kcal_kg": 4632.0,
        "fill_warnings": ["segment H5 <settled> late & slow"],
        "coals": [{"name": n, "symbol": n[0], "heating_value_kcal_kg": q} for n, q in COALS],
        "silo": SILO,
    }
    out.update(extra)
    return out


def outlet_rows(scale=1.0):
    """outlet.csv rows: RATES (x scale) per bin; composition shifts from coal 0 to coal 1."""
    rows, cumulative = [], 0.0
    for i, rate in enumerate(RATES):
        mass = rate * scale * BIN
        cumulative += mass
        if mass > 0:
            f1 = min(1.0, i / (len(RATES) - 1))
            fr = [1.0 - f1, f1]
            cal = fr[0] * COALS[0][1] + fr[1] * COALS[1][1]
        else:
            fr, cal = [None, None], None
        rows.append([i * BIN, (i + 1) * BIN, mass, mass / BIN, cumulative] + fr + [cal])
    return rows


def slab_rows():
    """Particles in an axial slab at 10 snapshot times (the report shows 8)."""
    rows, pid = [], 0
    r = 0.006
    for k in range(10):
        t = float(k)
        top = 0.6 - 0.05 * k
        for z in [0.004 + 2 * r * j for j in range(int(top / (2 * r)))]:
            half = 0.03 + z * (0.15 - 0.03) / 0.19 if z < 0.19 else 0.15
            x = -half + r
            while x < half - r:
                coal = 0 if z > 0.25 else 1
                vz = -0.5 * (1 - (x / half) ** 2) * (1.5 if z < 0.19 else 1.0)
                rows.append([t, pid, coal, round(x, 5), 0.0, round(z, 5), 0.0, 0.0,
                             round(vz, 5), r])
                pid += 1
                x += 2 * r
    return rows


def profile_rows():
    """Velocity profiles at three heights; outer bins of the lowest height are empty."""
    rows = []
    for h in (0.1, 0.3, 0.5):
        half = 0.03 + h * 0.12 / 0.19 if h < 0.19 else 0.15
        for j in range(15):
            x = -0.14 + 0.02 * j
            if abs(x) > half:
                rows.append([h, x, None, None, 0, 2.0, 6.0])
            else:
                rows.append([h, x, -0.3 * (1 - (x / half) ** 2), 0.02, 40, 2.0, 6.0])
    return rows


def make_run(path, title="Paper case", scenario="L3-I2", probes=True, measured=True,
             scale=1.0, **extra):
    """A complete synthetic run directory."""
    os.makedirs(path)
    s = summary(title, scenario, **extra)
    if measured:
        s["measured"] = {"file": "measured.csv", "points": 5, "rate_max_rel_error": 0.25,
                         "rate_mean_rel_error": 0.1234, "calorific_max_rel_error": None}
    with open(os.path.join(path, "summary.json"), "w") as f:
        json.dump(s, f)
    write_csv(os.path.join(path, "fill.csv"),
              ["segment", "coal", "z_low_m", "z_high_m", "z_low_settled_m", "z_high_settled_m",
               "particles", "mass_kg", "target_mass_kg", "bulk_density_kg_m3",
               "measured_bulk_density_kg_m3", "solid_fraction", "settle_time_s", "settled"],
              [["H1", "Indonesian", 0, 0.1266, 0, 0.1247, 469, 0.653, 0.6522, 751.6, 728, 0.5927,
                0.115, "true"],
               ["H2", "Longwanggou", 0.1266, 0.2532, 0.1247, 0.2503, 1630, 2.2695, 2.2691, 746.9,
                778, 0.589, 0.1606, "false"]])
    header = ["t_start_s", "t_end_s", "mass_kg", "rate_kg_s", "cumulative_kg"]
    header += ["fraction_" + n for n, _ in COALS] + ["calorific_kcal_kg"]
    write_csv(os.path.join(path, "outlet.csv"), header, outlet_rows(scale))
    if measured:
        write_csv(os.path.join(path, "measured.csv"), ["t_s", "rate_kg_s", "calorific_kcal_kg"],
                  MEASURED)
    if probes:
        write_probes(path)
    return path


def write_probes(path):
    """All probe_*.csv files."""
    write_csv(os.path.join(path, "probe_slab.csv"),
              ["t_s", "id", "coal", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s",
               "radius_m"], slab_rows())
    write_csv(os.path.join(path, "probe_velocity_profile.csv"),
              ["height_m", "x_m", "vz_mean_m_s", "vz_std_m_s", "samples", "t_from_s", "t_to_s"],
              profile_rows())
    ts = [0.25 * i for i in range(33)]
    write_csv(os.path.join(path, "probe_adhesion.csv"),
              ["t_s", "particles", "adhered", "adhered_share"],
              [[t, 1000, int(50 + 5 * t), (50 + 5 * t) / 1000] for t in ts])
    write_csv(os.path.join(path, "probe_cohesion_force.csv"),
              ["t_s", "particles", "mean_cohesive_force_n", "max_cohesive_force_n"],
              [[t, 1000, 0.01 * (1 + 0.1 * t), 0.6 + 0.05 * t] for t in ts])
    write_csv(os.path.join(path, "probe_level.csv"), ["t_s", "level_m"],
              [[t, None if t > 7.5 else 0.6 - 0.07 * t] for t in ts])
    write_csv(os.path.join(path, "probe_coordination.csv"),
              ["t_s", "particles", "mean_coordination"],
              [[t, 1000, 4.5 - 0.1 * t] for t in ts])


# Measured points against RATES (bins of 1 s) and the calorific values of outlet_rows():
#   t = 0.5: rate 0.40 vs 0.50 -> 0.2;   t = 1.0: 0.42 vs 0.35 -> 0.2 (bin [1, 2))
#   t = 2.9: 0.38 vs 0.38 -> 0;          t = 6.5: the bin is empty, and meas 0 -> skipped
#   t = 20: outside the simulated range -> skipped
# rate: max 0.2, mean 0.4 / 3.  calorific at t = 0.5 (4788): 4788 * 1.25 -> |4788 - 5985| / 5985
MEASURED = [[0.5, 0.50, 4788 * 1.25], [1.0, 0.35, None], [2.9, 0.38, None], [6.5, 0.0, 4000],
            [20.0, 0.3, 4000]]
EXPECTED_RATE = {"max": 0.2, "mean": 0.4 / 3, "points": 3}
EXPECTED_CALORIFIC = {"max": 0.2, "mean": 0.2, "points": 1}


# ---- helpers --------------------------------------------------------------------------------


def run_tool(*args):
    """Run a tool script from an unrelated cwd; returns the CompletedProcess."""
    return subprocess.run([PYTHON] + list(args), capture_output=True, text=True, cwd="/")


def read(path):
    """The text of a file."""
    with open(path, encoding="utf-8") as f:
        return f.read()


def label_records(stdout):
    """The LABELS records printed by --check-labels."""
    return [json.loads(line[len("LABELS "):]) for line in stdout.splitlines()
            if line.startswith("LABELS ")]


class ToolTestCase(unittest.TestCase):
    """Common checks."""

    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="silodem_tools_")
        self.tmp = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def assertPng(self, path):
        self.assertTrue(os.path.isfile(path), path)
        with open(path, "rb") as f:
            self.assertEqual(f.read(8), PNG_SIGNATURE, path)
        self.assertGreater(os.path.getsize(path), 5000, path)

    def assertLabelsHaveUnits(self, records, figures):
        self.assertTrue(records)
        self.assertEqual({r["figure"] for r in records}, set(figures))
        for r in records:
            where = "{} [{}]".format(r["figure"], r["axes"])
            if r["axes"].startswith("colorbar"):
                self.assertIsNone(r["xlabel"], where)
            else:
                self.assertRegex(r["xlabel"] or "", UNIT, where + " x label")
            self.assertRegex(r["ylabel"] or "", UNIT, where + " y label")


# ---- report ---------------------------------------------------------------------------------


class ReportTest(ToolTestCase):

    def test_full_run(self):
        run = make_run(os.path.join(self.tmp, "run"))
        p = run_tool(REPORT, "--check-labels", run)
        self.assertEqual(p.returncode, 0, p.stderr)
        html_text = read(os.path.join(run, "report.html"))
        for name in REPORT_FIGURES:
            path = os.path.join(run, "figures", name)
            self.assertPng(path)
            self.assertIn('src="figures/{}"'.format(name), html_text)
            self.assertIn(path, p.stdout)
        self.assertIn(os.path.join(run, "report.html"), p.stdout)
        for number in ("31.38", "2.16", "29.21", "0.01", "8 s", "0.27 kg/s", "1.87e-05",
                       "731.9", "4632", "4422", "26787", "751.6", "H2", "Longwanggou"):
            self.assertIn(number, html_text)
        self.assertIn("segment H5 &lt;settled&gt; late &amp; slow", html_text)  # escaped
        self.assertIn("25 %", html_text)      # rate_max_rel_error from summary.json
        self.assertIn("12.3 %", html_text)    # rate_mean_rel_error
        self.assertIn("20 %", html_text)      # recomputed by the tool
        self.assertNotIn("<script", html_text.lower())
        self.assertNotIn("http", html_text)
        self.assertLabelsHaveUnits(label_records(p.stdout), REPORT_FIGURES)

    def test_missing_probes_are_reported(self):
        run = make_run(os.path.join(self.tmp, "run"), probes=False, measured=False)
        p = run_tool(REPORT, run)
        self.assertEqual(p.returncode, 0, p.stderr)
        html_text = read(os.path.join(run, "report.html"))
        for name in REPORT_FIGURES[:3]:
            self.assertPng(os.path.join(run, "figures", name))
        for name in REPORT_FIGURES[3:]:
            self.assertFalse(os.path.exists(os.path.join(run, "figures", name)), name)
            self.assertRegex(html_text, re.escape(name) + r": not recorded")
        for probe in PROBE_FILES:
            self.assertIn(probe, html_text)

    def test_flow_stopped_and_incomplete_are_prominent(self):
        run = make_run(os.path.join(self.tmp, "run"), probes=False, flow_stopped=True,
                       complete=False, error="NaN <velocity>", end="flow stopped",
                       outlet_mean_calorific_kcal_kg="NaN")
        p = run_tool(REPORT, run)
        self.assertEqual(p.returncode, 0, p.stderr)
        html_text = read(os.path.join(run, "report.html"))
        self.assertIn('class="alert">Flow stopped', html_text)
        self.assertIn('class="alert">Run incomplete: NaN &lt;velocity&gt;', html_text)

    def test_missing_summary_is_an_error(self):
        empty = os.path.join(self.tmp, "empty")
        os.makedirs(empty)
        for target in (empty, os.path.join(self.tmp, "nonexistent")):
            p = run_tool(REPORT, target)
            self.assertEqual(p.returncode, 2)
            self.assertEqual(len(p.stderr.strip().splitlines()), 1, p.stderr)


# ---- compare --------------------------------------------------------------------------------


class CompareTest(ToolTestCase):

    def runs(self, n=3):
        return [make_run(os.path.join(self.tmp, "r{}".format(i)), title="Case", scenario="L3-I2",
                         scale=1.0 + 0.2 * i, probes=False, measured=(i == 0))
                for i in range(n)]

    def test_compare(self):
        runs = self.runs()
        out = os.path.join(self.tmp, "cmp")
        p = run_tool(COMPARE, "--check-labels", "--out", out, *runs)
        self.assertEqual(p.returncode, 0, p.stderr)
        html_text = read(os.path.join(out, "compare.html"))
        for name in COMPARE_FIGURES:
            self.assertPng(os.path.join(out, name))
            self.assertIn('src="{}"'.format(name), html_text)
        # identical default labels get the directory name appended
        for i in range(3):
            self.assertIn("Case, L3-I2 (run at k = 4) (r{})".format(i), html_text)
        for number in ("31.38", "2.16", "8", "0.27"):
            self.assertIn(number, html_text)
        self.assertLabelsHaveUnits(label_records(p.stdout), COMPARE_FIGURES)

    def test_labels_option(self):
        runs = self.runs(2)
        out = os.path.join(self.tmp, "cmp")
        p = run_tool(COMPARE, "--out", out, "--labels", "wet,dry", *runs)
        self.assertEqual(p.returncode, 0, p.stderr)
        html_text = read(os.path.join(out, "compare.html"))
        self.assertIn("<td>wet</td>", html_text)
        self.assertIn("<td>dry</td>", html_text)

    def test_refusals(self):
        runs = self.runs(2)
        out = os.path.join(self.tmp, "cmp")
        p = run_tool(COMPARE, "--out", out, runs[0])
        self.assertEqual(p.returncode, 2)
        self.assertFalse(os.path.exists(out))
        os.makedirs(out)
        open(os.path.join(out, "keep.txt"), "w").close()
        p = run_tool(COMPARE, "--out", out, *runs)
        self.assertEqual(p.returncode, 2)
        self.assertEqual(os.listdir(out), ["keep.txt"])
        p = run_tool(COMPARE, "--out", os.path.join(self.tmp, "c2"), runs[0],
                     os.path.join(self.tmp, "nonexistent"))
        self.assertEqual(p.returncode, 2)


# ---- in-process checks ----------------------------------------------------------------------


# ---- study and calibration ------------------------------------------------------------------

STUDY_COLS = ["state", "end", "flow_stopped", "filled_mass_kg", "discharged_mass_kg",
              "discharged_fraction", "discharge_time_s", "mean_rate_kg_s", "window_rate_kg_s",
              "outlet_mean_calorific_kcal_kg", "particles_lost", "wall_time_s"]


def study_row(name, factor, k, seed, rate, state="finished", stopped=False):
    """One study.csv row with a known mean rate."""
    out = 0.0 if stopped else 1.6
    end = "flow stopped (no outflow for stall_time)" if stopped else "emptied"
    return [name, factor, k, seed, state, '"{}"'.format(end) if " " in end else end,
            "true" if stopped else "false", 1.68, out, out / 1.68, 1.5, rate, rate, 4500.0, 0,
            30.0]


class StudyTest(ToolTestCase):
    """silodem_study.py on a synthetic study: 2 factors x 2 k x 2 seeds, one arched, one failed."""

    def make_study(self):
        d = os.path.join(self.tmp, "study")
        os.makedirs(os.path.join(d, "runs"))
        with open(os.path.join(d, "study.json"), "w") as f:
            json.dump({"title": "synthetic study", "base": "/x/case.toml", "vary": ["factor", "k"],
                       "vary_numeric": [True, True], "window_s": [0.2, 1.0], "runs": 8}, f)
        rows = []
        # (factor, k): the two seeds' rates. (0.2, 4) seed 2 arched; (0.2, 3) seed 2 failed
        # (a guard stopped it), with a rate that must not enter the mean.
        rates = {("0.1", "3"): (1.0, 1.2), ("0.1", "4"): (0.8, 1.0), ("0.2", "3"): (0.5, 99.0),
                 ("0.2", "4"): (0.4, 0.0)}
        for (factor, k), pair in rates.items():
            for seed, rate in zip((1, 2), pair):
                name = "factor={}_k={}_seed={}".format(factor, k, seed)
                failed = (factor, k) == ("0.2", "3") and seed == 2
                stopped = (factor, k) == ("0.2", "4") and seed == 2
                rows.append(study_row(name, factor, k, seed, rate,
                                      "failed" if failed else "finished", stopped))
                if not failed:
                    make_run(os.path.join(d, "runs", name), probes=False, measured=False,
                             scale=max(rate, 0.01))
        with open(os.path.join(d, "study.csv"), "w") as f:
            f.write(",".join(["run", "factor", "k", "seed"] + STUDY_COLS) + "\n")
            for r in rows:
                f.write(",".join(str(c) for c in r) + "\n")
        return d

    def test_study(self):
        d = self.make_study()
        p = run_tool(STUDY, d)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertNotIn("label without unit", p.stderr)
        for metric in ("discharged_fraction", "mean_rate_kg_s", "window_rate_kg_s",
                       "discharge_time_s", "outlet_mean_calorific_kcal_kg", "wall_time_s"):
            for key in ("factor", "k"):
                self.assertPng(os.path.join(d, "figures", "{}_vs_{}.png".format(metric, key)))
        for name in ("outlet_rate.png", "outlet_cumulative.png", "outlet_calorific.png"):
            self.assertPng(os.path.join(d, "figures", name))
        html = read(os.path.join(d, "report.html"))
        # Means +- sample standard deviations of the seeds: (1.0, 1.2) -> 1.1 +- 0.14;
        # (0.8, 1.0) -> 0.9 +- 0.14; (0.4, 0) -> 0.2 +- 0.28 (the arched seed counts as its 0).
        self.assertIn("1.1 \u00b1 0.14", html)
        self.assertIn("0.9 \u00b1 0.14", html)
        self.assertIn("0.2 \u00b1 0.28", html)
        # The failed run is left out: its point has one seed, 0.5, and no 99 in any mean.
        self.assertIn('<td>0.2</td><td>3</td><td class="num">1/2</td><td class="num">0</td>'
                      '<td class="num">0.9524</td><td class="num">0.5</td>', html)
        self.assertNotIn("49.75", html)
        self.assertIn("A guard stopped 1 run(s)", html)
        self.assertIn("Flow stopped (arched) in 1 of 8 runs", html)

    def test_not_a_study(self):
        p = run_tool(STUDY, self.tmp)
        self.assertEqual(p.returncode, 2)
        self.assertIn("not a study directory", p.stderr)


class CalibrateTest(ToolTestCase):
    """silodem_calibrate.py draws the metric against the parameter."""

    def test_figure(self):
        d = os.path.join(self.tmp, "cal")
        os.makedirs(d)
        with open(os.path.join(d, "calibration.json"), "w") as f:
            json.dump({"params": ["silo.outlet_diameter_mm"], "metric": "mean_rate_kg_s",
                       "target": 0.25, "tolerance": 0.03, "seeds": 1}, f)
        with open(os.path.join(d, "calibration.csv"), "w") as f:
            f.write("evaluation,x,seed,run,value,mean,standard_error," + ",".join(STUDY_COLS) +
                    "\n")
            for e, (x, v, stopped) in enumerate([(20.0, 0.0, True), (60.0, 0.9, False),
                                                 (40.0, 0.28, False), (37.2, 0.245, False)]):
                f.write("{},{},1,x={}_seed=1,{},{},0,finished,end,{},1,1,1,1,1,1,4500,0,10\n"
                        .format(e, x, x, v, v, "true" if stopped else "false"))
        p = run_tool(CALIBRATE, d)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertPng(os.path.join(d, "calibration.png"))
        p = run_tool(CALIBRATE, self.tmp)
        self.assertEqual(p.returncode, 2)


class UnitTest(unittest.TestCase):

    def test_relative_errors(self):
        with tempfile.TemporaryDirectory() as tmp:
            run = sp.Run(make_run(os.path.join(tmp, "run"), probes=False))
            errors = sp.measured_errors(run)
        for key, expected in (("rate", EXPECTED_RATE), ("calorific", EXPECTED_CALORIFIC)):
            self.assertEqual(errors[key]["points"], expected["points"], key)
            self.assertTrue(math.isclose(errors[key]["max"], expected["max"], rel_tol=1e-9), key)
            self.assertTrue(math.isclose(errors[key]["mean"], expected["mean"], rel_tol=1e-9),
                            key)

    def test_empty_measured_column_counts_as_not_measured(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = make_run(os.path.join(tmp, "run"), probes=False)
            write_csv(os.path.join(path, "measured.csv"), ["t_s", "rate_kg_s", "calorific_kcal_kg"],
                      [[0.5, 0.5, None], [1.5, 0.42, None]])
            run = sp.Run(path)
            self.assertIsNone(run.measured()["calorific"])
            errors = sp.measured_errors(run)
        self.assertIsNone(errors["calorific"])
        self.assertTrue(math.isclose(errors["rate"]["max"], 0.2, rel_tol=1e-9))

    def test_label_check_catches_a_missing_unit(self):
        fig, ax = sp.new_figure()
        ax.set_xlabel("time since valve opening (s)")
        ax.set_ylabel("mass flow rate")
        twin = ax.twinx()
        twin.set_ylabel("discharged mass (kg)")
        records = sp.axes_labels(fig, "bad.png")
        problems = sp.label_problems(records)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("mass flow rate", problems[0])
        self.assertEqual(records[1][2], "time since valve opening (s)")  # twin shares x
        self.assertFalse(sp.has_unit("speed ()"))
        self.assertTrue(sp.has_unit("share [%]"))


class PredictTableTest(unittest.TestCase):
    """studies/paper_predict_table.py on synthetic runs whose numbers follow by hand.

    The fill: Longwanggou (4788 kcal/kg) 1 + 2 kg in H1-H2, Indonesian (3108) 6 kg in H3, so
    9 kg, inventory (3 x 4788 + 6 x 3108) / 9 = 3668. The outflow in 1 s bins (k = 3) or 2 s bins
    (k = 4): 1.0 and 1.5 kg of Longwanggou, 2.0 kg a quarter Longwanggou (3528 kcal/kg), then
    Indonesian 2.0, 1.5, 0.5 and, at k = 3 only, 0.3 kg.
    """

    MASSES = [1.0, 1.5, 2.0, 2.0, 1.5, 0.5, 0.3]
    X_L = [1.0, 1.0, 0.25, 0.0, 0.0, 0.0, 0.0]

    def write_run(self, path, k, width, nbins, finished=True):
        os.makedirs(path)
        write_csv(os.path.join(path, "fill.csv"), ["segment", "coal", "mass_kg"],
                  [["H1", "Longwanggou", 1.0], ["H2", "Longwanggou", 2.0], ["H3", "Indonesian", 6.0]])
        rows, cum = [], 0.0
        for i in range(nbins):
            m, x = self.MASSES[i], self.X_L[i]
            cum += m
            rows.append([i * width, (i + 1) * width, m, m / width, cum, x, 1 - x, x * 4788 + (1 - x) * 3108])
        header = ["t_start_s", "t_end_s", "mass_kg", "rate_kg_s", "cumulative_kg", "fraction_Longwanggou",
                  "fraction_Indonesian", "calorific_kcal_kg"]
        if not finished:  # a committed unfinished/ folder: no summary.json, no case.toml
            write_csv(os.path.join(path, "outlet_so_far.csv"), header, rows)
            with open(os.path.join(path, "check.json"), "w") as f:
                json.dump({"k": k, "inventory_calorific_kcal_kg": 3668.0}, f)
            with open(os.path.join(path, "progress.json"), "w") as f:
                json.dump({"t_s": nbins * width + 0.4}, f)
            return
        write_csv(os.path.join(path, "outlet.csv"), header, rows)
        coals = [{"name": "Longwanggou", "symbol": "L", "heating_value_kcal_kg": 4788.0},
                 {"name": "Indonesian", "symbol": "I", "heating_value_kcal_kg": 3108.0}]
        stopped = nbins < len(self.MASSES)
        with open(os.path.join(path, "summary.json"), "w") as f:
            json.dump({"complete": True, "scenario": "I1-L2", "k": k, "coals": coals,
                       "end": "flow stopped" if stopped else "emptied", "discharged_mass_kg": cum,
                       "discharge_time_s": nbins * width, "inventory_calorific_kcal_kg": 3668.0}, f)

    def test_rows_and_ratios(self):
        with tempfile.TemporaryDirectory() as tmp:
            k3, k4, live = (os.path.join(tmp, n) for n in ("k3", "k4", "live"))
            self.write_run(k3, 3.0, 1.0, 7)
            self.write_run(k4, 4.0, 2.0, 6)
            # committed as validation/runs/ keeps it: the run directory holds only unfinished/
            self.write_run(os.path.join(live, "unfinished"), 3.0, 1.0, 2, finished=False)
            p = subprocess.run([PYTHON, PREDICT_TABLE, k3, k4, live], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        lines = p.stdout.splitlines()
        self.assertEqual(len(lines), 4, p.stdout)
        # k = 3: 8.8 kg in 7 s; 95% of the 9 kg fill (8.55 kg) is out 0.05 / 0.3 into the last bin;
        # the Longwanggou that left (3 kg) is 95% out by the end of bin 3; the outlet value
        # crosses (4788 + 3108) / 2 = 3948 between the centres 1.5 s (4788) and 2.5 s (3528), at
        # 1.5 + 840 / 1260 s; the outflow's mean is (3 x 4788 + 5.8 x 3108) / 8.8 = 3680.7.
        self.assertIn("I1-L2, k = 3: 8.80 of 9.00 kg in 7.0 s, 1.2571 kg/s, emptied; 95% of the fill "
                      "out at 6.2 s; bottom Longwanggou (3.00 kg): 95% of what left out by 3 s; outlet "
                      "kcal/kg: first bin 4788, midpoint crossed at 2.2 s, mean 3681 (inventory 3668)",
                      lines[0])
        # k = 4: 8.5 kg of 9 (94.4%) in 12 s, never 95%; the crossing at twice k = 3's time.
        self.assertIn("8.50 of 9.00 kg in 12.0 s, 0.7083 kg/s, flow stopped; 95% of the fill never "
                      "out (94.4%)", lines[1])
        self.assertIn("midpoint crossed at 4.3 s", lines[1])
        # The unfinished folder: its scenario from the fill's layers, its k from check.json, its
        # heating values from the finished runs beside it, its time the last bin's end.
        self.assertIn("I1-L2, k = 3: 2.50 of 9.00 kg in 2.0 s, 1.2500 kg/s, unfinished (outflow read "
                      "to 2.0 s, the run at 2.4 s); 95% of the fill not yet out (27.8%)", lines[2])
        self.assertIn("95% of what left so far out by 2 s", lines[2])
        self.assertIn("midpoint crossed at - (not yet), mean so far 4788 (inventory 3668)", lines[2])
        self.assertNotIn("experiment", p.stdout)  # measured numbers exist for L3-I2 only
        # 12 / 7, (8.5 / 12) / (8.8 / 7), no 95% time at k = 4, 4.333 / 2.1667.
        self.assertEqual(lines[3], "I1-L2: k = 4 / k = 3 (1 / 1 runs, their means): discharge time 1.714, "
                                   "mean rate 0.563, 95% of the fill out -, midpoint crossing 2.000 (k = 3: "
                                   "emptied; k = 4: flow stopped)")

    def test_unfinished_alone_solves_heating_from_its_bins(self):
        # An unfinished folder with no finished run beside it: the two heating values solved from
        # its bins (pure Longwanggou 4788, a quarter-Longwanggou mix 3528; no pure Indonesian bin
        # in 3 bins), so the crossing is k = 3's 1.5 + 840 / 1260 s; with bins of Longwanggou
        # only it stays "not yet" (above).
        with tempfile.TemporaryDirectory() as tmp:
            run = os.path.join(tmp, "run")
            self.write_run(os.path.join(run, "unfinished"), 3.0, 1.0, 3, finished=False)
            p = subprocess.run([PYTHON, PREDICT_TABLE, run], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("midpoint crossed at 2.2 s, mean so far", p.stdout)

    def test_means_over_seeds(self):
        # Two k = 3 seeds, the second with 2 s bins: means 10.5 s, (1.2571 + 0.6286) / 2 kg/s,
        # 95% out at (6.1667 + 12.333) / 2 s, crossings (2.1667 + 4.3333) / 2 s; one k = 4 run
        # with 1 s bins: 7 s, 1.2571 kg/s, 6.1667 s, 2.1667 s.
        with tempfile.TemporaryDirectory() as tmp:
            a, b, c = (os.path.join(tmp, n) for n in ("a", "b", "c"))
            self.write_run(a, 3.0, 1.0, 7)
            self.write_run(b, 3.0, 2.0, 7)
            self.write_run(c, 4.0, 1.0, 7)
            p = subprocess.run([PYTHON, PREDICT_TABLE, a, b, c], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(p.stdout.splitlines()[-1],
                         "I1-L2: k = 4 / k = 3 (1 / 2 runs, their means): discharge time 0.667, mean rate "
                         "1.333, 95% of the fill out 0.667, midpoint crossing 0.667 (k = 3: emptied, "
                         "emptied; k = 4: emptied)")


if __name__ == "__main__":
    unittest.main(verbosity=2)
