#!/usr/bin/python3
"""A mesh's cells as a point cloud for `domain.particles:` (docs/scene_format.md).

Each cell becomes one particle at its centroid, with the cell's area (2D) or volume (3D)
as point data "volume" (both from VTK's triangulation of the cell into simplices); with
--material NAME, the integer cell array NAME becomes point data "material", shifted so
that its smallest value is 0 (the index into the scene's `materials`). The output is a
.vtu that `pd run` reads (and ParaView shows).

Reads what VTK reads: .vtu, or legacy .vtk (gmsh writes it: `gmsh -2 body.geo -format vtk`).
In 2D only the mesh's 2D cells (triangles, quads, polygons) become particles, in 3D only
its 3D cells; boundary lines or faces a mesher adds are dropped.

usage: mesh_to_particles.py MESH OUT.vtu [--dim 2|3] [--material CELL_ARRAY] [--ascii]
"""
import argparse
import sys

try:
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkIntArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import VTK_VERTEX, vtkUnstructuredGrid
    from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
except ImportError as e:
    sys.exit(f"mesh_to_particles.py: VTK for Python is missing ({e}); apt-get install python3-vtk9")


def simplex_measure(p, dim):
    """Area of a triangle (dim 2) or volume of a tetrahedron (dim 3), and its centroid."""
    a = [[p[k][c] - p[0][c] for c in range(3)] for k in range(1, dim + 1)]
    if dim == 2:
        cx = [a[0][1] * a[1][2] - a[0][2] * a[1][1], a[0][2] * a[1][0] - a[0][0] * a[1][2], a[0][0] * a[1][1] - a[0][1] * a[1][0]]
        m = 0.5 * sum(c * c for c in cx) ** 0.5
    else:
        m = abs(a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])) / 6
    centre = [sum(q[c] for q in p) / (dim + 1) for c in range(3)]
    return m, centre


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mesh")
    ap.add_argument("out")
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--material", help="an integer cell array of the mesh (e.g. gmsh's gmsh:physical)")
    ap.add_argument("--ascii", action="store_true", help="write ASCII instead of appended binary")
    a = ap.parse_args()
    reader = vtkXMLUnstructuredGridReader() if a.mesh.endswith(".vtu") else vtkUnstructuredGridReader()
    reader.SetFileName(a.mesh)
    reader.Update()
    mesh = reader.GetOutput()
    if mesh is None or mesh.GetNumberOfCells() == 0:
        sys.exit(f"mesh_to_particles.py: {a.mesh}: VTK read no cells")
    groups = mesh.GetCellData().GetArray(a.material) if a.material else None
    if a.material and groups is None:
        sys.exit(f"mesh_to_particles.py: {a.mesh} has no cell array '{a.material}'")
    points, volume, material = vtkPoints(), vtkDoubleArray(), vtkIntArray()
    points.SetDataTypeToDouble()
    volume.SetName("volume")
    material.SetName("material")
    ids, simplex_points = vtkIdList(), vtkPoints()
    kept_groups = []
    for i in range(mesh.GetNumberOfCells()):
        cell = mesh.GetCell(i)
        if cell.GetCellDimension() != a.dim:
            continue
        cell.Triangulate(0, ids, simplex_points)  # simplices: dim + 1 points each
        total, centre = 0.0, [0.0, 0.0, 0.0]
        for s in range(0, simplex_points.GetNumberOfPoints(), a.dim + 1):
            m, c = simplex_measure([simplex_points.GetPoint(s + k) for k in range(a.dim + 1)], a.dim)
            total += m
            centre = [centre[k] + m * c[k] for k in range(3)]
        if total <= 0:
            sys.exit(f"mesh_to_particles.py: {a.mesh}: cell {i} has no {'area' if a.dim == 2 else 'volume'}")
        points.InsertNextPoint([c / total for c in centre])
        volume.InsertNextValue(total)
        if groups is not None:
            kept_groups.append(int(groups.GetTuple1(i)))
    if points.GetNumberOfPoints() == 0:
        sys.exit(f"mesh_to_particles.py: {a.mesh} has no {a.dim}D cells")
    out = vtkUnstructuredGrid()
    out.SetPoints(points)
    for i in range(points.GetNumberOfPoints()):
        out.InsertNextCell(VTK_VERTEX, 1, [i])
    out.GetPointData().AddArray(volume)
    if kept_groups:
        lowest = min(kept_groups)
        for g in kept_groups:
            material.InsertNextValue(g - lowest)
        out.GetPointData().AddArray(material)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(a.out)
    w.SetInputData(out)
    if a.ascii:
        w.SetDataModeToAscii()
    if not w.Write():
        sys.exit(f"mesh_to_particles.py: cannot write {a.out}")
    total = sum(volume.GetValue(i) for i in range(volume.GetNumberOfTuples()))
    print(f"{a.out}: {points.GetNumberOfPoints()} particles, total {'area' if a.dim == 2 else 'volume'} {total:.12g}")


if __name__ == "__main__":
    main()
