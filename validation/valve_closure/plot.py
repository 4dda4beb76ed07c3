"""Valve closure: top and side views of the three leaflets' mid-surfaces, open and closed, and
the closed mid-surfaces near the axis with the bending-only fold (fold.csv) in each leaflet's
corner. Usage: plot.py OUT_DIR (reads mid_surface.csv and fold.csv, writes valve_closure.png)."""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/mid_surface.csv")))
fig, (top, side, centre) = plt.subplots(1, 3, figsize=(16, 5))
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
# Near the axis: the closed mid-surface nodes and, in each leaflet's corner (bisector towards
# the open leaflet's centre), the mid-surface of the fold bending alone leaves.
fold_file = f"{out}/fold.csv"
fold = list(csv.DictReader(open(fold_file))) if os.path.exists(fold_file) else []
for k in ("1", "2", "3"):
    closed = [r for r in rows if r["leaflet"] == k and r["state"] == "closed"]
    near = [r for r in closed if math.hypot(float(r["x"]), float(r["y"])) < 2.5e-3]
    centre.scatter([1e3 * float(r["x"]) for r in near], [1e3 * float(r["y"]) for r in near],
                   s=6, color=f"C{int(k) - 1}", label=f"leaflet {k} closed")
    opened = [r for r in rows if r["leaflet"] == k and r["state"] == "open"]
    angle = math.atan2(sum(float(r["y"]) for r in opened), sum(float(r["x"]) for r in opened))
    c, s_ = math.cos(angle - math.pi / 2), math.sin(angle - math.pi / 2)
    if fold:
        fx = [1e3 * (c * float(q["x"]) - s_ * float(q["y"])) for q in fold]
        fy = [1e3 * (s_ * float(q["x"]) + c * float(q["y"])) for q in fold]
        centre.plot(fx, fy, "k-", lw=1, label="bending-only fold" if k == "1" else None)
centre.set_aspect("equal")
centre.set_xlim(-2.5, 2.5)
centre.set_ylim(-2.5, 2.5)
centre.set_xlabel("x [mm]")
centre.set_ylabel("y [mm]")
centre.set_title("closed, near the axis (all heights)")
centre.legend(fontsize=7, markerscale=2)
fig.tight_layout()
fig.savefig(f"{out}/valve_closure.png", dpi=110)
