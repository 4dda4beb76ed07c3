#!/usr/bin/env bash
# piv_mismatch_test.sh VALSALVA PIV_FIXTURE: compare-piv with a statistics bin file from another
# run (a self-consistent file for a mesh of fewer, then more, nodes than the statistics mesh) and
# with a mesh whose topology names a node it does not have must stop with a message naming both
# files and both sizes, never read past an array (issue 23, item 2).
set -eu
app=$1
fixture=$2
expect=$(cd "$(dirname "$0")" && pwd)/expect_error.sh
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$fixture" "$dir"
args=("$dir/stats/stats.xmf" "$dir/piv_m.csv" --origin 0.5,0.5,0.5 --ex 1,0,0 --ey 0,1,0 --no-plot)
cp "$dir/stats/stats_000000.h5" "$dir/bin.h5"
cp "$dir/stats/stats_mesh.h5" "$dir/mesh.h5"
for delta in -9 40; do
  /usr/bin/python3 - "$dir/bin.h5" "$dir/stats/stats_000000.h5" "$delta" <<'PY'
import sys, h5py, numpy as np
src, dst, delta = sys.argv[1], sys.argv[2], int(sys.argv[3])
with h5py.File(src, "r") as a, h5py.File(dst, "w") as b:
    n = int(a.attrs["global_nodes"]) + delta
    for k, v in a.attrs.items():
        b.attrs[k] = v
    b.attrs["global_nodes"] = float(n)
    for name, d in a.items():
        x = d[...]
        rows = np.resize(x, (n,) + x.shape[1:])  # another run's bin: n rows
        b.create_dataset(name, data=rows)
PY
  "$expect" "stats_000000\.h5' dataset 'mean_velocity' has [0-9]+ values \\(3 per node: (720|769) nodes\\), but the statistics mesh '.*stats_mesh\.h5' has 729 nodes" \
    "$app" compare-piv "${args[@]}" --out "$dir/out$delta"
done
cp "$dir/bin.h5" "$dir/stats/stats_000000.h5"
/usr/bin/python3 - "$dir/stats/stats_mesh.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    t = f["topology"][...]
    t[2] = 100000
    del f["topology"]
    f.create_dataset("topology", data=t)
PY
"$expect" "stats_mesh\.h5': topology entry 0 refers to node 100000, but the file has 729 nodes" \
  "$app" compare-piv "${args[@]}" --out "$dir/out_topology"
echo "mismatched statistics files refused"
