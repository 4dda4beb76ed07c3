#!/usr/bin/env python3
"""Builds valve_flow_rate.csv, the flow-rate waveform Q(t) of the reference pulse-duplicator
valve case (../../../shared/design/valve_case.md; the measured signal is not public).

The waveform honours the published facts: period 1 s (60 bpm), mean flow 58 mL/s (3.48 L/min),
forward (systolic) flow that opens the valve around t1 = 0.15 s with its peak at t3 = 0.26 s (PS),
still forward at t5 = 0.55 s (LS), then a small negative flow that closes the valve by
t6 = 0.80 s, and no flow in diastole. Construction, all pieces C1-smooth:
  systole   t in [ts, te] = [0.10, 0.65]: Q = Qs * beta(s; a, b), s = (t - ts) / (te - ts),
            beta(s) = s^a (1 - s)^b / max, a = 2, b chosen so that the peak a / (a + b) sits at
            t3 = 0.26 s (b = a (1 - s3) / s3 = 4.875);
  closing   t in [0.65, 0.85]: Q = -Qc sin^2(pi (t - 0.65) / 0.20), closing volume Vc = Qc 0.10 s;
  diastole  Q = 0.
Vc = 3 mL (a typical closing regurgitant volume of a polymer valve in a pulse duplicator); Qs is
then set by the mean flow: the forward volume is 58 mL + Vc.
Columns: t [s], Q [m^3/s]; 1001 rows, 1 ms apart, the last repeating the first (the solver
repeats the table with period t_last - t_first and interpolates linearly).
"""
import math
import os

T, MEAN = 1.0, 58e-6           # s, m^3/s
TS, TE, T3 = 0.10, 0.65, 0.26   # systole start, end, peak
TC0, TC1, VC = 0.65, 0.85, 3e-6  # closing dip and its volume [m^3]
A = 2.0
S3 = (T3 - TS) / (TE - TS)
B = A * (1 - S3) / S3


def beta(s):
    return s**A * (1 - s)**B / (S3**A * (1 - S3)**B)


def beta_integral(n=200000):  # int_0^1 beta(s) ds, midpoint rule
    return sum(beta((i + 0.5) / n) for i in range(n)) / n


QC = VC / (0.5 * (TC1 - TC0))
QS = (MEAN * T + VC) / ((TE - TS) * beta_integral())


def q(t):
    t = t % T
    if TS <= t <= TE:
        return QS * beta((t - TS) / (TE - TS))
    if TC0 < t < TC1:
        return -QC * math.sin(math.pi * (t - TC0) / (TC1 - TC0))**2
    return 0.0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    rows = [(i / 1000, q(i / 1000)) for i in range(1001)]
    with open(os.path.join(here, "valve_flow_rate.csv"), "w") as f:
        f.write("# Flow rate of the reference valve case, built by valve_flow_rate.py\n")
        f.write("t_s,Q_m3_per_s\n")
        for t, v in rows:
            f.write(f"{t:.3f},{v:.9e}\n")
    mean = sum(0.5 * (rows[i][1] + rows[i + 1][1]) * 1e-3 for i in range(1000))
    print(f"peak {1e6 * QS:.2f} mL/s at {T3} s, closing dip -{1e6 * QC:.2f} mL/s, "
          f"mean {1e6 * mean:.3f} mL/s")


if __name__ == "__main__":
    main()
