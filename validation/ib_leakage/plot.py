"""Immersed-membrane leakage: time histories of the load and the sustained jump, the leak flow,
the final membrane shape against the static solution, the centre-line pressure, and the leak
fraction and sustained jump per run against the reference study's ITBM result.
Usage: plot.py OUT_DIR (reads runs.csv, history.csv, membrane.csv, profile.csv)."""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

MMHG = 133.322387415
out = sys.argv[1]


def by_label(name):
    groups = defaultdict(list)
    for r in csv.DictReader(open(f"{out}/{name}")):
        groups[r["label"]].append(r)
    return groups


runs = list(csv.DictReader(open(f"{out}/runs.csv")))
hist, shape, prof = by_label("history.csv"), by_label("membrane.csv"), by_label("profile.csv")

fig, ax = plt.subplots(2, 3, figsize=(16, 9))
a, b, c, d, e, f = ax.ravel()
for lab, rows in hist.items():
    t = [1e3 * float(r["time"]) for r in rows]
    (line,) = a.plot(t, [float(r["jump"]) / MMHG for r in rows], label=lab)
    q_in = [float(r["flow_in"]) for r in rows]
    area = [float(r["area"]) for r in rows]
    # Instantaneous leak by mass balance: Q_in - dA/dt (central differences).
    leak = [q_in[i] - (area[i + 1] - area[i - 1]) / (1e-3 * (t[i + 1] - t[i - 1]))
            for i in range(1, len(t) - 1)]
    b.plot(t, [1e6 * q for q in q_in], color=line.get_color(), alpha=0.35)
    b.plot(t[1:-1], [1e6 * q for q in leak], color=line.get_color(), label=lab)
rows = next(iter(hist.values()))
a.plot([1e3 * float(r["time"]) for r in rows], [float(r["inlet_pressure"]) / MMHG for r in rows],
       "k--", label="imposed p_in - p_out")
a.set_xlabel("t [ms]")
a.set_ylabel("jump between region means [mmHg]")
a.set_title("pressure jump sustained by the membrane")
a.legend(fontsize=7)
b.set_xlabel("t [ms]")
b.set_ylabel("flow per depth [mm^2/s]")
b.set_title("inflow (faint) and leak Q_in - dA/dt")
b.legend(fontsize=7)
for lab, rows in shape.items():
    for which, style in (("final", "-"), ("static", ":")):
        pts = [r for r in rows if r["shape"] == which]
        c.plot([1e3 * float(r["x"]) for r in pts], [1e3 * float(r["y"]) for r in pts], style,
               label=f"{lab} {which}" if which == "final" else None)
c.set_xlabel("x [mm]")
c.set_ylabel("y [mm]")
c.set_title("membrane centre line: FSI (solid), static FE under the same jump (dotted)")
c.legend(fontsize=7)
for lab, rows in prof.items():
    d.plot([1e3 * float(r["x"]) for r in rows], [float(r["p"]) / MMHG for r in rows], label=lab)
d.set_xlabel("x [mm]")
d.set_ylabel("p [mmHg]")
d.set_title("centre-line pressure at the end")
d.legend(fontsize=7)
labels = [r["label"] for r in runs]
frac = [float(r["leak_fraction"]) for r in runs]
e.bar(range(len(runs)), [abs(x) for x in frac], color=["C0" if x >= 0 else "C3" for x in frac])
e.set_yscale("log")
e.set_xticks(range(len(runs)), labels, rotation=30, fontsize=7)
e.set_ylabel("|leak| / Bernoulli flow H sqrt(2 dp / rho)")
e.set_title("leak fraction (red: negative)")
jump = [float(r["jump_mmhg"]) / float(r["imposed_mmhg"]) for r in runs]
f.bar(range(len(runs)), jump, label="valsalva: sustained / imposed")
f.axhline(21.05 / 93.35, color="C3", ls="--", label="reference ITBM: 21.05 / 93.35 mmHg")
f.axhline(1.0, color="k", lw=0.8)
f.set_xticks(range(len(runs)), labels, rotation=30, fontsize=7)
f.set_ylabel("sustained jump / imposed")
f.set_ylim(0, 1.15)
f.set_title("pressure jump held by the immersed membrane")
f.legend(fontsize=7, loc="lower right")
for x in ax.ravel():
    x.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(f"{out}/ib_leakage.png", dpi=110)
