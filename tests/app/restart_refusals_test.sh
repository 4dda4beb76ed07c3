#!/bin/bash
# Restarts that must be refused (issue 23, items 5 and 6), each with exit code 1 and a message
# naming what is wrong, and the run directory left as it was; and the changes a restart accepts.
# Usage: restart_refusals_test.sh APP
set -euo pipefail
app=$1
here=$(cd "$(dirname "$0")" && pwd)
expect=$here/expect_error.sh
work=restart_refusals
rm -rf "$work" && mkdir "$work" && cd "$work"
cp "$here/scenes/restart_tgv.toml" scene.toml
"$app" run "$here/scenes/restart_tgv_half.toml" --out run --quiet > half.out
cp -r run pristine

# A scene change a restart must not make: named with both values, nothing written.
sed 's/^viscosity = 0.01/viscosity = 0.02/' scene.toml > viscosity.toml
$expect "flow\.viscosity = 0\.01 in the run, 0\.02 in .*viscosity\.toml" \
  "$app" run viscosity.toml --out run --restart latest
# An added probe (probes.csv has the columns of the first run's probes).
sed 's/^\[probe\.centre\]/[probe.corner]\nposition = [0.5, 0.5, 0.5]\n\n[probe.centre]/' scene.toml > probe.toml
$expect "probe\.corner\.position = \(absent\) in the run, \[ 0\.5, 0\.5, 0\.5 \] in" \
  "$app" run probe.toml --out run --restart latest
diff -r pristine run > /dev/null || { echo "a refused restart changed the run directory"; exit 1; }

# time.end before the checkpoint's time (t = 2.7 s after 8 steps).
sed 's/^end = 4.0/end = 1.0/' scene.toml > early.toml
$expect "early\.toml:[0-9]+:[0-9]+: key 'time\.end': 1 s is before the time of checkpoint '.*checkpoint_000000008\.h5', 2\.7[0-9]* s" \
  "$app" run early.toml --out run --restart latest

# A series the run wrote is gone: refused rather than continued without a header.
mv run/probes.csv probes.csv.saved
$expect "restart: '.*run/probes\.csv' is missing" "$app" run scene.toml --out run --restart latest
mv probes.csv.saved run/probes.csv

# A checkpoint whose data were altered after it was written.
cp run/checkpoints/checkpoint_000000008.h5 saved.h5
/usr/bin/python3 - run/checkpoints/checkpoint_000000008.h5 <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    f["pressure"][5] = f["pressure"][5] + 1e-9
PY
$expect "dataset 'pressure' does not match its checksum" "$app" run scene.toml --out run --restart latest
cp saved.h5 run/checkpoints/checkpoint_000000008.h5
# A checkpoint holding NaN with a valid checksum (rewritten as io/checkpoint.cpp computes it):
# refused naming the file, not blamed on the flow.
/usr/bin/python3 - run/checkpoints/checkpoint_000000008.h5 <<'PY'
import sys, h5py, numpy as np
def checksum(data):
    rows = data.reshape(data.shape[0], -1)
    total = 0
    for r, values in enumerate(rows):
        words = [r] + [int(w) for w in values.view(np.uint64)]
        if all(w == 0 for w in words[1:]):
            continue
        h = 14695981039346656037
        for w in words:
            h = ((h ^ w) * 1099511628211) % 2**64
        total = (total + h) % 2**64
    return total
with h5py.File(sys.argv[1], "r+") as f:
    p = f["pressure"][...]
    p[3] = np.nan
    f["pressure"][...] = p
    s = checksum(p)
    f.attrs["checksum_pressure_hi"], f.attrs["checksum_pressure_lo"] = float(s >> 32), float(s & 0xffffffff)
PY
$expect "checkpoint '.*checkpoint_000000008\.h5': the state is not finite \(velocity or pressure of node 3 is NaN" \
  "$app" run scene.toml --out run --restart latest
cp saved.h5 run/checkpoints/checkpoint_000000008.h5

# A checkpoint of another mesh, continued into a new directory (issue 18, bad input): refused
# naming both meshes, and the new directory is not made.
sed 's/^cells = \[8, 8, 3\]/cells = [10, 8, 3]/' scene.toml > finer.toml
$expect "checkpoint '.*checkpoint_000000008\.h5' was written for another mesh: 192 nodes, .*; this run's mesh has 240 nodes" \
  "$app" run finer.toml --out elsewhere --restart run/checkpoints/checkpoint_000000008.h5
test ! -e elsewhere || { echo "a refused restart made its run directory"; exit 1; }

# Accepted changes: a later end time and another output interval; the restart's scene is kept.
sed 's/^end = 4.0/end = 4.5/; s/^interval = 1.0/interval = 0.5/' scene.toml > longer.toml
"$app" run longer.toml --out run --restart latest --quiet > longer.out
grep -q '^end = 4.5' run/resolved_scene_restart_000000008.toml
grep -q '^end = 4.0' run/resolved_scene.toml
echo "refusals and accepted changes as expected"
