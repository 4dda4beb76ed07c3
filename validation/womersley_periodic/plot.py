#!/usr/bin/python3
"""Periodic Womersley pipe: u_z / u_peak against r / R at the 8 phases of the last period
(dots: every node of the laminar prism runs, lines: exact, curves.csv), one panel per level, and the error
convergence."""
import csv
import pathlib
import sys
from collections import defaultdict

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
points = defaultdict(lambda: defaultdict(list))
for row in csv.DictReader(open(out / "samples.csv")):
    points[row["case"]][float(row["time"])].append((float(row["r"]), float(row["u"]),
                                                    float(row["u_exact"])))
curves = defaultdict(lambda: defaultdict(list))
for row in csv.DictReader(open(out / "curves.csv")):
    curves[row["case"]][float(row["time"])].append((float(row["r"]), float(row["u_exact"])))
levels = list(csv.DictReader(open(out / "levels.csv")))
meta = {}
for row in csv.DictReader(open(out / "samples.csv")):
    meta[row["case"]] = (float(row["u_peak"]), float(row["radius"]))

cases = sorted(points, key=lambda c: float(c.split("_d")[1]))
fig, axes = plt.subplots(1, len(cases) + 1, figsize=(4.6 * (len(cases) + 1), 4.2), squeeze=False)
for ax, case in zip(axes[0], cases):
    peak, radius = meta[case]
    colours = plt.cm.viridis(np.linspace(0, 1, len(points[case])))
    for colour, t in zip(colours, sorted(points[case])):
        rows = sorted(points[case][t])
        r = np.array([p[0] for p in rows]) / radius
        ax.plot(r, [p[1] / peak for p in rows], ".", ms=2, color=colour)
        c = curves[case][t]
        ax.plot([p[0] / radius for p in c], [p[1] / peak for p in c], "-", lw=0.8,
                color=colour, label=f"t = {t:.3f} s")
    lv = next(x for x in levels if x["case"] == case)
    ax.set_title(f"{case}: max err {100 * float(lv['max_error']):.2f} %, "
                 f"L2 {100 * float(lv['l2_error']):.2f} %", fontsize=9)
    ax.set_xlabel("r / R")
    ax.set_ylabel("u_z / u_peak")
    ax.grid(alpha=0.3)
axes[0][0].legend(fontsize=6)
ax = axes[0][-1]
lam = [x for x in levels if x["les"] == "none" and x["cells"] == "prism"]
npd = np.array([float(x["nodes_per_diameter"]) for x in lam])
for key, mark in (("max_error", "o-"), ("l2_error", "s-")):
    ax.loglog(npd, [float(x[key]) for x in lam], mark, label=key.replace("_", " "))
ax.loglog(npd, float(lam[-1]["l2_error"]) * (npd[-1] / npd) ** 2, "k--", lw=0.8,
          label="slope 2")
ax.set_xlabel("D / h")
ax.set_ylabel("error / u_peak")
ax.legend(fontsize=8)
ax.grid(alpha=0.3, which="both")
fig.suptitle("Periodic Womersley pipe, Wo 17, pressure-gradient drive: dots = valsalva, "
             "lines = exact")
fig.tight_layout()
fig.savefig(out / "womersley_periodic.png", dpi=110)
