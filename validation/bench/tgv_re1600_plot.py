#!/usr/bin/python3
"""Plots of the Taylor-Green Re 1600 benchmark (bench_tgv_re1600): -dE/dt against time for every
run with the spectral reference, and the work-precision diagram (max error of -dE/dt against
CPU time). Usage: tgv_re1600_plot.py [OUT_DIR]  (default bench-results/tgv_re1600)."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "bench-results/tgv_re1600")
rows = list(csv.DictReader(open(out / "summary.csv")))

fig, ax = plt.subplots(figsize=(7, 4.5))
reference_drawn = False
for r in rows:
    f = out / f"tgv_{r['scheme']}_{r['n']}_np{r['ranks']}.csv"
    if not f.exists() or r["ranks"] != "1":
        continue
    data = list(csv.DictReader(open(f)))
    t = [float(d["t"]) for d in data]
    ax.plot(t, [float(d["dissipation"]) for d in data], label=f"{r['scheme']} {r['n']}^3")
    if not reference_drawn:
        ax.plot(t, [float(d["dissipation_reference"]) for d in data], "k--",
                label="spectral 512^3")
        reference_drawn = True
ax.set_xlabel("t (L/V0)")
ax.set_ylabel("-dE/dt")
ax.set_title("Taylor-Green vortex Re 1600")
ax.legend()
fig.tight_layout()
fig.savefig(out / "dissipation.png", dpi=120)

fig, ax = plt.subplots(figsize=(6, 4.5))
for scheme in sorted({r["scheme"] for r in rows}):
    pts = sorted((float(r["cpu_s"]), float(r["dissipation_error_max_rel"]), r["n"], r["ranks"])
                 for r in rows if r["scheme"] == scheme)
    ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=scheme)
    for p in pts:
        ax.annotate(f"{p[2]}^3 np{p[3]}", (p[0], p[1]), fontsize=8)
ax.set_xlabel("CPU time (s, all ranks)")
ax.set_ylabel("max |eps - eps_ref| / max eps_ref")
ax.set_title("Work-precision, TGV Re 1600 to t = 10")
ax.legend()
fig.tight_layout()
fig.savefig(out / "work_precision.png", dpi=120)
print(f"wrote {out / 'dissipation.png'} and {out / 'work_precision.png'}")
