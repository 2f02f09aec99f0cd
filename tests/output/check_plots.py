#!/usr/bin/python3
"""scripts/plot_*.py: a usage message (never a traceback) for missing or bad arguments
and files, and a picture from good input. The input is made here: a result.csv with a
damaged band, and a study's points.csv with two series.

usage: check_plots.py SOURCE_DIR WORK_DIR
"""
import os
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


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[-1])
    source, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    damage = os.path.join(source, "scripts", "plot_damage.py")
    study = os.path.join(source, "scripts", "plot_study.py")
    result = os.path.join(work, "result.csv")
    with open(result, "w") as f:
        f.write("id,x,y,u_x,u_y,damage\n")
        for i in range(400):
            x, y = (i % 20) / 20, (i // 20) / 20
            f.write(f"{i},{x},{y},0,{(y - 0.5) * 1e-3},{0.4 if abs(y - 0.5) < 0.06 and x < 0.5 else 0}\n")
    no_damage = os.path.join(work, "no_damage.csv")
    with open(no_damage, "w") as f:
        f.write("id,x,y,u_x,u_y\n0,0,0,0,0\n")
    expect_refusal(damage, [], "usage")
    expect_refusal(damage, [os.path.join(work, "missing.csv"), "p.png"], "cannot read")
    expect_refusal(damage, [no_damage, "p.png"], "no column damage")
    expect_picture(damage, [result, os.path.join(work, "damage.png"), "--title", "band"], os.path.join(work, "damage.png"))

    points = os.path.join(work, "study")
    os.makedirs(points, exist_ok=True)
    with open(os.path.join(points, "points.csv"), "w") as f:
        f.write("problem,law,influence,ratio,h,converged,error,total_s,non_dominated\n")
        for law in ("silling_plane_strain", "lps_plane_strain"):
            for k, h in enumerate((0.5, 0.25, 0.125)):
                f.write(f"shear,{law},cubic,3,{h},1,{1e-3 * h ** 2 * (2 if law[0] == 'l' else 1)},{0.1 * 4 ** k},{int(k == 2)}\n")
    expect_refusal(study, [], "usage")
    expect_refusal(study, [os.path.join(work, "nowhere")], "cannot read")
    expect_picture(study, [points], os.path.join(points, "shear_convergence.png"))
    if failures:
        sys.exit("\n".join(failures))
    print("plot scripts: usage messages and pictures as expected")


if __name__ == "__main__":
    main()
