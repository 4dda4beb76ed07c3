#!/usr/bin/env bash
# hypre_keys_sweep_test.sh APP [MPIEXEC NP]: every accepted value of every integer [poisson] key
# (read from `valsalva docs-scenes`, so a widened list is swept too) runs 2 steps of a tiny
# scene with a singular Poisson matrix (periodic box) and of one with a Dirichlet outlet
# (channel). Each run must exit 0, or exit 1/2 with a "valsalva: error:" line naming the key;
# a crash, an MPI abort or a signal fails the test.
set -u
app=$1
launch=()
np=1
if [ $# -ge 3 ]; then launch=("$2" --oversubscribe -n "$3"); np=$3; fi
work=hypre_sweep_np$np
rm -rf "$work" && mkdir "$work" && cd "$work" || exit 1

# "| `interp_type` | int | `6` | - | one of 0, 6 | ..." rows of the [poisson] table.
"$app" docs-scenes > docs.md || { echo "docs-scenes failed"; exit 1; }
rows=$(awk '/^## `\[poisson\]`/ { on = 1; next } /^## / { on = 0 } on && /^\| `[a-z_]+` \| int \|/' docs.md)
[ -n "$rows" ] || { echo "no integer keys in the [poisson] table"; exit 1; }

cat > periodic.toml <<'EOF'
[mesh]
source = "box"
[mesh.box]
cells = [4, 4, 4]
cell_type = "tetra"
periodic = ["x", "y", "z"]
[flow]
density = 1.0
viscosity = 0.01
[initial]
type = "taylor_green"
[initial.taylor_green]
velocity = 0.1
length = 0.15915494309189535
[time]
dt = 0.01
max_steps = 2
end = 1.0
EOF
cat > outlet.toml <<'EOF'
[mesh]
source = "box"
[mesh.box]
length = [2.0, 1.0, 0.375]
cells = [8, 4, 3]
periodic = ["z"]
[flow]
density = 1.0
viscosity = 0.05
[time]
dt = 0.005
max_steps = 2
end = 1.0
[boundary.xmin]
type = "inlet"
flow_rate = 0.0375
[boundary.xmax]
type = "pressure_outlet"
[boundary.ymin]
type = "wall"
[boundary.ymax]
type = "wall"
EOF

failures=0
runs=0
while IFS= read -r row; do
  key=$(sed 's/^| `\([a-z_]*\)`.*/\1/' <<< "$row")
  accepted=$(awk -F' \\| ' '{ print $5 }' <<< "$row")
  case "$accepted" in
    "one of "*) values=$(sed 's/^one of //; s/,/ /g' <<< "$accepted") ;;
    \[*\]) lo=$(sed 's/^\[\([0-9-]*\), .*/\1/' <<< "$accepted")
      hi=$(sed 's/.*, \([0-9-]*\)\]$/\1/' <<< "$accepted")
      values=$(seq "$lo" "$hi") ;;
    *) [ "$key" = max_iterations ] && continue  # PCG's own cap, not a hypre option
       echo "poisson.$key: accepted values '$accepted' cannot be swept"; failures=$((failures + 1)); continue ;;
  esac
  for value in $values; do
    for scene in periodic outlet; do
      runs=$((runs + 1))
      sed "/^\[time\]/i [poisson]\n$key = $value" $scene.toml > run.toml
      timeout 120 "${launch[@]}" "$app" run run.toml --out "out_${key}_${value}_$scene" --quiet \
        < /dev/null > run.out 2> run.err
      code=$?
      if [ $code -eq 0 ]; then continue; fi
      if { [ $code -eq 1 ] || [ $code -eq 2 ]; } && grep -q "valsalva: error: .*poisson\.$key" run.err; then
        continue
      fi
      echo "poisson.$key = $value ($scene): exit code $code"
      tail -5 run.err
      failures=$((failures + 1))
    done
  done
done <<< "$rows"
echo "$runs runs, $failures failed"
[ $failures -eq 0 ] && [ $runs -gt 0 ]
