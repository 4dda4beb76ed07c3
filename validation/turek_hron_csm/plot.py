"""Turek-Hron CSM1/CSM2: relative tip-displacement error against the FeatFlow reference versus
degrees of freedom. Usage: plot.py OUT_DIR (reads convergence.csv)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/convergence.csv")))
fig, ax = plt.subplots(figsize=(6, 4.5))
for i, case in enumerate(sorted({r["case"] for r in rows})):
    rr = [r for r in rows if r["case"] == case]
    dofs = [float(r["dofs"]) for r in rr]
    for comp, style in (("ux", "o-"), ("uy", "s--")):
        err = [max(abs(float(r[f"err_{comp}_rel"])), 1e-8) for r in rr]
        ax.loglog(dofs, err, style, color=f"C{i}", label=f"{case} {comp}")
ax.axhline(0.01, color="k", lw=0.8, ls=":", label="1% tolerance")
ax.set_xlabel("degrees of freedom")
ax.set_ylabel("|u_A - u_ref| / |u_ref|")
ax.set_title("Turek-Hron CSM, Q2 plane strain")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{out}/turek_hron_csm.png", dpi=120)
