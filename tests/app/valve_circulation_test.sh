#!/usr/bin/env bash
# valve_circulation_test.sh VALSALVA SOURCE_DIR: the coarse valve in its closed circulation
# (scenes/valve_quick_circulation.toml: elastance ventricle -> valve -> RCR aorta -> venous
# return), run to t = 0.03 s (about 250 steps). The loop holds its volume: V + C p_d (ventricle
# plus the aorta's compliance; the fluid domain's volume is fixed) stays within 1e-12 of its
# start (measured 6e-16, round-off: the venous return moves the volume between the two exactly,
# flow/lumped_outlets.hpp), and the inlet and outlet flux balance to 1e-12 of the start volume
# per second.
set -eu
app=$1
src=$2
. "$(dirname "$0")/valve_scene_copy.sh"
valve_scene_copy "$app" "$src" valve_quick_circulation.toml
"$app" check "$dir/scenes/valve_quick_circulation.toml"
"$app" run "$dir/scenes/valve_quick_circulation.toml" --quiet --out "$dir/run" --set time.end=0.03
capacitance=$(sed -n 's/^capacitance = //p' "$dir/scenes/valve_quick_circulation.toml")
awk -F, -v c="$capacitance" 'FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  { v = $col["volume_inlet"] + c * $col["distal_pressure_outlet"]
    if (FNR == 2) v0 = v
    d = v - v0; if (d < 0) d = -d; if (d > worst) worst = d
    b = $col["flux_inlet"] + $col["flux_outlet"]; if (b < 0) b = -b; if (b > imbalance) imbalance = b
    rows++ }
  END {
    printf "rows %d, V + C p_d = %.6e m3, largest change %.3e of it, flux imbalance %.3e m3/s\n", rows, v0, worst / v0, imbalance
    exit !(rows > 200 && worst <= 1e-12 * v0 && imbalance <= 1e-12 * v0) }' "$dir/run/outlets.csv"
