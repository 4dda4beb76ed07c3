#!/usr/bin/python3
"""Log-log plot of power spectral densities written by `valsalva psd`.

  plot_psd.py out.png psd_a.csv [psd_b.csv ...] [--title TEXT]

Each CSV has columns frequency,psd; the zero-frequency bin (removed mean) and zero values are
left out of the log axes. Uses matplotlib (Agg).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("png")
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    fig, ax = plt.subplots(figsize=(6, 4))
    for path in a.csv:
        with open(path, newline="") as f:
            rows = [(float(r["frequency"]), float(r["psd"])) for r in csv.DictReader(f)]
        pts = [(f, p) for f, p in rows if f > 0 and p > 0]
        if not pts:
            sys.exit(f"plot_psd: '{path}' has no positive values")
        name = os.path.basename(path)[len("psd_"):-len(".csv")]
        ax.loglog([f for f, _ in pts], [p for _, p in pts], label=name)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("PSD [units$^2$/Hz]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    if a.title:
        ax.set_title(a.title)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
