#!/bin/bash
# A run stopped by SIGTERM exits 0, names its checkpoint, and the checkpoint is a readable HDF5
# file with the state at the step it names; `--restart latest` then continues from it.
# With MPIEXEC NP the signal goes to mpiexec, which passes it to every rank: the ranks agree to
# stop (a collective OR), write one checkpoint together and exit 0; mpiexec itself then exits
# non-zero because it was signalled, so its code is not checked, everything else is.
# Usage: sigterm_test.sh APP [MPIEXEC NP]
set -euo pipefail
app=$1
here=$(cd "$(dirname "$0")" && pwd)
launch=()
if [ $# -ge 3 ]; then launch=("$2" --oversubscribe -n "$3"); fi
work=sigterm_np${3:-1}  # each variant in its own folder: ctest runs them in parallel
rm -rf "$work" && mkdir "$work" && cd "$work"
if [ ${#launch[@]} -eq 0 ]; then
  timeout --preserve-status -s TERM 2 "$app" run "$here/scenes/sigterm_tgv.toml" --out sigterm_run > sigterm.out
else
  timeout --preserve-status -s TERM 4 "${launch[@]}" "$app" run "$here/scenes/sigterm_tgv.toml" --out sigterm_run > sigterm.out || true
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
