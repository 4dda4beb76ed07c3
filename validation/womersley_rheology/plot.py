#!/usr/bin/python3
"""Womersley Wo 4, Carreau-Yasuda against Newtonian: the area-weighted mean wall shear stress
and the flow rate over the last period, 3D runs on the finest mesh (markers) against their
references (lines: Womersley's solution and the 1D radial solutions; the Newtonian one equals
Womersley's to 1e-6); with several meshes, the WSS and flow amplitude errors against h."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
rows = list(csv.DictReader(open(out / "series.csv")))
levels = list(csv.DictReader(open(out / "levels.csv")))
finest = max(int(lv["n"]) for lv in levels)
colours = {"newtonian": "C0", "carreau_yasuda": "C3", "newtonian_effective": "C2"}
names = {"newtonian": "Newtonian mu_inf", "carreau_yasuda": "Carreau-Yasuda",
         "newtonian_effective": "Newtonian mu_CY(4 U0/R)"}
fig, axes = plt.subplots(1, 3, figsize=(17, 4.6))
for fluid, colour in colours.items():
    for source, style in (("reference", "-"), ("3d", "o")):
        sel = [r for r in rows if r["fluid"] == fluid and r["source"] == source
               and int(r["n"]) == finest]
        if not sel:
            continue
        t = [float(r["time"]) for r in sel]
        t0 = min(t)
        kw = dict(color=colour, lw=1.5) if style == "-" else dict(color=colour, ms=2.5, ls="none",
                                                                   marker="o", markevery=max(1, len(t) // 60))
        label = f"{names[fluid]} ({'reference' if source == 'reference' else f'valsalva R/{finest}'})"
        axes[0].plot([x - t0 for x in t], [float(r["wss"]) for r in sel], label=label, **kw)
        axes[1].plot([x - t0 for x in t], [float(r["flow_rate"]) * 6e7 for r in sel], **kw)
axes[0].axhline(0, color="k", lw=0.5)
axes[1].axhline(0, color="k", lw=0.5)
axes[0].set_xlabel("t / T (last period)")
axes[0].set_ylabel("mean wall shear stress tau_z (Pa)")
axes[1].set_xlabel("t / T (last period)")
axes[1].set_ylabel("flow rate (mL/min)")
axes[0].legend(fontsize=7)
summary = [f"R/{finest}: TAWSS (Pa), OSI, peak WSS (Pa)"]
for lv in levels:
    if int(lv["n"]) == finest:
        summary.append(f"{names[lv['fluid']]}: {float(lv['tawss']):.4f}, {float(lv['osi']):.4f}, "
                       f"{float(lv['wss_max']):.4f}  (ref {float(lv['ref_tawss']):.4f}, "
                       f"{float(lv['ref_osi']):.4f}, {float(lv['ref_wss_max']):.4f})")
axes[1].set_title("\n".join(summary), fontsize=7)
sizes = sorted({int(lv["n"]) for lv in levels})
for fluid in ("newtonian", "carreau_yasuda"):
    sel = sorted((lv for lv in levels if lv["fluid"] == fluid), key=lambda lv: int(lv["n"]))
    h = [1 / int(lv["n"]) for lv in sel]
    wss = [abs(float(lv["wss_amplitude"]) / float(lv["ref_wss_amplitude"]) - 1) for lv in sel]
    flow = [abs(float(lv["flow_amplitude"]) / float(lv["ref_flow_amplitude"]) - 1) for lv in sel]
    axes[2].loglog(h, wss, "o-", color=colours[fluid], label=f"{names[fluid]}: WSS amplitude")
    axes[2].loglog(h, flow, "s--", color=colours[fluid], label=f"{names[fluid]}: flow amplitude")
if len(sizes) > 1:
    h = [1 / n for n in sizes]
    axes[2].loglog(h, [0.012 * (x * sizes[0]) ** 2 for x in h], "k:", label="h^2")
axes[2].set_xlabel("h / R")
axes[2].set_ylabel("|3D / reference - 1|")
axes[2].legend(fontsize=7)
fig.tight_layout()
fig.savefig(out / "womersley_rheology.png", dpi=110)
