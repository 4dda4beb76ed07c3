#!/usr/bin/python3
"""Periodic plane Poiseuille channel: the centreline start-up of each level against the series,
and the steady profile, wall-shear and start-up errors against the cell size."""
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
H, RHO, MU, F = 0.01, 1100.0, 3.6e-3, 28.8
NU, UMAX = MU / RHO, F * H * H / (8 * MU)
TAU = H * H / (math.pi ** 2 * NU)


def series(t):
    u = UMAX
    for n in range(1, 2001, 2):
        u -= (4 * F * H * H / (MU * math.pi ** 3 * n ** 3) * math.sin(n * math.pi / 2)
              * math.exp(-n * n * math.pi ** 2 * NU * t / (H * H)))
    return u


levels = list(csv.DictReader(open(out / "levels.csv")))
fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
ts = [TAU * 4 * k / 200 for k in range(201)]
a.plot([t / TAU for t in ts], [series(t) / UMAX for t in ts], "k-", lw=2, label="series")
for lv in levels:
    rows = list(csv.DictReader(open(out / "runs" / f"{lv['cells']}_{lv['n']}" / "probes.csv")))
    t = [float(r["time"]) / TAU for r in rows if float(r["time"]) <= 4 * TAU]
    u = [float(r["centre_u"]) / UMAX for r in rows][: len(t)]
    a.plot(t, u, "--", label=f"{lv['cells']} n {lv['n']}")
a.set_xlabel("t / tau  (tau = H^2 / (pi^2 nu))")
a.set_ylabel("u(H/2) / u_max")
a.set_title("start-up from rest")
a.legend()
tetra = [lv for lv in levels if lv["cells"] == "tetra"]
h = [float(lv["h"]) / H for lv in tetra]
for key, label in [("profile_l2_over_umax", "steady profile L2 / u_max"),
                   ("wss_relative_error", "wall shear stress, relative"),
                   ("startup_error_over_umax", "start-up / u_max")]:
    b.loglog(h, [max(float(lv[key]), 1e-16) for lv in tetra], "o-", label=label)
b.loglog(h, [0.5 * (x / h[0]) ** 2 * float(tetra[0]["profile_l2_over_umax"]) for x in h], "k:",
         label="h^2")
b.set_xlabel("h / H (20 % perturbed tetrahedra)")
b.set_ylabel("error")
b.set_title("errors against the cell size")
b.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "poiseuille_channel.png", dpi=110)
