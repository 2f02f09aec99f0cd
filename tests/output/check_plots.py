#!/usr/bin/python3
"""scripts/plot_*.py: a usage message (never a traceback) for missing or bad arguments
and files, and a picture from good input that shows that input. The input is made here: a
result.csv with a damaged band, and a study's points.csv with two series. The content check
runs each script in this process with Figure.savefig wrapped, and compares the saved figure's
artists with the CSV: the damaged scatter holds exactly the damaged particles (positions and
damage values), the undamaged one the rest, and each convergence line one law's (h, error).

usage: check_plots.py SOURCE_DIR WORK_DIR
"""
import os
import runpy
import subprocess
import sys

failures = []


def run(script, *args):
    r = subprocess.run(["/usr/bin/python3", script, *args], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def expect_refusal(script, args, words):
    code, text = run(script, *args)
    name = os.path.basename(script)
    if code == 0 or "Traceback" in text or words not in text:
        failures.append(f"{name} {' '.join(args)}: exit {code}, wanted a message with '{words}':\n{text}")


def expect_picture(script, args, picture):
    if os.path.exists(picture):
        os.remove(picture)
    code, text = run(script, *args)
    if code != 0 or not os.path.exists(picture) or os.path.getsize(picture) < 1000:
        failures.append(f"{os.path.basename(script)} {' '.join(args)}: exit {code}, no picture {picture}:\n{text}")


def saved_figures(script, args):
    """Runs `script` with `args` here and returns {picture path: the Figure saved there}."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.figure
    saved, original = {}, matplotlib.figure.Figure.savefig

    def record(fig, path, *a, **k):
        saved[str(path)] = fig
        return original(fig, path, *a, **k)

    matplotlib.figure.Figure.savefig = record
    argv = sys.argv
    try:
        sys.argv = [script, *args]
        runpy.run_path(script, run_name="__main__")
    finally:
        sys.argv, matplotlib.figure.Figure.savefig = argv, original
    return saved


def check(condition, message):
    if not condition:
        failures.append(message)


def check_damage_content(script, result, picture, rows):
    fig = saved_figures(script, [result, picture, "--magnification", "0"]).get(picture)
    if fig is None:
        return failures.append(f"plot_damage.py saved no figure at {picture}")
    ax = fig.axes[0]
    scatters = [c for c in ax.collections if len(c.get_offsets())]
    check(len(scatters) == 2, f"plot_damage.py: {len(scatters)} scatters, wanted the undamaged and the damaged")
    if len(scatters) != 2:
        return
    damaged = sorted((x, y, d) for x, y, d in rows if d > 0)
    intact = sorted((x, y) for x, y, d in rows if d == 0)
    shown = sorted((float(x), float(y), float(d)) for (x, y), d in zip(scatters[1].get_offsets(), scatters[1].get_array()))
    check(shown == damaged, f"plot_damage.py: the damaged scatter shows {len(shown)} points, the CSV has {len(damaged)} damaged")
    grey = sorted((float(x), float(y)) for x, y in scatters[0].get_offsets())
    check(grey == intact, f"plot_damage.py: the undamaged scatter shows {len(grey)} points, the CSV has {len(intact)}")
    lo, hi = scatters[1].get_clim()
    check((lo, hi) == (0, max(d for _, _, d in damaged)), f"plot_damage.py: colour range {lo}..{hi}")


def check_study_content(script, points_dir, series):
    picture = os.path.join(points_dir, "shear_convergence.png")
    fig = saved_figures(script, [points_dir]).get(picture)
    if fig is None:
        return failures.append(f"plot_study.py saved no figure at {picture}")
    lines = {tuple(zip(map(float, l.get_xdata()), map(float, l.get_ydata()))) for l in fig.axes[0].get_lines()}
    for law, points in series.items():
        check(tuple(sorted(points)) in lines, f"plot_study.py: no line of {law}'s (h, error) {points}; lines: {lines}")
    check(len(lines) == len(series), f"plot_study.py: {len(lines)} lines for {len(series)} series")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[-1])
    source, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    damage = os.path.join(source, "scripts", "plot_damage.py")
    study = os.path.join(source, "scripts", "plot_study.py")
    result = os.path.join(work, "result.csv")
    rows = []
    with open(result, "w") as f:
        f.write("id,x,y,u_x,u_y,damage\n")
        for i in range(400):
            x, y = (i % 20) / 20, (i // 20) / 20
            d = (0.4 if x < 0.25 else 0.2) if abs(y - 0.5) < 0.06 and x < 0.5 else 0
            rows.append((x, y, d))
            f.write(f"{i},{x},{y},0,{(y - 0.5) * 1e-3},{d}\n")
    no_damage = os.path.join(work, "no_damage.csv")
    with open(no_damage, "w") as f:
        f.write("id,x,y,u_x,u_y\n0,0,0,0,0\n")
    expect_refusal(damage, [], "usage")
    expect_refusal(damage, [os.path.join(work, "missing.csv"), "p.png"], "cannot read")
    expect_refusal(damage, [no_damage, "p.png"], "no column damage")
    expect_picture(damage, [result, os.path.join(work, "damage.png"), "--title", "band"], os.path.join(work, "damage.png"))
    check_damage_content(damage, result, os.path.join(work, "damage_content.png"), rows)

    points = os.path.join(work, "study")
    os.makedirs(points, exist_ok=True)
    series = {}
    with open(os.path.join(points, "points.csv"), "w") as f:
        f.write("problem,law,influence,ratio,h,converged,error,total_s,non_dominated\n")
        for law in ("silling_plane_strain", "lps_plane_strain"):
            for k, h in enumerate((0.5, 0.25, 0.125)):
                error = 1e-3 * h ** 2 * (2 if law[0] == 'l' else 1)
                series.setdefault(law, []).append((h, error))
                f.write(f"shear,{law},cubic,3,{h},1,{error},{0.1 * 4 ** k},{int(k == 2)}\n")
    expect_refusal(study, [], "usage")
    expect_refusal(study, [os.path.join(work, "nowhere")], "cannot read")
    expect_picture(study, [points], os.path.join(points, "shear_convergence.png"))
    check_study_content(study, points, series)
    if failures:
        sys.exit("\n".join(failures))
    print("plot scripts: usage messages and pictures as expected")


if __name__ == "__main__":
    main()
