"""Figures of docs/paper003.md from finished studies/paper003_plate.py runs: per law, the
probe's u_x(t), u_y(t) (paper 003 Figs. 13-16) and the central-axis displacements of the
plate in tension (Figs. 19-22), every delta/dx beside the SfePy reference; with --nonuniform,
the same for the paper's delta per law and k = 1, 2, 4 (Figs. 24-31); with --cutout, the
displacement fields of the plate with a square cut-out (studies/paper003_cutout.py, Figs. 33-39).

  /usr/bin/python3 studies/paper003_plots.py --study DIR --fem studies/paper003_fem --out docs/images
        [--nonuniform DIR ...] [--cutout DIR]
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from paper003_plate import axis_profile, read_result  # noqa: E402

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


# The paper's horizon per law in sections 5.3-5.5: delta = 3 dx for OSB, 2 dx for NOSB.
PAPER_DELTA = {"oterkus_plane_strain": 3, "correspondence_silling_plane_strain": 2}


def find_point(roots, sub, law, m):
    """The first finished run of the point among the study roots."""
    for root in roots:
        path = os.path.join(root, sub, f"{law}_m{m:g}")
        if os.path.exists(os.path.join(path, "summary.json")):
            return path
    return None


def nonuniform(roots, fem_dir, out):
    """Figs. 24-27 (the probe's history) and 28-31 (the central axes in tension), k = 1, 2, 4."""
    fem = np.genfromtxt(os.path.join(fem_dir, "plate_dynamic_fem.csv"), delimiter=",", names=True)
    rows = list(csv.DictReader(open(os.path.join(fem_dir, "plate_static_fem.csv"))))
    static_fem = {ax: np.array([[float(r["s"]), float(r["ux"]), float(r["uy"])] for r in rows if r["axis"] == ax])
                  for ax in "xy"}
    for case in ("dynamic", "static"):
        fig, axes = plt.subplots(2, 2, figsize=(9.5, 6.5))
        for row, (law, m) in enumerate(PAPER_DELTA.items()):
            for col, c in enumerate((0, 1)):
                ax = axes[row, col]
                if case == "dynamic":
                    comp = ("ux", "uy")[c]
                    ax.plot(fem["t"] * 1e3, fem[comp] * 1e3, "k-", lw=2.2, label="FEM (SfePy)")
                    ax.set_xlabel("t (ms)")
                    ax.set_title(f"{LAWS[law]}, δ₂ = {m} Δx₂: {comp[0]}_{comp[1]} at (0.255, 0.255)", fontsize=9)
                else:
                    ref = static_fem["xy"[c]]
                    ax.plot(ref[:, 0], ref[:, 1 + c] * 1e3, "k-", lw=2.2, label="FEM (SfePy)")
                    ax.set_xlabel("xy"[c] + " (m)")
                    ax.set_title(f"{LAWS[law]}, δ₂ = {m} Δx₂: " + ("u_x on y = 0", "u_y on x = 0")[c], fontsize=9)
                for k in (1, 2, 4):
                    path = find_point(roots, f"{case}_k{k}", law, m)
                    if path is None:
                        continue
                    if case == "dynamic":
                        r = list(csv.DictReader(open(os.path.join(path, "energies.csv"))))
                        t = np.array([float(q["time"]) for q in r])
                        ax.plot(t * 1e3, np.array([float(q[comp]) for q in r]) * 1e3, lw=1, label=f"k = {k}")
                    else:
                        x, u = read_result(path)
                        pos, val = axis_profile(x, u, c, c)
                        ax.plot(pos, val * 1e3, lw=1, label=f"k = {k}")
                if col == 0:
                    ax.set_ylabel("displacement (mm)")
        axes[0, 0].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"paper003_nonuniform_{'vibration' if case == 'dynamic' else 'tension'}.png"), dpi=90)


def cutout(study, fem_dir, out):
    """Figs. 33-35 (static) and 37-39 (t = 4e-4 s): u_x and u_y of FEM, OSB and NOSB at the paper's delta."""
    for case in ("static", "dynamic"):
        rows = list(csv.DictReader(open(os.path.join(fem_dir, f"cutout_{case}_fem.csv"))))
        fem = np.array([[float(r[k]) for k in ("x", "y", "ux", "uy")] for r in rows])
        panels = [("FEM (SfePy)", fem[:, :2], fem[:, 2:], 8)]
        for law, m in PAPER_DELTA.items():
            path = os.path.join(study, case, f"{law}_m{m:g}")
            if os.path.exists(os.path.join(path, "summary.json")):
                x, u = read_result(path)
                body = (x[:, 0] > 0) & (x[:, 0] < 0.5) & (x[:, 1] < 0) & (x[:, 1] > -0.5)
                panels.append((f"{LAWS[law]}, δ = {m} Δx", x[body], u[body], 30))
        fig, axes = plt.subplots(2, len(panels), figsize=(3.6 * len(panels), 6.4), squeeze=False)
        for c in (0, 1):
            lo, hi = fem[:, 2 + c].min(), fem[:, 2 + c].max()
            for col, (title, x, u, size) in enumerate(panels):
                ax = axes[c, col]
                sc = ax.scatter(x[:, 0], x[:, 1], c=u[:, c] * 1e3, s=size, marker="s", vmin=lo * 1e3, vmax=hi * 1e3,
                                cmap="viridis", linewidths=0)
                ax.set_aspect("equal")
                ax.set_title(f"{title}: u_{'xy'[c]} (mm)", fontsize=8)
                ax.set_xticks([0, 0.25, 0.5])
            fig.colorbar(sc, ax=list(axes[c]), shrink=0.8)
        fig.savefig(os.path.join(out, f"paper003_cutout_{case}.png"), dpi=80)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--study", default="")
    ap.add_argument("--nonuniform", nargs="+", default=[])
    ap.add_argument("--cutout")
    ap.add_argument("--fem", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.study and os.path.isdir(os.path.join(a.study, "dynamic")):
        dynamic(a.study, a.fem, a.out)
    if a.study and os.path.isdir(os.path.join(a.study, "static")):
        static(a.study, a.fem, a.out)
    if a.nonuniform:
        nonuniform(a.nonuniform, a.fem, a.out)
    if a.cutout:
        cutout(a.cutout, a.fem, a.out)


if __name__ == "__main__":
    main()
