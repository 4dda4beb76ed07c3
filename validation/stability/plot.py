#!/usr/bin/python3
"""Kinetic energy against time of the long-run stability case, both meshes."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
fig, ax = plt.subplots(figsize=(7, 4))
for f in sorted(out.glob("energy_*.csv")):
    rows = list(csv.DictReader(open(f)))
    ax.plot([float(r["step"]) for r in rows], [float(r["energy"]) / 0.25 for r in rows],
            label=f.stem.replace("energy_", ""))
ax.set_xlabel("step (dt at the RK4 stability limit)")
ax.set_ylabel("E / (U^2/4)")
ax.set_title("Forced Kolmogorov flow, largest admissible time step")
ax.legend()
fig.tight_layout()
fig.savefig(out / "energy.png", dpi=120)
