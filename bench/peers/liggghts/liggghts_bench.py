#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""silodem against LIGGGHTS 3.8.0 on the same settled silo bed, timed in one run.

1. `silodem bench CASE --export-bed WORK` fills (or loads the cached fill of) the silo, times the
   settled bed with 1 and 2 OpenMP threads and writes the bed (bed.csv) and its parameters
   (bed.json).
2. This script writes the same bed for LIGGGHTS: a data file with every particle's diameter,
   density and position, the cone and cylinder as an STL mesh, the valve as a plane, and the
   contact model closest to silodem's (README.md lists what differs).
3. LIGGGHTS runs it with 1 and 2 MPI ranks: a warm-up, then the same number of steps.
4. It prints particle-steps per second for each and the ratio of the best silodem figure to the
   best LIGGGHTS one, and writes WORK/result.json.

Usage: liggghts_bench.py [--silodem PATH] [--case CASE] [--steps N] [--work DIR]
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))


def run(cmd, **kw):
    print("+", " ".join(cmd), flush=True)
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw)


DRY = ["--set", "contact.particle_particle.cohesion.law=none",
       "--set", "contact.particle_wall.cohesion.law=none"]


def silodem_bench(exe, case, steps, threads, extra, export=None):
    cmd = [exe, "bench", case, "--threads", str(threads), "--steps", str(steps), "--json"] + extra
    if export:
        cmd += ["--export-bed", export]
    out = run(cmd).stdout
    return json.loads(out[out.index("{"):])


def write_data(work, bed, rows):
    """LIGGGHTS data file, atom_style granular: id type diameter density x y z."""
    xs = [r[2] for r in rows]
    ys = [r[3] for r in rows]
    zs = [r[4] for r in rows]
    silo = bed["silo"]
    half = 0.5 * silo["cylinder_diameter_m"] + 0.01
    zlo = min(min(zs), -silo["valve_gap_m"]) - 0.01
    zhi = max(max(zs), silo["cone_height_m"] + silo["cylinder_height_m"]) + 0.01
    lines = ["LIGGGHTS data file: silodem settled bed", "",
             f"{len(rows)} atoms", "3 atom types", "",
             f"{-half} {half} xlo xhi", f"{-half} {half} ylo yhi", f"{zlo} {zhi} zlo zhi", "",
             "Atoms", ""]
    for k, (pid, coal, x, y, z, r, m) in enumerate(rows):
        rho = m / (4.0 / 3.0 * math.pi * r ** 3)
        lines.append(f"{k + 1} {coal + 1} {2 * r!r} {rho!r} {x!r} {y!r} {z!r}")
    with open(os.path.join(work, "bed.data"), "w") as f:
        f.write("\n".join(lines) + "\n")


def write_stl(work, silo, segments=96):
    """The cone (outlet to junction) and the cylinder, as triangles (valve: a plane in the input)."""
    ro = 0.5 * silo["outlet_diameter_m"]
    rt = 0.5 * silo["cylinder_diameter_m"]
    hc = silo["cone_height_m"]
    ht = hc + silo["cylinder_height_m"]
    # Many rings, so that no triangle is a sliver (LIGGGHTS refuses meshes with tiny angles).
    rings = [(hc * k / 64, ro + (rt - ro) * k / 64) for k in range(65)]
    rings += [(hc + (ht - hc) * k / 8, rt) for k in range(1, 9)]
    tris = []
    for (z0, r0), (z1, r1) in zip(rings, rings[1:]):
        for s in range(segments):
            a0 = 2 * math.pi * s / segments
            a1 = 2 * math.pi * (s + 1) / segments
            p00 = (r0 * math.cos(a0), r0 * math.sin(a0), z0)
            p01 = (r0 * math.cos(a1), r0 * math.sin(a1), z0)
            p10 = (r1 * math.cos(a0), r1 * math.sin(a0), z1)
            p11 = (r1 * math.cos(a1), r1 * math.sin(a1), z1)
            tris += [(p00, p01, p11), (p00, p11, p10)]
    out = ["solid silo"]
    for a, b, c in tris:
        u = [b[i] - a[i] for i in range(3)]
        v = [c[i] - a[i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        ln = math.sqrt(sum(x * x for x in n)) or 1.0
        out.append(f"facet normal {n[0] / ln} {n[1] / ln} {n[2] / ln}")
        out.append("outer loop")
        for p in (a, b, c):
            out.append(f"vertex {p[0]!r} {p[1]!r} {p[2]!r}")
        out += ["endloop", "endfacet"]
    out.append("endsolid silo")
    with open(os.path.join(work, "silo.stl"), "w") as f:
        f.write("\n".join(out) + "\n")


def write_input(work, bed, masses, steps, warmup):
    """The input script. Types 1, 2: the coals; 3: the walls."""
    pp = {(p["a"], p["b"]): p for p in bed["particle_particle"]}
    pw = {a: w for a, w in enumerate(bed["particle_wall"])}

    def pair(a, b):  # (law parameters, effective mass) of a type pair, 0-based, 2 = wall
        if a == 2 and b == 2:
            return pw[0], masses[0]  # wall-wall: never used
        if a == 2 or b == 2:
            c = b if a == 2 else a
            return pw[c], masses[c]
        return pp[(a, b)], masses[a] * masses[b] / (masses[a] + masses[b])

    def matrix(fn):
        return " ".join(repr(fn(*pair(a, b))) for a in range(3) for b in range(3))

    def eta_n(law, meff):  # silodem: eta_n = 2 zeta sqrt(m_eff k_n)
        return 2.0 * law["damping_ratio"] * math.sqrt(meff * law["stiffness_n_N_m"])

    radii = {a: 0.5 * c["cg_diameter_m"] for a, c in enumerate(bed["coals"])}

    def r_eff(a, b):
        if a == 2 and b == 2:
            return radii[0]  # wall-wall: never used
        if a == 2 or b == 2:
            return radii[b if a == 2 else a]
        return radii[a] * radii[b] / (radii[a] + radii[b])

    def ced(a, b):  # sjkr: F = CED * contact area ~ CED * 2 pi R* delta; half of k_n delta
        law, _ = pair(a, b)
        return 0.5 * law["stiffness_n_N_m"] / (2.0 * math.pi * r_eff(a, b))

    ced_matrix = " ".join(repr(ced(a, b)) for a in range(3) for b in range(3))
    model = "model hooke/stiffness tangential history rolling_friction cdt"
    text = f"""# silodem settled bed in LIGGGHTS (written by liggghts_bench.py)
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
read_data bed.data
neighbor {bed['skin_m']!r} bin
neigh_modify delay 0
pair_style gran {model} absolute_damping on
pair_coeff * *
fix m1 all property/global kn peratomtypepair 3 {matrix(lambda l, m: l['stiffness_n_N_m'])}
fix m2 all property/global kt peratomtypepair 3 {matrix(lambda l, m: l['stiffness_t_N_m'])}
fix m3 all property/global gamman_abs peratomtypepair 3 {matrix(eta_n)}
fix m4 all property/global gammat_abs peratomtypepair 3 {matrix(lambda l, m: l['tangential_damping_fraction'] * eta_n(l, m))}
fix m5 all property/global coefficientFriction peratomtypepair 3 {matrix(lambda l, m: l['friction'])}
fix m6 all property/global coefficientRollingFriction peratomtypepair 3 {matrix(lambda l, m: l['rolling_friction'])}
fix m7 all property/global cohesionEnergyDensity peratomtypepair 3 {ced_matrix}
timestep {bed['time_step_s']!r}
fix grav all gravity {bed['gravity_m_s2']!r} vector 0 0 -1
fix cad all mesh/surface file silo.stl type 3 curvature_tolerant yes
fix walls all wall/gran {model} mesh n_meshes 1 meshes cad absolute_damping on
fix valve all wall/gran {model} primitive type 3 zplane {-bed['silo']['valve_gap_m']!r} absolute_damping on
fix integr all nve/sphere
compute contacts all contact/atom
compute coordination all reduce ave c_contacts
thermo_style custom step atoms ke c_coordination cpu
thermo 1000
run {warmup}
run {steps}
"""
    with open(os.path.join(work, "in.bench"), "w") as f:
        f.write(text)


def liggghts_run(work, ranks):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMP_NUM_THREADS="1")
    cmd = ["mpirun", "--oversubscribe", "-np", str(ranks), "liggghts", "-in", "in.bench",
           "-log", f"log.{ranks}"]
    t0 = time.time()
    p = subprocess.run(cmd, cwd=work, env=env, text=True, capture_output=True)
    if p.returncode != 0:
        sys.exit(f"LIGGGHTS failed ({ranks} ranks):\n{p.stdout[-3000:]}\n{p.stderr[-3000:]}")
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms",
                       p.stdout)
    if len(loops) < 2:
        sys.exit(f"LIGGGHTS output without two 'Loop time' lines ({ranks} ranks):\n{p.stdout[-3000:]}")
    sec, procs, steps, atoms = loops[-1]
    # Thermo rows of the timed run (step atoms ke coordination cpu): contacts per particle at its
    # start and end, to compare the work with silodem's.
    timed = p.stdout[p.stdout.rindex("Step"):]
    rows = [l.split() for l in timed.splitlines()[1:] if re.match(r"^\s*\d+\s", l)]
    return {"ranks": int(procs), "seconds": float(sec), "steps": int(steps), "atoms": int(atoms),
            "particle_steps_per_s": int(atoms) * int(steps) / float(sec),
            "contacts_per_particle_start": float(rows[0][3]),
            "contacts_per_particle_end": float(rows[-1][3]),
            "wall_s": time.time() - t0}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--silodem", default=os.path.join(ROOT, "build", "release", "silodem"))
    ap.add_argument("--case", default=os.path.join(ROOT, "cases", "paper", "L3-I2.toml"))
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--warmup", type=int, default=200)
    ap.add_argument("--work", default="liggghts-bench")
    ap.add_argument("--cohesive", action="store_true",
                    help="keep the case's moisture cohesion in silodem (LIGGGHTS has no "
                         "constant-force law: its bed falls apart, README.md)")
    a = ap.parse_args()
    extra = [] if a.cohesive else DRY
    if not shutil.which("liggghts"):
        sys.exit("liggghts is not installed: apt-get install -y liggghts (run.sh does it)")
    os.makedirs(a.work, exist_ok=True)
    ours = {t: silodem_bench(a.silodem, a.case, a.steps, t, extra, a.work if t == 1 else None)
            for t in (1, 2)}
    with open(os.path.join(a.work, "bed.json")) as f:
        bed = json.load(f)
    with open(os.path.join(a.work, "bed.csv")) as f:
        next(f)
        rows = [(int(r[0]), int(r[1]), *map(float, r[2:7])) for r in (l.split(",") for l in f)]
    masses = {}
    for r in rows:
        masses.setdefault(r[1], r[6])
    write_data(a.work, bed, rows)
    write_stl(a.work, bed["silo"])
    write_input(a.work, bed, masses, a.steps, a.warmup)
    theirs = {p: liggghts_run(a.work, p) for p in (1, 2)}
    best_ours = max(v["particle_steps_per_s"] for v in ours.values())
    best_theirs = max(v["particle_steps_per_s"] for v in theirs.values())
    print(f"\n{len(rows)} particles, {a.steps} steps, dt = {bed['time_step_s']:.3g} s")
    for t, v in ours.items():
        print(f"  silodem   {t} thread{'s' if t > 1 else ' '}: {v['particle_steps_per_s']:.3g} "
              f"particle-steps/s, {v['contacts_per_particle']:.2f} contacts per particle")
    for p, v in theirs.items():
        print(f"  LIGGGHTS  {p} rank{'s' if p > 1 else ' '}  : {v['particle_steps_per_s']:.3g} "
              f"particle-steps/s, {v['contacts_per_particle_start']:.2f} -> "
              f"{v['contacts_per_particle_end']:.2f} contacts per particle")
    print(f"  ratio (best silodem / best LIGGGHTS): {best_ours / best_theirs:.2f}")
    result = {"particles": len(rows), "steps": a.steps, "silodem": ours, "liggghts": theirs,
              "ratio": best_ours / best_theirs}
    with open(os.path.join(a.work, "result.json"), "w") as f:
        json.dump(result, f, indent=2)


if __name__ == "__main__":
    main()
