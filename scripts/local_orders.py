#!/usr/bin/python3
"""Local orders of convergence between successive resolutions of a `pd study`.

Usage: scripts/local_orders.py OUT_DIR [OUT_DIR ...]
Reads OUT_DIR/points.csv and prints, per series (problem, law, influence, delta/h), the
errors and log(e_i / e_(i+1)) / log(h_i / h_(i+1)) for each pair of successive h: how the
order approaches its limit (docs/paper000.md section 1, node against cell placement).
"""
import csv
import math
import os
import sys
from collections import defaultdict


def main(dirs):
    for d in dirs:
        path = os.path.join(d, "points.csv")
        if not os.path.isfile(path):
            sys.exit(f"local_orders.py: {path}: no such file (give a pd study output directory)")
        series = defaultdict(list)
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                if row["converged"] == "1" and float(row["error"]) > 0:
                    key = (row["problem"], row["law"], row["influence"], row["ratio"])
                    series[key].append((float(row["h"]), float(row["error"])))
        print(f"# {d}")
        for key, pts in sorted(series.items()):
            pts.sort(reverse=True)
            local = [math.log(e0 / e1) / math.log(h0 / h1) for (h0, e0), (h1, e1) in zip(pts, pts[1:])]
            print(f"{' '.join(key):<50} errors {' '.join(f'{e:.3e}' for _, e in pts)}  local orders "
                  f"{' '.join(f'{o:.3f}' for o in local)}")


if __name__ == "__main__":
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        sys.exit(0 if len(sys.argv) >= 2 else 2)
    main(sys.argv[1:])
