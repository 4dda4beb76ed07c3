#!/usr/bin/python3
# Compares two CSV time series with the same header (probes.csv, pressure_drop.csv): tolerance 0
# asks for identical text, otherwise max |a - b| <= tol * max(1, max |a|) per column.
# Usage: compare_csv.py A.csv B.csv TOL
import sys

import numpy as np

a_path, b_path, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
a_lines, b_lines = open(a_path).read().splitlines(), open(b_path).read().splitlines()
if a_lines[0] != b_lines[0]:
    sys.exit(f"headers differ: {a_lines[0]} / {b_lines[0]}")
if len(a_lines) != len(b_lines):
    sys.exit(f"{a_path} has {len(a_lines)} lines, {b_path} {len(b_lines)}")
if tol == 0:
    if a_lines != b_lines:
        sys.exit(f"{a_path} and {b_path} differ")
    print(f"{a_path}: {len(a_lines) - 1} rows, identical")
    sys.exit(0)
x = np.genfromtxt(a_path, delimiter=",", skip_header=1)
y = np.genfromtxt(b_path, delimiter=",", skip_header=1)
diff = np.nanmax(np.abs(x - y), axis=0)
scale = np.maximum(1.0, np.nanmax(np.abs(x), axis=0))
print(f"{a_path}: {x.shape[0]} rows, max |diff| / scale {np.max(diff / scale):.3e} (tolerance {tol:g})")
if np.any(diff > tol * scale):
    sys.exit(f"{a_path} and {b_path} differ")
