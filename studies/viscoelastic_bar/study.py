#!/usr/bin/env python3
"""Mitchell's viscoelastic law under a held strain and under a harmonic strain (issue 29,
docs/plasticity.md "Viscoelastic relaxation and loss angle").

Usage: /usr/bin/python3 studies/viscoelastic_bar/study.py [--pd build/bin/pd] [--out out/viscoelastic_bar]

The bar of studies/plastic_bar_loop/ (plane strain, 4 x 1, held in y everywhere: uniaxial
strain; left end fixed, right end moved along solver.load_path) with viscoelastic_plane_strain,
E = 200, nu = 0.3, lambda_i = 0.6, tau_b = 1, solved statically in physical time
(solver.duration). Writes the scenes into OUT, runs `pd run` on each and reads load_steps.csv:
the mean sigma_xx of the middle [1.5, 2.5] x [0.25, 0.75] and the strain between two
displacement probes 1.0 apart.

The continuum reading is the bar loop's: sigma_xx = kappa eps + s with kappa = K + G / 3 and
the in-plane deviator s = rho G (eps - lambda_i eps_b), where rho is the square lattice's
deviatoric stiffness factor at delta = 3h, measured here on the same scene with lambda_i = 0
(an elastic body), and eps_b the back strain: tau d(eps_b)/dt = eps - eps_b.

- Relaxation: a ramp over 0.05 tau (one load step), then a hold to 4 tau in 79 steps. The
  closed form: s / (rho G eps) = 1 - lambda_i g(t), g(T) = 1 - (tau / T)(1 - exp(-T / tau)) at
  the end of the ramp T, then g = 1 - (1 - g(T)) exp(-(t - T) / tau).
- Harmonic: eps = eps0 sin(omega t), 32 load steps a period, 6 periods, for omega tau = 0.3,
  1 and 3. The loss angle delta of s against eps, fitted (least squares on a sin + b cos) over
  the last period, against the law's closed form tan(delta) = lambda_i omega tau / (1 -
  lambda_i + (omega tau)^2), and the amplitude |s| / (rho G eps0) against
  |1 - lambda_i / (1 + i omega tau)|. The prescribed path is piecewise linear in time (the
  load path), so the same fit is made on the continuum law integrated exactly along the
  measured strains (the law's own update: exact for a piecewise-linear eps): the difference
  from the closed form that the sampling alone explains.

Prints the tables of docs/plasticity.md; writes docs/images/viscoelastic_relaxation.png and
docs/images/viscoelastic_harmonic.png. Needs numpy and matplotlib (/usr/bin/python3).
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

E, NU, LAMBDA, TAU = 200.0, 0.3, 0.6, 1.0
G = E / (2 * (1 + NU))
K = E / (3 * (1 - 2 * NU))
KAPPA = K + G / 3
GAUGE = 1.0
PULL = 0.004  # the right end's displacement at load factor 1: eps ~ 1e-3
RAMP, RELAX_STEPS = 0.05, 80  # relaxation: one ramp step of 0.05 tau, 80 steps in all
PER_PERIOD, PERIODS = 32, 6
OMEGA_TAUS = (0.3, 1.0, 3.0)
IMAGES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "images")

SCENE = """# written by studies/viscoelastic_bar/study.py
dimension: 2
domain:
  box: {{min: [0, 0], max: [4, 1]}}
  spacing: 0.04
horizon: {{ratio: 3.0}}
law: viscoelastic_plane_strain
materials:
  - {{E: {E}, nu: {NU}, parameters: {{lambda_i: {lam}, tau_b: {TAU}}}}}
boundary:
  - region: {{all: true}}
    fixed: [y]
  - region: {{side: left}}
    fixed: [x]
  - region: {{side: right}}
    displacement: {{x: {PULL}}}
solver:
  load_steps: {steps}
  load_path: [{path}]
  duration: {duration!r}
  tolerance: 1.0e-11
probes:
  - name: sigma_xx
    quantity: stress
    component: xx
    region: {{box: {{min: [1.5, 0.25], max: [2.5, 0.75]}}}}
  - name: u_x_left
    component: x
    region: {{box: {{min: [1.48, 0.25], max: [1.52, 0.75]}}}}
  - name: u_x_right
    component: x
    region: {{box: {{min: [2.48, 0.25], max: [2.52, 0.75]}}}}
output: {{directory: {directory}, vtu: false, csv: false}}
"""


def run(pd, out, name, lam, path, duration):
    directory = os.path.join(out, name)
    os.makedirs(directory, exist_ok=True)
    scene = os.path.join(out, name + ".yaml")
    with open(scene, "w") as f:
        f.write(SCENE.format(E=E, NU=NU, lam=lam, TAU=TAU, PULL=PULL, steps=len(path) - 1,
                             path=", ".join(repr(v) for v in path), duration=duration, directory=directory))
    started = time.time()
    try:
        subprocess.run([pd, "run", scene], check=True, stdout=subprocess.DEVNULL)
    except (OSError, subprocess.CalledProcessError) as e:
        sys.exit(f"study.py: `{pd} run {scene}` failed ({e}); build pd first (./scripts/build.sh) or pass --pd")
    seconds = time.time() - started
    with open(os.path.join(directory, "load_steps.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([0.0] + [float(r["time"]) for r in rows])
    eps = np.array([0.0] + [(float(r["u_x_right"]) - float(r["u_x_left"])) / GAUGE for r in rows])
    sigma = np.array([0.0] + [float(r["sigma_xx"]) for r in rows])
    return t, eps, sigma - KAPPA * eps, seconds


def back_strain(t, eps):
    """The law's update on the continuum: exact for eps linear in each step."""
    eb = np.zeros_like(eps)
    for n in range(1, len(t)):
        dt = t[n] - t[n - 1]
        d = math.exp(-dt / TAU)
        beta = 1 - (TAU / dt) * (1 - d)
        eb[n] = d * eb[n - 1] + (1 - d) * eps[n - 1] + beta * (eps[n] - eps[n - 1])
    return eb


def phase_and_amplitude(t, signal, omega):
    """a sin + b cos fitted over the last period: the phase lead of signal and its amplitude."""
    last = t > t[-1] - (1 - 1e-9) * 2 * math.pi / omega  # one period, its first point once
    basis = np.column_stack([np.sin(omega * t[last]), np.cos(omega * t[last])])
    (a, b), *_ = np.linalg.lstsq(basis, signal[last], rcond=None)
    return math.atan2(b, a), math.hypot(a, b)


def relaxation(pd, out):
    path = [0.0] + [1.0] * RELAX_STEPS
    duration = RAMP * RELAX_STEPS
    t, eps, s, seconds = run(pd, out, "relaxation", LAMBDA, path, duration)
    _, eps0, s0, _ = run(pd, out, "relaxation_elastic", 0.0, path, duration)
    rho = s0[1:] / (G * eps0[1:])
    g_ramp = 1 - (TAU / RAMP) * (1 - math.exp(-RAMP / TAU))
    g = 1 - (1 - g_ramp) * np.exp(-(t[1:] - RAMP) / TAU)
    closed = 1 - LAMBDA * g
    measured = s[1:] / (rho.mean() * G * eps[1:])
    # The middle's strain drifts in the hold (the ends' families relax differently): the law
    # integrated along the measured strains, read the same way.
    same_path = (eps - LAMBDA * back_strain(t, eps))[1:] / eps[1:]
    print(f"relaxation: {len(path) - 1} load steps, pd run {seconds:.1f} s")
    print(f"  rho (lambda_i = 0 run): {rho.mean():.6f}, spread over the steps {rho.max() - rho.min():.2e}")
    print(f"  strain in the middle: {eps[1]:.6e} at the ramp's end, {eps[-1]:.6e} at t = {t[-1]:g}")
    for k in (1, 2, 5, 10, 20, 40, 80):
        print(f"  t = {t[k]:5.2f}: s/(rho G eps) = {measured[k - 1]:.6f}, closed form {closed[k - 1]:.6f} "
              f"({measured[k - 1] - closed[k - 1]:+.2e}), law on the measured strains {same_path[k - 1]:.6f} "
              f"({measured[k - 1] - same_path[k - 1]:+.2e})")
    print(f"  largest |difference|: from the closed form {np.abs(measured - closed).max():.2e}, "
          f"from the law on the measured strains {np.abs(measured - same_path).max():.2e}")
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(t[1:], closed, "-", color="0.4", label="closed form $1 - \\lambda_i g(t)$")
    ax.plot(t[1:], measured, "o", ms=3, label="pd: $s / (\\rho G \\varepsilon)$, middle of the bar")
    ax.axhline(1 - LAMBDA, ls=":", color="0.6")
    ax.set_xlabel("t / $\\tau_b$")
    ax.set_ylabel("deviatoric stress / unrelaxed")
    ax.set_title("Held strain: relaxation ($\\lambda_i$ = 0.6, ramp over 0.05 $\\tau_b$)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, "viscoelastic_relaxation.png"), dpi=110)
    return rho.mean()


def harmonic(pd, out, rho):
    fig, axes = plt.subplots(1, len(OMEGA_TAUS), figsize=(12, 4))
    print("harmonic: omega tau | loss angle: pd, law on the same path, closed form (deg) | "
          "amplitude / (rho G eps0): pd, same path, closed form | pd run s")
    for ax, wt in zip(axes, OMEGA_TAUS):
        omega = wt / TAU
        steps = PER_PERIOD * PERIODS
        path = [math.sin(2 * math.pi * k / PER_PERIOD) for k in range(steps + 1)]
        path[0] = 0.0
        duration = PERIODS * 2 * math.pi / omega
        t, eps, s, seconds = run(pd, out, f"harmonic_{wt:g}", LAMBDA, path, duration)
        eps_phase, eps_amp = phase_and_amplitude(t, eps, omega)
        s_phase, s_amp = phase_and_amplitude(t, s, omega)
        same_path = rho * G * (eps - LAMBDA * back_strain(t, eps))
        c_phase, c_amp = phase_and_amplitude(t, same_path, omega)
        modulus = 1 - LAMBDA / complex(1, wt)
        closed_angle = math.degrees(math.atan2(modulus.imag, modulus.real))
        print(f"  {wt:4.1f} | {math.degrees(s_phase - eps_phase):7.3f} {math.degrees(c_phase - eps_phase):7.3f} "
              f"{closed_angle:7.3f} | {s_amp / (rho * G * eps_amp):.5f} {c_amp / (rho * G * eps_amp):.5f} "
              f"{abs(modulus):.5f} | {seconds:.1f}")
        print(f"       largest |s_pd - s_same_path| / (rho G eps0) over the run: "
              f"{np.abs(s - same_path).max() / (rho * G * eps_amp):.2e}")
        loop = t > t[-1] - (1 + 1e-9) * 2 * math.pi / omega  # the last period, closed
        ax.plot(eps[loop] * 1e3, same_path[loop] * 1e3, "-", color="0.4", label="law on the same path")
        ax.plot(eps[loop] * 1e3, s[loop] * 1e3, "o", ms=3, label="pd, middle of the bar")
        ax.set_title(f"$\\omega\\tau_b$ = {wt:g}: loss angle {math.degrees(s_phase - eps_phase):.2f}° "
                     f"({closed_angle:.2f}°)")
        ax.set_xlabel("$\\varepsilon$ × 1e3")
        ax.set_ylabel("s × 1e3")
    axes[0].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(IMAGES, "viscoelastic_harmonic.png"), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--pd", default="build/bin/pd")
    parser.add_argument("--out", default="out/viscoelastic_bar")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rho = relaxation(args.pd, args.out)
    harmonic(args.pd, args.out, rho)


if __name__ == "__main__":
    sys.exit(main())
