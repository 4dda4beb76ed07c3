#!/bin/bash
# The flow-rate control across a restart: restart_flow_rate.toml run to step 16 (checkpoints at
# 8 and 16) at NP_FULL ranks, a copy continued from checkpoint 8 at NP_REST ranks. log.csv (its
# force and every other column but the wall times) and sections.csv must equal the
# uninterrupted run's to TOL relative (0 = byte for byte), and the controlled section's flux
# must be the sine target at every step (to 1e-12 relative).
# Usage: restart_flow_rate_test.sh APP MPIEXEC NP_FULL NP_REST TOL
set -euo pipefail
app=$1 mpiexec=$2 np_full=$3 np_rest=$4 tol=$5
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/scenes/restart_flow_rate.toml
work=restart_flow_rate_np${np_full}_np${np_rest}
rm -rf "$work" && mkdir "$work" && cd "$work"
$mpiexec --oversubscribe -n "$np_full" "$app" run "$scene" --out full --quiet > full.out
test -s full/checkpoints/checkpoint_000000008.h5
cp -r full part
$mpiexec --oversubscribe -n "$np_rest" "$app" run "$scene" --out part \
  --restart part/checkpoints/checkpoint_000000008.h5 > rest.out
for d in full part; do
  /usr/bin/python3 - "$d/log.csv" > "$d.log.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
assert "force_z" in rows[0] and "flow_rate_target" in rows[0], rows[0]
keep = [i for i, c in enumerate(rows[0]) if c not in ("wall_per_step", "eta")]
for r in rows:
    print(",".join(r[i] for i in keep))
PY
done
[ "$(wc -l < full.log.csv)" -eq 17 ] || { echo "log.csv: expected header + 16 rows"; exit 1; }
/usr/bin/python3 "$here/compare_csv.py" full.log.csv part.log.csv "$tol"
/usr/bin/python3 "$here/compare_csv.py" full/sections.csv part/sections.csv "$tol"
# The target held: Q(t) = 2e-6 + 1e-6 sin(2 pi t / 0.1) through the section after every step.
/usr/bin/python3 - full/sections.csv <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
worst = max(abs(float(r["mid_flux"]) / (2e-6 + 1e-6 * math.sin(2 * math.pi * float(r["time"]) / 0.1)) - 1)
            for r in rows if float(r["time"]) > 0)
print(f"flow rate held to {worst:.2e} (relative)")
assert worst < 1e-12, worst
PY
