#!/usr/bin/python3
"""`mpirun -n 2 pd run` on a scene with solver.backend: petsc writes the files a serial run
writes, with the same displacement (1e-8 relative) and the same summary keys; a scene
on the serial backend under mpirun is refused with exit code 2.
Usage: pd_run_mpi.py PD MPIEXEC SCENES_DIR WORK_DIR"""
import csv, json, math, os, shutil, subprocess, sys

pd, mpiexec, scenes, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")
text = open(os.path.join(scenes, "uniaxial.yaml")).read().replace("count: 20", "count: 12")
serial_scene, petsc_scene = os.path.join(work, "serial.yaml"), os.path.join(work, "petsc.yaml")
open(serial_scene, "w").write(text)
open(petsc_scene, "w").write(text.replace("law: silling_plane_strain", "law: silling_plane_strain\nsolver: {backend: petsc}"))
failures = []

def run(cmd):
    return subprocess.run(cmd, env=env, capture_output=True, text=True)

def displacement(path):
    rows = list(csv.DictReader(open(path)))
    return [float(r[c]) for r in rows for c in ("u_x", "u_y")]

s = run([pd, "run", serial_scene, "--out", os.path.join(work, "serial")])
p = run([mpiexec, "-n", "2", "--oversubscribe", pd, "run", petsc_scene, "--out", os.path.join(work, "petsc"),
         "--petsc-options=-ksp_converged_reason -log_view"])
if s.returncode != 0 or p.returncode != 0:
    sys.exit(f"runs failed: serial {s.returncode}, mpirun {p.returncode}\n{s.stderr}\n{p.stdout}\n{p.stderr}")
files_s = sorted(os.listdir(os.path.join(work, "serial")))
files_p = sorted(os.listdir(os.path.join(work, "petsc")))
if files_s != files_p:
    failures.append(f"files differ: serial {files_s}, petsc {files_p}")
us, up = displacement(os.path.join(work, "serial", "result.csv")), displacement(os.path.join(work, "petsc", "result.csv"))
norm = math.sqrt(sum(v * v for v in us))
diff = math.sqrt(sum((a - b) ** 2 for a, b in zip(us, up)))
if len(us) != len(up) or not norm > 0 or diff / norm > 1e-8:
    failures.append(f"displacement differs: relative {diff / norm if norm else float('nan'):.3e}")
js, jp = (json.load(open(os.path.join(work, d, "summary.json"))) for d in ("serial", "petsc"))
if sorted(js) != sorted(jp):
    failures.append(f"summary keys differ: {sorted(set(js) ^ set(jp))}")
if p.stdout.count("PETSc backend on 2 MPI process(es)") != 1:
    failures.append("the log should come once, from rank 0:\n" + p.stdout)
if "Linear solve converged" not in p.stdout:
    failures.append("--petsc-options did not reach PETSc (-ksp_converged_reason printed nothing)")
# Paper 001's OBQ collocation (scenes/paper001_hole.yaml) on 2 ranks with a parallel direct factor
# of the collocation tangent (AMG does not precondition it): the serial run's §4 RMS error.
hole = open(os.path.join(scenes, "paper001_hole.yaml")).read()
hole_petsc = os.path.join(work, "hole_petsc.yaml")
open(hole_petsc, "w").write(hole + "\nsolver: {backend: petsc}\n")
hs = run([pd, "run", os.path.join(scenes, "paper001_hole.yaml"), "--out", os.path.join(work, "hole_serial")])
hp = run([mpiexec, "-n", "2", "--oversubscribe", pd, "run", hole_petsc, "--out", os.path.join(work, "hole_petsc"),
          "--petsc-options=-pc_type lu -pc_factor_mat_solver_type mumps"])
rms = lambda log: [l for l in log.splitlines() if "RMS error over the" in l]
if hs.returncode != 0 or hp.returncode != 0:
    failures.append(f"OBQ hole: serial exit {hs.returncode}, mpirun exit {hp.returncode}: {hs.stderr} {hp.stderr}")
elif not rms(hs.stdout) or rms(hs.stdout) != rms(hp.stdout):
    failures.append(f"OBQ hole: serial {rms(hs.stdout)} against 2 ranks {rms(hp.stdout)}")
# The 1000:1 inclusion (scenes/inclusion.yaml): GAMG (Debian's PETSc 3.18) is indefinite there, so
# the load step is solved again with hypre BoomerAMG, and the answer is the serial one.
inc = open(os.path.join(scenes, "inclusion.yaml")).read()
inc_serial, inc_petsc = os.path.join(work, "inc_serial.yaml"), os.path.join(work, "inc_petsc.yaml")
open(inc_serial, "w").write(inc)
open(inc_petsc, "w").write(inc + "\nsolver: {backend: petsc}\n")
i_s = run([pd, "run", inc_serial, "--out", os.path.join(work, "inc_serial")])
i_p = run([mpiexec, "-n", "2", "--oversubscribe", pd, "run", inc_petsc, "--out", os.path.join(work, "inc_petsc")])
if i_s.returncode != 0 or i_p.returncode != 0:
    failures.append(f"inclusion: serial exit {i_s.returncode}, mpirun exit {i_p.returncode}: {i_s.stderr} {i_p.stderr}")
else:
    if "again with hypre BoomerAMG" not in i_p.stdout:
        failures.append("inclusion: GAMG was expected to fail and hypre to take over:\n" + i_p.stdout)
    a = displacement(os.path.join(work, "inc_serial", "result.csv"))
    b = displacement(os.path.join(work, "inc_petsc", "result.csv"))
    na = math.sqrt(sum(v * v for v in a))
    d = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
    if len(a) != len(b) or not na > 0 or d / na > 1e-8:
        failures.append(f"inclusion: displacement differs from the serial run by {d / na if na else float('nan'):.3e}")
r = run([mpiexec, "-n", "2", "--oversubscribe", pd, "run", serial_scene, "--out", os.path.join(work, "refused")])
if "PETSc Performance Summary" not in p.stdout:
    failures.append("-log_view from --petsc-options printed no performance summary")
if r.returncode != 2 or "solver.backend is serial" not in r.stderr:
    failures.append(f"serial scene under mpirun: exit {r.returncode}, stderr {r.stderr!r}")
if failures:
    sys.exit("\n".join(failures))
print(f"mpirun -n 2 pd run: same files, displacement within {diff / norm:.2e} of the serial run")
