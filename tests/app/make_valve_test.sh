#!/usr/bin/env bash
# make_valve_test.sh VALSALVA SOURCE_DIR: a coarse `valsalva make-valve` (3 mm) writes valve.toml,
# leaflets.msh and root.msh; the shipped scene scenes/valve_root.toml passes `valsalva check` on
# that root.msh (patches inlet, outlet, wall, frame); a second call without --overwrite is refused
# and leaves the files alone.
set -eu
app=$1
src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$app" make-valve "$dir/runs/valve" --set mesh_size=3e-3 > "$dir/log.txt"
cat "$dir/log.txt"
for f in valve.toml leaflets.msh root.msh; do
  [ -s "$dir/runs/valve/$f" ] || { echo "missing $f"; exit 1; }
done
grep -q "45 Q2 hexahedra" "$dir/log.txt" || { echo "leaflet count is not 3 x 5 x 3"; exit 1; }
grep -q " 0 elsewhere" "$dir/log.txt" || { echo "attachment nodes outside fluid and frame"; exit 1; }
mkdir -p "$dir/scenes"
cp "$src/scenes/valve_root.toml" "$dir/scenes/"
"$app" check "$dir/scenes/valve_root.toml"
"$app" mesh-info "$dir/runs/valve/root.msh" | grep -E "inlet|outlet|wall|frame"
before=$(stat -c %Y "$dir/runs/valve/root.msh")
if "$app" make-valve "$dir/runs/valve" --set mesh_size=3e-3 2> "$dir/err.txt"; then
  echo "make-valve overwrote without --overwrite"; exit 1
fi
grep -q "exists (use --overwrite" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
[ "$(stat -c %Y "$dir/runs/valve/root.msh")" = "$before" ] || { echo "root.msh was touched"; exit 1; }
echo "make-valve test passed"
