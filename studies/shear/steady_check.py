#!/usr/bin/env python3
"""Issue 17, must-show 3, from committed shear tests (stdlib only).

usage: steady_check.py DIR [COAL=VARIANT ...]

DIR holds k=<k>/kc=2.5e4_[VARIANT_]<coal>_seed=<n>/shear_test.json, the layout that
studies/shear/steady_coal.sh writes (validation/shear/steady/). COAL=VARIANT picks a coal's
variant, e.g. Indonesian=roll0.8 for kc=2.5e4_roll0.8_Indonesian_seed=<n>.

Must-show 3: "The calibrated consolidation law reproduces both coals' C and phi within 10% in the
virtual test, and the result does not change by more than 10% between k = 3 and k = 4." For each
coal and k it prints the seeds' mean C and phi, their sample sd and the standard error of the
mean, the ratio to the measured value (Table 1 of the paper, PHYSICS.md: Longwanggou 0.67 kPa,
33.4 deg; Indonesian 0.68 kPa, 37.2 deg) and a verdict: pass or fail on the mean, with the margin
to the nearer edge of the band in standard errors (positive inside; under 1 the verdict could turn
with a few more seeds). Then each coal's k = 4 mean over its k = 3 mean, with its standard error
by propagation. A check with fewer than two seeds is "open". Exit status 0 only if every check
passes.
"""
import math
import pathlib
import re
import statistics
import sys

from compare_k import fit  # one coal's entry of a run's shear_test.json
from shear_summary import MEASURED_LOCUS as MEASURED  # kPa, deg (Table 1)

BAND = 0.10  # must-show 3: within 10%
KS = (4, 3)


def seeds(root, k, coal, variant):
    """(C kPa, phi deg) of every finished seed of one coal, k and variant."""
    tag = f"kc=2.5e4_{variant + '_' if variant else ''}{coal}_seed="
    found = []
    for d in sorted((root / f"k={k}").glob(tag + "*")):
        if not re.fullmatch(re.escape(tag) + r"\d+", d.name):
            continue
        if not (d / "shear_test.json").exists():
            continue
        c = fit(str(d), coal)
        found.append((c["cohesion_kpa"], c["friction_angle_deg"]))
    return found


def mean_se(values):
    """Mean, sample sd and standard error of the mean (nan for fewer than two values)."""
    m = statistics.mean(values) if values else math.nan
    if len(values) < 2:
        return m, math.nan, math.nan
    sd = statistics.stdev(values)
    return m, sd, sd / math.sqrt(len(values))


def verdict(ratio, se_ratio, n):
    """pass/fail of a ratio against 1 +- BAND, with the margin to the nearer edge in se."""
    if n < 2 or not math.isfinite(se_ratio) or se_ratio == 0:
        return "open", math.nan
    margin = (BAND - abs(ratio - 1.0)) / se_ratio
    return ("pass" if abs(ratio - 1.0) <= BAND else "fail"), margin


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 2
    root = pathlib.Path(argv[1])
    variants = {}
    for a in argv[2:]:
        coal, _, name = a.partition("=")
        if coal not in MEASURED or not name:
            print(f"steady_check.py: '{a}' is not COAL=VARIANT with COAL one of {list(MEASURED)}",
                  file=sys.stderr)
            return 2
        variants[coal] = name
    ok = True
    means = {}
    print("check,coal,k,seeds,mean,sd,se,ratio,se_ratio,verdict,margin_se")
    for coal, (c_meas, phi_meas) in MEASURED.items():
        for k in KS:
            got = seeds(root, k, coal, variants.get(coal, ""))
            for i, (name, meas) in enumerate((("C_kpa", c_meas), ("phi_deg", phi_meas))):
                m, sd, se = mean_se([g[i] for g in got])
                means[(coal, k, name)] = (m, se, len(got))
                v, margin = verdict(m / meas, se / meas, len(got))
                ok &= v == "pass"
                print(f"{name} vs measured,{coal},{k},{len(got)},{m:.4g},{sd:.3g},{se:.3g},"
                      f"{m / meas:.3f},{se / meas:.3f},{v},{margin:.2f}")
        for name in ("C_kpa", "phi_deg"):
            (m4, se4, n4), (m3, se3, n3) = means[(coal, 4, name)], means[(coal, 3, name)]
            r = m4 / m3 if m3 else math.nan
            se_r = abs(r) * math.hypot(se4 / m4, se3 / m3) if m4 and m3 else math.nan
            v, margin = verdict(r, se_r, min(n4, n3))
            ok &= v == "pass"
            print(f"{name} k=4 over k=3,{coal},4/3,{n4}/{n3},,,,{r:.3f},{se_r:.3f},{v},{margin:.2f}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
