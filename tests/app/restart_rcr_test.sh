#!/bin/bash
# Lumped outlets across a restart: restart_rcr.toml (two RCR outlets) in one go at NP_FULL ranks
# vs restart_rcr_half.toml (8 steps, checkpoint) at NP_HALF + `--restart latest` at NP_FULL: the
# outlet pressures, distal pressures and fluxes of log.csv and outlets.csv and the final fields
# agree to TOL
# (0 = identical text and bitwise fields); a copy of a run continued from its middle checkpoint
# writes outlets.csv as the run did. SCENE (default restart_rcr) names the pair SCENE.toml and
# SCENE_half.toml, COLUMNS the number of lumped columns of log.csv (restart_loop: the lumped
# inlets, with the ventricle's volume).
# Usage: restart_rcr_test.sh APP MPIEXEC NP_HALF NP_FULL TOL [SCENE COLUMNS]
set -euo pipefail
app=$1 mpiexec=$2 np_half=$3 np_full=$4 tol=$5 scene=${6:-restart_rcr} columns=${7:-10}
here=$(cd "$(dirname "$0")" && pwd)
work=${scene}_np${np_half}_np${np_full}
rm -rf "$work" && mkdir "$work" && cd "$work"
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/$scene.toml" --out full --quiet > full.out
$mpiexec --oversubscribe -n "$np_half" "$app" run "$here/scenes/${scene}_half.toml" --out part --quiet > half.out
test -s part/checkpoints/checkpoint_000000008.h5
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/$scene.toml" --out part --restart latest --quiet > rest.out
/usr/bin/python3 - full/log.csv part/log.csv "$tol" "$columns" <<'PY'
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
tol = float(sys.argv[3])
cols = [c for c in a[0] if c.startswith(("pressure_", "distal_pressure_", "flux_", "volume_"))]
assert len(cols) == int(sys.argv[4]), cols
assert [r["step"] for r in a] == [r["step"] for r in b] == [str(s) for s in range(1, 17)]
worst = 0.0
for c in cols:
    scale = max(1.0, max(abs(float(r[c])) for r in a))
    for x, y in zip(a, b):
        if tol == 0:
            assert x[c] == y[c], (c, x["step"], x[c], y[c])
        worst = max(worst, abs(float(x[c]) - float(y[c])) / scale)
print(f"log.csv: {len(a)} rows, {len(cols)} lumped-outlet columns, max relative diff {worst:.3e}")
assert worst <= tol
PY
# outlets.csv (every step, 17 digits) was cut back to the checkpoint and continued.
/usr/bin/python3 "$here/compare_csv.py" full/outlets.csv part/outlets.csv "$tol"
/usr/bin/python3 "$here/compare_fields.py" full/fields_000002.h5 part/fields_restart_000000008_000001.h5 "$tol" velocity pressure
# --overwrite knows outlets.csv as valsalva's own output.
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/${scene}_half.toml" --out full --overwrite --quiet > overwrite.out
# A crash past the checkpoint: a copy of a 16-step run with checkpoints at 8 and 16 continued in
# place from step 8 (outlets.csv holds rows 9..16 already): cut back and continued, no row twice.
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/$scene.toml" --out crashed --set output.checkpoint_every_steps=8 --quiet > crashed.out
cp -r crashed again
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/$scene.toml" --out again --restart again/checkpoints/checkpoint_000000008.h5 --set output.checkpoint_every_steps=8 > again.out
grep -q "restart: 8 rows of outlets.csv after the checkpoint removed" again.out
cmp crashed/outlets.csv again/outlets.csv
