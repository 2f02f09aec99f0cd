#!/usr/bin/python3
"""`domain.particles:` from .vtu files written by VTK itself (python3-vtk9).

1. A 2D lattice with a material array, written by VTK in every encoding it offers
   (ascii; inline binary; appended raw and base64; zlib-compressed or not; UInt32 and
   UInt64 headers; big-endian), is run by `pd run`: each result.csv equals, byte for
   byte, the run of the same cloud given as a CSV file.
2. A 3D lattice (appended, VTK's defaults) likewise.
3. scripts/mesh_to_particles.py turns a quad mesh with two materials into a point
   cloud: one particle per cell, their total area is the mesh's, the material groups
   become indices 0 and 1, and `pd run` runs it.
4. Files VTK wrote and then damaged are refused with exit 2, naming file:line, and no
   output is left.

usage: check_vtu_particles.py PD_EXE SOURCE_DIR WORK_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys

try:
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIntArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import VTK_QUAD, VTK_VERTEX, vtkUnstructuredGrid
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
except ImportError as e:  # the CI installs python3-vtk9 (scripts/install_deps.sh)
    sys.exit(f"check_vtu_particles.py: VTK for Python is missing ({e}); apt-get install python3-vtk9")

pd, source, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


REST = """horizon: {ratio: 3.0}
law: silling_plane_strain
influence: cubic
materials: [{name: rock, E: 1, nu: 0.25}, {name: glass, E: 2, nu: 0.25}]
boundary:
  - {region: {side: bottom}, fixed: [x, y]}
  - {region: {side: top}, displacement: {x: 0, y: 0.01}}
"""
REST_3D = REST.replace("silling_plane_strain", "silling_3d").replace("fixed: [x, y]", "fixed: [x, y, z]").replace(
    "{x: 0, y: 0.01}", "{x: 0, y: 0.01, z: 0}")


def lattice(n, dim):
    h = 1.0 / n
    pts = []
    for k in range(n + 1 if dim == 3 else 1):
        for j in range(n + 1):
            for i in range(n + 1):
                pts.append((i * h, j * h, k * h if dim == 3 else 0.0))
    return pts, h ** dim


def write_csv(path, pts, vol, dim, materials):
    with open(path, "w") as f:
        f.write("x,y,z,volume,material\n" if dim == 3 else "x,y,volume,material\n")
        for p, m in zip(pts, materials):
            f.write(",".join(repr(c) for c in p[:dim]) + f",{vol!r},{m}\n")


def write_vtu(path, pts, vol, materials, mode):
    grid = vtkUnstructuredGrid()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    for p in pts:
        points.InsertNextPoint(p)
    grid.SetPoints(points)
    for i in range(len(pts)):
        grid.InsertNextCell(VTK_VERTEX, 1, [i])
    v = vtkDoubleArray()
    v.SetName("volume")
    m = vtkIntArray()
    m.SetName("material")
    for mat in materials:
        v.InsertNextValue(vol)
        m.InsertNextValue(mat)
    grid.GetPointData().AddArray(v)
    grid.GetPointData().AddArray(m)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    if "ascii" in mode:
        w.SetDataModeToAscii()
    if "binary" in mode:
        w.SetDataModeToBinary()
    if "raw" in mode:
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
    if "nozlib" in mode:
        w.SetCompressorTypeToNone()
    if "uint64" in mode:
        w.SetHeaderTypeToUInt64()
    if "bigendian" in mode:
        w.SetByteOrderToBigEndian()
    check(w.Write() == 1, f"VTK could not write {path}")


def run(scene_text, name, expect=0):
    d = os.path.join(work, name)
    os.makedirs(d, exist_ok=True)
    scene = os.path.join(d, "scene.yaml")
    with open(scene, "w") as f:
        f.write(scene_text)
    out = os.path.join(d, "out")
    r = subprocess.run([pd, "run", scene, "--out", out], capture_output=True, text=True)
    check(r.returncode == expect, f"{name}: exit {r.returncode}, expected {expect}\n{r.stderr[-2000:]}")
    return r, out


def result(out):
    with open(os.path.join(out, "result.csv"), "rb") as f:
        return f.read()


# 1 and 2: every encoding gives the CSV's run exactly.
MODES = ["default", "ascii", "binary", "binary-nozlib", "raw", "raw-nozlib", "raw-uint64", "raw-nozlib-uint64",
         "default-bigendian", "raw-bigendian"]
for dim, n, modes in ((2, 10, MODES), (3, 4, ["default", "raw-nozlib"])):
    pts, vol = lattice(n, dim)
    materials = [1 if p[0] > 0.55 else 0 for p in pts]
    rest = REST if dim == 2 else REST_3D
    csv = os.path.join(work, f"cloud{dim}.csv")
    write_csv(csv, pts, vol, dim, materials)
    _, out = run(f"dimension: {dim}\ndomain: {{particles: {csv}}}\n" + rest, f"csv{dim}")
    reference = result(out)
    for mode in modes:
        vtu = os.path.join(work, f"cloud{dim}_{mode}.vtu")
        write_vtu(vtu, pts, vol, materials, mode)
        if mode == "default":
            check(b'compressor="vtkZLibDataCompressor"' in open(vtu, "rb").read(), f"{vtu}: VTK's default is compressed")
        r, out = run(f"dimension: {dim}\ndomain: {{particles: {vtu}}}\n" + rest, f"vtu{dim}_{mode}")
        if r.returncode == 0:
            check(result(out) == reference, f"{mode} ({dim}D): result.csv differs from the CSV cloud's")

# 3: the mesh recipe of docs/scene_format.md, on a 2D quad mesh (rock left, glass right).
mesh = vtkUnstructuredGrid()
points = vtkPoints()
nx, ny, L = 12, 6, 2.0
for j in range(ny + 1):
    for i in range(nx + 1):
        points.InsertNextPoint(L * i / nx, 1.0 * j / ny, 0.0)
mesh.SetPoints(points)
group = vtkIntArray()
group.SetName("gmsh:physical")
for j in range(ny):
    for i in range(nx):
        a = j * (nx + 1) + i
        mesh.InsertNextCell(VTK_QUAD, 4, [a, a + 1, a + nx + 2, a + nx + 1])
        group.InsertNextValue(7 if i < nx // 2 else 8)
mesh.GetCellData().AddArray(group)
w = vtkXMLUnstructuredGridWriter()
w.SetFileName(os.path.join(work, "mesh.vtu"))
w.SetInputData(mesh)
w.Write()
cloud = os.path.join(work, "mesh_particles.vtu")
r = subprocess.run(["/usr/bin/python3", os.path.join(source, "scripts", "mesh_to_particles.py"), os.path.join(work, "mesh.vtu"),
                    cloud, "--material", "gmsh:physical"], capture_output=True, text=True)
check(r.returncode == 0, f"mesh_to_particles.py failed: {r.stderr}")
m = re.search(r"(\d+) particles, total area ([0-9.e+-]+)", r.stdout)
check(m is not None and int(m.group(1)) == nx * ny and abs(float(m.group(2)) - L) < 1e-12, f"mesh_to_particles.py: {r.stdout}")
r, out = run(f"dimension: 2\ndomain: {{particles: {cloud}}}\n" + REST, "mesh")
if r.returncode == 0:
    with open(os.path.join(out, "summary.json")) as f:
        check(json.load(f)["particles"] == nx * ny, "the mesh run: one particle per cell")
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(cloud)
reader.Update()
c = reader.GetOutput()
mat = c.GetPointData().GetArray("material")
check(mat is not None and all(mat.GetTuple1(i) == (0 if c.GetPoint(i)[0] < L / 2 else 1) for i in range(c.GetNumberOfPoints())),
      "mesh_to_particles.py: material 0 (group 7) left, 1 (group 8) right")

# 4: VTK's files, damaged.
pts, vol = lattice(4, 2)
good = os.path.join(work, "good_raw.vtu")
write_vtu(good, pts, vol, [0] * len(pts), "raw-nozlib")
raw = open(good, "rb").read()
start = raw.index(b"_", raw.index(b"<AppendedData")) + 1


def damaged(name, data, message):
    path = os.path.join(work, name + ".vtu")
    with open(path, "wb") as f:
        f.write(data)
    r, out = run(f"dimension: 2\ndomain: {{particles: {path}}}\n" + REST, "bad_" + name, expect=2)
    check(re.search(message.replace("{file}", re.escape(path)), r.stderr) is not None, f"{name}: stderr {r.stderr!r}, expected /{message}/")
    check(not os.path.exists(out) or not os.listdir(out), f"{name}: files left in {out}")


damaged("truncated", raw[: start + 40], r"domain\.particles: {file}:\d+: Points: cannot decode the appended data: the data ends")
damaged("no_volume", raw.replace(b'Name="volume"', b'Name="Volume"'), r"{file}:\d+: no point data array 'volume'")
damaged("not_xml", raw[:start - 300], r"{file}:\d+: not a VTK XML file")
volume_at = raw.index(b'Name="volume"')
offset = int(re.search(rb'offset="(\d+)"', raw[volume_at:]).group(1))
nan_file = bytearray(raw)
nan_file[start + offset + 4: start + offset + 12] = bytes.fromhex("000000000000f87f")  # the first volume: NaN
damaged("nan_volume", bytes(nan_file), r"{file}:\d+: PointData 'volume': point id 0: volume must be positive and finite \(got nan\)")

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
