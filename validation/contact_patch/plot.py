"""Contact patch test: contact pressure / applied traction at every contact Gauss point of both
surfaces (half 0: the lower block's top face as slave, half 1: the upper block's bottom face),
against x, for each variant. Usage: plot.py OUT_DIR (reads contact_patch.csv)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/contact_patch.csv")))
variants = list(dict.fromkeys(r["variant"] for r in rows))
fig, axes = plt.subplots(1, len(variants), figsize=(4 * len(variants), 3.6), sharey=True)
for ax, v in zip(axes, variants):
    for half, marker in (("0", "o"), ("1", "x")):
        rr = [r for r in rows if r["variant"] == v and r["half"] == half]
        ax.plot([float(r["x"]) for r in rr], [float(r["p_over_t"]) for r in rr], marker, ms=3,
                ls="none", label=f"slave: {'lower' if half == '0' else 'upper'} face")
    ax.axhline(1 / (1 + 0.3e-3) ** 2, color="k", lw=0.8, label="exact t / (1 + nu t/E)^2")
    ax.axhspan(0.99, 1.01, color="0.9", label="1 % band")
    ax.set_title(v, fontsize=9)
    ax.set_xlabel("x")
axes[0].set_ylabel("contact pressure / applied traction")
axes[0].set_ylim(0.98, 1.02)
axes[0].legend(fontsize=7)
fig.tight_layout()
fig.savefig(f"{out}/contact_patch.png", dpi=120)
