#!/usr/bin/env bash
# valve_quick_test.sh VALSALVA SOURCE_DIR [MPIEXEC NP]: the shipped valve scene as a user runs it
# (scripts/make-valve-quick, then `valsalva run scenes/valve_quick.toml`), shortened to
# t = 0.13 s (the forward flow is 0.03 s old, about 600 steps). Checks on valve.csv:
#   mass: |inlet - outlet flow| <= 1e-6 of the waveform's peak flow (279 mL/s) at every sample
#     (the immersed leaflets move no fluid volume; the residual is the Poisson tolerance's);
#   the inlet carries the table: |inlet flow - Q(t)| <= 1e-9 of the peak (linear interpolation
#     of scenes/data/valve_flow_rate.csv, as the solver does);
#   every sample has a finite TPG, orifice area and stress;
#   `check` refuses a [valve] period other than the waveform's and accepts the scene.
set -eu
app=$1
src=$2
mpi=${3:-}
np=${4:-1}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# The meshes of the fixture valve_quick_meshes (made here when run alone), where the scene looks.
"$src/scripts/make-valve-quick" "$app" "$src/runs/valve_quick"
mkdir -p "$dir/runs"
ln -s "$src/runs/valve_quick" "$dir/runs/valve_quick"
mkdir -p "$dir/scenes/data"
cp "$src/scenes/data/valve_flow_rate.csv" "$dir/scenes/data/"
sed 's/^end = 1.0$/end = 0.13/' "$src/scenes/valve_quick.toml" > "$dir/scenes/valve_quick.toml"
grep -q "^end = 0.13$" "$dir/scenes/valve_quick.toml" || { echo "scene has no 'end = 1.0'"; exit 1; }
if [ -n "$mpi" ]; then run="$mpi -n $np $app"; else run="$app"; fi
# A [valve] period other than the inlet waveform's is refused by check, naming both periods.
sed 's/^\[valve\]$/[valve]\nperiod = 0.8/' "$dir/scenes/valve_quick.toml" > "$dir/scenes/bad_period.toml"
if out=$("$app" check "$dir/scenes/bad_period.toml" 2>&1); then
  echo "check accepted valve.period = 0.8 against a 1 s waveform"; exit 1
fi
echo "$out" | grep -q "key 'valve.period': 0.8 s differs from the period 1 s of the waveform of boundary.inlet" ||
  { echo "unexpected refusal: $out"; exit 1; }
"$app" check "$dir/scenes/valve_quick.toml"
$run run "$dir/scenes/valve_quick.toml" --quiet --out "$dir/run"
csv="$dir/run/valve.csv"
[ "$(wc -l < "$csv")" -gt 50 ] || { echo "valve.csv has too few rows"; exit 1; }
awk -F, -v table="$src/scenes/data/valve_flow_rate.csv" '
  BEGIN {
    n = 0
    while ((getline line < table) > 0) {
      if (line ~ /^#/ || line ~ /^t_s/) continue
      split(line, f, ","); t[n] = f[1]; q[n] = f[2]; n++
    }
    peak = 2.79e-4; worst_mass = 0; worst_table = 0
  }
  FNR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  {
    time = $col["time"]; inflow = $col["inlet_flow"]; outflow = $col["outlet_flow"]
    for (k = 0; k < n - 1 && t[k + 1] < time; k++) {}
    qt = q[k] + (q[k + 1] - q[k]) * (time - t[k]) / (t[k + 1] - t[k])
    m = inflow - outflow; if (m < 0) m = -m; if (m > worst_mass) worst_mass = m
    d = inflow - qt; if (d < 0) d = -d; if (d > worst_table) worst_table = d
    for (c in col) if ($col[c] == "nan" && c != "min_gap") { print "non-finite " c " at t = " time; bad = 1 }
    last_q = inflow
  }
  END {
    printf "mass imbalance %.3e of the peak, inlet vs table %.3e, last inlet flow %.4e m3/s\n", worst_mass / peak, worst_table / peak, last_q
    if (bad || worst_mass > 1e-6 * peak || worst_table > 1e-9 * peak || !(last_q > 1e-5)) exit 1
  }' "$csv"
echo "valve_quick test passed"
