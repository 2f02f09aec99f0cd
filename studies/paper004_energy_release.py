"""An independent check of the J-integral: the energy release rate of the discrete
peridynamic model itself, G = dU/da at fixed load, by a central difference in the notch
length (a - h and a + h: the tip stays halfway between two particle columns).

  /usr/bin/python3 studies/paper004_energy_release.py --out out/paper004_G [--points 6:3,6:6,3:3]

Under the tractions of paper 004 (linear, load-controlled) the strain energy at equilibrium
is U = (1/2) sum f_ext . u = -(1/2) sum f_int . u (the supports are statically determinate:
no reaction work). J of the post-processor (at notch a) should equal G = (U(a+h) - U(a-h)) / (2h)
up to the O(h^2) of the difference and the lattice's discreteness of the crack advance.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper004_scene as ps  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def energy_and_j(out, name, delta, m, a, double, law):
    d = os.path.join(out, name)
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, "scene.yaml")
    with open(path, "w") as f:
        f.write(ps.scene(delta, m, [ps.contour_around_tip(0.025)], double=double, law=law, directory=d, notch_length=a,
                         csv=True))
    p = subprocess.run(["nice", os.path.join(ROOT, "build/bin/pd"), "run", path], capture_output=True, text=True,
                       env=dict(os.environ, OMP_WAIT_POLICY="PASSIVE"))
    if p.returncode != 0:
        raise RuntimeError(p.stderr[-2000:])
    U = 0.0
    with open(os.path.join(d, "result.csv")) as f:
        for r in csv.DictReader(f):
            U -= 0.5 * (float(r["internal_force_x"]) * float(r["u_x"]) + float(r["internal_force_y"]) * float(r["u_y"]))
    with open(os.path.join(d, "summary.json")) as f:
        J = json.load(f)["j_integral"][0]["J"]
    return U, J


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default="out/paper004_G")
    ap.add_argument("--points", default="12:3,6:3,6:6,3:3")
    ap.add_argument("--law", default="bond_based_conical_2d")
    ap.add_argument("--double", action="store_true")
    a = ap.parse_args()
    rows = []
    for spec in a.points.split(","):
        dmm, m = spec.split(":")
        delta, m = float(dmm) * 1e-3, int(m)
        h = ps.L / ps.count_for(delta, m)
        t0 = time.time()
        tag = f"{'double' if a.double else 'single'}_d{dmm}_m{m}_{a.law}"
        U_minus, _ = energy_and_j(a.out, tag + "_minus", delta, m, ps.NOTCH - h, a.double, a.law)
        U_plus, _ = energy_and_j(a.out, tag + "_plus", delta, m, ps.NOTCH + h, a.double, a.law)
        _, J = energy_and_j(a.out, tag + "_mid", delta, m, ps.NOTCH, a.double, a.law)
        G = (U_plus - U_minus) / (2 * h)
        rows.append({"delta_mm": float(dmm), "m": m, "law": a.law, "double": a.double, "J": J, "G": G,
                     "relative": (J - G) / G, "seconds": time.time() - t0})
        print(json.dumps(rows[-1]), flush=True)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, f"energy_release_{a.law}{'_double' if a.double else ''}.json"), "w") as f:
        json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
