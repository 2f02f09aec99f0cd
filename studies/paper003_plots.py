"""Figures of docs/paper003.md from a finished studies/paper003_plate.py run: per law, the
probe's u_x(t), u_y(t) (paper 003 Figs. 13-16) and the central-axis displacements of the
plate in tension (Figs. 19-22), every delta/dx beside the SfePy reference.

  /usr/bin/python3 studies/paper003_plots.py --study DIR --fem studies/paper003_fem --out docs/images
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LAWS = {"oterkus_plane_strain": "OSB (Oterkus)", "correspondence_silling_plane_strain": "NOSB (Silling control)",
        "silling_plane_strain": "Silling dilatation", "bond_based_constant_2d": "bond-based"}


def ratios_of(directory, law):
    if not os.path.isdir(directory):
        return []
    found = [float(d.split("_m")[-1]) for d in os.listdir(directory) if d.startswith(law + "_m")]
    return sorted(found)


def dynamic(study, fem_dir, out):
    fem = np.genfromtxt(os.path.join(fem_dir, "plate_dynamic_fem.csv"), delimiter=",", names=True)
    fig, axes = plt.subplots(2, len(LAWS), figsize=(4.2 * len(LAWS), 6.5), sharex=True)
    for col, (law, title) in enumerate(LAWS.items()):
        for row, comp in enumerate(("ux", "uy")):
            ax = axes[row, col]
            ax.plot(fem["t"] * 1e3, fem[comp] * 1e3, "k-", lw=2.2, label="FEM (SfePy)")
            for m in ratios_of(os.path.join(study, "dynamic"), law):
                path = os.path.join(study, "dynamic", f"{law}_m{m:g}", "energies.csv")
                if not os.path.exists(path):
                    continue
                rows = list(csv.DictReader(open(path)))
                t = np.array([float(r["time"]) for r in rows])
                ax.plot(t * 1e3, np.array([float(r[comp]) for r in rows]) * 1e3, lw=1, label=f"δ = {m:g} Δx")
            ax.set_title(f"{title}: {comp[0]}_{comp[1]}", fontsize=9)
            if row == 1:
                ax.set_xlabel("t (ms)")
            if col == 0:
                ax.set_ylabel("displacement at (0.255, 0.255) (mm)")
    axes[0, 0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "paper003_vibration.png"), dpi=90)


def static(study, fem_dir, out):
    rows = list(csv.DictReader(open(os.path.join(fem_dir, "plate_static_fem.csv"))))
    fem = {ax: np.array([[float(r["s"]), float(r["ux"]), float(r["uy"])] for r in rows if r["axis"] == ax]) for ax in "xy"}
    fig, axes = plt.subplots(2, len(LAWS), figsize=(4.2 * len(LAWS), 6.5))
    for col, (law, title) in enumerate(LAWS.items()):
        for row, (comp, axis, along, c) in enumerate((("u_x on y = 0", 1, 0, 0), ("u_y on x = 0", 0, 1, 1))):
            ax = axes[row, col]
            ref = fem["x" if along == 0 else "y"]
            ax.plot(ref[:, 0], ref[:, 1 + c] * 1e3, "k-", lw=2.2, label="FEM (SfePy)")
            for m in ratios_of(os.path.join(study, "static"), law):
                path = os.path.join(study, "static", f"{law}_m{m:g}", "result.csv")
                if not os.path.exists(path):
                    continue
                r = list(csv.DictReader(open(path)))
                x = np.array([[float(q["x"]), float(q["y"])] for q in r])
                u = np.array([[float(q["u_x"]), float(q["u_y"])] for q in r])
                h = np.min(np.abs(x[:, 1]))  # the rows nearest the axis are at +-h/2
                near = (np.abs(np.abs(x[:, axis]) - h) < h / 2) & (x[:, 0] > -0.5)
                s = np.round(x[near, along] / h).astype(int)
                keys = np.unique(s)
                ax.plot(keys * h, [u[near][s == k, c].mean() * 1e3 for k in keys], lw=1, label=f"δ = {m:g} Δx")
            ax.set_title(f"{title}: {comp}", fontsize=9)
            ax.set_xlabel("x (m)" if along == 0 else "y (m)")
            if col == 0:
                ax.set_ylabel("displacement (mm)")
    axes[0, 0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "paper003_tension.png"), dpi=90)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--study", required=True)
    ap.add_argument("--fem", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if os.path.isdir(os.path.join(a.study, "dynamic")):
        dynamic(a.study, a.fem, a.out)
    if os.path.isdir(os.path.join(a.study, "static")):
        static(a.study, a.fem, a.out)


if __name__ == "__main__":
    main()
