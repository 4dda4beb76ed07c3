#!/usr/bin/python3
"""RCR outlet: the outlet pressure of each frequency's run against the periodic RCR solution,
and the stability sweep's flux roughness against R_d and C."""
import cmath
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
Q0, QA, RP, RD, C = 2e-6, 1.5e-6, 1e7, 1e8, 1e-9
TAU = RD * C

freqs = list(csv.DictReader(open(out / "frequencies.csv")))
fig, axes = plt.subplots(1, len(freqs) + 1, figsize=(4.2 * (len(freqs) + 1), 4))
for ax, f in zip(axes, freqs):
    wt = float(f["omega_tau"])
    w = wt / TAU
    z = RP + RD / complex(1, wt)
    rows = list(csv.DictReader(open(out / "runs" / f"pipe_wtau_{f['omega_tau']}" / "outlets.csv")))[1:]
    t = [float(r["time"]) for r in rows]
    p = [float(r["pressure_outlet"]) for r in rows]
    exact = [(RP + RD) * Q0 + QA * abs(z) * math.sin(w * s + cmath.phase(z)) for s in t]
    ax.plot([s * w / (2 * math.pi) for s in t], exact, "k-", lw=2, label="RCR, exact")
    ax.plot([s * w / (2 * math.pi) for s in t], p, "r--", label="outlet pressure")
    ax.set_xlabel("t / T")
    ax.set_ylabel("p [Pa]")
    ax.set_title(f"w tau = {wt:g}: amplitude err {float(f['amplitude_error']):.1e}")
    ax.legend()
sweep = list(csv.DictReader(open(out / "stability.csv")))
ax = axes[-1]
for c in sorted({float(s["capacitance"]) for s in sweep}):
    pts = [s for s in sweep if float(s["capacitance"]) == c and s["cells"] == "hexa"]
    ax.loglog([float(s["distal_resistance"]) for s in pts],
              [max(float(s["roughness"]), 1e-12) for s in pts], "o-", label=f"C = {c:.0e}")
ax.axhline(1e-2, color="k", ls=":", label="tolerance")
ax.set_xlabel("R_d [Pa s/m3]")
ax.set_ylabel("flux roughness")
ax.set_title("two RCR outlets: stability sweep")
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(out / "rcr_outlet.png", dpi=110)
