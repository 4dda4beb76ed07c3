#!/usr/bin/env bash
# The divergence number of an accelerating flat inflow (tests/app/scenes/accelerating_inlet.toml) at NP
# ranks, through `valsalva run` (run::Simulation): log.csv's div_h_over_u_free (max |div v| h /
# max |v| over the nodes the projection corrects, i.e. without wall and inflow nodes) must stay
# at most 0.1, the bound of issue 21's stability targets, over the second half of the
# acceleration (t >= T/4 = 0.1 s). The first steps start the flow from rest: each changes the
# velocity by O(U), the projection makes a potential flow with singular rims, and the number is
# O(1) there whatever the time step (Q ~ t^2); one flow-through time (24 mm at a mean 0.25 m/s
# at T/4) carries that start out of the pipe. div_h_over_u over all nodes is printed, not
# asserted: its maximum is at the no-slip rim of the inlet (u = 0 beside inflow nodes at U),
# fixed by the flat profile's data, which the projection does not change.
# Usage: inlet_divergence_test.sh VALSALVA MPIEXEC NP SOURCE_DIR
set -euo pipefail
app=$1 mpiexec=$2 np=$3 src=$4
out=inlet_divergence_np${np}
rm -rf "$out"
"$mpiexec" --oversubscribe -n "$np" "$app" run "$src/tests/app/scenes/accelerating_inlet.toml" \
  --out "$out" --quiet > "$out.out"
/usr/bin/python3 - "$out/log.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
late = [r for r in rows if float(r["time"]) >= 0.1]
if len(late) < 50:
    sys.exit(f"only {len(late)} logged steps at t >= 0.1 s")
free = max(float(r["div_h_over_u_free"]) for r in late)
every = max(float(r["div_h_over_u"]) for r in late)
print(f"t >= 0.1 s, {len(late)} steps: div_h_over_u_free max {free:.4f} (bound 0.1), "
      f"div_h_over_u (all nodes) max {every:.4f}")
if not free <= 0.1:
    sys.exit("div_h_over_u_free above 0.1")
PY
