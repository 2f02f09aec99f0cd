"""The Griffith check: J of the pressurised crack (scenes/paper004_griffith.yaml) against
K_I^2 / E' = p^2 pi a (1 - nu^2) / E as the lattice refines at fixed delta/h = 3 (delta -> 0).

  /usr/bin/python3 studies/paper004_griffith.py --out out/paper004_griffith [--counts 80,160,240,320]
"""
import argparse
import json
import math
import os
import re
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
P, A, E, NU = 0.1, 0.35, 60.0, 0.25
EXACT = P * P * math.pi * A * (1 - NU * NU) / E


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default="out/paper004_griffith")
    ap.add_argument("--counts", default="80,160,240,320")
    ap.add_argument("--laws", default="bond_based_conical_2d,silling_plane_strain")
    a = ap.parse_args()
    with open(os.path.join(ROOT, "scenes/paper004_griffith.yaml")) as f:
        base = f.read()
    rows = []
    for law in a.laws.split(","):
        for n in [int(c) for c in a.counts.split(",")]:
            d = os.path.join(a.out, f"{law}_{n}")
            os.makedirs(d, exist_ok=True)
            text = re.sub(r"count: 80", f"count: {n}", base)
            text = text.replace("law: bond_based_conical_2d", f"law: {law}").replace("out/paper004_griffith", d)
            path = os.path.join(d, "scene.yaml")
            with open(path, "w") as f:
                f.write(text)
            t0 = time.time()
            p = subprocess.run(["nice", os.path.join(ROOT, "build/bin/pd"), "run", path], capture_output=True, text=True,
                               env=dict(os.environ, OMP_WAIT_POLICY="PASSIVE"))
            if p.returncode != 0:
                raise RuntimeError(p.stderr[-2000:])
            with open(os.path.join(d, "summary.json")) as f:
                s = json.load(f)
            J = [c["J"] for c in s["j_integral"]]
            rows.append({"law": law, "count": n, "delta": 2.8 / n * 3, "J": J, "exact": EXACT,
                         "relative": [(j - EXACT) / EXACT for j in J], "seconds": time.time() - t0})
            print(json.dumps(rows[-1]), flush=True)
    with open(os.path.join(a.out, "griffith.json"), "w") as f:
        json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
