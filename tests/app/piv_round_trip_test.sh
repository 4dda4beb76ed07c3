#!/usr/bin/env bash
# The valve's PIV plane round trip (issue 18, item 6): the phase statistics validate_valve_quick
# wrote on the commissure plane x = 0 (scenes/valve_quick.toml, [statistics.piv], region
# "section"), written by `valsalva export-piv` on the experiment's grid (63 x 79 vectors 0.68 mm
# apart over the 43 x 54 mm window) and read back by `valsalva compare-piv`. Checks, per frame:
# - u, v, u_rms, v_rms RMSE exactly 0 (the file keeps 17 digits; compare-piv samples the same
#   points of the same statistics): nothing is lost on the way out and back;
# - every PIV point inside the mesh is compared (points + outside = 63 x 79): the section covers
#   every node interpolation on the plane needs (a slab of nodes 2 mm thick left 96 % masked);
# - at least 10 frames (the bins the 0.13 s run fills) and a non-zero velocity in each.
# Then an existing output of either command is refused without --overwrite.
set -euo pipefail
app=$1
d=validation-results/valve/run/statistics
out=validation-results/valve/piv_round_trip
rm -rf "$out" && mkdir -p "$out"
plane=(--origin 0,-0.02108,0.0005 --ex 0,1,0 --ey 0,0,1)
"$app" export-piv "$d/piv.xmf" "${plane[@]}" --out "$out/piv.csv" > "$out/export.out"
"$app" compare-piv "$d/piv.xmf" "$out/piv.csv" "${plane[@]}" --out "$out/compare" --no-plot \
  > "$out/compare.out"
awk -F, -v vectors=$((63 * 79)) '
  NR == 1 { next }
  {
    frames[$1] = 1
    if ($4 != 0) { print "FAIL: " $1 " " $3 " RMSE " $4 " (expected 0)"; bad = 1 }
    if ($7 + $9 != vectors) {
      print "FAIL: " $1 " " $3 ": " $7 " points compared + " $9 " outside != " vectors; bad = 1
    }
  }
  END {
    n = length(frames)
    if (n < 10) { print "FAIL: " n " frames (expected at least 10)"; bad = 1 }
    if (!bad) print "round trip exact: " n " frames of " vectors " vectors"
    exit bad
  }' "$out/compare/metrics.csv"
# Velocities present: the largest |u| of the exported file is above 1 mm/s.
awk -F, '/^[0-9-]/ && $7 == 1 { m = ($3 < 0 ? -$3 : $3); if (m > max) max = m }
  END { if (max < 1e-3) { print "FAIL: largest |u| " max " m/s"; exit 1 } }' "$out/piv.csv"
if "$app" export-piv "$d/piv.xmf" "${plane[@]}" --out "$out/piv.csv" 2> "$out/refused.err"; then
  echo "FAIL: export-piv overwrote $out/piv.csv without --overwrite"
  exit 1
fi
grep -q "exists; --overwrite replaces it" "$out/refused.err"
# compare-piv keeps an earlier comparison too, and replaces it with --overwrite.
if "$app" compare-piv "$d/piv.xmf" "$out/piv.csv" "${plane[@]}" --out "$out/compare" --no-plot \
  > /dev/null 2> "$out/refused_compare.err"; then
  echo "FAIL: compare-piv overwrote $out/compare without --overwrite"
  exit 1
fi
grep -q "holds an earlier comparison (metrics.csv); --overwrite replaces it" "$out/refused_compare.err"
"$app" compare-piv "$d/piv.xmf" "$out/piv.csv" "${plane[@]}" --out "$out/compare" --no-plot \
  --overwrite > /dev/null
