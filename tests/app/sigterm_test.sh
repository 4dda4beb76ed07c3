#!/bin/bash
# A run stopped by SIGTERM exits 0, names its checkpoint, and the checkpoint is a readable HDF5
# file with the state at the step it names; `--restart latest` then continues from it.
# Usage: sigterm_test.sh APP
set -euo pipefail
app=$1
here=$(cd "$(dirname "$0")" && pwd)
rm -rf sigterm_run sigterm.out
timeout --preserve-status -s TERM 2 "$app" run "$here/scenes/sigterm_tgv.toml" --out sigterm_run > sigterm.out
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
