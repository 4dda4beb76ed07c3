"""Leaflet closure: top view of the free edge (open and closed, three leaflets by 120-degree
rotation) and side view of the symmetry line. Usage: plot.py OUT_DIR (reads leaflet_lines.csv)."""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/leaflet_lines.csv")))
lines = {}
for r in rows:
    lines.setdefault(r["line"], []).append({k: float(v) for k, v in r.items() if k != "line"})

fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4.5))
edge = lines["free_edge"]
for k in range(3):
    c, s = math.cos(2 * math.pi * k / 3), math.sin(2 * math.pi * k / 3)
    for key, style, label in (("X", "--", "open"), ("x", "-", "closed")):
        yk = key.replace("x", "y").replace("X", "Y")
        px = [1e3 * (c * p[key] - s * p[yk]) for p in edge]
        py = [1e3 * (s * p[key] + c * p[yk]) for p in edge]
        a.plot(px, py, style, color=f"C{k}", label=f"{label}" if k == 0 else None)
a.set_aspect("equal")
a.set_xlabel("x [mm]")
a.set_ylabel("y [mm]")
a.set_title("free edge, top view (3 leaflets by symmetry)")
a.legend()
sym = lines["symmetry"]
b.plot([1e3 * p["X"] for p in sym], [1e3 * p["Z"] for p in sym], "--", label="open")
b.plot([1e3 * p["x"] for p in sym], [1e3 * p["z"] for p in sym], "-", label="closed")
b.axvline(0, color="k", lw=0.5)
b.set_aspect("equal")
b.set_xlabel("radial x [mm] (axis at 0)")
b.set_ylabel("z [mm]")
b.set_title("symmetry line theta = 0")
b.legend()
fig.tight_layout()
fig.savefig(f"{out}/leaflet_closure.png", dpi=120)
