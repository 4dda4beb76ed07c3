#!/usr/bin/python3
"""Womersley study (validation/bench/womersley_study.cpp --csv): the axial error over r on the
mid-length slab |z - L/2| <= h/2 at each file's worst phase, one panel per file (the periodic
pipe's files have L = 0: all nodes). Usage: plot_study.py OUT.png FILE.csv [FILE.csv ...]"""
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out, files = sys.argv[1], sys.argv[2:]
fig, axes = plt.subplots(1, len(files), figsize=(4.5 * len(files), 4), sharey=True, squeeze=False)
for ax, name in zip(axes[0], files):
    d = np.genfromtxt(name, delimiter=",", names=True)
    radius, length, h = d["radius"][0], d["length"][0], d["h"][0]
    error = (d["u"] - d["u_exact"]) / d["u_peak"][0]
    slab = np.abs(d["z"] - length / 2) <= h / 2 if length > 0 else np.ones(len(d), bool)
    worst = max(np.unique(d["time"]), key=lambda t: np.abs(error[slab & (d["time"] == t)]).max())
    m = slab & (d["time"] == worst)
    ax.plot(d["r"][m] / radius, 100 * error[m], ".", ms=3)
    ax.axvline(1 - np.sqrt(2) / 17, color="k", ls=":", lw=0.8)  # Stokes-layer edge at Wo 17
    ax.axhline(0, color="k", lw=0.5)
    ax.set_title(f"{name}\nt = {worst:.3f} s, max {100 * np.abs(error[m]).max():.2f} %", fontsize=9)
    ax.set_xlabel("r / R")
    ax.grid(alpha=0.3)
axes[0][0].set_ylabel("(u_z - u_exact) / u_peak [%]")
plt.tight_layout()
plt.savefig(out, dpi=110)
