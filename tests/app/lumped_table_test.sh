#!/bin/bash
# The lumped inlets' tables (boundary.X.elastance = "table", pressure_waveform = "table") against
# the closed forms they sample: scenes/restart_loop.toml (raised-cosine elastance, sine inlet
# pressure 50 + 30 sin(2 pi t / 0.05) Pa) and scenes/lumped_table.toml (the same from tables: the
# elastance's rows sample the raised cosine over one cycle, 0.08 s, the pressure table's rows the
# sine's 30 sin(...) over one period, 0.05 s, with pressure = 50 added to them), both for 32 steps
# of 5e-3 s (two elastance cycles, 3.2 pressure periods: the tables wrap). Both laws are evaluated
# only at step times (flow/lumped_outlets.cpp), every one of which is a table row (rows every
# dt / 2), where linear interpolation returns the row: the two runs' lumped columns of log.csv
# must agree to round-off (TOL, relative to the column's largest value). Then pressure = 0 must
# move the inlet's pressure column by 50 Pa (the offset is applied, and the comparison sees it).
# Usage: lumped_table_test.sh APP MPIEXEC NP TOL
set -euo pipefail
app=$1 mpiexec=$2 np=$3 tol=$4
here=$(cd "$(dirname "$0")" && pwd)
work=lumped_table_np$np
rm -rf "$work" && mkdir "$work" && cd "$work"
/usr/bin/python3 - <<'PY'
import math
dt = 5e-3
with open("elastance.csv", "w") as f:  # restart_loop.toml: 2e7 .. 5e8 Pa/m3, cycle 0.08 s, systole 0.03 s
    for k in range(33):
        t = k * dt / 2
        s = 0.5 * (1 - math.cos(2 * math.pi * t / 0.03)) if t < 0.03 else 0.0
        f.write(f"{t!r},{2e7 + (5e8 - 2e7) * s!r}\n")
with open("pressure.csv", "w") as f:  # the sine's variable part, period 0.05 s
    for k in range(21):
        t = k * dt / 2
        f.write(f"{t!r},{30 * math.sin(2 * math.pi * t / 0.05)!r}\n")
PY
run() { $mpiexec --oversubscribe -n "$np" "$app" run "$@" --set time.end=0.16 --quiet; }
run "$here/scenes/restart_loop.toml" --out closed > closed.out
tables=(--set "boundary.xmin.elastance_file=\"$PWD/elastance.csv\"" --set "boundary.ymax.pressure_file=\"$PWD/pressure.csv\"")
run "$here/scenes/lumped_table.toml" --out table "${tables[@]}" > table.out
run "$here/scenes/lumped_table.toml" --out offset0 "${tables[@]}" --set boundary.ymax.pressure=0.0 > offset0.out
/usr/bin/python3 - closed/log.csv table/log.csv offset0/log.csv "$tol" <<'PY'
import csv, sys
a, b, c = (list(csv.DictReader(open(f))) for f in sys.argv[1:4])
tol = float(sys.argv[4])
cols = [k for k in a[0] if k.startswith(("pressure_", "distal_pressure_", "flux_", "volume_"))]
assert "volume_xmin" in cols and "pressure_ymax" in cols, cols
assert [r["step"] for r in a] == [r["step"] for r in b] == [str(s) for s in range(1, 33)]
worst = 0.0
for k in cols:
    scale = max(abs(float(r[k])) for r in a) or 1.0  # walls: flux 0
    for x, y in zip(a, b):
        worst = max(worst, abs(float(x[k]) - float(y[k])) / scale)
print(f"log.csv: {len(a)} rows, {len(cols)} lumped columns, tables vs closed forms: max relative diff {worst:.3e}")
assert worst <= tol, worst
shift = [float(x["pressure_ymax"]) - float(y["pressure_ymax"]) for x, y in zip(b, c)]
print(f"pressure = 50 vs 0 with the table: inlet pressure shifted by {min(shift):.12g} .. {max(shift):.12g} Pa")
assert all(abs(d - 50) <= 1e-9 * 50 for d in shift), shift
PY
