#!/usr/bin/python3
"""Lid-driven cavity Re 100 and Re 1000: centreline profiles on every mesh against Ghia et al.
(1982), and the max deviation against the cell size."""
import csv
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
reynolds = sorted({int(m.group(1)) for f in out.glob("ghia_Re*.csv")
                   if (m := re.fullmatch(r"ghia_Re(\d+)", f.stem))})
if not reynolds:
    sys.exit(f"plot.py: no ghia_Re*.csv in {out}")


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


fig, axes = plt.subplots(len(reynolds), 2, figsize=(11, 5 * len(reynolds)), squeeze=False)
for (au, av), re_number in zip(axes, reynolds):
    files = sorted(out.glob(f"profiles_Re{re_number}_N*.csv"),
                   key=lambda f: int(f.stem.rsplit("N", 1)[1]))
    for f in files:
        prof = rows(f)
        s = [float(r["s"]) for r in prof]
        n = f.stem.rsplit("N", 1)[1]
        au.plot([float(r["u_at_x_half"]) for r in prof], s, label=f"N = {n}")
        av.plot(s, [float(r["v_at_y_half"]) for r in prof], label=f"N = {n}")
    ghia = rows(out / f"ghia_Re{re_number}.csv")
    gu = [r for r in ghia if r["line"] == "u"]
    gv = [r for r in ghia if r["line"] == "v"]
    au.plot([float(r["value"]) for r in gu], [float(r["s"]) for r in gu], "ko", mfc="none",
            label="Ghia et al. 1982")
    av.plot([float(r["s"]) for r in gv], [float(r["value"]) for r in gv], "ko", mfc="none",
            label="Ghia et al. 1982")
    au.set_xlabel("u / U at x = 0.5")
    au.set_ylabel("y / L")
    av.set_xlabel("x / L")
    av.set_ylabel("v / U at y = 0.5")
    if len(files) >= 2:  # Richardson h -> 0 estimate of the two finest levels
        au.plot([float(r["extrapolated"]) for r in gu], [float(r["s"]) for r in gu], "k+",
                label="h -> 0 (Richardson)")
        av.plot([float(r["s"]) for r in gv], [float(r["extrapolated"]) for r in gv], "k+",
                label="h -> 0 (Richardson)")
    for a in (au, av):
        a.set_title(f"Re = {re_number}")
        a.grid(alpha=0.3)
        a.legend()
fig.suptitle("Lid-driven cavity, hexahedral slab, centreline profiles")
fig.tight_layout()
fig.savefig(out / "cavity_profiles.png", dpi=110)

conv = out / "convergence.csv"
if conv.exists():
    table = rows(conv)
    fig, ax = plt.subplots(figsize=(6.5, 5))
    for re_number, colour in zip(reynolds, ("C0", "C3", "C2", "C1")):
        sel = [r for r in table if int(float(r["re"])) == re_number]
        if not sel:
            continue
        h = [float(r["h"]) for r in sel]
        for key, style, line in (("max_dev_u", "o-", "u(y)"), ("max_dev_v", "s--", "v(x)")):
            ax.loglog(h, [float(r[key]) for r in sel], style, color=colour,
                      label=f"Re {re_number}: {line} vs Ghia")
        if len(sel) >= 2:
            d = [float(r["diff_to_coarser"]) for r in sel[1:]]
            ax.loglog(h[1:], d, "x:", color=colour,
                      label=f"Re {re_number}: |profile_N - profile_coarser|")
        ax.loglog(h, [float(sel[0]["max_dev"]) * (x / h[0]) ** 2 for x in h], ":",
                  color="grey", lw=0.8)
        ghia = rows(out / f"ghia_Re{re_number}.csv")
        if len(sel) >= 2:
            limit = max(abs(float(r["extrapolated"]) - float(r["value"])) for r in ghia)
            ax.axhline(limit, color=colour, lw=0.8, ls="-.",
                       label=f"Re {re_number}: h -> 0 estimate vs Ghia")
    ax.axhline(0.01, color="k", lw=0.8, label="1 % of U (target)")
    ax.set_xlabel("h / L")
    ax.set_ylabel("max over Ghia's points / U")
    ax.set_title("deviation from Ghia et al. 1982 (grey dotted: h^2)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "cavity_convergence.png", dpi=110)
