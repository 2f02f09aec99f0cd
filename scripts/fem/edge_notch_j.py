"""Classical J of paper 004's edge-notched plates with a real FEM library (SfePy), so the
reference is not only the paper's Abaqus number (19.76 Pa m single, 12.90 double).

  /usr/bin/python3 scripts/fem/edge_notch_j.py [--n 64] [--order 2] [--double] [--check J --tolerance r]

Measured (one run each, order 2, da = 0.2 mm): single notch n = 16, 32, 64, 128: J = 19.6908,
19.7406, 19.7489, 19.7503 Pa m (Abaqus, paper 004: 19.76); double notch n = 32, 64, 128:
12.8898, 12.8925, 12.8930 Pa m (Abaqus: 12.90). n = 64 with da = 0.1 mm: 19.7482.

Plate 10 x 10 cm, notch 5 cm from the left edge along y = 5 cm, sigma = 1 MPa on top and
bottom, E = 72 GPa, nu = 1/3, plane stress. Mode I symmetry: the upper half is modelled,
u_y = 0 on the ligament (y = 5 cm, x > a), the crack face free; --double adds u_x = 0 on the
right edge (the double-edge-notch half, paper 004 section 5.2). Quadrilateral Lagrange
elements of order --order on an n x n/2 tensor mesh graded toward the tip (x and y mapped
by a power 2.5 law, the tip a node).

J by the energy release at fixed load (virtual crack extension by remeshing): under the
tractions, the strain energy of the whole plate is U = sigma * int_top u_y dx (twice the
half's (1/2) int t.u), and J = G = dU/da, by the central difference of U at a +- da (the
same mesh, its grading recentred on the tip). Printed: J for the element size and the
difference step, so the convergence is visible.
"""
import argparse

import numpy as np
import sfepy_ready  # noqa: F401  (before SfePy: ~/.sfepy created race-free, issue 34)
from sfepy.base.base import IndexedStruct
from sfepy.discrete import Equation, Equations, FieldVariable, Integral, Material, Problem
from sfepy.discrete.conditions import Conditions, EssentialBC
from sfepy.discrete.fem import FEDomain, Field, Mesh
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.mesh.mesh_generators import gen_block_mesh
from sfepy.solvers.ls import ScipyDirect
from sfepy.solvers.nls import Newton
from sfepy.terms import Term

L, H, E, NU, SIGMA = 0.1, 0.05, 72e9, 1.0 / 3.0, 1e6
GRADING = 2.5


def graded(X, a):
    """Uniform X in [0, L] -> x in [0, L] with x(L/2) = a and nodes crowded at a."""
    left = X < L / 2
    s = np.where(left, 1 - X / (L / 2), (X - L / 2) / (L / 2))
    return np.where(left, a - a * s ** GRADING, a + (L - a) * s ** GRADING)


def energy(a, n, order, double):
    base = gen_block_mesh([L, H], [n + 1, n // 2 + 1], [L / 2, H / 2], name="plate", verbose=False)
    coors = base.coors.copy()
    coors[:, 0] = graded(coors[:, 0], a)
    coors[:, 1] = H * (coors[:, 1] / H) ** GRADING
    mesh = Mesh.from_data("plate", coors, None, [base.get_conn("2_4")], [np.zeros(base.n_el, dtype=np.int32)], ["2_4"])
    domain = FEDomain("domain", mesh)
    eps = 1e-9 * L
    omega = domain.create_region("Omega", "all")
    top = domain.create_region("Top", f"vertices in y > {H - eps:.12e}", "facet")
    ligament = domain.create_region("Ligament", f"vertices in (y < {eps:.12e}) & (x > {a - eps:.12e})", "facet")
    field = Field.from_args("fu", np.float64, "vector", omega, approx_order=order)
    u = FieldVariable("u", "unknown", field)
    v = FieldVariable("v", "test", field, primary_var_name="u")
    solid = Material("solid", D=stiffness_from_youngpoisson(2, E, NU, plane="stress"))
    load = Material("load", val=np.array([[0.0], [SIGMA]]))
    integral = Integral("i", order=2 * order + 1)
    t1 = Term.new("dw_lin_elastic(solid.D, v, u)", integral, omega, solid=solid, v=v, u=u)
    t2 = Term.new("dw_surface_ltr(load.val, v)", integral, top, load=load, v=v)
    bcs = [EssentialBC("sym", ligament, {"u.1": 0.0})]
    if double:
        right = domain.create_region("Right", f"vertices in x > {L - eps:.12e}", "facet")
        bcs.append(EssentialBC("right", right, {"u.0": 0.0}))
    else:
        corner = domain.create_region("Corner", f"vertices in (x > {L - eps:.12e}) & (y < {eps:.12e})", "vertex")
        bcs.append(EssentialBC("corner", corner, {"u.0": 0.0}))
    pb = Problem("plate", equations=Equations([Equation("balance", t1 - t2)]))
    pb.set_bcs(ebcs=Conditions(bcs))
    pb.set_solver(Newton({}, lin_solver=ScipyDirect({}), status=IndexedStruct()))
    pb.solve(save_results=False)
    uval = pb.get_variables()["u"]().reshape(-1, 2)
    x = field.get_coor()
    on_top = np.abs(x[:, 1] - H) < eps
    order_idx = np.argsort(x[on_top, 0])
    xs, uy = x[on_top, 0][order_idx], uval[on_top, 1][order_idx]
    # int_top u_y dx: Simpson-like exactness is not needed, the top field is smooth
    return SIGMA * np.trapz(uy, xs)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=64)
    ap.add_argument("--order", type=int, default=2)
    ap.add_argument("--double", action="store_true")
    ap.add_argument("--da", type=float, default=2e-4)
    ap.add_argument("--a", type=float, default=0.05, help="notch length (m)")
    ap.add_argument("--check", type=float, help="exit 1 unless J is within --tolerance of this value")
    ap.add_argument("--tolerance", type=float, default=0.005)
    a = ap.parse_args()
    a0 = a.a
    U_minus, U_plus = energy(a0 - a.da, a.n, a.order, a.double), energy(a0 + a.da, a.n, a.order, a.double)
    J = (U_plus - U_minus) / (2 * a.da)
    print(f"{'double' if a.double else 'single'} edge notch a = {a0:g} m: n = {a.n}, order {a.order}, da = {a.da:g} m: "
          f"U = {0.5 * (U_plus + U_minus):.9g} J/m, J = {J:.6f} Pa m")
    if a.check is not None and abs(J - a.check) > a.tolerance * abs(a.check):
        print(f"FAIL: J = {J:.6f} differs from {a.check} by more than {a.tolerance:.1%}")
        raise SystemExit(1)


if __name__ == "__main__":
    main()
