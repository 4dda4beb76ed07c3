#!/usr/bin/python3
"""PNG plots of a run's valve.csv (and valve_cycles.csv): TPG, flow rate, opening area and
ratio, leaflet tips, with the reference instants of the design note marked (valsalva plot-valve).
Writes plotted.json (instants and ranges) next to the PNGs, for the tests."""
import argparse, csv, json, math, os, sys

INSTANTS = [("t1 opening", 0.15), ("t2 ES", 0.20), ("t3 PS", 0.26), ("t4 MS", 0.35),
            ("t5 LS", 0.55), ("t6 closing", 0.80)]
NEEDED = ["time", "inlet_flow", "outlet_flow", "tpg_mmHg", "orifice_area", "opening_ratio"] + \
    [f"tip{i}_{c}" for i in (1, 2, 3) for c in ("z", "r")]


def fail(msg):
    print(f"plot_valve: {msg}", file=sys.stderr)
    sys.exit(2)


def read_csv(path, needed, min_rows):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        fail(f"{path}: empty file (no header line)")
    header = rows[0]
    for name in needed:
        if name not in header:
            fail(f"{path}:1: missing column '{name}'")
    data = {n: [] for n in header}
    for ln, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            fail(f"{path}:{ln}: {len(row)} values, the header has {len(header)}")
        for n, v in zip(header, row):
            try:
                data[n].append(float(v))
            except ValueError:
                fail(f"{path}:{ln}: column '{n}': '{v}' is not a number")
    if len(rows) - 1 < min_rows:
        fail(f"{path}: {len(rows) - 1} data rows, need at least {min_rows}")
    return data


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run_dir")
    ap.add_argument("out_dir")
    ap.add_argument("--period", type=float, default=1.0)
    ap.add_argument("--cycle-offset", type=float, default=0.0)
    a = ap.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    v = read_csv(os.path.join(a.run_dir, "valve.csv"), NEEDED, 2)
    t = v["time"]
    t0, t1 = min(t), max(t)
    marks = []
    k = math.floor((t0 - a.cycle_offset) / a.period)
    while a.cycle_offset + k * a.period <= t1:
        for name, s in INSTANTS:
            x = a.cycle_offset + k * a.period + s * a.period
            if t0 <= x <= t1:
                marks.append((name, x))
        k += 1
    report = {"time_range": [t0, t1], "instants": [[n, x] for n, x in marks], "plots": {}}

    def mark(ax):
        for n, x in marks:
            ax.axvline(x, color="0.6", lw=0.8, ls="--")
            ax.text(x, 1.0, n.split()[0], transform=ax.get_xaxis_transform(), fontsize=7,
                    ha="center", va="bottom", color="0.4")

    def save(fig, name, series):
        fig.tight_layout()
        fig.savefig(os.path.join(a.out_dir, name), dpi=110)
        plt.close(fig)
        report["plots"][name] = {k: [min(s), max(s)] for k, s in series.items()}

    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(t, v["tpg_mmHg"], lw=1)
    ax.set(xlabel="t (s)", ylabel="TPG (mmHg)")
    mark(ax)
    save(fig, "tpg.png", {"tpg_mmHg": v["tpg_mmHg"]})

    qi = [q * 1e6 for q in v["inlet_flow"]]
    qo = [q * 1e6 for q in v["outlet_flow"]]
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(t, qi, lw=1, label="inlet")
    ax.plot(t, qo, lw=1, ls=":", label="outlet")
    ax.set(xlabel="t (s)", ylabel="flow rate (mL/s)")
    ax.legend()
    mark(ax)
    save(fig, "flow_rate.png", {"inlet_mL_s": qi, "outlet_mL_s": qo})

    area = [x * 1e6 for x in v["orifice_area"]]
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(t, area, lw=1, color="C0")
    ax.set(xlabel="t (s)", ylabel="orifice area (mm$^2$)")
    ax2 = ax.twinx()
    ax2.plot(t, v["opening_ratio"], lw=1, color="C1", ls="--")
    ax2.set_ylabel("opening ratio", color="C1")
    mark(ax)
    save(fig, "opening_area.png", {"area_mm2": area, "opening_ratio": v["opening_ratio"]})

    fig, (ar, az) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    series = {}
    for i in (1, 2, 3):
        r = [x * 1e3 for x in v[f"tip{i}_r"]]
        z = [x * 1e3 for x in v[f"tip{i}_z"]]
        ar.plot(t, r, lw=1, label=f"tip {i}")
        az.plot(t, z, lw=1, label=f"tip {i}")
        series[f"tip{i}_r_mm"] = r
        series[f"tip{i}_z_mm"] = z
    ar.set_ylabel("tip radius (mm)")
    az.set(xlabel="t (s)", ylabel="tip height z (mm)")
    ar.legend(fontsize=8)
    mark(ar)
    mark(az)
    save(fig, "tips.png", series)

    cpath = os.path.join(a.run_dir, "valve_cycles.csv")
    if os.path.exists(cpath):
        c = read_csv(cpath, ["cycle", "tpg_max_mmHg", "tpg_min_mmHg"], 0)
        if c["cycle"]:
            fig, ax = plt.subplots(figsize=(6, 4))
            ax.plot(c["cycle"], c["tpg_max_mmHg"], "o-", label="TPG_max")
            ax.plot(c["cycle"], c["tpg_min_mmHg"], "s-", label="TPG_min")
            ax.set(xlabel="cycle", ylabel="TPG (mmHg)")
            ax.legend()
            save(fig, "tpg_cycles.png",
                 {"tpg_max_mmHg": c["tpg_max_mmHg"], "tpg_min_mmHg": c["tpg_min_mmHg"]})
    with open(os.path.join(a.out_dir, "plotted.json"), "w") as f:
        json.dump(report, f, indent=1)


if __name__ == "__main__":
    main()
