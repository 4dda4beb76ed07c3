#!/usr/bin/python3
# Recomputes sgs_energy_fraction of a field file from its nu_sgs_over_nu and velocity by hand:
# k_sgs = (nu_sgs / (0.094 Delta))^2 (Yoshizawa), fraction = k_sgs / (k_sgs + |u|^2 / 2), and
# requires agreement to 1e-12 and some model activity (max fraction > MIN); with L, also
# pope_sgs_fraction = 3/2 C (DELTA / (pi L))^(2/3), C = 1.5, at every node to 1e-14.
# Usage: check_sgs_fraction.py FIELDS.h5 NU DELTA MIN [L]
import sys

import h5py
import numpy as np

path, nu, delta, least = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
with h5py.File(path, "r") as f:
    ratio = np.asarray(f["nu_sgs_over_nu"]).ravel()
    u = np.asarray(f["velocity"]).reshape(-1, 3)
    fraction = np.asarray(f["sgs_energy_fraction"]).ravel()
    pope = np.asarray(f["pope_sgs_fraction"]).ravel() if len(sys.argv) > 5 else None
k_sgs = (ratio * nu / (0.094 * delta)) ** 2
k_res = 0.5 * np.sum(u * u, axis=1)
expected = np.where(k_sgs + k_res > 0, k_sgs / np.maximum(k_sgs + k_res, 1e-300), 0.0)
diff = float(np.max(np.abs(fraction - expected)))
print(f"{path}: {fraction.size} nodes, sgs_energy_fraction in [{fraction.min():.4g}, "
      f"{fraction.max():.4g}], max |written - by hand| {diff:.3e}")
if diff > 1e-12 or fraction.max() <= least:
    sys.exit("sgs_energy_fraction does not match the hand computation (or the model is idle)")
if pope is not None:
    expected_pope = 1.5 * 1.5 * (delta / (np.pi * float(sys.argv[5]))) ** (2.0 / 3.0)
    pope_diff = float(np.max(np.abs(pope - expected_pope)))
    print(f"pope_sgs_fraction {expected_pope:.6f} expected, max |written - by hand| {pope_diff:.3e}")
    if pope.size != fraction.size or pope_diff > 1e-14:
        sys.exit("pope_sgs_fraction does not match 3/2 C (Delta / (pi L))^(2/3)")
