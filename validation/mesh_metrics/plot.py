"""Plot of the mesh-metric identity errors per mesh against their tolerances."""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = Path(sys.argv[1])
rows = list(csv.DictReader(open(out / "identities.csv")))
names = [r["mesh"] for r in rows]
floor = 1e-18  # exact zeros are drawn at the floor of the log axis
fig, ax = plt.subplots(figsize=(10, 4.5))
for k, (key, tol, marker) in enumerate(
    [("volume_error", 1e-12, "o"), ("closure_error", 1e-12, "s"), ("gradient_error", 1e-10, "^")]
):
    values = [max(float(r[key]), floor) for r in rows]
    ax.semilogy(range(len(rows)), values, marker, label=f"{key} (tolerance {tol:g})")
    ax.axhline(tol, color=f"C{k}", ls="--", lw=0.8)
ax.set_xticks(range(len(rows)))
ax.set_xticklabels(names, rotation=40, ha="right", fontsize=8)
ax.set_ylabel("relative error")
ax.set_title("Median-dual identities on every mesh type")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "mesh_metrics.png", dpi=110)
