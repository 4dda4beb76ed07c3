#!/usr/bin/python3
"""Non-Newtonian pipe flow: the steady profile of each fluid on its finest mesh (nodes of rank 0)
against its reference, and the power-law profile error against the mesh size."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
levels = list(csv.DictReader(open(out / "levels.csv")))
fluids = ["power_law", "casson", "carreau_yasuda"]
fig, axes = plt.subplots(1, 4, figsize=(17, 4.2))
for ax, fluid in zip(axes, fluids):
    runs = [lv for lv in levels if lv["fluid"] == fluid]
    if not runs:  # --set fluid=... ran the others only
        ax.set_axis_off()
        continue
    finest = max(runs, key=lambda lv: int(lv["n"]))
    rows = list(csv.DictReader(open(out / "runs" / f"{fluid}_{finest['n']}" / "profile.csv")))
    rows.sort(key=lambda r: float(r["r"]))
    r = [float(x["r"]) * 1e3 for x in rows]
    ax.plot(r, [float(x["u_reference"]) for x in rows], "k-", lw=2, label="reference")
    ax.plot(r, [float(x["u"]) for x in rows], ".", ms=3, label=f"valsalva R/{finest['n']}")
    ax.set_xlabel("r (mm)")
    ax.set_ylabel("u_z (m/s)")
    ax.set_title(fluid.replace("_", " "))
    ax.legend(fontsize=8)
power = [lv for lv in levels if lv["fluid"] == "power_law"]
if not power:
    power = [{"h": "nan", "profile_l2_over_umax": "nan"}]
h = [float(lv["h"]) * 1e3 for lv in power]
e = [float(lv["profile_l2_over_umax"]) for lv in power]
axes[3].loglog(h, e, "o-", label="power law n 1.5, L2 / u_max")
axes[3].loglog(h, [e[0] * (x / h[0]) ** 2 for x in h], "k:", label="h^2")
axes[3].set_xlabel("mesh size (mm)")
axes[3].set_ylabel("profile error")
axes[3].legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "non_newtonian_pipe.png", dpi=110)
