#!/usr/bin/python3
"""Lid-driven cavity Re 100: centreline profiles on every mesh against Ghia et al. (1982),
and the max deviation against the cell size."""
import csv
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
ghia = list(csv.DictReader(open(out / "ghia_Re100.csv")))
files = sorted(out.glob("profiles_N*.csv"), key=lambda f: int(re.findall(r"\d+", f.stem)[0]))

fig, (au, av) = plt.subplots(1, 2, figsize=(11, 5))
for f in files:
    rows = list(csv.DictReader(open(f)))
    s = [float(r["s"]) for r in rows]
    n = f.stem.replace("profiles_N", "")
    au.plot([float(r["u_at_x_half"]) for r in rows], s, label=f"N = {n}")
    av.plot(s, [float(r["v_at_y_half"]) for r in rows], label=f"N = {n}")
gu = [r for r in ghia if r["line"] == "u"]
gv = [r for r in ghia if r["line"] == "v"]
au.plot([float(r["value"]) for r in gu], [float(r["s"]) for r in gu], "ko", mfc="none",
        label="Ghia et al. 1982")
av.plot([float(r["s"]) for r in gv], [float(r["value"]) for r in gv], "ko", mfc="none",
        label="Ghia et al. 1982")
au.set_xlabel("u / U at x = 0.5")
au.set_ylabel("y / L")
av.set_xlabel("x / L")
av.set_ylabel("v / U at y = 0.5")
for a in (au, av):
    a.grid(alpha=0.3)
    a.legend()
fig.suptitle("Lid-driven cavity, Re = 100, hexahedral slab")
fig.tight_layout()
fig.savefig(out / "cavity_profiles.png", dpi=120)

conv = out / "convergence.csv"
if conv.exists():
    rows = list(csv.DictReader(open(conv)))
    h = [float(r["h"]) for r in rows]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for key, label in (("max_dev_u", "u(y) at x = 0.5"), ("max_dev_v", "v(x) at y = 0.5")):
        ax.loglog(h, [float(r[key]) for r in rows], "o-", label=label)
    ax.loglog(h, [float(rows[0]["max_dev"]) * (x / h[0]) ** 2 for x in h], "k--",
              label="h^2")
    ax.axhline(0.01, color="r", lw=0.8, label="1 % of U")
    ax.set_xlabel("h / L")
    ax.set_ylabel("max |computed - Ghia| / U")
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "cavity_convergence.png", dpi=120)
