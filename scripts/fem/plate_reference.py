"""FEM reference for paper 003's square plate (Wang, Oterkus & Oterkus 2020, sections 5.1-5.2),
where the paper used ANSYS. A real FEM library (SfePy) solves the same plate, plane stress.

  /usr/bin/python3 scripts/fem/plate_reference.py --out DIR [--n 50] [--order 2]
        [--dt 1e-6] [--t-end 1e-3] [--probe 0.255 0.255] [--only static|dynamic] [--check]

Plate L = W = 1 m centred on the origin, E = 200 GPa, nu = 0.25, rho = 7850 kg/m^3, plane stress
(the thickness, 0.01 m, cancels). The left edge x = -0.5 is clamped (u = v = 0) in both cases,
as the paper's Figs. 12 and 18 fix it with a fictitious region.

* static (section 5.2, Figs. 19-22): traction sigma* = 200 MPa in x on the right edge x = +0.5.
  Writes DIR/plate_static_fem.csv: rows `axis,s,ux,uy` along the central axes, axis = x (the
  line y = 0, s = x) and axis = y (the line x = 0, s = y), 201 points each.
* dynamic (section 5.1, Figs. 13-16): released from rest in a uniaxial strain u = eps0 (x + 0.5),
  v = 0 (eps0 = 1e-3: the paper's Fig. 11 gives the state but its value is not in the text; the
  response is linear in eps0, so relative errors do not depend on it). Writes
  DIR/plate_dynamic_fem.csv: rows `t,ux,uy` at the probe (--probe, default the paper's
  (0.255, 0.255)) every --dt.
  Time integration: Newmark's average-acceleration rule (beta = 1/4, gamma = 1/2) on SfePy's
  consistent mass and stiffness matrices; it is unconditionally stable and conserves the
  discrete energy of this undamped linear system exactly, which --check asserts.

--check (CI, coarse mesh) exits 1 unless: the static right-edge mean of u_x is within 2% of the
uniaxial-stress value sigma* L / E = 1 mm (the clamped edge stiffens the plate by ~1%), the
assembled edge load sums to sigma* L to 1e-9, and the dynamic energy (v'Mv + u'Ku)/2 stays
constant to 1e-9 relative.
"""
import argparse
import os
import time

import numpy as np
import scipy.sparse.linalg as spla
import sfepy_ready  # noqa: F401  (before SfePy: ~/.sfepy created race-free, issue 34)
from sfepy.discrete import Equation, Equations, FieldVariable, Integral, Material, Problem
from sfepy.discrete.conditions import Conditions, EssentialBC
from sfepy.discrete.fem import FEDomain, Field
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.mesh.mesh_generators import gen_block_mesh
from sfepy.terms import Term

L, E, NU, RHO = 1.0, 200e9, 0.25, 7850.0
SIGMA = 200e6
EPS0 = 1e-3


class Plate:
    """The clamped plate's FE space and its reduced (free-dof) stiffness and mass matrices."""

    def __init__(self, n, order):
        mesh = gen_block_mesh([L, L], [n + 1, n + 1], [0.0, 0.0], name="plate", verbose=False)
        self.domain = FEDomain("domain", mesh)
        eps = 1e-9 * L
        self.omega = self.domain.create_region("Omega", "all")
        self.left = self.domain.create_region("Left", f"vertices in x < {-L / 2 + eps:.12e}", "facet")
        self.right = self.domain.create_region("Right", f"vertices in x > {L / 2 - eps:.12e}", "facet")
        self.field = Field.from_args("fu", np.float64, "vector", self.omega, approx_order=order)
        self.u = FieldVariable("u", "unknown", self.field)
        self.v = FieldVariable("v", "test", self.field, primary_var_name="u")
        self.solid = Material("solid", D=stiffness_from_youngpoisson(2, E, NU, plane="stress"), rho=RHO)
        self.load = Material("load", val=np.array([[SIGMA], [0.0]]))
        self.qorder = 2 * order + 1
        integral = Integral("i", order=self.qorder)
        tk = Term.new("dw_lin_elastic(solid.D, v, u)", integral, self.omega, solid=self.solid, v=self.v, u=self.u)
        tf = Term.new("dw_surface_ltr(load.val, v)", integral, self.right, load=self.load, v=self.v)
        self.pb = Problem("plate", equations=Equations([Equation("balance", tk - tf)]))
        self.pb.set_bcs(ebcs=Conditions([EssentialBC("clamp", self.left, {"u.all": 0.0})]))
        self.pb.time_update()
        self.variables = self.pb.equations.variables
        q = self.qorder
        self.K = self.matrix(f"dw_lin_elastic.{q}.Omega(solid.D, v, u)")
        self.M = self.matrix(f"dw_dot.{q}.Omega(solid.rho, v, u)")
        self.f = self.pb.evaluate(f"dw_surface_ltr.{q}.Right(load.val, v)", mode="weak", dw_mode="vector",
                                  load=self.load, copy_materials=False)

    def matrix(self, term):
        return self.pb.evaluate(term, mode="weak", dw_mode="matrix", solid=self.solid, copy_materials=False).tocsc()

    def full(self, reduced):
        """Nodal displacements (n_nodes x 2) from the free-dof vector (clamped dofs are zero)."""
        return self.pb.equations.make_full_vec(reduced).reshape(-1, 2)

    def reduce(self, nodal):
        return self.pb.equations.strip_state_vector(nodal.ravel())

    def at(self, reduced, points):
        """Displacements at arbitrary points (FE interpolation)."""
        return self.field.evaluate_at(np.asarray(points, dtype=float), self.full(reduced))


def solve_static(plate, out):
    t0 = time.perf_counter()
    K, f = plate.K, plate.f
    u = spla.spsolve(K, f)
    s = np.linspace(-L / 2, L / 2, 201)
    on_x = plate.at(u, np.column_stack([s, np.zeros_like(s)]))
    on_y = plate.at(u, np.column_stack([np.zeros_like(s), s]))
    with open(os.path.join(out, "plate_static_fem.csv"), "w") as fh:
        fh.write("axis,s,ux,uy\n")
        for name, vals in (("x", on_x), ("y", on_y)):
            for si, (ux, uy) in zip(s, vals):
                fh.write(f"{name},{si:.6f},{ux:.12e},{uy:.12e}\n")
    edge = plate.at(u, np.column_stack([np.full_like(s, L / 2), s]))
    mean_edge_ux = np.trapz(edge[:, 0], s) / L
    total_load = float(f.sum())  # x components only: the load has no y part
    applied = SIGMA * L
    print(f"static: {plate.field.n_nod} nodes, solved in {time.perf_counter() - t0:.2f} s; "
          f"u_x(0.5, 0) = {on_x[-1, 0]:.9e} m, mean right-edge u_x = {mean_edge_ux:.9e} m "
          f"(sigma L / E = {SIGMA * L / E:.3e}); u_y(0, 0.5) = {on_y[-1, 1]:.9e} m; load {total_load:.6e} N/m")
    return mean_edge_ux, total_load / applied - 1.0


def solve_dynamic(plate, out, dt, t_end, probe):
    t0 = time.perf_counter()
    K, M = plate.K, plate.M
    coors = plate.field.get_coor()
    nodal = np.zeros_like(coors)
    nodal[:, 0] = EPS0 * (coors[:, 0] + L / 2)
    u = plate.reduce(nodal)
    v = np.zeros_like(u)
    a = spla.splu(M).solve(-(K @ u))
    beta, gamma = 0.25, 0.5
    lu = spla.splu((M + beta * dt * dt * K).tocsc())
    steps = int(round(t_end / dt))
    rows = [(0.0, *plate.at(u, [probe])[0])]
    energy0 = 0.5 * (v @ (M @ v) + u @ (K @ u))
    drift = 0.0
    for n in range(1, steps + 1):
        predictor = u + dt * v + (0.5 - beta) * dt * dt * a
        a_new = lu.solve(-(K @ predictor))
        u = predictor + beta * dt * dt * a_new
        v = v + dt * ((1 - gamma) * a + gamma * a_new)
        a = a_new
        rows.append((n * dt, *plate.at(u, [probe])[0]))
        energy = 0.5 * (v @ (M @ v) + u @ (K @ u))
        drift = max(drift, abs(energy / energy0 - 1.0))
    with open(os.path.join(out, "plate_dynamic_fem.csv"), "w") as fh:
        fh.write("t,ux,uy\n")
        for t, ux, uy in rows:
            fh.write(f"{t:.9e},{ux:.12e},{uy:.12e}\n")
    r = np.array(rows)
    print(f"dynamic: {steps} steps of {dt:g} s in {time.perf_counter() - t0:.1f} s; probe u_x in "
          f"[{r[:, 1].min():.4e}, {r[:, 1].max():.4e}], u_y in [{r[:, 2].min():.4e}, {r[:, 2].max():.4e}] m; "
          f"energy drift {drift:.2e}")
    return drift


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--n", type=int, default=50, help="elements per side")
    ap.add_argument("--order", type=int, default=2)
    ap.add_argument("--dt", type=float, default=1e-6)
    ap.add_argument("--t-end", type=float, default=1e-3)
    ap.add_argument("--probe", nargs=2, type=float, default=[0.255, 0.255])
    ap.add_argument("--only", choices=["static", "dynamic"])
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    plate = Plate(a.n, a.order)
    failures = []
    if a.only != "dynamic":
        mean_ux, load_error = solve_static(plate, a.out)
        if abs(mean_ux / (SIGMA * L / E) - 1) > 0.02:
            failures.append(f"mean right-edge u_x {mean_ux:.6e} is not within 2% of sigma L / E")
        if abs(load_error) > 1e-9:
            failures.append(f"the assembled load differs from sigma* L by {load_error:.2e}")
    if a.only != "static":
        drift = solve_dynamic(plate, a.out, a.dt, a.t_end, a.probe)
        if drift > 1e-9:
            failures.append(f"Newmark energy drift {drift:.2e} > 1e-9")
    if a.check and failures:
        for f in failures:
            print("FAIL:", f)
        raise SystemExit(1)


if __name__ == "__main__":
    main()
