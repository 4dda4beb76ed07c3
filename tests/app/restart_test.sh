#!/bin/bash
# Restart test: restart_tgv.toml in one go at NP_FULL ranks vs restart_tgv_half.toml (8 steps,
# checkpoints) at NP_HALF ranks + `--restart latest` at NP_FULL ranks; the final velocity and
# pressure must agree to TOL (0 = bitwise). Usage: restart_test.sh APP MPIEXEC NP_HALF NP_FULL TOL
set -euo pipefail
app=$1 mpiexec=$2 np_half=$3 np_full=$4 tol=$5
here=$(cd "$(dirname "$0")" && pwd)
work=restart_np${np_half}_np${np_full}
rm -rf "$work" && mkdir "$work" && cd "$work"
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/restart_tgv.toml" --out full > full.out
$mpiexec --oversubscribe -n "$np_half" "$app" run "$here/scenes/restart_tgv_half.toml" --out part > half.out
test -s part/checkpoints/checkpoint_000000008.h5
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/restart_tgv.toml" --out part --restart latest > rest.out
grep -q 'restart: .*checkpoint_000000008.h5 (step 8' rest.out
# The restart kept the first half's fields and continued the log.
test -s part/fields_000000.h5 && test -s part/fields.xmf
grep -q '^8,' part/log.csv && grep -q '^12,' part/log.csv
# A second restart from the same checkpoint into the same directory is refused.
if "$app" run "$here/scenes/restart_tgv.toml" --out part --restart latest > again.out 2>&1; then
  echo "second restart was not refused"; exit 1
fi
grep -q 'already restarted' again.out
full_last=$(ls full/fields_0*.h5 | sort | tail -1)
part_last=$(ls part/fields_restart_000000008_0*.h5 | sort | tail -1)
/usr/bin/python3 "$here/compare_fields.py" "$full_last" "$part_last" "$tol"
# The analysis continued across the restart: the probe and pressure-drop series (appended) and
# the phase statistics (restored from the checkpoint) equal the uninterrupted run's.
/usr/bin/python3 "$here/compare_csv.py" full/probes.csv part/probes.csv "$tol"
/usr/bin/python3 "$here/compare_csv.py" full/pressure_drop.csv part/pressure_drop.csv "$tol"
for bin in 000000 000003; do
  /usr/bin/python3 "$here/compare_fields.py" full/statistics/phase_$bin.h5 part/statistics/phase_$bin.h5 "$tol" \
    mean_velocity rms_velocity mean_pressure k
done
cmp full/statistics/phase_phases.csv part/statistics/phase_phases.csv
