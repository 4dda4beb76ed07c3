#!/bin/bash
# The last step of a run with periodic checkpoints is checkpointed, so a finished run can be
# extended: restart_tgv.toml stopped by time.max_steps = 7 with checkpoints every 5 steps keeps
# checkpoints at steps 5 and 7, and `--restart latest` with a later end continues from step 7.
# Without periodic checkpoints (only the default checkpoint_on_signal) a finished run writes none.
# Usage: final_checkpoint_test.sh APP MPIEXEC NP
set -euo pipefail
app=$1 mpiexec=$2 np=$3
here=$(cd "$(dirname "$0")" && pwd)
work=final_checkpoint_np${np}
rm -rf "$work" && mkdir "$work" && cd "$work"
run() { $mpiexec --oversubscribe -n "$np" "$app" run "$here/scenes/restart_tgv.toml" "$@"; }
run --out periodic --set output.checkpoint_every_steps=5 --set time.max_steps=7 > periodic.out
test -s periodic/checkpoints/checkpoint_000000005.h5
test -s periodic/checkpoints/checkpoint_000000007.h5
run --out periodic --restart latest --set time.max_steps=10 > extended.out
grep -q 'restart: .*checkpoint_000000007.h5 (step 7' extended.out
grep -q '^10,' periodic/log.csv
run --out plain --set time.max_steps=7 > plain.out
test ! -e plain/checkpoints || test -z "$(ls -A plain/checkpoints)"
echo "final checkpoint at step 7, restart continued to step 10; none without periodic checkpoints"
