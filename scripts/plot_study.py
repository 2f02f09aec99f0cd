#!/usr/bin/env python3
"""Plots of a study directory (pd study): error against h with fitted orders, and error
against wall time (the accuracy/cost frontier, non-dominated points marked). One PNG per
problem and kind, each kept small (dpi 90)."""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(out):
    rows = [r for r in csv.DictReader(open(os.path.join(out, "points.csv"))) if r["converged"] == "1" and float(r["error"]) > 0]
    by_problem = defaultdict(list)
    for r in rows:
        by_problem[r["problem"]].append(r)
    for problem, pts in by_problem.items():
        series = defaultdict(list)
        for r in pts:
            series[(r["law"], r["influence"], float(r["ratio"]))].append(r)
        for kind in ("convergence", "cost"):
            fig, ax = plt.subplots(figsize=(7, 4.5))
            for (law, inf, ratio), s in sorted(series.items()):
                s.sort(key=lambda r: float(r["h"]))
                e = [float(r["error"]) for r in s]
                x = [float(r["h"]) for r in s] if kind == "convergence" else [float(r["total_s"]) for r in s]
                label = "%s %s %.1f" % (law.replace("_plane_strain", ""), inf, ratio)
                if kind == "convergence" and len(s) >= 2:
                    lx, ly = [math.log(v) for v in x], [math.log(v) for v in e]
                    n = len(lx)
                    m = (n * sum(a * b for a, b in zip(lx, ly)) - sum(lx) * sum(ly)) / (n * sum(a * a for a in lx) - sum(lx) ** 2)
                    label += " (order %.2f)" % m
                (line,) = ax.loglog(x, e, marker="o", ms=3, lw=1, label=label)
                if kind == "cost":
                    nd = [(float(r["total_s"]), float(r["error"])) for r in s if r["non_dominated"] == "1"]
                    if nd:
                        ax.loglog([a for a, _ in nd], [b for _, b in nd], ls="none", marker="*", ms=10, color=line.get_color())
            ax.set_xlabel("h" if kind == "convergence" else "wall time (s): setup + assembly + solve")
            ax.set_ylabel("error")
            ax.set_title("%s: %s" % (problem, "error against h" if kind == "convergence" else "error against time (stars: non-dominated)"))
            ax.grid(True, which="both", lw=0.3)
            ax.legend(fontsize=6, ncol=2)
            fig.tight_layout()
            fig.savefig(os.path.join(out, "%s_%s.png" % (problem, kind)), dpi=90)
            plt.close(fig)


if __name__ == "__main__":
    main(sys.argv[1])
