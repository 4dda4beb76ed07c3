#!/bin/bash
# A restart in place after a crash past a checkpoint: restart_section.toml run to step 16
# (checkpoints at 8 and 16), a copy continued from checkpoint 8 with `--restart FILE` (the
# interrupted run's rows 9..16 are in every series). sections.csv, probes.csv and log.csv (but
# its wall-time columns) must equal the uninterrupted run's byte for byte: each series cut back
# to the checkpoint and continued, no row twice. Then --overwrite accepts the run directory
# (sections.csv is valsalva's own output) and the new run writes the same sections.csv. Usage: restart_section_test.sh APP
set -euo pipefail
app=$1
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/scenes/restart_section.toml
work=restart_section
rm -rf "$work" && mkdir "$work" && cd "$work"
"$app" run "$scene" --out full --quiet > full.out
test -s full/checkpoints/checkpoint_000000008.h5
cp -r full part
"$app" run "$scene" --out part --restart part/checkpoints/checkpoint_000000008.h5 > rest.out
for csv in sections.csv probes.csv; do
  cmp "full/$csv" "part/$csv"
  echo "$csv: identical ($(wc -l < "full/$csv") lines)"
done
# What was cut, as the restart reports it.
grep -q "restart: 8 rows of sections.csv after the checkpoint removed" rest.out
[ "$(wc -l < full/sections.csv)" -eq 18 ] || { echo "sections.csv: expected header + 17 rows"; exit 1; }
# log.csv: all but the wall-time columns (wall_per_step, eta).
for d in full part; do
  /usr/bin/python3 - "$d/log.csv" > "$d.log.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, c in enumerate(rows[0]) if c not in ("wall_per_step", "eta")]
assert len(keep) == len(rows[0]) - 2, rows[0]
for r in rows:
    print(",".join(r[i] for i in keep))
PY
done
cmp full.log.csv part.log.csv
echo "log.csv: identical but the wall-time columns ($(wc -l < full.log.csv) lines)"
[ "$(wc -l < full.log.csv)" -eq 17 ] || { echo "log.csv: expected header + 16 rows"; exit 1; }
# --overwrite replaces the run directory (every file in it is valsalva's).
cp full/sections.csv sections.saved
"$app" run "$scene" --out full --overwrite --quiet > overwrite.out
cmp sections.saved full/sections.csv
