#!/usr/bin/python3
# Relative error of the mean wall shear stress and of the pressure drop against R/h (log-log),
# with the node-to-node range of tau_w as a band.
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = Path(sys.argv[1])
rows = list(csv.DictReader(open(out / "poiseuille_wss.csv")))
r = [float(x["r_over_h"]) for x in rows]
fig, ax = plt.subplots(figsize=(6, 4.5))
ax.loglog(r, [abs(float(x["wss_mean_error"])) for x in rows], "o-", label="|mean TAWSS error|")
ax.loglog(r, [abs(float(x["dp_error"])) for x in rows], "s-", label="|pressure drop error|")
ax.loglog(r, [0.046 * (r[0] / q) ** 2 for q in r], "k--", label="slope -2")
ax.axhline(0.02, color="r", lw=0.8, label="2 % target")
ax.set(xlabel="R / h", ylabel="relative error", title="Poiseuille pipe: wall shear stress")
ax.grid(alpha=0.3, which="both")
ax.legend()
fig.tight_layout()
fig.savefig(out / "poiseuille_wss.png", dpi=120)
