#!/usr/bin/python3
"""Plots of a study directory (pd study): error against h with fitted orders (smoothed
errors, eq. 49, dashed where recorded), and error against wall time (the accuracy/cost frontier, non-dominated points starred).

A problem with few series (the crack study) gets one line plot of each kind. A sweep with
many series (the constant-strain study: 75 per problem) is faceted like paper 000's Figs.
8-10 instead -- one figure per law, rows = influence functions, columns = problems, one
line per delta/h -- and one cost figure with a panel per problem. PNGs stay small (dpi 80).
Legends sit beside the axes (line plots) or where they cover the fewest points (facets).
The error axis is the study's error: the relative field error of paper 000 eq. (48),
sum|u - u_ref|^2 / sum|u_ref|^2 (no unit), for scenes with a reference field, else the
first probe's |u - u_ref| (a length); h is in the scenes' length unit (--length-unit).

usage: scripts/plot_study.py STUDY_OUT_DIR [--length-unit mm]   (runs with /usr/bin/python3,
which has Debian's python3-matplotlib; `pd study` calls it)"""
import csv
import math
import os
import sys
from collections import defaultdict

plt = None  # matplotlib.pyplot, imported once the arguments are known to be good
NullFormatter = None

FEW_SERIES = 12
LENGTH = "mm"  # --length-unit
ERROR_LABEL = "error (eq. 48, relative)"
SMOOTHED_STYLE = {"const": ":", "linear": "--", "cubic": "-."}


def order(xs, es):
    lx, ly = [math.log(v) for v in xs], [math.log(v) for v in es]
    n = len(lx)
    den = n * sum(a * a for a in lx) - sum(lx) ** 2
    return (n * sum(a * b for a, b in zip(lx, ly)) - sum(lx) * sum(ly)) / den if n >= 2 and den else float("nan")


def short(law):
    return law.replace("_plane_strain", "").replace("correspondence", "F")


def series_of(rows):
    series = defaultdict(list)
    for r in rows:
        series[(r["law"], r["influence"], float(r["ratio"]))].append(r)
    for s in series.values():
        s.sort(key=lambda r: float(r["h"]))
    return series


def line_plots(out, problem, pts):
    series = series_of(pts)
    for kind in ("convergence", "cost"):
        fig, ax = plt.subplots(figsize=(9.5, 4.5))
        for (law, inf, ratio), s in sorted(series.items()):
            e = [float(r["error"]) for r in s]
            x = [float(r["h"]) for r in s] if kind == "convergence" else [float(r["total_s"]) for r in s]
            label = "%s %s %.1f" % (short(law), inf, ratio)
            if kind == "convergence" and len(s) >= 2:
                label += " (order %.2f)" % order(x, e)
            (line,) = ax.loglog(x, e, marker="o", ms=3, lw=1, label=label)
            # Smoothed errors (eq. 49), where the study recorded them: dashed, in the series' colour.
            for column in [c for c in s[0] if c.startswith("error_smoothed_")] if kind == "convergence" else []:
                xs = [(float(r["h"]), float(r[column])) for r in s if r.get(column)]
                if len(xs) >= 2:
                    label = "%s %s %.1f, smoothed %s (order %.2f)" % (short(law), inf, ratio, column[15:],
                                                                       order([a for a, _ in xs], [b for _, b in xs]))
                    ax.loglog([a for a, _ in xs], [b for _, b in xs], ls=SMOOTHED_STYLE.get(column[15:], "--"), marker="x", ms=3, lw=0.8,
                              label=label, color=line.get_color(), alpha=0.8)
            if kind == "cost":
                nd = [(float(r["total_s"]), float(r["error"])) for r in s if r["non_dominated"] == "1"]
                if nd:
                    ax.loglog([a for a, _ in nd], [b for _, b in nd], ls="none", marker="*", ms=10, color=line.get_color())
        ax.set_xlabel("h (%s)" % LENGTH if kind == "convergence" else "wall time (s): setup + assembly + solve")
        ax.set_ylabel(ERROR_LABEL)
        ax.set_title("%s: %s" % (problem, "error against h" if kind == "convergence" else "error against time (stars: non-dominated)"))
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)  # beside the data, not on it
        fig.tight_layout()
        fig.savefig(os.path.join(out, "%s_%s.png" % (problem, kind)), dpi=80)
        plt.close(fig)


def faceted_plots(out, rows, problems):
    laws = sorted({r["law"] for r in rows})
    influences = list(dict.fromkeys(r["influence"] for r in rows))
    for law in laws:
        fig, axes = plt.subplots(len(influences), len(problems), figsize=(3.2 * len(problems), 2.0 * len(influences)),
                                 sharex=True, squeeze=False)
        for i, inf in enumerate(influences):
            for j, problem in enumerate(problems):
                ax = axes[i][j]
                pts = [r for r in rows if r["law"] == law and r["influence"] == inf and r["problem"] == problem]
                for (_, _, ratio), s in sorted(series_of(pts).items()):
                    x, e = [float(r["h"]) for r in s], [float(r["error"]) for r in s]
                    ax.loglog(x, e, marker="o", ms=2, lw=0.8, label="%.1f: %.2f" % (ratio, order(x, e)))
                ax.grid(True, which="both", lw=0.3)
                ax.tick_params(labelsize=6)
                ax.xaxis.set_minor_formatter(NullFormatter())  # h spans one decade: minor labels overlap
                ax.legend(fontsize=5, title="δ/h: order", title_fontsize=5, loc="best")
                if i == 0:
                    ax.set_title(problem, fontsize=8)
                if j == 0:
                    ax.set_ylabel("%s\n%s" % (inf, ERROR_LABEL), fontsize=7)
                if i == len(influences) - 1:
                    ax.set_xlabel("h (%s)" % LENGTH, fontsize=7)
        fig.suptitle("%s: error against h (cf. paper 000 Figs. 8-10)" % short(law), fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "convergence_%s.png" % short(law)), dpi=80)
        plt.close(fig)
    fig, axes = plt.subplots(1, len(problems), figsize=(4.2 * len(problems), 3.8), squeeze=False)
    colours = dict(zip(laws, plt.rcParams["axes.prop_cycle"].by_key()["color"]))
    for j, problem in enumerate(problems):
        ax = axes[0][j]
        for law in laws:
            pts = [r for r in rows if r["problem"] == problem and r["law"] == law]
            ax.loglog([float(r["total_s"]) for r in pts], [float(r["error"]) for r in pts], ls="none", marker=".", ms=3,
                      alpha=0.5, color=colours[law], label=short(law))
            nd = sorted((float(r["total_s"]), float(r["error"]), r) for r in pts if r["non_dominated"] == "1")
            if nd:
                ax.loglog([a for a, _, _ in nd], [b for _, b, _ in nd], ls="none", marker="*", ms=9, color=colours[law])
        front = sorted((float(r["total_s"]), float(r["error"])) for r in rows if r["problem"] == problem and r["non_dominated"] == "1")
        ax.loglog([a for a, _ in front], [b for _, b in front], lw=0.8, color="k")
        ax.set_title("%s (stars: non-dominated)" % problem, fontsize=8)
        ax.set_xlabel("wall time (s)", fontsize=7)
        ax.grid(True, which="both", lw=0.3)
        ax.tick_params(labelsize=6)
        if j == 0:
            ax.set_ylabel(ERROR_LABEL, fontsize=7)
            ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "cost.png"), dpi=80)
    plt.close(fig)


def main(argv):
    global LENGTH
    usage = "usage: scripts/plot_study.py STUDY_OUT_DIR [--length-unit mm]"
    if "--length-unit" in argv:
        i = argv.index("--length-unit")
        if i + 1 >= len(argv):
            sys.exit(usage)
        LENGTH = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    if len(argv) != 1 or argv[0] in ("-h", "--help"):
        sys.exit(usage)
    out = argv[0]
    path = os.path.join(out, "points.csv")
    try:
        with open(path, newline="") as f:
            all_rows = list(csv.DictReader(f))
    except OSError as e:
        sys.exit("plot_study.py: cannot read %s: %s (the output directory of `pd study`)" % (path, e.strerror))
    missing = {"problem", "law", "influence", "ratio", "h", "error", "converged", "total_s", "non_dominated"} - set(all_rows[0] if all_rows else [])
    if missing:
        sys.exit("plot_study.py: %s lacks the column(s) %s" % (path, ", ".join(sorted(missing))))
    global plt, NullFormatter
    try:
        import matplotlib
    except ImportError:
        sys.exit("plot_study.py: matplotlib is missing: run it with /usr/bin/python3 (apt-get install python3-matplotlib)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter
    rows = [r for r in all_rows if r["converged"] == "1" and float(r["error"]) > 0]
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    if max((len(series_of([r for r in rows if r["problem"] == p])) for p in problems), default=0) <= FEW_SERIES:
        for problem in problems:
            line_plots(out, problem, [r for r in rows if r["problem"] == problem])
    else:
        faceted_plots(out, rows, problems)


if __name__ == "__main__":
    main(sys.argv[1:])
