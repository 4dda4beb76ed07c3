"""Time-order study: velocity L2 error against dt and against CPU time for each time integrator
(validation/time_order, errors.csv), with dt^2 and dt^4 slopes for comparison."""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = Path(sys.argv[1])
data = defaultdict(list)
meta = None
for r in csv.DictReader(open(out / "errors.csv")):
    if r["level"] == "reference":
        continue
    meta = (r["n"], r["t_end"])
    data[r["variant"]].append((float(r["dt"]), float(r["velocity_l2"]), float(r["cpu_seconds"])))
fig, (ax_dt, ax_cpu) = plt.subplots(1, 2, figsize=(11, 4.5))
for i, (variant, pts) in enumerate(data.items()):
    pts.sort()
    style = ("-" if "classic" in variant else "--") + ("o" if "project" in variant else "s")
    ax_dt.loglog([p[0] for p in pts], [p[1] for p in pts], style, color=f"C{i}", label=variant)
    ax_cpu.loglog([p[2] for p in pts], [p[1] for p in pts], style, color=f"C{i}", label=variant)
first = next(iter(data.values()))
dt0, e0 = first[-1][0], first[-1][1]
dts = [p[0] for p in first]
ax_dt.loglog(dts, [e0 * (d / dt0) ** 2 for d in dts], "k:", lw=0.8, label="dt^2")
ax_dt.loglog(dts, [e0 * (d / dt0) ** 4 for d in dts], "k-.", lw=0.8, label="dt^4")
ax_dt.set_xlabel("dt [s]")
ax_cpu.set_xlabel("CPU time [s] (summed over ranks)")
for ax in (ax_dt, ax_cpu):
    ax.set_ylabel("velocity L2 error vs reference run [m/s]")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7)
fig.suptitle(f"3D Taylor-Green Re 1600, {meta[0]}^3, t = {meta[1]}: time integration error")
fig.tight_layout()
fig.savefig(out / "time_order.png", dpi=110)
