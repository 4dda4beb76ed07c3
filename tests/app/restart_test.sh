#!/bin/bash
# Restart test: SCENE.toml in one go at NP_FULL ranks vs SCENE_half.toml (8 steps, checkpoints)
# at NP_HALF ranks + `--restart latest` at NP_FULL ranks; the final fields (velocity, pressure and
# whatever else the scene writes) must agree to TOL (0 = bitwise).
# Usage: restart_test.sh APP MPIEXEC NP_HALF NP_FULL TOL [SCENE, default restart_tgv]
set -euo pipefail
app=$1 mpiexec=$2 np_half=$3 np_full=$4 tol=$5 scene=${6:-restart_tgv}
here=$(cd "$(dirname "$0")" && pwd)
work=${scene}_np${np_half}_np${np_full}
rm -rf "$work" && mkdir "$work" && cd "$work"
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/$scene.toml" --out full > full.out
$mpiexec --oversubscribe -n "$np_half" "$app" run "$here/scenes/${scene}_half.toml" --out part > half.out
test -s part/checkpoints/checkpoint_000000008.h5
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/$scene.toml" --out part --restart latest > rest.out
grep -q 'restart: .*checkpoint_000000008.h5 (step 8' rest.out
# The restart kept the first half's fields and continued the log.
test -s part/fields_000000.h5 && test -s part/fields.xmf
grep -q '^8,' part/log.csv && grep -q '^12,' part/log.csv
# A second restart from the same checkpoint (as after a second crash) recomputes the same steps:
# it replaces the first restart's fields and cuts the logs back to the checkpoint, so nothing is
# written twice (the comparisons below then hold for it).
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/$scene.toml" --out part --restart latest > again.out
grep -q 'restart: .*fields_restart_000000008.xmf (an earlier restart' again.out
full_last=$(ls full/fields_0*.h5 | sort | tail -1)
part_last=$(ls part/fields_restart_000000008_0*.h5 | sort | tail -1)
# LES scenes also write nu_sgs/nu and the subgrid energy fraction: compared as well.
les=$(/usr/bin/python3 -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r'); print(' '.join(n for n in ('nu_sgs_over_nu', 'sgs_energy_fraction') if n in f))" "$full_last")
/usr/bin/python3 "$here/compare_fields.py" "$full_last" "$part_last" "$tol" velocity pressure $les
# The analysis continued across the restart: the probe and pressure-drop series (appended) and
# the phase statistics (restored from the checkpoint) equal the uninterrupted run's.
/usr/bin/python3 "$here/compare_csv.py" full/probes.csv part/probes.csv "$tol"
/usr/bin/python3 "$here/compare_csv.py" full/pressure_drop.csv part/pressure_drop.csv "$tol"
for bin in 000000 000003; do
  /usr/bin/python3 "$here/compare_fields.py" full/statistics/phase_$bin.h5 part/statistics/phase_$bin.h5 "$tol" \
    mean_velocity rms_velocity mean_pressure k
done
cmp full/statistics/phase_phases.csv part/statistics/phase_phases.csv
