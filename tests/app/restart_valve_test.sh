#!/bin/bash
# A valve run continued in place after a crash past its checkpoint: restart_valve.toml (the
# coarse valve, meshes by scripts/make-valve-quick) run to step 40 with checkpoints at 20 and 40,
# a copy continued from checkpoint 20 with `--restart FILE` (the interrupted run's rows after
# step 20 are in every series). valve.csv, valve_cycles.csv and structures.csv must equal the
# uninterrupted run's byte for byte (each cut back to the checkpoint and continued; a cycle
# completed after the checkpoint is written once), then --overwrite accepts the run directory.
# Last, a run ending on a cycle boundary off valve.every_steps must close that cycle.
# Usage: restart_valve_test.sh APP SOURCE_DIR
set -euo pipefail
app=$1 src=$2
here=$(cd "$(dirname "$0")" && pwd)
work=restart_valve
rm -rf "$work" && mkdir "$work" && cd "$work"
# The meshes of the fixture valve_quick_meshes (made here when run alone).
"$src/scripts/make-valve-quick" "$app" "$src/runs/valve_quick" > mesh.out 2>&1
ln -s "$src/runs/valve_quick" mesh
cp "$here/scenes/restart_valve.toml" scene.toml
"$app" run scene.toml --out full --quiet > full.out
test -s full/checkpoints/checkpoint_000000020.h5
# The test needs a cycle completed on each side of the checkpoint (row 2 and after it).
/usr/bin/python3 - full/valve_cycles.csv full/log.csv <<'PY'
import csv, sys
cycles = list(csv.DictReader(open(sys.argv[1])))
t20 = float(list(csv.DictReader(open(sys.argv[2])))[19]["time"])
before = [c for c in cycles if float(c["end"]) <= t20]
after = [c for c in cycles if float(c["end"]) > t20]
print(f"valve_cycles.csv: {len(before)} cycles completed by step 20 (t = {t20:.6g} s), {len(after)} after")
assert before and after
PY
cp -r full part
"$app" run scene.toml --out part --restart part/checkpoints/checkpoint_000000020.h5 > rest.out
for csv in valve.csv valve_cycles.csv structures.csv; do
  cmp "full/$csv" "part/$csv"
  echo "$csv: identical ($(wc -l < "full/$csv") lines)"
done
# What was cut, as the restart reports it.
grep -q "restart: 20 rows of valve.csv after the checkpoint removed" rest.out
grep -q "restart: 1 rows of valve_cycles.csv after the checkpoint removed" rest.out
[ "$(wc -l < full/valve.csv)" -eq 42 ] || { echo "valve.csv: expected header + 41 rows"; exit 1; }
# --overwrite replaces the run directory (valve.csv and valve_cycles.csv are valsalva's).
"$app" run scene.toml --out full --overwrite --quiet > overwrite.out
cmp part/valve_cycles.csv full/valve_cycles.csv
# A run that ends on a cycle boundary closes its last cycle although its last step is not one of
# valve.every_steps: two 2 ms cycles, a row every 7 steps, output times on the cycle ends.
sed -e 's/^every_steps = 1$/every_steps = 7/' -e 's/^end = 1.0$/end = 0.004/' \
  -e '/^max_steps = 40$/d' -e 's/^interval = 1.0$/interval = 0.002/' scene.toml > cycles.toml
grep -q "^every_steps = 7$" cycles.toml && grep -q "^end = 0.004$" cycles.toml
"$app" run cycles.toml --out cycles --quiet > cycles.out
/usr/bin/python3 - cycles/valve.csv cycles/valve_cycles.csv <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
cycles = list(csv.DictReader(open(sys.argv[2])))
last = rows[-1]
print(f"valve.csv: last row step {last['step']} t {last['time']}; valve_cycles.csv: {len(cycles)} cycles")
assert float(last["time"]) == 0.004 and int(last["step"]) % 7 != 0, "no row at the run's end"
assert len(cycles) == 2 and float(cycles[-1]["end"]) == 0.004, "the last cycle was not closed"
PY
