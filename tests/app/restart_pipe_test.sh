#!/bin/bash
# Wall-shear statistics across a restart: restart_pipe.toml in one go at NP_FULL ranks vs
# restart_pipe_half.toml (30 steps, checkpoint) at NP_HALF + `--restart latest` at NP_FULL:
# wall_shear.csv (TAWSS, OSI, last tau_w per wall node, sorted by node) and pressure_drop.csv
# agree to TOL (0 = identical text); so do wall_shear_summary.csv and the wall_shear_surface
# files, each checked against wall_shear.csv (check_wall_shear.py).
# Usage: restart_pipe_test.sh APP MPIEXEC NP_HALF NP_FULL TOL
set -euo pipefail
app=$1 mpiexec=$2 np_half=$3 np_full=$4 tol=$5
here=$(cd "$(dirname "$0")" && pwd)
work=restart_pipe_np${np_half}_np${np_full}
rm -rf "$work" && mkdir "$work" && cd "$work"
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/restart_pipe.toml" --out full --quiet > full.out
$mpiexec --oversubscribe -n "$np_half" "$app" run "$here/scenes/restart_pipe_half.toml" --out part --quiet > half.out
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/restart_pipe.toml" --out part --restart latest --quiet > rest.out
/usr/bin/python3 - full/wall_shear.csv part/wall_shear.csv "$tol" <<'PY'
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
tol = float(sys.argv[3])
assert len(a) == len(b) > 100, (len(a), len(b))
assert [r["node"] for r in a] == [r["node"] for r in b]
diff = max(abs(float(x[k]) - float(y[k])) for x, y in zip(a, b) for k in ("tawss", "osi", "rrt", "tau_x", "tau_y", "tau_z"))
print(f"wall_shear.csv: {len(a)} wall nodes, max |diff| {diff:.3e} Pa (tolerance {tol:g} x 1 Pa)")
assert diff <= tol
PY
/usr/bin/python3 "$here/compare_csv.py" full/pressure_drop.csv part/pressure_drop.csv "$tol"
/usr/bin/python3 "$here/check_wall_shear.py" full part "$tol"
