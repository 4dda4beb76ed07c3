#!/usr/bin/python3
"""Non-Newtonian pipe flow: the steady profile of each fluid on its finest mesh (nodes of rank 0)
against its reference, and the power-law profile errors against the mesh size."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
levels = list(csv.DictReader(open(out / "levels.csv")))
fluids = ["power_law", "power_law_thinning", "casson", "carreau_yasuda"]
titles = ["power law n 1.5", "power law n 0.5", "casson", "carreau yasuda"]
fig, axes = plt.subplots(1, 5, figsize=(21, 4.2))
for ax, fluid, title in zip(axes, fluids, titles):
    runs = [lv for lv in levels if lv["fluid"] == fluid]
    if not runs:  # --set fluid=... ran the others only
        ax.set_axis_off()
        continue
    finest = max(runs, key=lambda lv: int(lv["n"]))
    rows = list(csv.DictReader(open(out / f"profile_{fluid}_{finest['n']}.csv")))
    rows.sort(key=lambda r: float(r["r"]))
    r = [float(x["r"]) * 1e3 for x in rows]
    ax.plot(r, [float(x["u_reference"]) for x in rows], "k-", lw=2, label="reference")
    ax.plot(r, [float(x["u"]) for x in rows], ".", ms=3, label=f"valsalva R/{finest['n']}")
    ax.set_xlabel("r (mm)")
    ax.set_ylabel("u_z (m/s)")
    ax.set_title(title)
    ax.legend(fontsize=8)
for fluid, label in (("power_law", "n 1.5"), ("power_law_thinning", "n 0.5")):
    power = [lv for lv in levels if lv["fluid"] == fluid]
    if not power:
        continue
    h = [float(lv["h"]) * 1e3 for lv in power]
    e = [float(lv["profile_l2_over_umax"]) for lv in power]
    axes[4].loglog(h, e, "o-", label=f"power law {label}, L2 / u_max")
    axes[4].loglog(h, [e[0] * (x / h[0]) ** 2 for x in h], "k:")
axes[4].plot([], [], "k:", label="h^2")
axes[4].set_xlabel("mesh size (mm)")
axes[4].set_ylabel("profile error")
axes[4].legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "non_newtonian_pipe.png", dpi=110)
