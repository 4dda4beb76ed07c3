#!/usr/bin/python3
"""Turek-Hron FSI1/FSI3: time series of the tip displacement and the forces, FSI1 convergence
table against TH2006, FSI3 last periods with the reference amplitude band."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])
REF1 = {"ux_A": 0.0227e-3, "uy_A": 0.8209e-3, "drag": 14.295, "lift": 0.7638}
REF3 = {"uy_A": (1.48e-3, 34.38e-3), "drag": (457.3, 22.66), "lift": (2.22, 149.78)}


def columns(path):
    rows = list(csv.DictReader(open(path)))
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def save(fig, title, name):
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out / name, dpi=110)


series1 = sorted(out.glob("fsi1_series_level*.csv"))
if series1:
    fig, axes = plt.subplots(2, 2, figsize=(11, 7))
    late = {k: [REF1[k]] for k in REF1}  # values after the start-up, for the axis limits
    for path in series1:
        c = columns(path)
        for ax, key in zip(axes.flat, ["ux_A", "uy_A", "drag", "lift"]):
            ax.plot(c["t"], c[key], label=path.stem.replace("fsi1_series_", ""))
            late[key] += [v for t, v in zip(c["t"], c[key]) if t > 0.3 * c["t"][-1]]
    for ax, key in zip(axes.flat, ["ux_A", "uy_A", "drag", "lift"]):
        ax.axhline(REF1[key], color="k", ls="--", label="TH2006")
        ax.set_title(key)
        ax.set_xlabel("t [s]")
    axes[0, 0].legend()
    for ax, key in zip(axes.flat, ["ux_A", "uy_A", "drag", "lift"]):
        lo, hi = min(late[key]), max(late[key])
        ax.set_ylim(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo))
    save(fig, "Turek-Hron FSI1 (Re 20): approach to the steady state", "fsi1_series.png")

table = out / "fsi1_convergence.csv"
if table.exists():
    c = columns(table)
    if c:
        fig, axes = plt.subplots(1, 4, figsize=(14, 3.6))
        for ax, key in zip(axes, ["ux_A", "uy_A", "drag", "lift"]):
            ax.plot(c["size_near"], c[key], "o-", label="valsalva")
            ax.axhline(REF1[key], color="k", ls="--", label="TH2006")
            ax.set_xlabel("size near bar / cylinder [m]")
            ax.set_title(key)
            ax.invert_xaxis()
        axes[0].legend()
        save(fig, "Turek-Hron FSI1: mesh convergence", "fsi1_convergence.png")

series3 = out / "fsi3_series.csv"
if series3.exists():
    c = columns(series3)
    s = columns(out / "fsi3_summary.csv") if (out / "fsi3_summary.csv").exists() else {}
    fig, axes = plt.subplots(3, 1, figsize=(11, 9), sharex=True)
    for ax, key, scale, unit in zip(axes, ["uy_A", "drag", "lift"], [1e3, 1, 1],
                                    ["mm", "N/m", "N/m"]):
        ax.plot(c["t"], [v * scale for v in c[key]], lw=0.8)
        mean, amp = REF3[key]
        for v in (mean - amp, mean + amp):
            ax.axhline(v * scale, color="k", ls="--", lw=0.8)
        ax.set_ylabel(f"{key} [{unit}]")
    if s:
        for ax in axes:
            ax.axvspan(s["t_end"][0] - 1.5, s["t_end"][0], color="0.9")
    axes[-1].set_xlabel("t [s]")
    save(fig, "Turek-Hron FSI3 (Re 200); dashed: TH2006 mean +- amplitude", "fsi3_series.png")
