#!/usr/bin/env python3
"""Markdown tables laid out like paper 000's, from a finished `pd study` directory.

  scripts/paper000_tables.py constant OUT   Tables 3, 4, 5 (+ the series the paper calls non-convergent)
  scripts/paper000_tables.py crack OUT      Tables 7, 8 and the cost of every point
  scripts/paper000_tables.py crack_norm OUT the same with sqrt(eq. 48), the relative L2 norm

Each cell is "ours (paper)"; the orders are read from OUT/orders.md (written by pd study,
least squares on log e against log h, eq. 37), the costs from OUT/points.csv."""
import csv
import math
import os
import sys

PROBLEMS = [("uniaxial", "Uniaxial"), ("shear", "Shear"), ("biaxial", "Isotropic")]
F, SILLING, OTERKUS = "correspondence_plane_strain", "silling_plane_strain", "oterkus_plane_strain"


def read_orders(out):
    """Series of OUT/orders.md keyed (problem, law, influence, ratio) when unsmoothed and
    (problem, law, influence, ratio, smoothing influence) when smoothed (eq. 49)."""
    rows = {}
    for line in open(os.path.join(out, "orders.md")):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 11 or cells[0] in ("problem", "---"):
            continue
        problem, law, inf, ratio, smoothed, points, order, fine, min_error, paper, paper_min = cells
        key = (problem, law, inf, float(ratio)) + ((smoothed,) if smoothed != "no" else ())
        rows[key] = {"order": order.strip("*"), "fine": fine, "min_error": min_error, "paper": paper,
                     "paper_min": paper_min}
    return rows


def cell(rows, key, field="order"):
    r = rows.get(key)
    if not r:
        return "not run"
    return "%s (%s)" % (r[field], r["paper"]) if r["paper"] else r[field]


def constant(out):
    rows = read_orders(out)
    print("**Table 3** — deformation gradient (F), δ/h = 1.5: order, ours (paper)\n")
    print("| w(r) | " + " | ".join(n for _, n in PROBLEMS) + " |\n|---|---|---|---|")
    for inf in ("const", "inv", "linear", "quadr", "cubic"):
        print("| %s | %s |" % (inf, " | ".join(cell(rows, (p, F, inf, 1.5)) for p, _ in PROBLEMS)))
    print("\n**Table 4** — F, cubic influence: order, ours (paper)\n")
    print("| δ/h | " + " | ".join(n for _, n in PROBLEMS) + " |\n|---|---|---|---|")
    for ratio in (1.5, 2.0, 2.5, 3.0, 3.5):
        print("| %.1f | %s |" % (ratio, " | ".join(cell(rows, (p, F, "cubic", ratio)) for p, _ in PROBLEMS)))
    print("\n**Table 5** — dilatation laws, cubic influence, on their convergent problems: order, ours (paper)\n")
    print("| δ/h | Silling, isotropic | Oterkus, shear |\n|---|---|---|")
    for ratio in (1.5, 2.0, 2.5, 3.0, 3.5):
        print("| %.1f | %s | %s |" % (ratio, cell(rows, ("biaxial", SILLING, "cubic", ratio)),
                                     cell(rows, ("shear", OTERKUS, "cubic", ratio))))
    print("\n**Not in the paper's tables** — the dilatation laws on the other problems, cubic influence: order over "
          "h = 1 to 0.125 mm / order of the two finest (0.25, 0.125 mm); the paper reports these as not converging\n")
    print("| δ/h | Silling, uniaxial | Silling, shear | Oterkus, uniaxial | Oterkus, isotropic |\n|---|---|---|---|---|")
    for ratio in (1.5, 2.0, 2.5, 3.0, 3.5):
        cells = []
        for p, law in (("uniaxial", SILLING), ("shear", SILLING), ("uniaxial", OTERKUS), ("biaxial", OTERKUS)):
            r = rows.get((p, law, "cubic", ratio))
            cells.append("%s / %s" % (r["order"], r["fine"]) if r else "not run")
        print("| %.1f | %s |" % (ratio, " | ".join(cells)))
    converging_frontier(out)


def converging_frontier(out):
    """The raw frontier rewards lucky cancellations (a non-converging series whose probe
    error crosses zero at one h); this one keeps the series that converge at first order
    (order and finest-pair order above 0.8) and finds the non-dominated points among them."""
    rows = read_orders(out)
    ok = {k for k, r in rows.items() if r["fine"] and float(r["order"]) > 0.8 and float(r["fine"]) > 0.8}
    pts = [r for r in csv.DictReader(open(os.path.join(out, "points.csv")))
           if r["converged"] == "1" and (r["problem"], r["law"], r["influence"], float(r["ratio"])) in ok]
    print("\n**Error/time frontier among the converging series** (non-dominated in wall time and error)\n")
    print("| problem | law | influence | δ/h | n | error (mm) | seconds |\n|---|---|---|---|---|---|---|")
    for problem in dict.fromkeys(r["problem"] for r in pts):
        mine = sorted((r for r in pts if r["problem"] == problem), key=lambda r: (float(r["total_s"]), float(r["error"])))
        best = float("inf")
        for r in mine:
            if float(r["error"]) < best:
                best = float(r["error"])
                print("| %s | %s | %s | %s | %s | %.3e | %.3f |" % (problem, r["law"].replace("_plane_strain", ""),
                      r["influence"], r["ratio"], r["count"], best, float(r["total_s"])))


# Paper 000 Table 7 (F, NP = 200: unsmoothed, then smoothed with const, linear, cubic) and
# Table 8 (order, minimum error; "F, smoothed" entered as the linear smoothing, its Fig. 14).
PAPER7 = {1.5: (0.2105, 0.0836, 0.0708, 0.1810), 2.0: (0.3022, 0.0868, 0.0429, 0.1697),
          2.5: (0.5409, 0.1080, 0.0670, 0.1628), 3.0: (1.0375, 0.1604, 0.1004, 0.1965),
          3.5: (2.6741, 0.2684, 0.1452, 0.3302)}
PAPER8 = {(SILLING, 3.5): (1.8022, 0.022), (OTERKUS, 3.5): (0.4622, 0.057), (F, 1.5): (1.0200, 0.117),
          (F, 1.5, "linear"): (1.0836, 0.041)}


def crack(out, norm=False):
    """Tables 7 and 8 from a crack study. norm=True reports sqrt(eq. 48) -- the relative L2
    norm of the displacement error -- and its order (half that of eq. 48)."""
    rows = read_orders(out)
    pts = list(csv.DictReader(open(os.path.join(out, "points.csv"))))
    problem = pts[0]["problem"]
    measure = (lambda e: math.sqrt(e)) if norm else (lambda e: e)
    slope = 0.5 if norm else 1.0
    name = "√(eq. 48), the relative L2 norm of the displacement error" if norm else "field error eq. (48)"
    columns = ("error", "error_smoothed_const", "error_smoothed_linear", "error_smoothed_cubic")
    print("**Table 7** — F, cubic influence, NP = 200: %s, unsmoothed and smoothed (eq. 49) "
          "with three influence functions, ours (paper)\n" % name)
    print("| δ/h | unsmoothed | const | linear | cubic |\n|---|---|---|---|---|")
    for ratio, paper in PAPER7.items():
        p = [r for r in pts if r["law"] == F and float(r["ratio"]) == ratio and r["count"] == "200"]
        values = []
        for column, value in zip(columns, paper):
            ours = "not run" if not p else "failed" if p[0]["converged"] != "1" else (
                "%.4g" % measure(float(p[0][column])) if p[0].get(column) else "not run")
            values.append("%s (%.4f)" % (ours, value))
        print("| %.1f | %s |" % (ratio, " | ".join(values)))
    print("\n**Table 8** — order of the %s (all resolutions / the 3 finest) and the smallest, "
          "ours (paper)\n" % name)
    print("| method | order | order, 3 finest | min. error |\n|---|---|---|---|")
    for label, key in (("Silling, δ/h 3.5", (SILLING, 3.5)), ("Oterkus, δ/h 3.5", (OTERKUS, 3.5)),
                       ("F unsmoothed, δ/h 1.5", (F, 1.5)), ("F smoothed (linear), δ/h 1.5", (F, 1.5, "linear")),
                       ("F smoothed (const), δ/h 1.5", (F, 1.5, "const")),
                       ("F smoothed (cubic), δ/h 1.5", (F, 1.5, "cubic")),
                       ("Silling, δ/h 1.5", (SILLING, 1.5)), ("Oterkus, δ/h 1.5", (OTERKUS, 1.5))):
        r = rows.get((problem, key[0], "cubic") + key[1:])
        if not r:
            continue
        paper = PAPER8.get(key)
        fine = "%.3f" % (slope * float(r["fine"])) if r["fine"] else ""
        print("| %s | %.3f%s | %s | %.3g%%%s |" % (
            label, slope * float(r["order"]), " (%.4f)" % paper[0] if paper else "", fine,
            100 * measure(float(r["min_error"])), " (%.1f%%)" % (100 * paper[1]) if paper else ""))
    print("\n**Cost of every point** — solver that reached it, Newton and Krylov iterations, nonzeros (of the "
          "tangent; matrix-free: of the short-horizon preconditioner), wall time, peak resident memory\n")
    print("| law | δ/h | n | particles | error | solver | Newton | Krylov | nonzeros | seconds | peak MiB |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(pts, key=lambda r: (r["law"], float(r["ratio"]), int(r["count"]))):
        ok = r["converged"] == "1"
        print("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %.1f | %s |" % (
            r["law"].replace("_plane_strain", ""), r["ratio"], r["count"], r["particles"],
            "%.3e" % float(r["error"]) if ok else "failed", r["solver"] if ok else r["failure"][:60], r["newton_iterations"],
            r["krylov_iterations"], r["nonzeros"], float(r["total_s"]),
            "%.0f" % float(r["peak_rss_mb"]) if float(r["peak_rss_mb"]) >= 0 else ""))


if __name__ == "__main__":
    {"constant": constant, "crack": crack, "crack_norm": lambda out: crack(out, norm=True)}[sys.argv[1]](sys.argv[2])
