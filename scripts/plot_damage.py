#!/usr/bin/python3
"""Plots the damage field of a dynamic run's result.csv (README picture).

usage: scripts/plot_damage.py OUT_DIR/result.csv PICTURE.png [--title TEXT]
Particles are drawn at their deformed positions (displacement magnified so the opening
shows), coloured by damage (the broken fraction of each family)."""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

src, dst = sys.argv[1], sys.argv[2]
title = sys.argv[sys.argv.index("--title") + 1] if "--title" in sys.argv else ""
rows = list(csv.DictReader(open(src)))
x = [float(r["x"]) for r in rows]
y = [float(r["y"]) for r in rows]
ux = [float(r["u_x"]) for r in rows]
uy = [float(r["u_y"]) for r in rows]
d = [float(r["damage"]) for r in rows]
span = max(x) - min(x)
umax = max(max(abs(v) for v in ux), max(abs(v) for v in uy)) or 1.0
scale = min(0.02 * span / umax, 20.0)
fig, ax = plt.subplots(figsize=(4.2, 4.0), dpi=90)
sc = ax.scatter([a + scale * b for a, b in zip(x, ux)], [a + scale * b for a, b in zip(y, uy)], c=d, s=3.0 if len(x) < 5000 else 1.2,
                cmap="inferno_r", vmin=0, vmax=0.5, linewidths=0)
fig.colorbar(sc, ax=ax, label="damage", shrink=0.8)
ax.set_aspect("equal")
ax.set_xticks([])
ax.set_yticks([])
ax.set_title(title, fontsize=9)
fig.tight_layout()
fig.savefig(dst, dpi=90)
