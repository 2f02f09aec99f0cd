#!/usr/bin/env python3
"""Solves of the pressurised crack (scenes/crack.yaml, Silling plane strain, cubic influence)
on n x n grids with each linear-solver path, one `pd run` process per point, so each peak
resident set belongs to one solve alone (os.wait4 gives the child's own ru_maxrss).

Writes JSON lines to --out: grid, delta/h, solver, wall seconds of setup / assembly /
linear solve / total, Newton and Krylov iterations, peak memory, field error, or why the
point was skipped. A point is skipped (not run) when the same solver's previous, smaller
grid scaled linearly in particles projects past --max-seconds or --max-memory-gb: time and
memory grow at least linearly with the particle count (a direct factor faster), so the
larger point cannot fit, and on a shared machine an out-of-memory kill would hit others.

Usage: bench/solve_bench.py --pd build/bin/pd --scene scenes/crack.yaml --grids 100 200 400
       --ratio 3.5 --out build/bench/solves.jsonl [--max-seconds 600]
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

# solver label -> the scene's solver section
SOLVERS = {
    "cholmod": "{linear: cholmod}",
    "cg+ic (assembled)": "{linear: cg, preconditioner: ic}",
    "matrix-free + short horizon": "{linear: matrix_free, preconditioner: short_horizon}",
    "matrix-free + jacobi": "{linear: matrix_free, preconditioner: diagonal}",
    "auto": "{linear: auto}",
}


def scene_text(base, count, ratio, solver, out_dir):
    text = open(base).read()
    text = re.sub(r"(\n\s*count:\s*)\d+", r"\g<1>%d" % count, text)
    text = re.sub(r"horizon:\s*\{ratio:\s*[0-9.]+\}", "horizon: {ratio: %g}" % ratio, text)
    text = re.sub(r"\noutput:.*", "", text)
    text = re.sub(r"\nsolver:.*", "", text)
    return text + "\noutput: {directory: %s, vtu: false, csv: false}\nsolver: %s\n" % (out_dir, SOLVERS[solver])


def run_point(pd, base, count, ratio, solver, workdir):
    out_dir = os.path.join(workdir, "out")
    path = os.path.join(workdir, "scene.yaml")
    with open(path, "w") as f:
        f.write(scene_text(base, count, ratio, solver, out_dir))
    load_before = os.getloadavg()[0]
    start = time.monotonic()
    proc = subprocess.Popen([pd, "run", path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    log = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    row = {"grid": count, "ratio": ratio, "solver": solver, "wall_seconds": wall,
           "peak_mb": usage.ru_maxrss / 1024.0, "exit": os.waitstatus_to_exitcode(status),
           # the 1-minute load average before and after: the machine is shared, and a
           # point run beside other work can take several times longer
           "load": [load_before, os.getloadavg()[0]]}
    summary = os.path.join(out_dir, "summary.json")
    if row["exit"] != 0 or not os.path.exists(summary):
        row["error"] = log.strip().splitlines()[-1] if log.strip() else "no output"
        return row
    s = json.load(open(summary))
    its = s["newton"]["iterations"]
    row.update({
        "particles": s.get("particles"), "unknowns": s.get("unknowns"), "nonzeros": s.get("nonzeros"),
        "method": s["linear_solver"]["method"], "path": s["linear_solver"].get("path", ""),
        "newton_iterations": max(0, len(its) - 1), "krylov_iterations": sum(i["linear_iterations"] for i in its),
        "setup_seconds": s["seconds"]["setup"], "assembly_seconds": s["seconds"]["assembly"],
        "linear_seconds": s["seconds"]["linear_solve"], "solve_seconds": s["seconds"]["solve"],
        "field_error": s.get("field_error_eq48"), "converged": s["newton"]["converged"]})
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pd", required=True)
    ap.add_argument("--scene", required=True)
    ap.add_argument("--grids", nargs="+", type=int, required=True)
    ap.add_argument("--ratio", type=float, default=3.5)
    ap.add_argument("--solvers", nargs="+", default=[k for k in SOLVERS if k != "auto"])
    ap.add_argument("--max-seconds", type=float, default=600)
    ap.add_argument("--max-memory-gb", type=float, default=10)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    with open(a.out, "w") as out:
        for solver in a.solvers:
            previous = None  # (grid, seconds, peak MB) of this solver's last point
            for n in sorted(a.grids):
                scale = (n / previous[0]) ** 2 if previous else 0
                if previous and previous[1] * scale > a.max_seconds:
                    row = {"grid": n, "ratio": a.ratio, "solver": solver,
                           "skipped": "%d² took %.0f s; at least %.0f s projected (linear in particles), over %.0f s" % (
                               previous[0], previous[1], previous[1] * scale, a.max_seconds)}
                elif previous and previous[2] * scale > a.max_memory_gb * 1024:
                    row = {"grid": n, "ratio": a.ratio, "solver": solver,
                           "skipped": "%d² peaked at %.1f GB; at least %.1f GB projected (linear in particles), over %.0f GB" % (
                               previous[0], previous[2] / 1024, previous[2] * scale / 1024, a.max_memory_gb)}
                else:
                    print("solve_bench: %d², delta/h %g, %s ..." % (n, a.ratio, solver), file=sys.stderr, flush=True)
                    with tempfile.TemporaryDirectory() as work:
                        row = run_point(a.pd, a.scene, n, a.ratio, solver, work)
                    previous = (n, row["wall_seconds"], row["peak_mb"])
                out.write(json.dumps(row) + "\n")
                out.flush()


if __name__ == "__main__":
    main()
