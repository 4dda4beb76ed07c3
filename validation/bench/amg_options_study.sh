#!/usr/bin/env bash
# BoomerAMG options against the instructions a flow step costs (issue 19, target 4). Opt-in, not a
# test. Counts with valgrind's callgrind (independent of the machine's load, as the brief asks
# for a shared machine) the instructions inside flow::ProjectionRK4::step and, of those, inside
# HYPRE_BoomerAMGSolve, for each [poisson] variant on two scenes run by `valsalva run`:
#   tgv:  validation/tgv_les/tgv_les.toml at 24^3 hexahedra, central2, no model, 10 steps of 0.1
#         (periodic: singular Poisson matrix);
#   root: scenes/valve_root_stability.toml on the root of scripts/make-valve-quick (Gmsh
#         tetrahedra, 6,765 nodes), a constant 0.2 L/s flat inflow from rest, sigma model,
#         20 steps (Dirichlet pressure at the outlet).
# Prints one line per case and variant: step instructions, AMG-solve instructions, mean Poisson
# iterations per step, and the last step's kinetic energy (the results agree to the Poisson
# tolerance). About 30 min on one core; ONLY="default thr025" runs those variants only.
# Usage: validation/bench/amg_options_study.sh [BUILD_DIR] [OUT_DIR]   (from the repository root;
#        the root case needs runs/valve_quick/geom/root.msh from scripts/make-valve-quick)
set -euo pipefail
build=${1:-build}
out=${2:-bench-results/amg_options}
app=$(realpath "$build/bin/valsalva")
repo=$(pwd)
mkdir -p "$out"
cd "$out"

variants=("default:" "relax8:poisson.relax_type=8" "relax18:poisson.relax_type=18"
  "pmis:poisson.coarsen_type=8" "interp17:poisson.interp_type=17"
  "agg1:poisson.aggressive_levels=1" "thr025:poisson.strong_threshold=0.25"
  "agg1_thr025:poisson.aggressive_levels=1,poisson.strong_threshold=0.25"
  "tol1e6:poisson.tolerance=1e-6")

sed -e 's|^waveform = "table"|waveform = "constant"\nflow_rate = 2e-4|' -e '/^file = "data\/valve_flow_rate.csv"/d' \
  -e "s|^file = \"../runs/valve_m1/geom/root.msh\"|file = \"$repo/runs/valve_quick/geom/root.msh\"|" \
  "$repo/scenes/valve_root_stability.toml" > root.toml

count() {  # count NAME SCENE SETTINGS... -> prints the summary line
  local name=$1 scene=$2
  shift 2
  valgrind --tool=callgrind --toggle-collect='valsalva::flow::ProjectionRK4::step*' \
    --callgrind-out-file="$name.callgrind" "$app" run "$scene" --out "run_$name" \
    --set run.log_every=1 --set output.interval=0 "$@" > "$name.log" 2>&1
  local step amg its energy
  step=$(callgrind_annotate "$name.callgrind" | awk '/PROGRAM TOTALS/ {print $1}')
  amg=$(callgrind_annotate --inclusive=yes "$name.callgrind" | awk '/HYPRE_BoomerAMGSolve / {print $1; exit}')
  its=$(awk -F, 'NR > 1 {s += $8; n++} END {printf "%.2f", s / n}' "run_$name/log.csv")
  energy=$(tail -1 "run_$name/log.csv" | cut -d, -f7)
  echo "$name step_instructions=$step amg_solve=$amg poisson_its_mean=$its kinetic_energy=$energy"
}

for v in "${variants[@]}"; do
  name=${v%%:*}
  if [ -n "${ONLY:-}" ] && [[ " $ONLY " != *" $name "* ]]; then continue; fi
  sets=()
  IFS=',' read -ra pairs <<< "${v#*:}"
  for p in "${pairs[@]}"; do [ -n "$p" ] && sets+=(--set "$p"); done
  count "tgv_$name" "$repo/validation/tgv_les/tgv_les.toml" --set 'mesh.box.cells=[24,24,24]' \
    --set flow.scheme=central2 --set les.model=none --set partition.ghost_layers=1 \
    --set time.end=1.0 --set time.dt=0.1 "${sets[@]+"${sets[@]}"}"
  count "root_$name" root.toml --set time.max_steps=20 "${sets[@]+"${sets[@]}"}"
done
