#!/bin/bash
# A run stopped by SIGTERM exits 0, names its checkpoint, and the checkpoint is a readable HDF5
# file with the state at the step it names; `--restart latest` then continues from it.
# With MPIEXEC NP every rank gets SIGTERM itself, as from a batch scheduler (signalling mpiexec
# instead is not reliable: Open MPI may kill the ranks before they finish the step): the ranks
# agree to stop (a collective OR), write one checkpoint together and exit 0.
# Usage: sigterm_test.sh APP [MPIEXEC NP]
set -euo pipefail
app=$1
here=$(cd "$(dirname "$0")" && pwd)
np=${3:-1}
work=sigterm_np$np  # each variant in its own folder: ctest runs them in parallel
rm -rf "$work" && mkdir "$work" && cd "$work"
out=sigterm_run_np$np
if [ "$np" -eq 1 ]; then
  timeout --preserve-status -s TERM 2 "$app" run "$here/scenes/sigterm_tgv.toml" --out $out > sigterm.out
else
  "$2" --oversubscribe -n "$np" "$app" run "$here/scenes/sigterm_tgv.toml" --out $out > sigterm.out &
  launcher=$!
  for _ in $(seq 60); do  # until every rank is stepping (at most 30 s)
    sleep 0.5
    grep -q '^step ' sigterm.out 2>/dev/null && break
  done
  pkill -TERM -f "^$app run .*--out $out"  # the ranks, not mpiexec
  wait $launcher
fi
grep -q 'stopped by signal 15' sigterm.out
ckpt=$(sed -n 's/.*checkpoint \(.*\.h5\)$/\1/p' sigterm.out)
test -s "$ckpt"
/usr/bin/python3 - "$ckpt" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    step, n = int(f.attrs["step"]), int(f.attrs["global_nodes"])
    assert step > 0 and f["velocity"].shape == (n, 3) and f["pressure"].shape == (n,)
    assert np.all(np.isfinite(f["velocity"][...]))
    print(f"{sys.argv[1]}: step {step}, t = {float(f.attrs['time']):.6g} s, {n} nodes")
PY
