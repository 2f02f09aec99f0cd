#!/usr/bin/env python3
"""The stress-strain loops of studies/plastic_bar_loop/ against the laws' closed forms.

Usage: plot.py [OUT [OUT_HARDENING]]  (defaults out/plastic_bar_loop, out/plastic_bar_loop_hardening)

Reads OUT/load_steps.csv (pd run of bar_loop.yaml) and, if it exists, OUT_HARDENING/
load_steps.csv (pd run of bar_loop_hardening.yaml); takes the mean axial strain from the two
displacement probes (1.0 apart) and the mean axial stress of the middle, and integrates the
laws' own continuum reading along the same strain path: uniaxial strain in plane strain,
in-plane deviator s = G eps (elastic; s is its xx component), von Mises stress of the in-plane
deviator sqrt(3) |s| (laws/elastic_plastic.cpp: psi0 calibrated so that G^2 eps_d:eps_d =
sigma_y^2 / 6 yields), sigma_xx = kappa eps + s with kappa = K + G/3. The return is the
radial return of laws/elastic_plastic_hardening.cpp with linear isotropic hardening,
sigma_y(lambda) = sigma_y + H lambda, d_lambda = f / (3 G + H); H = 0 is the perfectly
plastic law (|s| <= sigma_y / sqrt(3)).

Prints, for each loop: the first step's slopes, the deviator s = sigma_xx - kappa eps and the
von Mises stress sqrt(3)|s| it implies at the three turning points, the strain where each
unloading branch crosses zero stress, and the largest difference from the closed form
relative to sigma_y. Writes docs/images/plastic_bar_loop.png (and
docs/images/plastic_bar_loop_hardening.png). Needs numpy and matplotlib: run with
/usr/bin/python3.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

E, NU, SIGMA_Y = 200.0, 0.3, 0.25
H_HARDENING = 50.0  # bar_loop_hardening.yaml
G = E / (2 * (1 + NU))
K = E / (3 * (1 - 2 * NU))
KAPPA = K + G / 3
GAUGE = 1.0  # between the two displacement probes
IMAGES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "images")


def read(out):
    with open(os.path.join(out, "load_steps.csv")) as f:
        rows = list(csv.DictReader(f))
    strain = [(float(r["u_x_right"]) - float(r["u_x_left"])) / GAUGE for r in rows]
    stress = [float(r["sigma_xx"]) for r in rows]
    return [0.0] + strain, [0.0] + stress


def closed_form(strain, hardening):
    """Radial return with linear isotropic hardening on the scalar in-plane deviator.

    Returns sigma_xx, the deviator s and the yield stress sigma_y + H lambda at each strain."""
    s, lam, previous = 0.0, 0.0, 0.0
    sigma, dev, yield_stress = [], [], []
    for eps in strain:
        trial = s + G * (eps - previous)
        previous = eps
        mises = math.sqrt(3) * abs(trial)
        f = mises - (SIGMA_Y + hardening * lam)
        if f > 0:
            lam += f / (3 * G + hardening)
            trial *= (SIGMA_Y + hardening * lam) / mises
        s = trial
        sigma.append(KAPPA * eps + s)
        dev.append(s)
        yield_stress.append(SIGMA_Y + hardening * lam)
    return sigma, dev, yield_stress


def refine(strain, per_branch=400):
    """The same path through the measured turning points, finely: the closed form's kinks."""
    turns = [0.0] + [strain[i] for i in range(1, len(strain) - 1)
                     if (strain[i] - strain[i - 1]) * (strain[i + 1] - strain[i]) < 0] + [strain[-1]]
    path = [0.0]
    for a, b in zip(turns, turns[1:]):
        path += [a + (b - a) * k / per_branch for k in range(1, per_branch + 1)]
    return path


def turning_points(strain):
    return [i for i in range(1, len(strain)) if i == len(strain) - 1 or
            (strain[i] - strain[i - 1]) * (strain[i + 1] - strain[i]) < 0]


def zero_crossings(strain, stress):
    """Strains where the loop crosses sigma = 0 after the first step: on the unloading
    branches (linear interpolation between the two steps around it)."""
    out = []
    for i in range(1, len(strain)):
        a, b = stress[i - 1], stress[i]
        if i > 1 and a != 0 and (a > 0) != (b > 0):
            out.append(strain[i - 1] + (strain[i] - strain[i - 1]) * a / (a - b))
    return out


def report(label, strain, stress, hardening):
    sigma_cf, dev_cf, yield_cf = closed_form(strain, hardening)
    dev = [sg - KAPPA * e for sg, e in zip(stress, strain)]
    diffs = [abs(a - b) for a, b in zip(stress, sigma_cf)]
    worst = max(range(len(diffs)), key=diffs.__getitem__)
    print(f"== {label} (H = {hardening:g})")
    print(f"steps: {len(strain) - 1}; eps_max {max(strain):.4e}, eps_min {min(strain):.4e}, "
          f"yield strain {SIGMA_Y / math.sqrt(3) / G:.4e}")
    print(f"first step: slope {stress[1] / strain[1]:.2f} (kappa + G = {KAPPA + G:.2f}); "
          f"deviatoric slope {dev[1] / strain[1]:.2f} (G = {G:.2f})")
    for i in turning_points(strain):
        print(f"step {i:2d}, eps {strain[i]:+.4e}: sigma_xx {stress[i]:+.5f} (closed form {sigma_cf[i]:+.5f}); "
              f"s {dev[i]:+.5f} ({dev_cf[i]:+.5f}); sqrt(3)|s| {math.sqrt(3) * abs(dev[i]):.5f} "
              f"(yield stress {yield_cf[i]:.5f})")
    fine = refine(strain)
    sigma_fine = closed_form(fine, hardening)[0]
    pd_zero, cf_zero = zero_crossings(strain, stress), zero_crossings(fine, sigma_fine)
    print("strain at zero stress on unloading: pd " + ", ".join(f"{z:+.4e}" for z in pd_zero)
          + "; closed form " + ", ".join(f"{z:+.4e}" for z in cf_zero))
    print(f"largest |sigma_pd - sigma_closed| / sigma_y over the loop: {diffs[worst] / SIGMA_Y:.4f} "
          f"(step {worst}, eps {strain[worst]:+.4e})")
    dev_diff = max(abs(a - b) for a, b in zip(dev, dev_cf))
    print(f"largest |s_pd - s_closed| / (sigma_y / sqrt(3)): {dev_diff / (SIGMA_Y / math.sqrt(3)):.4f}")
    lattice(strain, dev, hardening)
    return fine, sigma_fine, closed_form(fine, hardening)[1], dev


def lattice(strain, dev, hardening):
    """What the discrete family changes: the deviatoric stiffness of the lattice family for
    this strain, rho G (rho from the first, elastic, step), and with it the yield. With w = 1
    the squared norm of the deviatoric force state is 2 alpha times the deviatoric energy, so
    it is rho times the continuum's and the law's von Mises stress is sqrt(rho) times the
    continuum's: s_pd(eps) = sqrt(rho) s_closed(sqrt(rho) eps). What remains is fitted by
    c eps^2 (the bond extension |Y| - |xi| and the first Piola-Kirchhoff stress are not the
    small-strain closed form's)."""
    rho = dev[1] / strain[1] / G
    lat = [math.sqrt(rho) * s for s in closed_form([math.sqrt(rho) * e for e in strain], hardening)[1]]
    rest = [a - b for a, b in zip(dev, lat)]
    c = sum(r * e * e for r, e in zip(rest, strain)) / sum(e**4 for e in strain)
    worst = max(abs(r) for r in rest) / SIGMA_Y
    worst_fit = max(abs(r - c * e * e) for r, e in zip(rest, strain)) / SIGMA_Y
    print(f"lattice: rho = {rho:.4f}, sqrt(rho) = {math.sqrt(rho):.4f}; against sqrt(rho) s_closed(sqrt(rho) eps) the "
          f"largest difference is {worst:.4f} sigma_y; fitted c eps^2 with c = {c:.1f} "
          f"({c * max(strain)**2 / SIGMA_Y:.4f} sigma_y at eps_max), what is left {worst_fit:.4f} sigma_y")


def plot(label, strain, stress, hardening, target):
    fine, sigma_fine, dev_fine, dev = report(label, strain, stress, hardening)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax.plot(fine, sigma_fine, "k-", lw=1, label="closed form (the law's continuum reading)")
    ax.plot(strain, stress, "o", ms=3.5, mfc="none", label="pd run, mean of the middle")
    ax.set_xlabel("axial strain eps (between the probes)")
    ax.set_ylabel("mean axial stress sigma_xx")
    ax.set_title(f"{label}, uniaxial strain: 0 -> +eps -> -eps -> +eps", fontsize=9)
    bx.plot(fine, dev_fine, "k-", lw=1, label="closed form")
    bx.plot(strain, dev, "o", ms=3.5, mfc="none", label="pd run")
    bx.axhline(SIGMA_Y / math.sqrt(3), color="grey", ls=":", lw=1, label="+-sigma_y / sqrt(3)")
    bx.axhline(-SIGMA_Y / math.sqrt(3), color="grey", ls=":", lw=1)
    bx.set_xlabel("axial strain eps")
    bx.set_ylabel("deviator s = sigma_xx - kappa eps")
    bx.set_title(f"the deviatoric part (H = {hardening:g})", fontsize=9)
    for a in (ax, bx):
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(target, dpi=120)
    plt.close(fig)
    print("wrote", os.path.normpath(target))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "out/plastic_bar_loop"
    out_h = sys.argv[2] if len(sys.argv) > 2 else "out/plastic_bar_loop_hardening"
    strain, stress = read(out)
    plot("elastic_plastic_plane_strain", strain, stress, 0.0, os.path.join(IMAGES, "plastic_bar_loop.png"))
    if not os.path.exists(os.path.join(out_h, "load_steps.csv")):
        print(f"no {out_h}/load_steps.csv: run build/bin/pd run studies/plastic_bar_loop/bar_loop_hardening.yaml")
        return
    strain, stress = read(out_h)
    plot("elastic_plastic_hardening_plane_strain", strain, stress, H_HARDENING,
         os.path.join(IMAGES, "plastic_bar_loop_hardening.png"))


if __name__ == "__main__":
    main()
