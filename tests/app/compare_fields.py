#!/usr/bin/python3
# Compares datasets (default velocity and pressure) of two field files (valsalva FieldOutput
# HDF5): tolerance 0 asks for bitwise equality, otherwise max |a - b| <= tol * max(1, max |a|).
# Usage: compare_fields.py A.h5 B.h5 TOL [DATASET ...]
import sys

import h5py
import numpy as np

a_path, b_path, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
names = sys.argv[4:] or ["velocity", "pressure"]
with h5py.File(a_path, "r") as a, h5py.File(b_path, "r") as b:
    for name in names:
        x, y = np.asarray(a[name]), np.asarray(b[name])
        if x.shape != y.shape:
            sys.exit(f"{name}: shapes {x.shape} and {y.shape} differ")
        diff = float(np.max(np.abs(x - y)))
        scale = max(1.0, float(np.max(np.abs(x))))
        ok = np.array_equal(x.view(np.uint64), y.view(np.uint64)) if tol == 0 else diff <= tol * scale
        print(f"{name}: {x.size} values, max |diff| {diff:.3e} (tolerance {tol:g} x {scale:.3g})")
        if not ok:
            sys.exit(f"{name}: {a_path} and {b_path} differ")
