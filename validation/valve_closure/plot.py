"""Valve closure: top and side views of the three leaflets' mid-surfaces, open and closed.
Usage: plot.py OUT_DIR (reads mid_surface.csv, writes valve_closure.png)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/mid_surface.csv")))
fig, (top, side) = plt.subplots(1, 2, figsize=(11, 5))
for k in ("1", "2", "3"):
    for state, alpha, size in (("open", 0.15, 1), ("closed", 0.8, 2)):
        p = [r for r in rows if r["leaflet"] == k and r["state"] == state]
        x = [1e3 * float(r["x"]) for r in p]
        y = [1e3 * float(r["y"]) for r in p]
        z = [1e3 * float(r["z"]) for r in p]
        label = f"leaflet {k} {state}"
        top.scatter(x, y, s=size, alpha=alpha, color=f"C{int(k) - 1}", label=label)
        side.scatter(x, z, s=size, alpha=alpha, color=f"C{int(k) - 1}")
top.set_aspect("equal")
top.set_xlabel("x [mm]")
top.set_ylabel("y [mm]")
top.set_title("mid-surfaces, top view (from the aorta)")
top.legend(fontsize=7, markerscale=4)
side.set_aspect("equal")
side.set_xlabel("x [mm]")
side.set_ylabel("z [mm] (flow towards +z)")
side.set_title("side view")
fig.tight_layout()
fig.savefig(f"{out}/valve_closure.png", dpi=110)
