#!/bin/bash
# scenes/poiseuille_pipe.toml at NP ranks writes every analysis output, and the XDMF series of
# the fields and the statistics parse back (tests/io/check_xdmf.py: XML, times, HDF5 datasets and
# shapes). Usage: analysis_run_test.sh APP MPIEXEC NP SOURCE_DIR
set -euo pipefail
app=$1 mpiexec=$2 np=$3 src=$4
out=analysis_np$np
rm -rf "$out"
$mpiexec --oversubscribe -n "$np" "$app" run "$src/scenes/poiseuille_pipe.toml" --out "$out" --quiet > "$out.log"
for f in probes.csv pressure_drop.csv wall_shear.csv wall_shear_history.csv \
         statistics/mean.xmf statistics/mid_plane.xmf statistics/mid_plane_phases.csv \
         statistics/diameter.csv sections.csv samples/axis_000000000.csv; do
  test -s "$out/$f" || { echo "missing $out/$f"; exit 1; }
done
test "$(ls "$out"/samples/cross_section_*.csv | wc -l)" -eq 3
head -1 "$out/probes.csv" | grep -q '^time,centre_u,centre_v,centre_w,centre_p,near_wall_u'
head -1 "$out/pressure_drop.csv" | grep -q '^time,pipe_upstream,pipe_downstream,pipe_mmHg$'
/usr/bin/python3 "$src/tests/io/check_xdmf.py" "$out/fields.xmf" 3
/usr/bin/python3 "$src/tests/io/check_xdmf.py" "$out/statistics/mid_plane.xmf" 4
/usr/bin/python3 "$src/tests/io/check_xdmf.py" "$out/statistics/mean.xmf" 1
# Poiseuille: pressure drop within 10 % of 16.30 Pa = 0.1222 mmHg and mean wall shear stress
# within 15 % of 2.037 Pa on this 1 mm mesh (measured +5 % and +12 %; validation/poiseuille_wss
# has the convergence study).
/usr/bin/python3 - "$out" <<'PY'
import csv, sys
d = sys.argv[1]
# The section flux sums the projected face fluxes: the inlet flow rate to the Poisson
# tolerance (analysis/section_flux.hpp), at every step.
q = [float(r["mid_flux"]) for r in csv.DictReader(open(f"{d}/sections.csv"))][1:]
assert q and max(abs(x / 2e-6 - 1) for x in q) < 1e-8, q[-1]  # poisson.tolerance 1e-8
# The diameter's time-averaged axial velocity peaks at the centre (s = 5 mm).
line = list(csv.DictReader(open(f"{d}/statistics/diameter.csv")))
centre = max(line, key=lambda r: float(r["mean_w"]))
assert abs(float(centre["s"]) - 0.005) < 1e-9 and int(centre["samples"]) > 0, centre
drop = list(csv.DictReader(open(f"{d}/pressure_drop.csv")))[-1]
wss = list(csv.DictReader(open(f"{d}/wall_shear_history.csv")))[-1]
mmhg, tau = float(drop["pipe_mmHg"]), float(wss["wall_mean_wss"])
print(f"pressure drop {mmhg:.5f} mmHg (exact 0.12224), mean wall shear {tau:.4f} Pa (exact 2.0372)")
assert abs(mmhg / 0.12224 - 1) < 0.10 and abs(tau / 2.0372 - 1) < 0.15
PY
