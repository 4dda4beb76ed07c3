#!/usr/bin/env bash
# valve_wall_shear_test.sh VALSALVA SOURCE_DIR MPIEXEC: [wall_shear] on the root wall and the
# frame of the closed coarse valve (scenes/valve_quick_hold.toml) for its first 0.01 s, at 1 and
# 2 ranks. The files are consistent with themselves and equal at both rank counts
# (check_wall_shear.py; 1e-6 of each column's largest value: measured 1.3e-7, the iterative
# solves' tolerances acting on different partitions over 80 steps), and support_fraction marks the nodes inside the leaflets' kernel
# support: nearly all of the frame (the attachment runs along it: at least 90 % of its nodes),
# some of the root wall, and none of the wall farther than 10 mm upstream of the frame (z = 0)
# or 30 mm downstream (the leaflets reach z = 17 mm, the kernel 2 cells of 2 mm beyond).
set -eu
app=$1
src=$2
mpiexec=$3
. "$(dirname "$0")/valve_scene_copy.sh"
valve_scene_copy "$app" "$src" valve_quick_hold.toml valve_hold_pressure.csv
for np in 1 2; do
  $mpiexec -n $np "$app" run "$dir/scenes/valve_quick_hold.toml" --quiet --out "$dir/np$np" \
    --set time.end=0.01 --set 'wall_shear.patches=["wall", "frame"]' --set wall_shear.start_time=0
done
/usr/bin/python3 "$src/tests/app/check_wall_shear.py" "$dir/np1" "$dir/np2" 1e-6
/usr/bin/python3 - "$dir/np1/wall_shear.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
frame = [float(r["support_fraction"]) for r in rows if r["patch"] == "frame"]
wall = [(float(r["z"]), float(r["support_fraction"])) for r in rows if r["patch"] == "wall"]
far = [s for z, s in wall if z < -0.010 or z > 0.030]
inside = sum(s > 0 for _, s in wall)
share = sum(s > 0 for s in frame) / len(frame)
print(f"support: {share:.3f} of {len(frame)} frame nodes, {inside} of {len(wall)} wall nodes, "
      f"{sum(s > 0 for s in far)} of the {len(far)} far ones")
assert share >= 0.9, share
assert 0 < inside < len(wall), inside
assert not any(s > 0 for s in far)
PY
