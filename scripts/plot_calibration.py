#!/usr/bin/python3
"""Plots the calibration study (bench/calibration_study.cpp, docs/calibration.md).

Usage: /usr/bin/python3 scripts/plot_calibration.py [DIR] [IMAGE]
Reads DIR/fits.csv (default out/calibration_study) and writes IMAGE (default
docs/images/calibration_noise.png): each fitted E and nu against the noise level, with its
one-standard-error bar, beside the truth; and prints the share of fits within 2 standard
errors of it. Needs numpy and matplotlib (Debian's python3-matplotlib)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TRUTH = {"E": 170.0, "nu": 0.22}


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else "out/calibration_study"
    image = sys.argv[2] if len(sys.argv) > 2 else "docs/images/calibration_noise.png"
    with open(directory + "/fits.csv", newline="") as f:
        rows = [r for r in csv.DictReader(f) if float(r["level"]) > 0]
    if not rows:
        sys.exit(f"{directory}/fits.csv: no noisy fits")
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key in zip(axes, ("E", "nu")):
        within = 0
        for r in rows:
            level, value, std = 100 * float(r["level"]), float(r[key]), float(r[key + "_std"])
            offset = 0.04 * (int(r["seed"]) - 4.5) * level  # spread the seeds of one level
            ax.errorbar(level + offset, value, yerr=std, fmt="o", ms=3, color="tab:blue", capsize=2)
            within += abs(value - TRUTH[key]) <= 2 * std
        ax.axhline(TRUTH[key], color="k", lw=1, label=f"truth {key} = {TRUTH[key]}")
        ax.set_xscale("log")
        ax.set_xlabel("noise, % of max |u|")
        ax.set_ylabel(f"fitted {key} (bar: one standard error)")
        ax.legend()
        print(f"{key}: {within} of {len(rows)} noisy fits within 2 standard errors of the truth")
    fig.suptitle("Plate with a hole, plane stress: (E, nu) fitted to noisy synthetic displacement fields")
    fig.tight_layout()
    fig.savefig(image, dpi=110)
    print(f"wrote {image}")


if __name__ == "__main__":
    main()
