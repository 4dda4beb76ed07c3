#!/usr/bin/python3
"""DFG 2D-1 and 2D-2: force histories of every level and the finest-level values against the
number of nodes, with the 1996 reference intervals (dfg_2d1.png, dfg_2d2.png)."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = pathlib.Path(sys.argv[1])


def read(name):
    path = out / name
    return list(csv.DictReader(open(path))) if path.exists() else []


def histories(name):
    levels = {}
    for r in read(name):
        levels.setdefault(int(r["level"]), []).append(r)
    return levels


def convergence(ax, rows, key, lo, hi, title):
    nodes = [float(r["nodes"]) for r in rows]
    ax.semilogx(nodes, [float(r[key]) for r in rows], "o-", label="valsalva")
    ax.axhspan(lo, hi, color="0.8", label="Schaefer & Turek 1996")
    ax.set_xlabel("fluid nodes")
    ax.set_title(title)


def plot_case(case, table, history, quantities, hist_keys, t_from, suptitle):
    rows = read(table)
    if not rows:
        return
    levels = histories(history)
    fig, axes = plt.subplots(2, len(quantities), figsize=(4.2 * len(quantities), 7.2))
    for ax, (key, lo, hi, title) in zip(axes[0], quantities):
        convergence(ax, rows, key, lo, hi, title)
    axes[0][0].legend(fontsize=8)
    for ax, (key, label, band) in zip(axes[1], hist_keys):
        for lev, h in sorted(levels.items()):
            t = [float(r["t"]) for r in h if float(r["t"]) >= t_from]
            v = [float(r[key]) for r in h if float(r["t"]) >= t_from]
            ax.plot(t, v, lw=0.8, label=f"level {lev} ({rows[lev]['size_near']} / "
                    f"{rows[lev]['size_far']})" if lev < len(rows) else f"level {lev}")
        if band:
            ax.axhspan(band[0], band[1], color="0.8")
        ax.set_xlabel("t (s)")
        ax.set_title(label)
    axes[1][0].legend(fontsize=8)
    for ax in axes[1][len(hist_keys):]:
        ax.axis("off")
    fig.suptitle(suptitle)
    fig.tight_layout()
    fig.savefig(out / f"dfg_{case}.png", dpi=110)


plot_case("2d1", "dfg_2d1.csv", "dfg_2d1_history.csv",
          [("c_D", 5.57, 5.59, "c_D"), ("c_L", 0.0104, 0.0110, "c_L"),
           ("dp", 0.1172, 0.1176, "dp")],
          [("c_D", "c_D history", (5.57, 5.59)), ("c_L", "c_L history", (0.0104, 0.0110)),
           ("dp", "dp history", (0.1172, 0.1176))], 0.5,
          "DFG cylinder 2D-1 (Re 20), prism slab: finest values and histories")
plot_case("2d2", "dfg_2d2.csv", "dfg_2d2_history.csv",
          [("c_D_max", 3.22, 3.24, "c_D max"), ("c_L_max", 0.99, 1.01, "c_L max"),
           ("St", 0.295, 0.305, "St")],
          [("c_D", "c_D history (band: c_D max interval)", (3.22, 3.24)),
           ("c_L", "c_L history", (0.99, 1.01)), ("dp", "dp history", None)], 3.5,
          "DFG cylinder 2D-2 (Re 100), prism slab: window values and histories")
