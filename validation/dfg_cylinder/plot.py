#!/usr/bin/python3
"""DFG 2D-1: c_D, c_L and dp against the number of nodes, with the 1996 reference intervals."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
rows = list(csv.DictReader(open(out / "dfg_2d1.csv")))
nodes = [float(r["nodes"]) for r in rows]
fig, axes = plt.subplots(1, 3, figsize=(12, 3.8))
for ax, key, lo, hi in zip(axes, ["c_D", "c_L", "dp"], [5.57, 0.0104, 0.1172],
                           [5.59, 0.0110, 0.1176]):
    ax.semilogx(nodes, [float(r[key]) for r in rows], "o-", label="valsalva")
    ax.axhspan(lo, hi, color="0.8", label="Schaefer & Turek 1996")
    ax.set_xlabel("fluid nodes")
    ax.set_title(key)
axes[0].legend()
fig.suptitle("DFG cylinder 2D-1 (Re 20), tetrahedral slab")
fig.tight_layout()
fig.savefig(out / "dfg_2d1.png", dpi=120)
