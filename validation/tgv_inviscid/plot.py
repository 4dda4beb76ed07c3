"""Inviscid Taylor-Green vortex: relative kinetic-energy change against time (CFL 0.5) and the
drift at t = 10 against dt (colour = mesh, solid = central2, dashed = central4)."""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = Path(sys.argv[1])
series = defaultdict(lambda: ([], []))
for r in csv.DictReader(open(out / "energy.csv")):
    if float(r["cfl"]) == 0.5:
        s = series[(r["mesh"], r["scheme"])]
        s[0].append(float(r["t"]))
        s[1].append(float(r["relative_energy_change"]))
drift = defaultdict(list)
for r in csv.DictReader(open(out / "drift.csv")):
    drift[(r["mesh"], r["scheme"])].append((float(r["dt"]), abs(float(r["drift"]))))
meshes = sorted({m for m, _ in series})
style = {"central2": "-", "central4": "--"}
fig, (ax_t, ax_d) = plt.subplots(1, 2, figsize=(11, 4.5))
for (mesh, scheme), (t, e) in series.items():
    ax_t.plot(t, e, style[scheme], color=f"C{meshes.index(mesh)}", label=f"{mesh} {scheme}")
for (mesh, scheme), pts in drift.items():
    pts.sort()
    ax_d.loglog([p[0] for p in pts], [p[1] for p in pts], "o" + style[scheme],
                color=f"C{meshes.index(mesh)}", label=f"{mesh} {scheme}")
ax_t.set_xlabel("t [L/U0]")
ax_t.set_ylabel("E(t)/E(0) - 1 (CFL 0.5)")
ax_d.set_xlabel("dt [s]")
ax_d.set_ylabel("|E(10)/E(0) - 1|")
for ax in (ax_t, ax_d):
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7)
fig.suptitle("Inviscid Taylor-Green vortex (steady Euler solution), 10 convective times")
fig.tight_layout()
fig.savefig(out / "tgv_inviscid.png", dpi=110)
