#!/bin/bash
# A restart that moves wall_shear.start_time past the checkpoint's averaging window starts the
# window afresh: restart_pipe_half.toml (averaging from 0.01 s, checkpoint at step 30, time T)
# continued with --set wall_shear.start_time=T gives the same wall_shear.csv and summary as
# restart_pipe.toml run in one go with start_time = T (identical text at 1 rank), and the
# summary's window starts at T. A run that ends before the window opens says so instead of
# printing zeros.
# Usage: restart_wall_shear_window_test.sh APP
set -euo pipefail
app=$1
here=$(cd "$(dirname "$0")" && pwd)
work=restart_wall_shear_window
rm -rf "$work" && mkdir "$work" && cd "$work"
"$app" run "$here/scenes/restart_pipe.toml" --out early --set time.end=0.005 > early.out
grep -q "wall_shear wall: no TAWSS, OSI or RRT yet: the run ended at t = 0.005 s, before the averaging window opens at wall_shear.start_time = 0.01 s" early.out
"$app" run "$here/scenes/restart_pipe_half.toml" --out part --quiet > half.out
t=$(tail -n 1 part/log.csv | cut -d, -f2)
"$app" run "$here/scenes/restart_pipe.toml" --out part --restart latest --quiet \
  --set wall_shear.start_time="$t" > rest.out
grep -q "TAWSS, OSI and RRT start afresh" rest.out
"$app" run "$here/scenes/restart_pipe.toml" --out full --quiet --set wall_shear.start_time="$t" > full.out
cmp full/wall_shear.csv part/wall_shear.csv
cmp full/wall_shear_summary.csv part/wall_shear_summary.csv
/usr/bin/python3 - part/wall_shear_summary.csv "$t" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
t = float(sys.argv[2])
assert all(abs(float(r["window_start"]) - t) <= 1e-12 for r in rows), (rows, t)
print(f"window from {t} s, as asked; wall_shear.csv and the summary equal the one-go run's")
PY
