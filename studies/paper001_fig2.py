#!/usr/bin/env python3
"""Paper 001 Fig. 2: u_x along the row through the inclusion for mu2/mu1 = 2^k.

Runs build/bin/paper001_fig2 (the solves; see its header for the set-up) and draws the
paper's three panels into docs/images/paper001_fig2.png:
  left:   mu2/mu1 = 2^-6 (1/64) at n = 16, 32, 64 beside the analytic field;
  centre: mu2/mu1 = 2^6 (64) at the same grids;
  right:  n = 64, mu2/mu1 = 2^-8, 2^-6, ..., 2^8.
Usage: /usr/bin/python3 studies/paper001_fig2.py --bin build/bin/paper001_fig2 [--out docs/images]
The RMS error and time of every run are printed (the binary's stderr).
"""
import argparse
import csv
import io
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def run(binary, n, ks):
    p = subprocess.run([binary, "--n", str(n), "--ks", ",".join(str(k) for k in ks)],
                       check=True, capture_output=True, text=True)
    sys.stderr.write(p.stderr)
    rows = list(csv.DictReader(io.StringIO(p.stdout)))
    out = {}
    for r in rows:
        out.setdefault(float(r["ratio"]), []).append((float(r["x"]), float(r["ux"]), float(r["ux_exact"])))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default="build/bin/paper001_fig2")
    ap.add_argument("--out", default="docs/images")
    a = ap.parse_args()
    all_ks = list(range(-8, 9, 2))
    wide = run(a.bin, 64, all_ks)
    grids = {n: run(a.bin, n, [-6, 6]) for n in (16, 32)}
    grids[64] = {r: v for r, v in wide.items() if r in (2.0 ** -6, 2.0 ** 6)}
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    for ax, ratio, title in ((axes[0], 2.0 ** -6, "mu2/mu1 = 1/64"), (axes[1], 2.0 ** 6, "mu2/mu1 = 64")):
        for n, marker in ((16, "o"), (32, "s"), (64, "^")):
            pts = sorted(grids[n][ratio])
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, ms=4, mfc="none", label=f"{n}$^2$")
        pts = sorted(grids[64][ratio])
        ax.plot([p[0] for p in pts], [p[2] for p in pts], "k-", lw=1, label="analytic (at the 64$^2$ row)")
        ax.set_title(title)
        ax.set_xlabel("x")
        ax.set_ylabel("u_x")
        ax.axvline(0.3, color="0.7", lw=0.5)
        ax.axvline(0.7, color="0.7", lw=0.5)
        ax.legend(fontsize=8)
    ax = axes[2]
    cmap = plt.get_cmap("coolwarm")
    for i, k in enumerate(all_ks):
        pts = sorted(wide[2.0 ** k])
        c = cmap(i / (len(all_ks) - 1))
        ax.plot([p[0] for p in pts], [p[2] for p in pts], "-", color=c, lw=1)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], ".", color=c, ms=3, label=f"2^{k}")
    ax.set_yscale("symlog", linthresh=1e-2)
    ax.set_title("64$^2$, mu2/mu1 = 2^-8 ... 2^8 (lines: analytic)")
    ax.set_xlabel("x")
    ax.set_ylabel("u_x")
    ax.legend(fontsize=7, ncol=3)
    fig.suptitle("Paper 001 Fig. 2: inclusion a = 0.2, nu = 1/4, mu1 = 1, P = 1; LPS + OBQ, harmonic pair means; row y = 0.5 + h/2")
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, "paper001_fig2.png")
    fig.savefig(path, dpi=90)
    print(path)


if __name__ == "__main__":
    main()
