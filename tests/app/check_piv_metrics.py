#!/usr/bin/python3
# Checks compare-piv's metrics.csv against the noise of a synthetic PIV file (its first line
# states sigma): every frame's u RMSE (a component the flow does not have: pure noise) must lie
# in [0.9, 1.2] sigma (384 points per frame: the estimate scatters by ~4 %), every v RMSE in
# [0.9 sigma, MAX_V sigma] (noise plus the simulation's own error), each with >= 100 points.
# Usage: check_piv_metrics.py METRICS.csv PIV.csv MAX_V
import csv
import re
import sys

metrics, piv, upper = sys.argv[1], sys.argv[2], float(sys.argv[3])
sigma = float(re.search(r"sigma \(m/s\) = ([0-9.eE+-]+)", open(piv).readline()).group(1))
rows = [r for r in csv.DictReader(open(metrics)) if r["quantity"] in ("u", "v")]
if len(rows) < 2:
    sys.exit(f"{metrics}: no u/v rows")
for r in rows:
    ratio = float(r["rmse"]) / sigma
    print(f"frame {r['frame']} {r['quantity']}: RMSE {float(r['rmse']):.4e} = {ratio:.3f} sigma, {r['points']} points")
    hi = 1.2 if r["quantity"] == "u" else upper
    if not (0.9 <= ratio <= hi) or int(r["points"]) < 100:
        sys.exit(f"frame {r['frame']} {r['quantity']}: RMSE/sigma {ratio:.3f} outside [0.9, {hi}]")
