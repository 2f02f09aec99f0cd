#!/usr/bin/python3
"""Plots the damage field of a run's result.csv (the README picture).

Particles are drawn at their deformed positions, the displacement magnified so the
opening shows (the factor is written on the plot), coloured by damage (the broken
fraction of each family) over the full range of the run, 0 to its largest value;
undamaged particles are drawn in grey so they stay visible against the white page.
The legend and the colour bar sit outside the axes, off the data.

Runs with /usr/bin/python3, which has Debian's python3-matplotlib (scripts/install_deps.sh)."""
import argparse
import csv
import sys


def parse_args(argv):
    p = argparse.ArgumentParser(prog="plot_damage.py", description=__doc__.splitlines()[0])
    p.add_argument("result_csv", help="OUT_DIR/result.csv of `pd run`")
    p.add_argument("picture", help="the PNG to write")
    p.add_argument("--title", default="")
    p.add_argument("--length-unit", default="mm", help="the scene's length unit, for the axes (default: mm)")
    p.add_argument("--magnification", type=float, default=None,
                   help="displacement factor (default: the displacement peak drawn as 2 %% of the body, at most 20)")
    return p.parse_args(argv)


def read_rows(path):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit(f"plot_damage.py: cannot read {path}: {e.strerror}")
    if not rows:
        sys.exit(f"plot_damage.py: {path} has no particle rows")
    missing = [c for c in ("x", "y", "u_x", "u_y", "damage") if c not in rows[0]]
    if missing:
        sys.exit(f"plot_damage.py: {path} has no column {', '.join(missing)} (a result.csv of a run with damage is needed)")
    try:
        return {c: [float(r[c]) for r in rows] for c in ("x", "y", "u_x", "u_y", "damage")}
    except ValueError as e:
        sys.exit(f"plot_damage.py: {path}: {e}")


def main(argv):
    args = parse_args(argv)
    data = read_rows(args.result_csv)
    try:
        import matplotlib
    except ImportError:
        sys.exit("plot_damage.py: matplotlib is missing: run it with /usr/bin/python3 (apt-get install python3-matplotlib)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x, y, ux, uy, d = data["x"], data["y"], data["u_x"], data["u_y"], data["damage"]
    span = max(max(x) - min(x), max(y) - min(y)) or 1.0
    umax = max(max(abs(v) for v in ux), max(abs(v) for v in uy))
    scale = args.magnification if args.magnification is not None else (min(0.02 * span / umax, 20.0) if umax > 0 else 1.0)
    X = [a + scale * b for a, b in zip(x, ux)]
    Y = [a + scale * b for a, b in zip(y, uy)]
    size = 3.0 if len(x) < 5000 else 1.2
    dmax = max(d)
    fig, ax = plt.subplots(figsize=(5.6, 4.0), dpi=90)
    intact = [i for i, v in enumerate(d) if v == 0]
    damaged = [i for i, v in enumerate(d) if v > 0]
    ax.scatter([X[i] for i in intact], [Y[i] for i in intact], s=size, color="0.75", linewidths=0,
               label=f"undamaged ({len(intact)})")
    if damaged:
        sc = ax.scatter([X[i] for i in damaged], [Y[i] for i in damaged], c=[d[i] for i in damaged], s=size, cmap="plasma",
                        vmin=0, vmax=dmax, linewidths=0)
        fig.colorbar(sc, ax=ax, label=f"damage (broken fraction), 0 to max {dmax:.3g}", shrink=0.8, pad=0.02)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x ({args.length_unit})")
    ax.set_ylabel(f"y ({args.length_unit})")
    ax.set_title((args.title + "\n" if args.title else "") + f"deformed shape: displacement x {scale:.3g}", fontsize=9)
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, -0.14), fontsize=7, frameon=False, markerscale=3)
    fig.tight_layout()
    fig.savefig(args.picture, dpi=90)


if __name__ == "__main__":
    main(sys.argv[1:])
