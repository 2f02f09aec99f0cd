#!/usr/bin/python3
"""The pressurised penny crack (scenes/penny_crack.yaml) against Sneddon's opening
    w(r) = 8 (1 - nu^2) p a sqrt(1 - r^2/a^2) / (pi E)
at several lattice counts and cube sides. For each: the opening of every pair of
particles facing each other across the crack plane (z = +-h/2) inside r < a, its ratio
to Sneddon's at the centre pair, and the rms relative error over r < 0.8 a (the tip zone,
one horizon wide, is left out: there the peridynamic crack is blunt by construction).

Usage: penny_crack.py --pd build/bin/pd [--counts 16 24 32] [--side 6] [--work DIR]
       [--check]   (exit 1 when a count's rms error exceeds h / (2a))
The bound of --check: on a lattice the crack's edge is known to within half a spacing
(a bond is cut or not as a whole), and the opening scales with the radius, w(0) ~ a, so
an error of h / (2a) in the opening is the discretisation's own; a wrong modulus, load
scale or pressure 25% off fails it at the counts of CI (20) and of the scene (24).
Prints one table row per count; docs/scaling.md ("3D scenes") holds the measured table."""
import argparse, csv, math, os, re, resource, subprocess, sys, time

E, NU, P, A = 60.0, 0.25, 0.1, 1.0


def scene_text(source, count, side):
    """The scene at `count` particles along a cube of side `side` a: the box and the three
    support boxes (each holding the one corner particle at this spacing) follow."""
    h = side / count
    half = side / 2
    c = -half + 0.6 * h  # the corner particle's centre is at -half + h/2
    text = open(source).read()
    text = re.sub(r"count: \d+", f"count: {count}", text, count=1)
    text = re.sub(r"  box: \{min: \[[^\]]*\], max: \[[^\]]*\]\}", f"  box: {{min: [{-half}, {-half}, {-half}], max: [{half}, {half}, {half}]}}", text, count=1)
    supports = [f"[{-half}, {-half}, {-half}], max: [{c}, {c}, {c}]",
                f"[{-c}, {-half}, {-half}], max: [{half}, {c}, {c}]",
                f"[{-half}, {-c}, {-half}], max: [{c}, {half}, {c}]"]
    old = re.findall(r"region: \{box: \{min: (\[[^\]]*\], max: \[[^\]]*\])\}\}", text)
    assert len(old) == 3, old
    for o, s in zip(old, supports):
        text = text.replace(o, s)
    return text


def opening(result_csv):
    rows = list(csv.DictReader(open(result_csv)))
    h = 2 * min(abs(float(r["z"])) for r in rows)
    face = lambda sign: {(round(float(r["x"]), 9), round(float(r["y"]), 9)): float(r["u_z"])
                         for r in rows if abs(float(r["z"]) - sign * h / 2) < 1e-9 * max(1, h)}
    top, bottom = face(1), face(-1)
    w0 = 8 * (1 - NU ** 2) * P * A / (math.pi * E)
    pts = sorted((math.hypot(*k), top[k] - bottom[k], w0 * math.sqrt(1 - (math.hypot(*k) / A) ** 2))
                 for k in top if math.hypot(*k) < A)
    inner = [(w, s) for r, w, s in pts if r < 0.8 * A]
    rms = math.sqrt(sum((w - s) ** 2 for w, s in inner) / sum(s * s for w, s in inner))
    return len(rows), h, pts[0][1] / pts[0][2], rms


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pd", required=True)
    ap.add_argument("--scene", default=os.path.join(os.path.dirname(__file__), "..", "..", "scenes", "penny_crack.yaml"))
    ap.add_argument("--counts", type=int, nargs="+", default=[16, 24, 32])
    ap.add_argument("--side", type=float, default=6.0)
    ap.add_argument("--work", default="/tmp/penny_crack_study")
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    print("| side / a | count | h / a | particles | w(centre pair) / Sneddon | rms error, r < 0.8a | CPU s |")
    print("|---|---|---|---|---|---|---|")
    failures = []
    for count in args.counts:
        path = os.path.join(args.work, f"penny_{count}_{args.side:g}.yaml")
        open(path, "w").write(scene_text(args.scene, count, args.side))
        out = os.path.join(args.work, f"out_{count}_{args.side:g}")
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        r = subprocess.run([args.pd, "run", path, "--out", out], capture_output=True, text=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if r.returncode != 0:
            sys.exit(f"pd run {path} failed ({r.returncode}):\n{r.stderr}")
        n, h, centre, rms = opening(os.path.join(out, "result.csv"))
        cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
        print(f"| {args.side:g} | {count} | {h:.4g} | {n} | {centre:.4f} | {rms:.4f} | {cpu:.1f} |", flush=True)
        if args.check and not rms <= h / (2 * A):
            failures.append(f"count {count}: rms opening error {rms:.4f} exceeds h / (2a) = {h / (2 * A):.4f}")
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
