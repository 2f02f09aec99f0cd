"""Paper 003's plate in tension (section 5.2) with the surface correction (eq. 19) off and on,
beside paper 002's compensation factor, against SfePy: the static points of
studies/paper003_plate.py with one domain key added.

  /usr/bin/python3 studies/paper003_surface.py --pd build/bin/pd --fem studies/paper003_fem --out DIR
        [--laws oterkus_plane_strain silling_plane_strain bond_based_constant_2d] [--ratios 3 4]
        [--variants none terms responses compensation]

Variants: none (the study's scenes as they are), terms and responses (`domain.surface_correction`,
docs/scene_format.md), compensation (`domain.compensation: true`, paper 002; only for a law
with an energy kernel). Errors are those of paper003_plate.py (relative to the FEM curve's
largest magnitude, u_x along y = 0 and u_y along x = 0). The table goes to
DIR/paper003_surface.csv and is printed.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import paper003_plate as plate  # noqa: E402

DOMAIN_KEY = {"none": "", "terms": "  surface_correction: terms", "responses": "  surface_correction: responses",
              "compensation": "  compensation: true"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pd", required=True)
    ap.add_argument("--fem", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--laws", nargs="+", default=["oterkus_plane_strain", "silling_plane_strain", "bond_based_constant_2d"])
    ap.add_argument("--ratios", nargs="+", type=float, default=[3, 4])
    ap.add_argument("--variants", nargs="+", default=list(DOMAIN_KEY), choices=list(DOMAIN_KEY))
    ap.add_argument("--spacing", type=float, default=0.01)
    args = ap.parse_args()
    args.probe, args.boundary = [0.255, 0.255], "held"
    fem = plate.read_fem(args.fem)
    base_scene = plate.scene
    table = []
    out_root = args.out
    for variant in args.variants:
        key = DOMAIN_KEY[variant]

        def scene_with_key(*a, key=key, **k):
            text = base_scene(*a, **k)
            anchor = "  quadrature: partial_linear"
            assert anchor in text, "paper003_plate.scene no longer writes the quadrature line"
            return text.replace(anchor, anchor + ("\n" + key if key else ""), 1)

        plate.scene = scene_with_key
        args.out = os.path.join(out_root, variant)
        for law in args.laws:
            for ratio in args.ratios:
                point = plate.static_point(args, law, ratio, fem)
                point.update(case="static", law=law, ratio=ratio, variant=variant)
                table.append(point)
                print(f"{variant:12s} " + plate.format_row(point), flush=True)
    plate.scene = base_scene
    os.makedirs(out_root, exist_ok=True)
    keys = ["variant", "law", "ratio", "status", "ux_rms", "ux_peak", "uy_rms", "uy_peak", "seconds"]
    with open(os.path.join(out_root, "paper003_surface.csv"), "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=keys, extrasaction="ignore")
        w.writeheader()
        w.writerows(table)


if __name__ == "__main__":
    main()
