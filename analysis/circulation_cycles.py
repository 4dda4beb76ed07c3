"""Per-cycle figures of a run whose valve sits in a lumped circulation (outlets.csv of an
elastance or pressure inlet and a resistance or RCR outlet): forward, regurgitant and net volume
through the inlet, regurgitant fraction, aortic (outlet) and ventricular (inlet) pressure
extremes and mean, the mean flow in diastole, and each figure's change from the previous cycle
(how periodic the loop is). Used by plot_valve.py (valsalva plot-valve), which writes them as
circulation_cycles.csv and draws circulation.png."""
import csv

MMHG = 133.322387415  # Pa
COLUMNS = ["cycle", "start_s", "end_s", "forward_volume_mL", "regurgitant_volume_mL",
           "net_volume_mL", "regurgitant_fraction", "aorta_max_mmHg", "aorta_min_mmHg",
           "aorta_mean_mmHg", "ventricle_max_mmHg", "ventricle_min_mmHg",
           "diastolic_mean_flow_mL_s", "net_volume_change_mL", "aorta_min_change_mmHg"]


class OutletsError(Exception):
    pass


def read_outlets(path):
    """time, flux_inlet, pressure_inlet, pressure_outlet columns of outlets.csv as floats."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise OutletsError(f"{path}: empty file (no header line)")
    header = rows[0]
    needed = ["time", "flux_inlet", "pressure_inlet", "pressure_outlet"]
    for name in needed:
        if name not in header:
            raise OutletsError(f"{path}:1: missing column '{name}'")
    index = [header.index(n) for n in needed]
    data = {n: [] for n in needed}
    for ln, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            raise OutletsError(f"{path}:{ln}: {len(row)} values, the header has {len(header)}")
        for n, i in zip(needed, index):
            try:
                data[n].append(float(row[i]))
            except ValueError:
                raise OutletsError(f"{path}:{ln}: column '{n}': '{row[i]}' is not a number")
    return data


def _window(t, values, a, b):
    """The samples in [a, b] with the ends interpolated, for trapezoidal integrals."""
    ts, vs = [], []
    for k in range(1, len(t)):
        if t[k] <= a or t[k - 1] >= b:
            continue
        for x in (max(a, t[k - 1]), min(b, t[k])):
            w = (x - t[k - 1]) / (t[k] - t[k - 1])
            if not ts or x > ts[-1]:
                ts.append(x)
                vs.append((1 - w) * values[k - 1] + w * values[k])
    return ts, vs


def _integral(ts, vs):
    return sum(0.5 * (vs[k - 1] + vs[k]) * (ts[k] - ts[k - 1]) for k in range(1, len(ts)))


def _positive_integral(ts, vs):
    """Integral of max(v, 0) for v linear between the samples (split at each zero crossing)."""
    total = 0.0
    for k in range(1, len(ts)):
        a, b, dt = vs[k - 1], vs[k], ts[k] - ts[k - 1]
        if a >= 0 and b >= 0:
            total += 0.5 * (a + b) * dt
        elif a > 0 or b > 0:
            top = max(a, b)
            total += 0.5 * top * dt * top / (abs(a) + abs(b))
    return total


def cycles(data, period, offset, diastole):
    """One dict per complete cycle [offset + k period, offset + (k + 1) period] in the data.
    diastole: the fraction of the period from which the diastolic mean flow is taken."""
    t = data["time"]
    out = []
    if len(t) < 2:
        return out
    k = 0
    while offset + (k + 1) * period <= t[-1] + 1e-9 * period:
        a, b = offset + k * period, offset + (k + 1) * period
        k += 1
        if a < t[0] - 1e-9 * period:
            continue
        ts, q = _window(t, data["flux_inlet"], a, b)
        _, pin = _window(t, data["pressure_inlet"], a, b)
        _, pout = _window(t, data["pressure_outlet"], a, b)
        # flux_inlet is the outward flux of the inlet patch: negative while the ventricle ejects.
        forward = _positive_integral(ts, [-v for v in q]) * 1e6
        regurgitant = _positive_integral(ts, q) * 1e6
        td, qd = _window(t, data["flux_inlet"], a + diastole * period, b)
        row = {
            "cycle": len(out), "start_s": a, "end_s": b,
            "forward_volume_mL": forward, "regurgitant_volume_mL": regurgitant,
            "net_volume_mL": forward - regurgitant,
            "regurgitant_fraction": regurgitant / forward if forward > 0 else float("nan"),
            "aorta_max_mmHg": max(pout) / MMHG, "aorta_min_mmHg": min(pout) / MMHG,
            "aorta_mean_mmHg": _integral(ts, pout) / period / MMHG,
            "ventricle_max_mmHg": max(pin) / MMHG, "ventricle_min_mmHg": min(pin) / MMHG,
            "diastolic_mean_flow_mL_s": _integral(td, qd) / (td[-1] - td[0]) * 1e6,
        }
        prev = out[-1] if out else None
        row["net_volume_change_mL"] = (
            row["net_volume_mL"] - prev["net_volume_mL"] if prev else float("nan"))
        row["aorta_min_change_mmHg"] = (
            row["aorta_min_mmHg"] - prev["aorta_min_mmHg"] if prev else float("nan"))
        out.append(row)
    return out


def write(rows, path):
    with open(path, "w") as f:
        f.write(",".join(COLUMNS) + "\n")
        for r in rows:
            f.write(",".join(f"{r[c]:.9g}" for c in COLUMNS) + "\n")
