"""FEM reference for paper 003's square plate with a square cut-out (Wang, Oterkus & Oterkus 2020,
section 5.5, Figs. 32-39), where the paper used ANSYS; SfePy solves it, plane stress.

  /usr/bin/python3 studies/paper003_fem/cutout_reference.py --out DIR [--n 50] [--order 2]
        [--dt 1e-6] [--t-end 4e-4] [--only static|dynamic] [--check]

The paper's text gives the boundary conditions -- "displacement loading at the right edge; the
left and upper boundaries constrained in x and y" -- but neither the plate's nor the hole's size
nor the load (they are only drawn in Figs. 32 and 36). Constraining the left edge in x and the
upper edge in y are the two symmetry planes of a plate with a central hole, so the model is its
quarter; chosen here (docs/paper003.md says so again):
* the quarter x in [0, 0.5], y in [-0.5, 0] of the 1 m plate of sections 5.1-5.4 (same steel:
  E = 200 GPa, nu = 0.25, rho = 7850 kg/m^3), the hole's quarter [0, A] x [-A, 0], A = 0.1 m
  (a central 0.2 m square hole); left edge u_x = 0, upper edge u_y = 0, lower edge and hole free;
* static (5.5.1): u_x = U = 5e-4 m on the right edge x = 0.5 (a nominal strain of 1e-3; the
  right edge is a roller, its u_y free);
* dynamic (5.5.2): released from rest in the uniaxial strain u_x = EPS0 x (EPS0 = 1e-3) of the
  whole body, the same symmetry planes, the right edge free; the field at t = 4e-4 s (the
  paper's Figs. 37-39).

Writes DIR/cutout_static_fem.csv and DIR/cutout_dynamic_fem.csv: rows `x,y,ux,uy` on the node
lattice of spacing 0.005 m inside the body (it contains the particle centres of the PD grids
dx = 0.01 and 0.02, so the study reads the reference at its particles without interpolation
in space), the dynamic one at t = --t-end.

Mesh: an n x n grid of quadrilaterals on the quarter with the elements inside the hole removed
(n a multiple of 5 so that the hole's edges are element edges), Q2 by default. Time
integration as scripts/fem/plate_reference.py: Newmark's average acceleration on the consistent
mass and stiffness, energy-conserving.

The prescribed dofs (left u_x, top u_y, statically right u_x) are eliminated by partitioning
SfePy's full stiffness and mass matrices. --check (CI, coarse mesh) exits 1 unless the reaction
on the left edge balances the one on the right (to 1e-9), the free dofs' residual is below 1e-9
of the load, and the dynamic energy stays constant to 1e-9 relative.
"""
import argparse
import os
import sys
import time

import numpy as np
import scipy.sparse.linalg as spla

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts', 'fem'))
import sfepy_ready  # noqa: E402,F401  (before SfePy: ~/.sfepy created race-free, issue 34)
from sfepy.discrete import Equation, Equations, FieldVariable, Integral, Material, Problem
from sfepy.discrete.conditions import Conditions, EssentialBC
from sfepy.discrete.fem import FEDomain, Field, Mesh
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.terms import Term

E, NU, RHO = 200e9, 0.25, 7850.0
SIDE, A = 0.5, 0.1  # the quarter's side and the hole's half side
U_RIGHT, EPS0 = 5e-4, 1e-3
SAMPLE = 0.005  # the output lattice


def quarter_mesh(n):
    """Quadrilaterals on [0, SIDE] x [-SIDE, 0] without the hole [0, A] x [-A, 0]."""
    if n % 5:
        raise SystemExit("--n must be a multiple of 5 (the hole's edges on element edges)")
    s = np.linspace(0.0, SIDE, n + 1)
    xs, ys = np.meshgrid(s, s - SIDE, indexing="xy")
    coors = np.column_stack([xs.ravel(), ys.ravel()])
    node = lambda i, j: j * (n + 1) + i  # noqa: E731
    cells = []
    for j in range(n):
        for i in range(n):
            cx, cy = 0.5 * (s[i] + s[i + 1]), 0.5 * (s[j] + s[j + 1]) - SIDE
            if cx < A and cy > -A:
                continue  # inside the hole
            cells.append([node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)])
    cells = np.array(cells)
    used = np.unique(cells)
    renumber = -np.ones(coors.shape[0], dtype=int)
    renumber[used] = np.arange(used.size)
    return Mesh.from_data("cutout", coors[used], None, [renumber[cells]], [np.zeros(len(cells), dtype=np.int32)],
                          ["2_4"])


class Cutout:
    """The quarter plate's FE space, its full stiffness and consistent mass, and the dofs its
    symmetry planes (and, statically, the loaded edge) prescribe."""

    def __init__(self, n, order, static):
        self.domain = FEDomain("domain", quarter_mesh(n))
        omega = self.domain.create_region("Omega", "all")
        self.field = Field.from_args("fu", np.float64, "vector", omega, approx_order=order)
        u = FieldVariable("u", "unknown", self.field)
        v = FieldVariable("v", "test", self.field, primary_var_name="u")
        solid = Material("solid", D=stiffness_from_youngpoisson(2, E, NU, plane="stress"), rho=RHO)
        q = 2 * order + 1
        tk = Term.new("dw_lin_elastic(solid.D, v, u)", Integral("i", order=q), omega, solid=solid, v=v, u=u)
        pb = Problem("cutout", equations=Equations([Equation("balance", tk)]))
        pb.time_update()
        evaluate = lambda term: pb.evaluate(term, mode="weak", dw_mode="matrix", solid=solid,  # noqa: E731
                                            active_only=False, copy_materials=False).tocsr()
        self.K = evaluate(f"dw_lin_elastic.{q}.Omega(solid.D, v, u)")
        self.M = evaluate(f"dw_dot.{q}.Omega(solid.rho, v, u)")
        x = self.field.get_coor()
        self.coors = x
        eps = 1e-9
        self.value = np.full(2 * x.shape[0], np.nan)  # prescribed dof values (interleaved x, y)
        self.value[2 * np.flatnonzero(x[:, 0] < eps)] = 0.0  # left: symmetry plane, u_x = 0
        self.value[2 * np.flatnonzero(x[:, 1] > -eps) + 1] = 0.0  # top: symmetry plane, u_y = 0
        if static:
            self.value[2 * np.flatnonzero(x[:, 0] > SIDE - eps)] = U_RIGHT
        self.fixed = ~np.isnan(self.value)
        self.free = np.flatnonzero(~self.fixed)

    def sample(self, nodal):
        """(points, displacements) on the SAMPLE node lattice inside the body."""
        s = np.arange(0, round(SIDE / SAMPLE) + 1) * SAMPLE
        xs, ys = np.meshgrid(s, s - SIDE, indexing="xy")
        pts = np.column_stack([xs.ravel(), ys.ravel()])
        inside = ~((pts[:, 0] < A - 1e-12) & (pts[:, 1] > -A + 1e-12))
        pts = pts[inside]
        return pts, self.field.evaluate_at(pts, np.ascontiguousarray(nodal.reshape(-1, 2)))


def write(path, pts, vals):
    with open(path, "w") as fh:
        fh.write("x,y,ux,uy\n")
        for (x, y), (ux, uy) in zip(pts, vals):
            fh.write(f"{x:.6f},{y:.6f},{ux:.10e},{uy:.10e}\n")


def solve_static(n, order, out):
    t0 = time.perf_counter()
    c = Cutout(n, order, static=True)
    u = np.where(c.fixed, c.value, 0.0)
    f = c.free
    u[f] = spla.spsolve(c.K[f][:, f].tocsc(), -(c.K[f] @ u))
    pts, vals = c.sample(u)
    write(os.path.join(out, "cutout_static_fem.csv"), pts, vals)
    reaction = (c.K @ u).reshape(-1, 2)
    left = reaction[c.coors[:, 0] < 1e-9, 0].sum()
    right = reaction[c.coors[:, 0] > SIDE - 1e-9, 0].sum()
    free_residual = np.abs(reaction.ravel()[f]).max() / abs(right)
    print(f"static: {c.coors.shape[0]} nodes in {time.perf_counter() - t0:.1f} s; reactions left {left:.6e}, right "
          f"{right:.6e} N/m (mean stress {right / SIDE / 1e6:.2f} MPa over the full section); u_x in "
          f"[{vals[:, 0].min():.4e}, {vals[:, 0].max():.4e}], u_y in [{vals[:, 1].min():.4e}, {vals[:, 1].max():.4e}] m")
    return abs(left + right) / abs(right), free_residual


def solve_dynamic(n, order, out, dt, t_end):
    t0 = time.perf_counter()
    c = Cutout(n, order, static=False)
    f = c.free
    K, M = c.K[f][:, f].tocsc(), c.M[f][:, f].tocsc()
    u = (EPS0 * c.coors[:, 0:1] * np.array([[1.0, 0.0]])).ravel()[f]
    v = np.zeros_like(u)
    a = spla.splu(M).solve(-(K @ u))
    beta, gamma = 0.25, 0.5
    lu = spla.splu((M + beta * dt * dt * K).tocsc())
    steps = int(round(t_end / dt))
    energy0 = 0.5 * (v @ (M @ v) + u @ (K @ u))
    drift = 0.0
    for _ in range(steps):
        predictor = u + dt * v + (0.5 - beta) * dt * dt * a
        a_new = lu.solve(-(K @ predictor))
        u = predictor + beta * dt * dt * a_new
        v = v + dt * ((1 - gamma) * a + gamma * a_new)
        a = a_new
        drift = max(drift, abs(0.5 * (v @ (M @ v) + u @ (K @ u)) / energy0 - 1.0))
    full = np.zeros(c.fixed.size)
    full[f] = u
    pts, vals = c.sample(full)
    write(os.path.join(out, "cutout_dynamic_fem.csv"), pts, vals)
    print(f"dynamic: {steps} steps of {dt:g} s in {time.perf_counter() - t0:.1f} s; at t = {steps * dt:g} s u_x in "
          f"[{vals[:, 0].min():.4e}, {vals[:, 0].max():.4e}], u_y in [{vals[:, 1].min():.4e}, {vals[:, 1].max():.4e}] m; "
          f"energy drift {drift:.2e}")
    return drift


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--n", type=int, default=50, help="elements per side of the quarter (a multiple of 5)")
    ap.add_argument("--order", type=int, default=2)
    ap.add_argument("--dt", type=float, default=1e-6)
    ap.add_argument("--t-end", type=float, default=4e-4)
    ap.add_argument("--only", choices=["static", "dynamic"])
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    failures = []
    if a.only != "dynamic":
        imbalance, residual = solve_static(a.n, a.order, a.out)
        if imbalance > 1e-9:
            failures.append(f"left and right reactions differ by {imbalance:.2e} of the load")
        if residual > 1e-9:
            failures.append(f"the free dofs' residual is {residual:.2e} of the load")
    if a.only != "static":
        drift = solve_dynamic(a.n, a.order, a.out, a.dt, a.t_end)
        if drift > 1e-9:
            failures.append(f"Newmark energy drift {drift:.2e} > 1e-9")
    if a.check and failures:
        for f in failures:
            print("FAIL:", f)
        raise SystemExit(1)


if __name__ == "__main__":
    main()
