"""Tables (markdown) and the m- and delta-convergence plots of paper 004 Figs. 10 and 13
from studies/paper004_tables.py's results.json.

  /usr/bin/python3 studies/paper004_report.py out/paper004/results.json [--images docs/images]
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FEM = {"single": 19.76, "double": 12.90}


def table(points, kind, deltas, skipped):
    by = {(p["delta_mm"], p["m"]): p for p in points if p["name"].startswith(kind + "_")}
    sk = {s["name"]: s["particles"] for s in skipped}
    head = "| | " + " | ".join(f"δ = {d:g} mm" for d in deltas) + " |"
    lines = [head, "|---" * (len(deltas) + 1) + "|"]
    for m in (3, 6, 9):
        cells = []
        for d in deltas:
            p = by.get((d, m))
            if p is None:
                n = sk.get(f"{kind}_d{d:g}_m{m}")
                cells.append(f"not run ({n} particles)" if n else "—")
            else:
                cells.append(f"{p['J'][0]:.2f} / {p['paper'][0]:.2f} ({(p['J'][0] - p['paper'][0]) / p['paper'][0]:+.1%}), "
                             f"{p['seconds']:.0f} s")
        lines.append(f"| m = {m} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def plot(points, kind, path):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.6))
    pts = [p for p in points if p["name"].startswith(kind + "_")]
    for m in (3, 6, 9):
        s = sorted((p for p in pts if p["m"] == m), key=lambda p: p["delta_mm"])
        if s:
            ax1.plot([p["delta_mm"] for p in s], [100 * (p["J"][0] - FEM[kind]) / FEM[kind] for p in s], "o-", label=f"m = {m} (here)")
            ax1.plot([p["delta_mm"] for p in s], [100 * (p["paper"][0] - FEM[kind]) / FEM[kind] for p in s], "x--",
                     color=ax1.lines[-1].get_color(), label=f"m = {m} (paper)")
    for d in sorted({p["delta_mm"] for p in pts}):
        s = sorted((p for p in pts if p["delta_mm"] == d), key=lambda p: p["m"])
        if len(s) > 1:
            ax2.plot([p["m"] for p in s], [100 * (p["J"][0] - FEM[kind]) / FEM[kind] for p in s], "o-", label=f"δ = {d:g} mm (here)")
            ax2.plot([p["m"] for p in s], [100 * (p["paper"][0] - FEM[kind]) / FEM[kind] for p in s], "x--",
                     color=ax2.lines[-1].get_color(), label=f"δ = {d:g} mm (paper)")
    ax1.set_xscale("log")
    ax1.set_xlabel("δ (mm)")
    ax2.set_xlabel("m = δ/Δx")
    for ax in (ax1, ax2):
        ax.set_ylabel("(J − J_FEM) / J_FEM (%)")
        ax.axhline(0, color="k", lw=0.5)
        ax.legend(fontsize=6)
    ax1.set_title(f"{kind} edge notch: δ-convergence")
    ax2.set_title("m-convergence")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--images", default="docs/images")
    a = ap.parse_args()
    with open(a.results) as f:
        r = json.load(f)
    pts, sk = r["points"], r["skipped"]
    print("Table 2 (single edge notch): J here / paper (difference), wall time\n")
    print(table(pts, "single", [24, 12, 6, 3, 1.5], sk))
    print("\nTable 3 (double edge notch): J here / paper (difference), wall time\n")
    print(table(pts, "double", [6, 3, 1.5], sk))
    print("\nTables 4-5 (three contours): J on (a), (b), (c); (a) and (c) relative to (b)\n")
    print("| point | (a) | (b) | (c) | (a) vs (b) | (c) vs (b) | time |\n|---|---|---|---|---|---|---|")
    for p in pts:
        if p["name"].startswith("contours_"):
            a_, b_, c_ = p["J"]
            print(f"| {p['name']} | {a_:.3f} | {b_:.3f} | {c_:.3f} | {(a_ - b_) / b_:+.2%} | {(c_ - b_) / b_:+.2%} | {p['seconds']:.0f} s |")
    for kind in ("single", "double"):
        plot(pts, kind, os.path.join(a.images, f"paper004_{kind}_convergence.png"))


if __name__ == "__main__":
    main()
