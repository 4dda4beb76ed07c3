"""Membrane relaxation: enclosed-volume drift and shape deviation against time, and the
equatorial section at the start and the end against the stress-free circle.
Usage: plot.py OUT_DIR (reads relaxation.csv, equator.csv)."""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(f"{out}/relaxation.csv"))]
eq = list(csv.DictReader(open(f"{out}/equator.csv")))

fig, (a, b, c) = plt.subplots(1, 3, figsize=(14, 4.2))
t = [r["time"] for r in rows]
a.plot(t, [100 * r["volume_drift"] for r in rows])
a.set_xlabel("t [s]")
a.set_ylabel("V/V0 - 1 [%]")
a.set_title("enclosed volume drift (IB leakage)")
a.grid(alpha=0.3)
b.semilogy(t, [max(r["shape_deviation"], 1e-6) for r in rows])
b.set_xlabel("t [s]")
b.set_ylabel("(r_max - r_min) / r_mean")
b.set_title("shape deviation from a sphere")
b.grid(alpha=0.3, which="both")
r_end = rows[-1]["mean_radius"]
for when, style in (("start", "o"), ("end", ".")):
    pts = [(float(p["x"]), float(p["y"])) for p in eq if p["when"] == when]
    cx = sum(p[0] for p in pts) / len(pts)
    cy = sum(p[1] for p in pts) / len(pts)
    pts.sort(key=lambda p: math.atan2(p[1] - cy, p[0] - cx))
    c.plot([p[0] for p in pts], [p[1] for p in pts], style, ms=3, label=when)
th = [2 * math.pi * k / 200 for k in range(201)]
c.plot([cx + r_end * math.cos(s) for s in th], [cy + r_end * math.sin(s) for s in th], "k-",
       lw=0.7, label="circle, final mean radius")
c.set_aspect("equal")
c.set_xlabel("x [m]")
c.set_ylabel("y [m]")
c.set_title("inner surface, equatorial section")
c.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{out}/membrane_relaxation.png", dpi=120)
