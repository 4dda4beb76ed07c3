#!/usr/bin/env python3
"""Independent check of an XdmfWriter time series: the .xmf must be well-formed XML with one
temporal collection of STEPS uniform grids, increasing times, and every DataItem must name an
existing HDF5 dataset (read with h5py) whose shape equals the stated Dimensions.
Usage: check_xdmf.py FILE.xmf STEPS   (exit code 0 when every check passes)"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py


def main(path, steps):
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
        if topo is None or topo.get("TopologyType") != "Mixed":
            errors.append(f"{grid.get('Name')}: no Mixed topology")
        for item in grid.iter("DataItem"):
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            fname, dset = item.text.strip().split(":")
            h5path = os.path.join(os.path.dirname(path), fname)
            with h5py.File(h5path, "r") as f:
                if dset not in f:
                    errors.append(f"{fname}:{dset} missing")
                elif f[dset].shape != dims:
                    errors.append(f"{fname}:{dset} shape {f[dset].shape}, xmf says {dims}")
    for e in errors:
        print("check_xdmf:", e, file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))
