#!/usr/bin/python3
"""Side-by-side PIV / simulation plots from the CSV files of analysis/piv_compare.

  plot_piv.py frame.csv out.png [--profile profile.csv ...] [--title TEXT]

frame.csv (write_comparison_csv): x,y,valid,piv_u,piv_v,sim_u,sim_v[,piv_urms,...]
profile.csv (write_profile_csv):  s,x,y,sim_u,sim_v,piv_u,piv_v
Panels: in-plane speed of PIV, simulation and their difference (masked points left blank), the
streamwise RMS pair when present, then one panel per profile. Uses matplotlib (Agg).
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_piv: '{path}' has no rows")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("frame")
    ap.add_argument("png")
    ap.add_argument("--profile", action="append", default=[])
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    d = read(a.frame)
    ok = [v == 1 and math.isfinite(pu) and math.isfinite(su)
          for v, pu, su in zip(d["valid"], d["piv_u"], d["sim_u"])]
    x = [1e3 * v for v, k in zip(d["x"], ok) if k]
    y = [1e3 * v for v, k in zip(d["y"], ok) if k]

    def pick(name):
        return [v for v, k in zip(d[name], ok) if k]

    piv = [math.hypot(u, v) for u, v in zip(pick("piv_u"), pick("piv_v"))]
    sim = [math.hypot(u, v) for u, v in zip(pick("sim_u"), pick("sim_v"))]
    # (title, values, shared colour range or None for a diverging difference map)
    speed_range = (min(piv + sim), max(piv + sim))
    maps = [("PIV |u|", piv, speed_range), ("simulation |u|", sim, speed_range),
            ("simulation - PIV", [s - p for s, p in zip(sim, piv)], None)]
    if "piv_urms" in d:
        pr, sr = pick("piv_urms"), pick("sim_urms")
        rms_range = (min(pr + sr), max(pr + sr))
        maps += [("PIV u_rms", pr, rms_range), ("simulation u_rms", sr, rms_range)]
    n = len(maps) + len(a.profile)
    fig, axes = plt.subplots(1, n, figsize=(4 * n, 4), squeeze=False)
    for ax, (title, values, shared) in zip(axes[0], maps):
        if shared:
            sc = ax.scatter(x, y, c=values, s=12, cmap="viridis", vmin=shared[0], vmax=shared[1])
        else:
            m = max(abs(v) for v in values) or 1.0
            sc = ax.scatter(x, y, c=values, s=12, cmap="coolwarm", vmin=-m, vmax=m)
        fig.colorbar(sc, ax=ax, label="m/s")
        ax.set_title(title)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_aspect("equal")
    for ax, path in zip(axes[0][len(maps):], a.profile):
        p = read(path)
        ax.plot(p["s"], p["sim_u"], "-", label="simulation u")
        ax.plot(p["s"], p["piv_u"], "o", ms=3, label="PIV u")
        ax.plot(p["s"], p["sim_v"], "--", label="simulation v")
        ax.plot(p["s"], p["piv_v"], "s", ms=3, label="PIV v")
        ax.set_xlabel("distance along line [m]")
        ax.set_ylabel("m/s")
        ax.set_title(path.split("/")[-1])
        ax.legend(fontsize=7)
    if a.title:
        fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
