#!/bin/bash
# The end-of-run [wall_shear] files (wall_shear.csv, wall_shear_summary.csv, wall_shear_surface)
# of restart_pipe.toml at 1 and at 2 ranks: each consistent with itself and the two equal to TOL
# (check_wall_shear.py). Usage: wall_shear_ranks_test.sh APP MPIEXEC TOL
set -euo pipefail
app=$1 mpiexec=$2 tol=$3
here=$(cd "$(dirname "$0")" && pwd)
work=wall_shear_ranks
rm -rf "$work" && mkdir "$work" && cd "$work"
for np in 1 2; do
  $mpiexec --oversubscribe -n $np "$app" run "$here/scenes/restart_pipe.toml" --out np$np > np$np.out
  grep '^wall_shear wall: ' np$np.out
done
/usr/bin/python3 "$here/../io/check_xdmf.py" np2/wall_shear_surface.xmf 1
/usr/bin/python3 "$here/check_wall_shear.py" np1 np2 "$tol"
