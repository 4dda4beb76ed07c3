#!/bin/bash
# The flow-rate drive with a waveform CSV target (flow_rate_table.toml, 30 steps over 1.5
# periods of the table): the section's flux after every step must be the table's linear
# interpolation, repeated with its period, to 1e-12 of its largest value; log.csv's
# flow_rate_target column must say the same. Usage: flow_rate_table_test.sh APP
set -euo pipefail
app=$1
here=$(cd "$(dirname "$0")" && pwd)
work=flow_rate_table
rm -rf "$work" && mkdir "$work" && cd "$work"
"$app" run "$here/scenes/flow_rate_table.toml" --out run --quiet > run.out
/usr/bin/python3 - run/sections.csv run/log.csv <<'PY'
import csv, sys
t_tab, q_tab = [0.0, 0.01, 0.02, 0.04], [1.0e-6, 3.0e-6, 2.0e-6, 1.0e-6]
def target(t):
    s = t % 0.04
    for k in range(1, len(t_tab)):
        if s <= t_tab[k]:
            w = (s - t_tab[k - 1]) / (t_tab[k] - t_tab[k - 1])
            return (1 - w) * q_tab[k - 1] + w * q_tab[k]
rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["time"]) > 0]
assert len(rows) == 30, len(rows)
worst = max(abs(float(r["mid_flux"]) - target(float(r["time"]))) for r in rows) / max(q_tab)
log = list(csv.DictReader(open(sys.argv[2])))
worst_log = max(abs(float(r["flow_rate_target"]) - target(float(r["time"]))) for r in log) / max(q_tab)
print(f"flux against the table: {worst:.2e}, log target: {worst_log:.2e} (of the largest Q)")
assert worst < 1e-12 and worst_log < 1e-12, (worst, worst_log)
PY
