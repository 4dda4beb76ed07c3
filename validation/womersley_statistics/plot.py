#!/usr/bin/python3
# Phase-mean and RMS axial velocity against radius on the mid cross-section, per phase bin:
# simulation (dots) vs the analytic Womersley profile sampled at the same instants (lines).
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = Path(sys.argv[1])
rows = list(csv.DictReader(open(out / "womersley_statistics.csv")))
bins = sorted({int(r["bin"]) for r in rows})
fig, (ax_mean, ax_rms) = plt.subplots(1, 2, figsize=(11, 4.5))
for b in bins:
    pts = sorted(((float(r["r"]), r) for r in rows if int(r["bin"]) == b), key=lambda p: p[0])
    r = [p[0] * 1e3 for p in pts]
    colour = plt.cm.viridis(b / max(1, len(bins) - 1))
    label = f"phase {float(pts[0][1]['phase_time']):.3f} s"
    ax_mean.plot(r, [float(p[1]["w_mean_exact"]) for p in pts], "-", color=colour, label=label)
    ax_mean.plot(r, [float(p[1]["w_mean"]) for p in pts], ".", color=colour)
    ax_rms.plot(r, [float(p[1]["w_rms_exact"]) for p in pts], "-", color=colour)
    ax_rms.plot(r, [float(p[1]["w_rms"]) for p in pts], ".", color=colour)
ax_mean.set(xlabel="r (mm)", ylabel="phase-mean w (m/s)", title="Womersley Wo 4: phase mean")
ax_rms.set(xlabel="r (mm)", ylabel="w RMS in the bin (m/s)", title="within-bin RMS")
ax_mean.legend(fontsize=7)
for ax in (ax_mean, ax_rms):
    ax.grid(alpha=0.3)
fig.suptitle("dots: valsalva (phase statistics), lines: analytic sampled at the same steps")
fig.tight_layout()
fig.savefig(out / "womersley_statistics.png", dpi=120)
