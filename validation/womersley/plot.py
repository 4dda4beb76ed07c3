#!/usr/bin/python3
"""Womersley pipe: axial velocity on the mid-length section at 8 phases, numeric (dots, signed
radius x / |x| r) against the exact profile (lines), one panel per laminar case; error table
in the title."""
import csv
import pathlib
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
points = defaultdict(lambda: defaultdict(list))
for row in csv.DictReader(open(out / "profiles.csv")):
    points[row["case"]][float(row["time"])].append(row)
curves = defaultdict(lambda: defaultdict(list))
for row in csv.DictReader(open(out / "curves.csv")):
    curves[row["case"]][float(row["time"])].append(row)
levels = {r["case"]: r for r in csv.DictReader(open(out / "levels.csv"))}

cases = [c for c in points if levels.get(c, {}).get("les", "none") == "none"]
columns = min(3, len(cases))
rows = (len(cases) + columns - 1) // columns
fig, axes = plt.subplots(rows, columns, figsize=(5.2 * columns, 4.6 * rows), squeeze=False)
for ax in axes.flat[len(cases):]:
    ax.axis("off")
for ax, case in zip(axes.flat, cases):
    colours = plt.cm.viridis([i / 8 for i in range(8)])
    for colour, t in zip(colours, sorted(points[case])):
        rows = points[case][t]
        radius = float(rows[0]["radius"])
        peak = float(rows[0]["u_peak"])
        s = [float(r["r"]) / radius * (1 if float(r["x"]) >= 0 else -1) for r in rows]
        ax.plot(s, [float(r["u"]) / peak for r in rows], ".", ms=3, color=colour)
        c = curves[case][t]
        ax.plot([float(r["s"]) for r in c], [float(r["u_exact"]) / peak for r in c], "-",
                color=colour, lw=1, label=f"t = {t:.3f} s")
    lv = levels[case]
    ax.set_title(f"Wo {float(lv['wo']):g}, D/{float(lv['nodes_per_diameter']):g}, "
                 f"{lv['mesh']} mesh ({lv['nodes']} nodes), {lv['outlet']} outlet\nmax err {100 * float(lv['max_error']):.2f} %, "
                 f"L2 {100 * float(lv['l2_error']):.2f} % of u_peak", fontsize=9)
    ax.set_xlabel("signed r / R")
    ax.set_ylabel("u_z / u_peak")
    ax.grid(alpha=0.3)
axes[0][0].legend(fontsize=7, loc="lower center")
fig.suptitle("Womersley pipe: dots = valsalva (mid-length section nodes), lines = exact")
fig.tight_layout()
fig.savefig(out / "womersley_profiles.png", dpi=120)
