# Sourced by the valve scene tests: `valve_scene_copy APP SRC SCENE [DATA_FILE ...]` makes the
# coarse valve's meshes (scripts/make-valve-quick, once) and a temporary tree $dir with
# scenes/SCENE, its data files and runs/valve_quick where the scene looks; removed on exit.
valve_scene_copy() {
  local app=$1 src=$2 scene=$3
  shift 3
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
  "$src/scripts/make-valve-quick" "$app" "$src/runs/valve_quick"
  mkdir -p "$dir/runs" "$dir/scenes/data"
  ln -s "$src/runs/valve_quick" "$dir/runs/valve_quick"
  cp "$src/scenes/$scene" "$dir/scenes/"
  for data in "$@"; do cp "$src/scenes/data/$data" "$dir/scenes/data/"; done
}
