"""Hertz contact: contact pressure p / p0 against x / a (Hertz values for the measured load) per
mesh with the Hertz ellipse, and the errors of a and p0 against the mesh size.
Usage: plot.py OUT_DIR (reads hertz_contact.csv and hertz_pressure.csv)."""
import csv
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
levels = list(csv.DictReader(open(f"{out}/hertz_contact.csv")))
prof = list(csv.DictReader(open(f"{out}/hertz_pressure.csv")))
fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
for i, lv in enumerate(levels):
    rr = [r for r in prof if r["nx"] == lv["nx"]]
    a.plot([float(r["x_over_a_hertz"]) for r in rr], [float(r["p_over_p0_hertz"]) for r in rr],
           "o", ms=3, color=f"C{i}", label=f"{lv['nx']}x{lv['ny']} Q2")
s = np.linspace(0, 1, 200)
a.plot(s, np.sqrt(1 - s * s), "k-", lw=1, label="Hertz")
a.set_xlabel("x / a (Hertz)")
a.set_ylabel("p / p0 (Hertz)")
a.set_xlim(0, 1.5)
a.legend(fontsize=8)
n = [int(r["nx"]) for r in levels]
b.loglog(n, [max(abs(float(r["a_error"])), 1e-6) for r in levels], "o-", label="|a error|")
b.loglog(n, [max(abs(float(r["p0_error"])), 1e-6) for r in levels], "s-", label="|p0 error|")
b.axhline(0.05, color="k", ls=":", lw=0.8, label="5 % target")
b.set_xlabel("elements along the half-width W")
b.set_ylabel("relative error")
b.legend(fontsize=8)
fig.suptitle("cylinder on a rigid plane, plane strain")
fig.tight_layout()
fig.savefig(f"{out}/hertz_contact.png", dpi=120)
