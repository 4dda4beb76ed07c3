"""Taylor-Green vortex Re 100: velocity L2 error against h and against wall time (colour = mesh,
solid = central2, dashed = central4 with the 4th-order
viscous, pressure-gradient and divergence operators), and the truncation error of each momentum term against h."""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = Path(sys.argv[1])
rows = defaultdict(list)
for r in csv.DictReader(open(out / "errors.csv")):
    rows[(r["mesh"], r["scheme"])].append(r)
terms = defaultdict(list)
for r in csv.DictReader(open(out / "terms.csv")):
    terms[(r["mesh"], r["scheme"])].append(r)
meshes = sorted({m for m, _ in rows}, key=["hexa", "tetra", "tetra_perturbed"].index)
style = {"central2": "o-", "central4": "s--"}
fig, (ax_h, ax_t, ax_e) = plt.subplots(1, 3, figsize=(16, 4.8))
for (mesh, scheme), rs in rows.items():
    c = f"C{meshes.index(mesh)}"
    h = [float(r["h"]) for r in rs]
    e = [float(r["velocity_l2"]) for r in rs]
    t = [float(r["wall_seconds"]) for r in rs]
    ax_h.loglog(h, e, style[scheme], color=c, label=f"{mesh} {scheme}")
    ax_t.loglog(t, e, style[scheme], color=c, label=f"{mesh} {scheme}")
h0 = sorted({float(r["h"]) for rs in rows.values() for r in rs})
for p, ls in ((2, ":"), (4, "-.")):
    ax_h.loglog(h0, [3e-3 * (x / h0[-1]) ** p for x in h0], "k" + ls, lw=0.8, label=f"slope {p}")
for (mesh, scheme), rs in terms.items():
    c = f"C{meshes.index(mesh)}"
    h = [float(r["h"]) for r in rs]
    ax_e.loglog(h, [float(r["convection_l2"]) for r in rs], style[scheme], color=c,
                label=f"convection {mesh} {scheme}")
    ax_e.loglog(h, [float(r["viscous_l2"]) for r in rs], "^:" if scheme == "central2" else "v-.",
                color=c, label=f"viscous {mesh} {scheme}")
ax_h.set_xlabel("h [m]")
ax_t.set_xlabel("wall time [s]")
ax_e.set_xlabel("h [m]")
for ax in (ax_h, ax_t):
    ax.set_ylabel("velocity L2 error at t = 1 [m/s]")
ax_e.set_ylabel("truncation error on the exact fields (L2) [m/s2]")
for ax in (ax_h, ax_t, ax_e):
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=6)
fig.suptitle("Taylor-Green vortex, Re 100, t = 1: central2 (solid), central4 + 4th-order operators, "
             "dt ~ h^2 (dashed)")
fig.tight_layout()
fig.savefig(out / "taylor_green.png", dpi=110)
