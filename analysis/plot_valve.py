#!/usr/bin/python3
"""PNG plots of a run's valve.csv (and valve_cycles.csv): TPG, flow rate, opening area and
ratio, leaflet tips, with the reference instants of the design note marked (valsalva plot-valve);
and, when the run has phase-averaged line statistics statistics/p1.csv ... p3.csv (the PIV
profiles of scenes/valve_*.toml), the mean and RMS streamwise velocity across them at ES, PS, MS
and LS (profiles.png, profiles.csv); and, when the run has a lumped circulation (outlets.csv with
inlet and outlet pressures), the ventricular and aortic pressure and the valve flow against time
(circulation.png) with per-cycle volumes and pressures (circulation_cycles.csv,
circulation_cycles.py). Writes plotted.json (instants and ranges) next to the PNGs,
for the tests."""
import argparse, csv, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import circulation_cycles  # noqa: E402

INSTANTS = [("t1 opening", 0.15), ("t2 ES", 0.20), ("t3 PS", 0.26), ("t4 MS", 0.35),
            ("t5 LS", 0.55), ("t6 closing", 0.80)]
# The phases of the study's PIV profiles (valve_case.md): early, peak, mid and late systole.
PROFILE_PHASES = [("ES", 0.20), ("PS", 0.26), ("MS", 0.35), ("LS", 0.55)]
PROFILE_COLUMNS = ["bin", "phase_time", "y", "samples", "mean_w", "rms_w"]
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


def profiles(run_dir, out_dir, plt, save):
    """Streamwise (w) mean and RMS along the lines p1-p3 in the bins that hold the phases."""
    stats = os.path.join(run_dir, "statistics")
    names = [n for n in ("p1", "p2", "p3") if os.path.exists(os.path.join(stats, n + ".csv"))]
    if not names:
        return
    fig, axes = plt.subplots(len(names), 2, figsize=(10, 3.2 * len(names)), squeeze=False)
    rows, series = [], {}
    for i, name in enumerate(names):
        d = read_csv(os.path.join(stats, name + ".csv"), PROFILE_COLUMNS, 1)
        count = int(max(d["bin"])) + 1
        for label, phase in PROFILE_PHASES:
            b = min(int(math.floor(phase * count + 1e-9)), count - 1)  # the bin holding it
            at = [k for k, x in enumerate(d["bin"]) if x == b and d["samples"][k] > 0]
            if not at:
                continue  # the run has no sample of that phase yet
            t = d["phase_time"][at[0]]
            y = [d["y"][k] * 1e3 for k in at]
            w = [d["mean_w"][k] for k in at]
            r = [d["rms_w"][k] for k in at]
            axes[i][0].plot(y, w, lw=1, label=f"{label} (phase {t:.3g} s)")
            axes[i][1].plot(y, r, lw=1, label=label)
            series[f"{name}_{label}_mean_w"] = w
            rows += [(name, label, t, d["y"][k], d["mean_w"][k], d["rms_w"][k], d["samples"][k])
                     for k in at]
        axes[i][0].set(ylabel=f"{name.upper()}: mean w (m/s)")
        axes[i][1].set(ylabel=f"{name.upper()}: RMS w (m/s)")
        if axes[i][0].lines:
            axes[i][0].legend(fontsize=7)
    for ax in axes[-1]:
        ax.set_xlabel("y (mm)")
    if not series:
        plt.close(fig)
        return
    save(fig, "profiles.png", series)
    with open(os.path.join(out_dir, "profiles.csv"), "w") as f:
        f.write("line,phase,phase_time_s,y_m,mean_w_m_s,rms_w_m_s,samples\n")
        for row in rows:
            f.write("{},{},{:.6g},{:.6e},{:.6e},{:.6e},{:.0f}\n".format(*row))


def circulation(run_dir, out_dir, plt, save, mark, period, offset, diastole):
    """Ventricle and aorta pressure and the valve flow (outlets.csv), and per-cycle figures."""
    path = os.path.join(run_dir, "outlets.csv")
    if not os.path.exists(path):
        return
    with open(path, newline="") as f:
        header = f.readline().strip().split(",")
    if "pressure_inlet" not in header or "pressure_outlet" not in header:
        return
    try:
        d = circulation_cycles.read_outlets(path)
    except circulation_cycles.OutletsError as e:
        fail(str(e))
    mmhg = circulation_cycles.MMHG
    t = d["time"]
    pv = [p / mmhg for p in d["pressure_inlet"]]
    pa = [p / mmhg for p in d["pressure_outlet"]]
    q = [-x * 1e6 for x in d["flux_inlet"]]
    fig, (ap, aq) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    ap.plot(t, pv, lw=0.8, label="ventricle (inlet)")
    ap.plot(t, pa, lw=0.8, label="aorta (outlet)")
    ap.set_ylabel("pressure (mmHg)")
    ap.legend(fontsize=8)
    aq.plot(t, q, lw=0.8, color="C2")
    aq.axhline(0, color="0.5", lw=0.5)
    aq.set(xlabel="t (s)", ylabel="valve flow (mL/s, + forward)")
    mark(ap)
    mark(aq)
    save(fig, "circulation.png",
         {"ventricle_mmHg": pv, "aorta_mmHg": pa, "valve_flow_mL_s": q})
    circulation_cycles.write(circulation_cycles.cycles(d, period, offset, diastole),
                             os.path.join(out_dir, "circulation_cycles.csv"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run_dir")
    ap.add_argument("out_dir")
    ap.add_argument("--period", type=float, default=1.0)
    ap.add_argument("--cycle-offset", type=float, default=0.0)
    ap.add_argument("--diastole", type=float, default=0.6,
                    help="fraction of the period from which the diastolic mean flow is taken")
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
    profiles(a.run_dir, a.out_dir, plt, save)
    circulation(a.run_dir, a.out_dir, plt, save, mark, a.period, a.cycle_offset, a.diastole)
    with open(os.path.join(a.out_dir, "plotted.json"), "w") as f:
        json.dump(report, f, indent=1)


if __name__ == "__main__":
    main()
