#!/usr/bin/env python3
"""Paper 001 Fig. 1 (hole): RMS error against N and against seconds, from the CSV files of
build/bin/paper001_fig1 --csv (docs/paper001.md "Fig. 1 (hole)").
usage: scripts/paper001_fig1_plot.py OUT.png CSV [CSV ...]"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = {}
for path in sys.argv[2:]:
    for r in csv.DictReader(open(path)):
        key = (r["law"], float(r["nu"]), float(r["perturbation"]))
        rows.setdefault(key, {})[int(r["n"])] = (float(r["rms_error"]), float(r["seconds"]))

fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
for (law, nu, pert), pts in sorted(rows.items()):
    ns = sorted(pts)
    label = f"{law.replace('_plane_strain', '')}, nu={nu:g}, {'perturbed' if pert else 'uniform'}"
    style = dict(marker="o" if pert else "s", ls="-" if "corrected" not in law else "--")
    ax.loglog(ns, [pts[n][0] for n in ns], label=label, **style)
    bx.loglog([pts[n][1] for n in ns], [pts[n][0] for n in ns], **style)
n0 = min(n for pts in rows.values() for n in pts)
e0 = max(pts[n0][0] for pts in rows.values() if n0 in pts)
ax.loglog([n0, 4 * n0], [e0, e0 / 4], "k:", label="order 1")
ax.set_xlabel("N (particles per side)")
ax.set_ylabel("RMS displacement error")
ax.set_title("Paper 001 Fig. 1: hole, a = 0.2, delta = 3.5 h")
ax.legend(fontsize=7)
bx.set_xlabel("seconds (weights + assembly + solve, loaded 2-core machine)")
bx.set_ylabel("RMS displacement error")
bx.set_title("what accuracy costs")
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)
