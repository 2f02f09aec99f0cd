#!/usr/bin/python3
"""Every output kind `pd run` writes, read back by a real reader (VTK's XML readers).

Runs a static scene and a dynamic one (snapshots + animation.pvd) with `pd`, then
checks with VTK that each .vtu opens, has the expected point count, the array names and
component counts, and the same values (bit for bit: the writer stores raw Float64) as
result.csv; that every .pvd entry names a readable snapshot at increasing times; and
that the last snapshot of the dynamic run equals its result; and that summary.json, the
.pvd and every .vtu of a run carry one run_id, and .pd.files lists the run's files.

usage: check_outputs.py PD_EXE WORK_DIR
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as e:  # the CI installs python3-vtk9 (scripts/install_deps.sh)
    sys.exit(f"check_outputs.py: VTK for Python is missing ({e}); apt-get install python3-vtk9")

STATIC = """dimension: 2
domain: {box: {min: [0, 0], max: [1, 1]}, count: 8, placement: node}
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: cubic
materials: [{name: rock, E: 1000, nu: 0.0, plane: strain}]
boundary:
  - {region: {side: bottom}, fixed: [x, y]}
  - {region: {side: left}, fixed: [x]}
  - {region: {side: top}, traction: [0, -0.001]}
"""

DYNAMIC = """dimension: 2
domain: {box: {min: [0, 0], max: [1, 0.1]}, spacing: 0.025}
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: const
materials: [{name: bar, E: 1.0, nu: 0.0, density: 1.0}]
boundary:
  - {region: {all: true}, fixed: [y]}
damage: {critical_stretch: 0.5}
dynamics:
  method: explicit
  steps: 20
  output_every: 5
  snapshot_every: 10
  threads: 1
  initial:
    - {region: {all: true}, displacement: [1.0e-3, 0], gaussian: {axis: x, center: 0.5, width: 0.1}}
"""

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def run_pd(pd, scene_text, out):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    scene = os.path.join(out, "scene.yaml")
    with open(scene, "w") as f:
        f.write(scene_text)
    r = subprocess.run([pd, "run", scene, "--out", out], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"pd run {scene} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")


def read_vtu(path):
    """The point arrays of a .vtu as {name: (components, flat list)}, plus points."""
    check(open(path, "rb").read().find(b'format="appended"') > 0, f"{path}: not written in binary (appended)")
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    check(reader.GetErrorCode() == 0 and grid.GetNumberOfPoints() > 0, f"{path}: VTK could not read it")
    arrays = {"position": (3, vtk_to_numpy(grid.GetPoints().GetData()).reshape(-1))}
    data = grid.GetPointData()
    for k in range(data.GetNumberOfArrays()):
        a = data.GetArray(k)
        arrays[a.GetName()] = (a.GetNumberOfComponents(), vtk_to_numpy(a).reshape(-1))
    check(grid.GetNumberOfCells() == grid.GetNumberOfPoints(), f"{path}: one vertex cell per particle")
    return grid.GetNumberOfPoints(), arrays


def run_id_of(path):
    """The run_id attribute of a VTK XML file's root (.vtu or .pvd)."""
    with open(path, "rb") as f:
        head = f.read(1024).decode("latin-1")
    m = re.search(r'<VTKFile [^>]*run_id="([^"]+)"', head)
    check(m is not None, f"{path}: no run_id on <VTKFile>")
    return m.group(1) if m else None


def check_one_run(directory, files):
    """summary.json's run_id is the one in every VTK file of the run."""
    with open(os.path.join(directory, "summary.json")) as f:
        rid = json.load(f).get("run_id")
    check(bool(rid), f"{directory}/summary.json has no run_id")
    for p in files:
        check(run_id_of(p) == rid, f"{p}: run_id {run_id_of(p)} is not summary.json's {rid}")
    leftovers = [n for n in os.listdir(directory)
                 if n.endswith(".tmp") or (n.startswith(".pd.") and n != ".pd.files") or n.startswith("unfinished-")]
    check(not leftovers, f"{directory}: temporaries, lock or staging directory left: {leftovers}")
    # .pd.files lists what the run published (output/staging.hpp): every file of the run, and only those.
    with open(os.path.join(directory, ".pd.files")) as f:
        listed = set(f.read().split())
    present = {os.path.relpath(os.path.join(root, n), directory) for root, _, names in os.walk(directory) for n in names}
    check(listed == present - {".pd.files", "scene.yaml"}, f"{directory}/.pd.files lists {sorted(listed)}, the run wrote "
          f"{sorted(present - {'.pd.files', 'scene.yaml'})}")


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return header, [[float(v) for v in r] for r in body]


def csv_columns(header, name, components, dim):
    """The CSV columns of a VTU array (the CSV names vectors name_x, name_y[, name_z])."""
    axes = "xyz"
    if name == "position":
        return [header.index(a) if a in header else None for a in axes[:components]]
    if name == "displacement":
        return [header.index("u_" + a) if "u_" + a in header else None for a in axes[:components]]
    if components == 1:
        return [header.index(name)]
    return [header.index(f"{name}_{a}") if f"{name}_{a}" in header else None for a in axes[:components]]


def compare_with_csv(vtu, csv_path, dim):
    n, arrays = read_vtu(vtu)
    header, rows = read_csv(csv_path)
    check(n == len(rows), f"{vtu}: {n} points, {len(rows)} CSV rows")
    covered = {"id"}
    for name, (components, values) in arrays.items():
        columns = csv_columns(header, name, components, dim)
        for c, col in enumerate(columns):
            for i in range(n):
                expected = rows[i][col] if col is not None else 0.0  # 2D: z padded with 0
                if values[i * components + c] != expected:
                    check(False, f"{vtu}: {name}[{i}][{c}] = {values[i * components + c]!r}, CSV {expected!r}")
                    break
            if col is not None:
                covered.add(header[col])
    check(covered == set(header), f"{vtu}: CSV columns without a VTU array: {sorted(set(header) - covered)}")
    return arrays


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[-1])
    pd, work = sys.argv[1], sys.argv[2]
    static = os.path.join(work, "static")
    run_pd(pd, STATIC, static)
    arrays = compare_with_csv(os.path.join(static, "result.vtu"), os.path.join(static, "result.csv"), 2)
    for name in ("displacement", "material", "damage", "internal_force"):
        check(name in arrays, f"static result.vtu has no {name}")
    check_one_run(static, [os.path.join(static, "result.vtu")])

    dynamic = os.path.join(work, "dynamic")
    run_pd(pd, DYNAMIC, dynamic)
    arrays = compare_with_csv(os.path.join(dynamic, "result.vtu"), os.path.join(dynamic, "result.csv"), 2)
    for name in ("displacement", "velocity", "material", "damage"):
        check(name in arrays, f"dynamic result.vtu has no {name}")
    collection = ET.parse(os.path.join(dynamic, "animation.pvd")).getroot()
    check(collection.get("type") == "Collection", "animation.pvd is not a VTK collection")
    entries = collection.findall("./Collection/DataSet")
    check(len(entries) == 3, f"animation.pvd lists {len(entries)} snapshots, expected steps 0, 10, 20")
    times = [float(e.get("timestep")) for e in entries]
    check(times == sorted(times) and len(set(times)) == len(times), f"animation.pvd times not increasing: {times}")
    last = None
    for e in entries:
        path = os.path.join(dynamic, e.get("file"))
        check(os.path.exists(path), f"animation.pvd names a missing file {e.get('file')}")
        if os.path.exists(path):
            n, last = read_vtu(path)
            check(n == len(arrays["position"][1]) // 3, f"{path}: {n} points")
    check_one_run(dynamic, [os.path.join(dynamic, "result.vtu"), os.path.join(dynamic, "animation.pvd")] +
                  [os.path.join(dynamic, e.get("file")) for e in entries])
    if last is not None:
        for name in ("displacement", "velocity", "damage"):
            check(list(last[name][1]) == list(arrays[name][1]), f"the last snapshot's {name} differs from result.vtu")
    if failures:
        sys.exit(f"{len(failures)} output check(s) failed")
    print("all outputs read back by VTK", vtk_version())


def vtk_version():
    from vtkmodules.vtkCommonCore import vtkVersion
    return vtkVersion.GetVTKVersion()


if __name__ == "__main__":
    main()
