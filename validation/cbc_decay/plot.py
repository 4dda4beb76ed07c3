"""Spectra and resolved-energy decay of the cbc_decay case against Comte-Bellot & Corrsin 1971.

Usage: /usr/bin/python3 plot.py OUT_DIR   (reads spectra.csv, energy.csv, decay.csv)
Writes spectra.png (E(k) at tU0/M = 42, 98, 171 per mesh, every model, the measured spectrum
filtered to the mesh's shells) and energy.png (resolved energy vs tU0/M; dots: the shell-filtered energy the check compares).
"""
import csv
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = Path(sys.argv[1])


def rows(name):
    with open(out / name) as f:
        return list(csv.DictReader(f))


spectra = rows("spectra.csv")
energy = rows("energy.csv")
decay = rows("decay.csv")
meshes = sorted({int(r["n"]) for r in spectra})
models = list(dict.fromkeys(r["model"] for r in spectra))
colours = {"sigma": "C0", "wale": "C1", "smagorinsky": "C2", "none": "C3"}
station_style = {42: ":", 98: "-", 171: "--"}
exp_marker = {42: "^", 98: "o", 171: "s"}

fig, axes = plt.subplots(1, len(meshes), figsize=(6 * len(meshes), 5), squeeze=False)
for ax, n in zip(axes[0], meshes):
    exp_done = set()
    for model in models:
        series = defaultdict(lambda: ([], [], []))
        for r in spectra:
            if int(r["n"]) == n and r["model"] == model:
                s = series[int(r["station"])]
                s[0].append(float(r["k"]) / 100)  # 1/cm
                s[1].append(float(r["E"]) * 1e6)  # cm^3/s^2
                s[2].append(float(r["E_exp"]) * 1e6)
        for station, (k, e, ee) in sorted(series.items()):
            if station == 42 and model != models[0]:
                continue
            ax.loglog(k, e, station_style[station], color=colours.get(model, "k"),
                      label=f"{model} {station}" if station != 42 else "initial (42)")
            if station not in exp_done:
                ax.loglog(k, ee, "k" + exp_marker[station], ms=4, mfc="none",
                          label=f"experiment {station}")
                exp_done.add(station)
    ax.set_title(f"{n}^3 hexahedra, box 11 M")
    ax.set_xlabel("k [1/cm]")
    ax.set_ylabel("E(k) [cm^3/s^2]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(out / "spectra.png", dpi=120)

fig, axes = plt.subplots(1, len(meshes), figsize=(6 * len(meshes), 4.5), squeeze=False)
for ax, n in zip(axes[0], meshes):
    for model in models:
        t = [float(r["t_u0_over_m"]) for r in decay if int(r["n"]) == n and r["model"] == model]
        e = [float(r["energy"]) * 1e4 for r in decay if int(r["n"]) == n and r["model"] == model]
        ax.plot(t, e, color=colours.get(model, "k"), label=f"{model} (all modes)")
        # What the check compares: the shells 1 .. n/2 - 1 at the stations.
        st = [(int(r["station"]), float(r["resolved"]) * 1e4) for r in energy
              if int(r["n"]) == n and r["model"] == model]
        ax.plot([p[0] for p in st], [p[1] for p in st], "o", color=colours.get(model, "k"), ms=4)
    pts = [(int(r["station"]), float(r["resolved_exp"]) * 1e4) for r in energy
           if int(r["n"]) == n and r["model"] == models[0]]
    ax.plot([p[0] for p in pts], [p[1] for p in pts], "ks", mfc="none",
            label="experiment, filtered")
    ax.set_title(f"resolved energy, {n}^3 (dots: shells 1 .. n/2 - 1, as compared)")
    ax.set_xlabel("tU0/M")
    ax.set_ylabel("1/2 <u.u> [cm^2/s^2]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "energy.png", dpi=120)
