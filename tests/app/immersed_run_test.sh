#!/bin/bash
# A scene with an immersed structure (scenes/flap_quick.toml: a clamped flap in a channel, 40
# steps) in one go at NP_FULL ranks vs 20 steps at NP_HALF ranks + `--restart latest` at NP_FULL
# ranks. The fluid fields (with the force density), the flap's Lagrangian mesh and structures.csv
# must agree to TOL (0 = bitwise), and the outputs must be readable: fields.xmf and
# structures/flap.xmf parse back with the HDF5 datasets they name, the flap has moved downstream
# and the run reported its coupling.
# COUPLING (default per_stage) is the scene's immersed.coupling: implicit carries the last marker
# displacement in its checkpoints.
# Usage: immersed_run_test.sh APP MPIEXEC NP_HALF NP_FULL TOL [COUPLING]
set -euo pipefail
app=$1 mpiexec=$2 np_half=$3 np_full=$4 tol=$5 coupling=${6:-per_stage}
here=$(cd "$(dirname "$0")" && pwd)
check_xdmf="$here/../io/check_xdmf.py"
set_coupling=(--set "immersed.coupling=$coupling")
work=immersed_${coupling}_np${np_half}_np${np_full}
rm -rf "$work" && mkdir "$work" && cd "$work"
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/flap_quick.toml" --out full "${set_coupling[@]}" > full.out
grep -q "immersed: 1 structure(s), 663 markers, kernel peskin4 width 4 h, coupling $coupling" full.out
$mpiexec --oversubscribe -n "$np_half" "$app" run "$here/scenes/flap_quick_half.toml" --out part "${set_coupling[@]}" > half.out
test -s part/checkpoints/checkpoint_000000020.h5
$mpiexec --oversubscribe -n "$np_full" "$app" run "$here/scenes/flap_quick.toml" --out part --restart latest "${set_coupling[@]}" > rest.out
grep -q 'restart: .*checkpoint_000000020.h5 (step 20' rest.out
# Readable outputs: 3 fluid steps (t = 0, 2, 4 ms) and 3 Lagrangian steps.
/usr/bin/python3 "$check_xdmf" full/fields.xmf 3
/usr/bin/python3 "$check_xdmf" full/structures/flap.xmf 3 Hexahedron_27
# The restart continued the structure where the checkpoint left it.
full_last=$(ls full/fields_0*.h5 | sort | tail -1)
part_last=$(ls part/fields_restart_000000020_0*.h5 | sort | tail -1)
/usr/bin/python3 "$here/compare_fields.py" "$full_last" "$part_last" "$tol" velocity pressure force_density
/usr/bin/python3 "$here/compare_fields.py" full/structures/flap_000002.h5 \
  "$(ls part/structures/flap_restart_000000020_0*.h5 | sort | tail -1)" "$tol" geometry marker_velocity von_mises
/usr/bin/python3 "$here/compare_csv.py" full/structures.csv part/structures.csv "$tol"
# The flap bends downstream (+x) at its free end: 0.1-1 mm after 4 ms of an impulsive 0.1 m/s
# mean flow (measured 0.38 mm at 30 steps), and stays attached (clamped face within 1 um; with
# the implicit coupling, whose force on the tethered face is first order in time and damps the
# tether's start-up oscillation differently, measured 3.6 um at this step: within 5 um).
held_limit=1e-6
[ "$coupling" = implicit ] && held_limit=5e-6
/usr/bin/python3 - full/structures/flap_000002.h5 "$held_limit" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1]) as f:
    x, X = f["geometry"][:], f["reference"][:]
top = X[:, 1] > X[:, 1].max() - 1e-12
base = X[:, 1] < 1e-12
tip = (x - X)[top].mean(axis=0)[0]
held = np.abs(x - X)[base].max()
print(f"tip x-displacement {tip:.4e} m, clamped face moved {held:.2e} m")
sys.exit(0 if 1e-4 < tip < 1e-3 and held < float(sys.argv[2]) else 1)
PY
