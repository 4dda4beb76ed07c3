"""Dissipation rate -dE/dt of the tgv_les runs against the 512^3 spectral reference.

Usage: /usr/bin/python3 plot.py OUT_DIR   (reads dissipation.csv)
Writes dissipation.png: one panel per scheme, every model, the reference in black.
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = Path(sys.argv[1])
with open(out / "dissipation.csv") as f:
    rows = list(csv.DictReader(f))
curves = defaultdict(lambda: ([], []))
reference = {}
for r in rows:
    key = (r["scheme"], r["model"], r["update"], r["n"])
    curves[key][0].append(float(r["t"]))
    curves[key][1].append(float(r["dissipation"]))
    reference.setdefault(r["scheme"], ([], []))
    if len(reference[r["scheme"]][0]) < len(curves[key][0]):
        reference[r["scheme"]][0].append(float(r["t"]))
        reference[r["scheme"]][1].append(float(r["dissipation_reference"]))
schemes = sorted({k[0] for k in curves}, reverse=True)
colours = {"sigma": "C0", "wale": "C1", "smagorinsky": "C2", "none": "C3"}
fig, axes = plt.subplots(1, len(schemes), figsize=(6 * len(schemes), 4.5), squeeze=False)
for ax, scheme in zip(axes[0], schemes):
    t, e = reference[scheme]
    ax.plot(t, e, "k-", lw=2, label="spectral 512$^3$ (reference)")
    for (s, model, update, n), (t, e) in curves.items():
        if s != scheme:
            continue
        style = "--" if update == "stage" else "-"
        ax.plot(t, e, style, color=colours.get(model, "C4"), label=f"{model} ({update}), {n}$^3$")
    ax.set_title(f"TGV Re 1600, {scheme}")
    ax.set_xlabel("t")
    ax.set_ylabel("-dE/dt")
    ax.set_ylim(0, 0.02)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "dissipation.png", dpi=120)
