"""Taylor-Green vortex: velocity L2 error against h and against wall time, one line per mesh."""
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
    rows[r["mesh"]].append(r)
fig, (ax_h, ax_t) = plt.subplots(1, 2, figsize=(11, 4.5))
for k, (mesh, rs) in enumerate(rows.items()):
    h = [float(r["h"]) for r in rs]
    e = [float(r["velocity_l2"]) for r in rs]
    t = [float(r["wall_seconds"]) for r in rs]
    ax_h.loglog(h, e, "o-", color=f"C{k}", label=mesh)
    ax_t.loglog(t, e, "o-", color=f"C{k}", label=mesh)
h0 = [float(r["h"]) for r in next(iter(rows.values()))]
e0 = float(next(iter(rows.values()))[0]["velocity_l2"])
ax_h.loglog(h0, [e0 * (x / h0[0]) ** 2 for x in h0], "k--", lw=0.8, label="slope 2")
ax_h.set_xlabel("h [m]")
ax_t.set_xlabel("wall time [s]")
for ax in (ax_h, ax_t):
    ax.set_ylabel("velocity L2 error [m/s]")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
fig.suptitle("Taylor-Green vortex, Re 100, t = 1, 2nd-order centred scheme")
fig.tight_layout()
fig.savefig(out / "taylor_green.png", dpi=110)
