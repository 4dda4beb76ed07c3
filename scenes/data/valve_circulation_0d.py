#!/usr/bin/env python3
"""0-D model of scenes/valve_quick_circulation.toml's loop, used to tune its lumped parameters and
start values (docs/valve.md, "The valve in its circulation").

Elastance ventricle p_lv = E(t) (V - V0) (raised cosine over `systole`), the valve as a quadratic
resistance p_lv - p_ao = k Q^2 while p_lv > p_d (closed otherwise: no flow), an RCR aorta
p_ao = p_d + R_p Q, C dp_d/dt = Q - p_d / R_d, and the distal flow p_d / R_d back into the
ventricle. k is valve_quick's measured resistance, 76 mmHg at 279 mL/s, times `k_factor`.
Prints per cycle the aortic and ventricular pressures, the mean flow and the stroke volume.

usage: valve_circulation_0d.py [k_factor]   (explicit Euler, dt 1e-4 s, 12 cycles)
"""
import sys

import numpy as np

MMHG = 133.322


def run(k_factor=1.0, cycles=12, dt=1e-4):
    e_min, e_max, period, systole = 1e7, 3e8, 1.0, 0.4
    v, v0 = 1.4e-4, 1e-5
    r_p, r_d, c, p_d = 1.4e7, 2.16e8, 1.1e-8, 10170.0
    k = k_factor * 76 * MMHG / 279e-6**2
    rows = []
    for n in range(int(cycles * period / dt)):
        t = n * dt
        s = t % period
        e = e_min + (e_max - e_min) * (1 - np.cos(2 * np.pi * s / systole)) / 2 if s < systole else e_min
        p_lv = e * (v - v0)
        drive = p_lv - p_d
        q = (-r_p + np.sqrt(r_p * r_p + 4 * k * drive)) / (2 * k) if drive > 0 else 0.0
        rows.append((t, p_lv, p_d + r_p * q, q))
        v += dt * (p_d / r_d - q)
        p_d += dt * (q - p_d / r_d) / c
    return np.array(rows)


def main():
    out = run(float(sys.argv[1]) if len(sys.argv) > 1 else 1.0)
    for cycle in range(int(out[-1, 0]) + 1):
        w = out[(out[:, 0] >= cycle) & (out[:, 0] < cycle + 1)]
        print(f"cycle {cycle}: aorta {w[:, 2].max() / MMHG:.1f}/{w[:, 2].min() / MMHG:.1f} mmHg, "
              f"ventricle max {w[:, 1].max() / MMHG:.1f} mmHg, mean flow {w[:, 3].mean() * 1e6:.1f} mL/s, "
              f"closed-valve gradient {(w[:, 1] - w[:, 2]).min() / MMHG:.1f} mmHg")


if __name__ == "__main__":
    main()
