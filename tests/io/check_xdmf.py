#!/usr/bin/env python3
"""Independent check of an XdmfWriter time series: the .xmf must be well-formed XML with one
temporal collection of STEPS uniform grids, increasing times, and every DataItem must name an
existing HDF5 dataset (read with h5py) whose shape equals the stated Dimensions.
Where VTK's Python module is installed (python3-vtk9; Debian's build has no XDMF reader), the
mixed topology is also loaded into a vtkUnstructuredGrid: every face VTK defines for a cell must
have its normal pointing out of the cell, i.e. the node order is VTK's (as XDMF's is).
Usage: check_xdmf.py FILE.xmf STEPS [TOPOLOGY]   (exit code 0 when every check passes)
TOPOLOGY (default Mixed, the fluid mesh) is the expected TopologyType, e.g. Hexahedron_27 for the
Lagrangian meshes of immersed structures (no VTK orientation check for those)."""
import os
import sys
import xml.etree.ElementTree as ET

import h5py


def vtk_orientation(directory, collection):
    try:
        import numpy as np
        from vtkmodules import vtkCommonCore as core  # the two modules only: fast to import
        from vtkmodules import vtkCommonDataModel as model
    except ImportError:
        print("check_xdmf: VTK not installed, cell orientation not checked")
        return []
    grid = collection.find("Grid")
    def dataset(tag):
        fname, dset = grid.find(tag + "/DataItem").text.strip().split(":")
        with h5py.File(os.path.join(directory, fname), "r") as f:
            return f[dset][:]
    xyz, topo = dataset("Geometry"), dataset("Topology")
    points = core.vtkPoints()
    for p in xyz:
        points.InsertNextPoint(*p)
    mesh = model.vtkUnstructuredGrid()
    mesh.SetPoints(points)
    # Surface cells (triangles, quads of a boundary) have no faces: only loaded.
    vtk_type = {4: (model.VTK_TRIANGLE, 3), 5: (model.VTK_QUAD, 4), 6: (model.VTK_TETRA, 4),
                7: (model.VTK_PYRAMID, 5), 8: (model.VTK_WEDGE, 6), 9: (model.VTK_HEXAHEDRON, 8)}
    pos = 0
    while pos < len(topo):
        kind, n = vtk_type[int(topo[pos])]
        ids = core.vtkIdList()
        for node in topo[pos + 1:pos + 1 + n]:
            ids.InsertNextId(int(node))
        mesh.InsertNextCell(kind, ids)
        pos += 1 + n
    errors = []
    for c in range(mesh.GetNumberOfCells()):
        cell = mesh.GetCell(c)
        centre = np.mean([xyz[cell.GetPointId(i)] for i in range(cell.GetNumberOfPoints())], axis=0)
        for f in range(cell.GetNumberOfFaces()):
            face = cell.GetFace(f)
            p = np.array([xyz[face.GetPointId(i)] for i in range(face.GetNumberOfPoints())])
            normal = sum(np.cross(p[i], p[(i + 1) % len(p)]) for i in range(len(p)))  # Newell
            if np.dot(normal, p.mean(axis=0) - centre) <= 0:
                errors.append(f"cell {c} ({cell.GetClassName()}): face {f} points inwards")
    print(f"check_xdmf: VTK orientation of {mesh.GetNumberOfCells()} cells checked")
    return errors


def main(path, steps, topology="Mixed"):
    root = ET.parse(path).getroot()  # raises on malformed XML
    errors = []
    collections = root.findall("./Domain/Grid")
    if len(collections) != 1 or collections[0].get("CollectionType") != "Temporal":
        errors.append("expected one temporal collection under Domain")
    grids = collections[0].findall("Grid") if collections else []
    if len(grids) != steps:
        errors.append(f"{len(grids)} steps, expected {steps}")
    times = [float(g.find("Time").get("Value")) for g in grids]
    if times != sorted(times) or len(set(times)) != len(times):
        errors.append(f"times not increasing: {times}")
    for grid in grids:
        topo = grid.find("Topology")
        if topo is None or topo.get("TopologyType") != topology:
            errors.append(f"{grid.get('Name')}: no {topology} topology")
        for item in grid.iter("DataItem"):
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            fname, dset = item.text.strip().split(":")
            h5path = os.path.join(os.path.dirname(path), fname)
            with h5py.File(h5path, "r") as f:
                if dset not in f:
                    errors.append(f"{fname}:{dset} missing")
                elif f[dset].shape != dims:
                    errors.append(f"{fname}:{dset} shape {f[dset].shape}, xmf says {dims}")
    if topology == "Mixed":
        errors += vtk_orientation(os.path.dirname(path), collections[0] if collections else None)
    for e in errors:
        print("check_xdmf:", e, file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2]), *sys.argv[3:4]))
