#!/usr/bin/env python3
"""The stress-strain loop of studies/plastic_bar_loop/bar_loop.yaml against the closed form.

Reads OUT/load_steps.csv (pd run of the scene; OUT defaults to out/plastic_bar_loop), takes
the mean axial strain from the two displacement probes (1.0 apart) and the mean axial stress
of the middle, and integrates the law's own continuum reading along the same strain path:
uniaxial strain in plane strain, in-plane deviator s = G eps (elastic), yield on the in-plane
deviator at |s| = sigma_y / sqrt(3) (laws/elastic_plastic.cpp: psi0 calibrated so that
G^2 eps_d:eps_d = sigma_y^2 / 6 yields), sigma_xx = kappa eps + s with kappa = K + G/3.
Prints the largest difference relative to sigma_y, writes docs/images/plastic_bar_loop.png.
Needs numpy and matplotlib: run with /usr/bin/python3.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

E, NU, SIGMA_Y = 200.0, 0.3, 0.25
G = E / (2 * (1 + NU))
K = E / (3 * (1 - 2 * NU))
KAPPA = K + G / 3
GAUGE = 1.0  # between the two displacement probes


def read(out):
    with open(os.path.join(out, "load_steps.csv")) as f:
        rows = list(csv.DictReader(f))
    strain = [(float(r["u_x_right"]) - float(r["u_x_left"])) / GAUGE for r in rows]
    stress = [float(r["sigma_xx"]) for r in rows]
    return [0.0] + strain, [0.0] + stress


def closed_form(strain):
    """Radial return on the scalar in-plane deviator along the strain path."""
    s_max = SIGMA_Y / math.sqrt(3)
    s, out, previous = 0.0, [], 0.0
    for eps in strain:
        s = max(-s_max, min(s_max, s + G * (eps - previous)))
        previous = eps
        out.append(KAPPA * eps + s)
    return out


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out/plastic_bar_loop"
    strain, stress = read(out)
    reference = closed_form(strain)
    worst = max(abs(a - b) for a, b in zip(stress, reference)) / SIGMA_Y
    slope = stress[1] / strain[1] if strain[1] else float("nan")
    print(f"steps: {len(strain) - 1}; eps_max {max(strain):.4e}, yield strain {SIGMA_Y / math.sqrt(3) / G:.4e}")
    print(f"first-step slope {slope:.2f} (closed form kappa + G = {KAPPA + G:.2f})")
    print(f"largest |sigma_pd - sigma_closed| / sigma_y over the loop: {worst:.4f}")
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(strain, reference, "k-", lw=1, label="closed form (the law's continuum reading)")
    ax.plot(strain, stress, "o", ms=3.5, mfc="none", label="pd run, mean of the middle")
    ax.set_xlabel("axial strain (between the probes)")
    ax.set_ylabel("mean axial stress sigma_xx")
    ax.set_title("elastic_plastic_plane_strain, uniaxial strain: 0 -> +eps -> -eps -> +eps")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    target = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "images", "plastic_bar_loop.png")
    fig.savefig(target, dpi=120)
    print("wrote", os.path.normpath(target))


if __name__ == "__main__":
    main()
