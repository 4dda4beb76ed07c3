#!/usr/bin/env bash
# piv_scale_test.sh VALSALVA PIV_FIXTURE: compare-piv on a PIV file in m and on its copy in mm
# and mm/s read with --length-scale 0.001 --velocity-scale 0.001 must write the same metrics.csv
# (numbers to 1e-9 relative: the mm file's values are the m values x 1000 printed with 17
# digits, so they differ by round-off only); the mm file read without the scales must not.
set -eu
app=$1
fixture=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$fixture" "$dir"
origin=0.5,0.5,0.5
"$app" compare-piv "$dir/stats/stats.xmf" "$dir/piv_m.csv" --origin $origin --ex 1,0,0 --ey 0,1,0 \
  --out "$dir/m" --no-plot
"$app" compare-piv "$dir/stats/stats.xmf" "$dir/piv_mm.csv" --origin $origin --ex 1,0,0 \
  --ey 0,1,0 --length-scale 0.001 --velocity-scale 0.001 --out "$dir/mm" --no-plot
"$app" compare-piv "$dir/stats/stats.xmf" "$dir/piv_mm.csv" --origin $origin --ex 1,0,0 \
  --ey 0,1,0 --out "$dir/raw" --no-plot > /dev/null
# same A B: every field equal, numbers within 1e-9 relative (1e-15 absolute near zero).
same() {
  paste -d '|' "$1" "$2" | awk -F'|' '{ n = split($1, a, ","); split($2, b, ",");
    for (i = 1; i <= n; i++) { if (a[i] == b[i]) continue;
      d = a[i] - b[i]; if (d < 0) d = -d; s = a[i] < 0 ? -a[i] : a[i];
      if (a[i] + 0 != a[i] || d > 1e-9 * s + 1e-15) { print "line " NR ": " a[i] " vs " b[i]; bad = 1 } } }
    END { exit bad }'
}
cat "$dir/m/metrics.csv"
same "$dir/m/metrics.csv" "$dir/mm/metrics.csv"
if same "$dir/m/metrics.csv" "$dir/raw/metrics.csv" > /dev/null; then
  echo "FAILED: the mm file without scales gave the metrics of the m file"; exit 1
fi
# The comparison is not trivially empty: 441 points, none outside.
grep -q '^"all",nan,u,.*,441,0,0$' "$dir/m/metrics.csv"
