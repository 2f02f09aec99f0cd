"""Paper 004 Tables 2-5 (and the no-notch check) with `pd run`, at the sizes that run here.

  /usr/bin/python3 studies/paper004_tables.py --out out/paper004 [--max-particles N] [--only table2,table3,...]

Each point writes a scene (studies/paper004_scene.py), runs build/bin/pd on it, and reads J
from summary.json; results.json and tables.md collect J, the paper's value, the relative
difference, particles, bonds and the wall time of every point. Points above
--max-particles are listed as skipped with their particle count (the cost grows as
particles x m^2).
"""
import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper004_scene as ps  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FEM_SINGLE, FEM_DOUBLE = 19.76, 12.90  # Abaqus, paper 004 sections 5.1 and 5.2 (Pa m)
TABLE2 = {3: [30.15, 23.64, 21.74, 20.83, 20.41], 6: [26.52, 23.05, 21.54, 20.85, 20.51], 9: [26.17, 22.95, 21.53, 20.86, 20.53]}
DELTAS2 = [0.024, 0.012, 0.006, 0.003, 0.0015]
TABLE3 = {3: [14.83, 14.01, 13.58], 6: [15.49, 14.50, 13.99], 9: [15.90, 14.77, 14.17]}
DELTAS3 = [0.006, 0.003, 0.0015]
TABLE4 = {"single": [20.11, 20.54, 19.84], "double": [13.88, 14.17, 13.37]}  # contours a, b, c at delta 1.5 mm, m 9
MIDDLE = 0.025  # half-width of the contour in the middle of the plate (the paper's Fig. 6 square, contour (b))


def three_contours(delta):
    """Paper 004 Fig. 14: (a) one horizon from the tip, (b) the middle, (c) one horizon from the boundary."""
    return [ps.contour_around_tip(delta + 1e-9), ps.contour_around_tip(MIDDLE), ps.contour_around_tip(ps.L / 2 - delta)]


def run_point(out, name, delta, m, contours, double=False, notch=True, law="bond_based_conical_2d", tips=None):
    d = os.path.join(out, name)
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, "scene.yaml")
    with open(path, "w") as f:
        f.write(ps.scene(delta, m, contours, double=double, notch=notch, law=law, directory=d, tips=tips))
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    t0 = time.time()
    p = subprocess.run(["nice", os.path.join(ROOT, "build/bin/pd"), "run", path], capture_output=True, text=True, env=env)
    wall = time.time() - t0
    with open(os.path.join(d, "log.txt"), "w") as f:
        f.write(p.stdout + p.stderr)
    if p.returncode != 0:
        raise RuntimeError(f"{name}: pd run failed:\n{p.stderr[-2000:]}")
    with open(os.path.join(d, "summary.json")) as f:
        s = json.load(f)
    return {"name": name, "delta_mm": delta * 1e3, "m": m, "law": law, "particles": s["particles"], "bonds": s["bonds"],
            "J": [c["J"] for c in s["j_integral"]], "pairwise": [c["pairwise_eq21"] for c in s["j_integral"]],
            "contours": [c["integrated"] for c in s["j_integral"]], "seconds": wall,
            "linear_solver": s["linear_solver"]["method"]}


def particles(delta, m):
    return ps.count_for(delta, m) ** 2


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default="out/paper004")
    ap.add_argument("--max-particles", type=int, default=40000)
    ap.add_argument("--only", default="nonotch,table2,table3,table45")
    ap.add_argument("--law", default="bond_based_conical_2d")
    ap.add_argument("--tips", choices=["cut", "kept"], default=None,
                    help="the crack-tip rule of every notch (default: the scene default, cut)")
    a = ap.parse_args()
    only = a.only.split(",")
    results = {"max_particles": a.max_particles, "points": [], "skipped": []}
    rpath = os.path.join(a.out, "results.json")
    if os.path.exists(rpath):
        with open(rpath) as f:
            results = json.load(f)
    done = {p["name"] for p in results["points"]}

    def point(name, delta, m, paper, **kw):
        if name in done:
            return
        n = particles(delta, m)
        if n > a.max_particles:
            results["skipped"].append({"name": name, "particles": n, "paper": paper})
            return
        r = run_point(a.out, name, delta, m, tips=a.tips, **kw)
        r["tips"] = a.tips or "cut"
        r["paper"] = paper
        results["points"].append(r)
        print(f"{name}: J = {r['J']} (paper {paper}), {r['particles']} particles, {r['seconds']:.1f} s", flush=True)
        with open(rpath, "w") as f:
            json.dump(results, f, indent=1)

    sfx = "" if a.law == "bond_based_conical_2d" else "_" + a.law
    if "nonotch" in only:
        point("nonotch_d6_m3" + sfx, 0.006, 3, [0.0], contours=[ps.contour_around_tip(MIDDLE)], notch=False, law=a.law)
    # cheapest first, so that a cap on the time leaves the trend
    order = sorted(((particles(d, m), d, m) for d in DELTAS2 for m in (3, 6, 9)))
    if "table2" in only:
        for _, d, m in order:
            point(f"single_d{d * 1e3:g}_m{m}" + sfx, d, m, [TABLE2[m][DELTAS2.index(d)]],
                  contours=[ps.contour_around_tip(MIDDLE)], law=a.law)
    if "table3" in only:
        for _, d, m in order:
            if d in DELTAS3:
                point(f"double_d{d * 1e3:g}_m{m}" + sfx, d, m, [TABLE3[m][DELTAS3.index(d)]],
                      contours=[ps.contour_around_tip(MIDDLE)], double=True, law=a.law)
    if "table45" in only:
        # the paper's point is delta 1.5 mm, m 9 (360 000 particles); here the finest that fits
        for d, m in [(0.006, 3), (0.006, 6), (0.003, 3), (0.003, 6), (0.0015, 3)]:
            for kind in ("single", "double"):
                point(f"contours_{kind}_d{d * 1e3:g}_m{m}" + sfx, d, m, TABLE4[kind], contours=three_contours(d),
                      double=kind == "double", law=a.law)
    with open(rpath, "w") as f:
        json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
