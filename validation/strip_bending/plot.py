"""Thin-strip bending: computed tip deflection against beam theory (small load) and the
elastica (large load) for each mesh, and (full run) the locking study at alpha = 5, aspect 7.
Usage: plot.py OUT_DIR (reads strip_bending.csv and, if present, strip_bending_locking.csv)."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/strip_bending.csv")))
locking = f"{out}/strip_bending_locking.csv"
study = list(csv.DictReader(open(locking))) if os.path.exists(locking) else []
fig, axes = plt.subplots(1, 3 if study else 2, figsize=(16 if study else 10, 4))
a, b = axes[0], axes[1]
for i, n in enumerate(sorted({int(r["n_length"]) for r in rows})):
    rr = sorted((r for r in rows if int(r["n_length"]) == n), key=lambda r: float(r["alpha"]))
    al = [float(r["alpha"]) for r in rr]
    a.plot(al, [float(r["deflection_over_L"]) for r in rr], "o", color=f"C{i}", label=f"{n} elements")
    b.semilogy(al, [max(abs(float(r["rel_error"])), 1e-8) for r in rr], "o", color=f"C{i}", label=f"{n} elements")
ref = sorted({(float(r["alpha"]), float(r["reference_over_L"]), r["reference"]) for r in rows})
a.plot([r[0] for r in ref], [r[1] for r in ref], "kx", label="reference (beam / elastica)")
a.set_xlabel("load parameter alpha")
a.set_ylabel("tip deflection / L")
a.legend(fontsize=8)
b.axhline(0.02, color="k", ls=":", lw=0.8, label="2% tolerance")
b.set_xlabel("load parameter alpha")
b.set_ylabel("relative error")
b.legend(fontsize=8)
if study:
    c = axes[2]
    y = range(len(study))
    c.barh(y, [abs(float(r["rel_error"])) for r in study], color="C2")
    c.set_yticks(list(y), [r["setting"] for r in study], fontsize=7)
    c.axvline(0.02, color="k", ls=":", lw=0.8)
    c.set_xscale("log")
    c.set_xlabel("|relative error|, alpha 5, aspect 7 unless noted")
fig.suptitle("cantilever strip, one Q2 element through 0.15 mm")
fig.tight_layout()
fig.savefig(f"{out}/strip_bending.png", dpi=120)
