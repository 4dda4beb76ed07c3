#!/usr/bin/env bash
# The cost of a valve cardiac cycle by `valsalva run` (issue 18's bench_valve_cycle: the baseline
# of issue 19 target 1). Opt-in, not a test.
#   1. Runs SCENE (default scenes/valve_quick.toml) to time.end = END (default 1.0: one cycle)
#      at each rank count of NP (default "1 2"), one after the other; prints wall and CPU
#      seconds, steps, dt (min / median / max) and what bounded dt per step: the convective CFL
#      target (cfl = time.cfl), the Fourier target (fourier = time.fourier), or neither (the
#      coupling's stiffness bound, [immersed] / `valsalva check`, or a landing on an output).
#   2. Counts with callgrind (independent of the machine's load) PROFILE_STEPS steps (default 10,
#      0 = skip) at one rank from the scene's start and prints each part's share of the time
#      loop (RunLoop::run, inclusive): flow step, Poisson, immersed-boundary stage forces (solid
#      forces, contact, spreading, interpolation, marker location), subgrid model, analysis.
#      The first steps start from rest with the valve closed: contact weighs more there than
#      over a whole cycle.
# Writes OUT/summary.txt (what it prints) and OUT/np<N>/ (the runs), OUT/profile.callgrind.
# Usage (from the repository root, after scripts/make-valve-quick or scripts/make-valve-m1):
#   validation/bench/valve_cycle.sh [BUILD_DIR] [OUT_DIR]
#   SCENE=scenes/valve_m1.toml END=0.05 NP=2 validation/bench/valve_cycle.sh build out  # M1 part
set -euo pipefail
build=${1:-build}
out=${2:-bench-results/valve_cycle}
scene=$(realpath "${SCENE:-scenes/valve_quick.toml}")
end=${END:-1.0}
nps=${NP:-"1 2"}
profile_steps=${PROFILE_STEPS:-10}
app=$(realpath "$build/bin/valsalva")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
out=$(realpath "$out")
summary="$out/summary.txt"
: > "$summary"
say() { echo "$@" | tee -a "$summary"; }

targets=$("$app" run "$scene" --out "$out/resolved" --set time.end=0 --overwrite --quiet > /dev/null 2>&1 &&
  awk -F' = ' '/^\[time\]/ {t = 1; next} /^\[/ {t = 0} t && $1 ~ /^(cfl|fourier)$/ {print $1 "=" $2}' \
    "$out/resolved/resolved_scene.toml" | tr '\n' ' ')
say "scene $scene to t = $end s; time targets: $targets"
cfl=$(echo "$targets" | sed -n 's/.*cfl=\([^ ]*\).*/\1/p')
fourier=$(echo "$targets" | sed -n 's/.*fourier=\([^ ]*\).*/\1/p')

for np in $nps; do
  run="$out/np$np"
  rm -rf "$run"
  /usr/bin/time -f "%e %U %S" -o "$out/time_np$np" mpiexec --oversubscribe -n "$np" "$app" run \
    "$scene" --out "$run" --set time.end="$end" --set run.log_every=1 --set output.interval=0 \
    --quiet > "$out/run_np$np.log" 2>&1
  read -r wall user sys < "$out/time_np$np"
  /usr/bin/python3 - "$run/log.csv" "$np" "$wall" "$user" "$sys" "$cfl" "$fourier" <<'PY' | tee -a "$summary"
import csv, statistics, sys
path, np, wall, user, sys_s, cfl, fourier = sys.argv[1:]
rows = list(csv.DictReader(open(path)))
dt = [float(r["dt"]) for r in rows]
by_cfl = sum(float(r["cfl"]) >= 0.995 * float(cfl) for r in rows)
by_fourier = sum(float(r["cfl"]) < 0.995 * float(cfl) and float(r["fourier"]) >= 0.995 * float(fourier) for r in rows)
n, wall = len(rows), float(wall)
print(f"np {np}: wall {wall:.1f} s, CPU {float(user) + float(sys_s):.1f} s, {n} steps to t = {rows[-1]['time']} s "
      f"({wall / n:.4f} s wall per step); dt min {min(dt):.3g} / median {statistics.median(dt):.3g} / max {max(dt):.3g} s; "
      f"dt set by CFL {100 * by_cfl / n:.1f} %, Fourier {100 * by_fourier / n:.1f} %, "
      f"other (coupling bound, landing) {100 * (n - by_cfl - by_fourier) / n:.1f} % of the steps")
PY
done

if [ "$profile_steps" -gt 0 ]; then
  rm -rf "$out/profile_run"
  valgrind --tool=callgrind --toggle-collect='valsalva::run::RunLoop::run*' \
    --callgrind-out-file="$out/profile.callgrind" "$app" run "$scene" \
    --out "$out/profile_run" --set time.max_steps="$profile_steps" --set output.interval=0 \
    --quiet > "$out/profile.log" 2>&1
  callgrind_annotate --inclusive=yes --threshold=100 "$out/profile.callgrind" > "$out/profile.txt"
  loop=$(awk '/valsalva::run::RunLoop::run\(\)/ {gsub(",", "", $1); print $1; exit}' "$out/profile.txt")
  say "profile: $profile_steps steps at 1 rank from the start; share of the time loop (RunLoop::run, $loop instructions):"
  part() {  # part LABEL PATTERN
    awk -v label="$1" -v pattern="$2" -v loop="$loop" '
      index($0, pattern) { gsub(",", "", $1); printf "  %-44s %5.1f %%\n", label, 100 * $1 / loop; found = 1; exit }
      END { if (!found) printf "  %-44s     - (not called)\n", label }' "$out/profile.txt" | tee -a "$summary"
  }
  part "flow step (ProjectionRK4::step, all below)" "valsalva::flow::ProjectionRK4::step("
  part "  Poisson solve (PCG + BoomerAMG)" "valsalva::flow::PressurePoisson::solve("
  part "  immersed stage forces" "valsalva::ibm::ImmersedStructure::stage_force("
  part "    solid internal forces (FE)" "valsalva::structure::SolidForces::internal_forces("
  part "    contact" "valsalva::structure::Contact::add_forces("
  part "    spreading (markers to nodes)" "valsalva::ibm::DiracTransfer::spread("
  part "    interpolation (nodes to markers)" "valsalva::ibm::DiracTransfer::interpolate("
  part "    marker location (re-location)" "valsalva::ibm::DiracTransfer::relocate("
  part "subgrid model (nu_sgs)" "valsalva::les::compute_nu_sgs("
  part "run observers: statistics, checkpoints" "RunHooks::Moment), valsalva::run::Simulation::run()::{lambda"
  part "valve monitor (TPG, orifice area)" "valsalva::valve::ValveMonitor::sample("
fi
