#!/usr/bin/env python3
"""The end-of-run files of [wall_shear] in a run directory checked against each other and, with a
second directory, against another run of the same scene (another rank count):
- wall_shear.csv: rrt = 1 / ((1 - 2 osi) tawss) where defined, nan exactly where (1 - 2 osi) tawss
  vanishes (Himburg et al. 2004);
- wall_shear_summary.csv: area, area-weighted means and maxima recomputed from wall_shear.csv;
- wall_shear_surface (XDMF + HDF5, read with h5py): every (patch, node) of wall_shear.csv is a
  surface node, and its tawss, osi, rrt, tau and position equal the CSV's (a mesh without
  periodic images, whose surface nodes sit apart from their dual node);
- with OTHER: the three files agree to TOL (relative to each column's largest magnitude).
Usage: check_wall_shear.py DIR [OTHER TOL]"""
import csv
import math
import os
import sys

import h5py
import numpy as np

# CSV values carry 10 significant digits: 1e-8 relative covers their rounding, summed over nodes.
CSV_RTOL = 1e-8


def read_csv(path):
    return list(csv.DictReader(open(path)))


def col(rows, key):
    return np.array([float(r[key]) for r in rows])


def close(a, b, rtol, what):
    a, b = np.asarray(a, float), np.asarray(b, float)
    assert a.shape == b.shape, (what, a.shape, b.shape)
    assert np.array_equal(np.isnan(a), np.isnan(b)), f"{what}: nan at different places"
    ok = ~np.isnan(a)
    scale = max(np.max(np.abs(b[ok]), initial=0.0), 1e-300)
    err = np.max(np.abs(a[ok] - b[ok]), initial=0.0) / scale
    assert err <= rtol, f"{what}: relative difference {err:.3e} > {rtol:g}"
    return err


def check_nodes(rows):
    tawss, osi, rrt = col(rows, "tawss"), col(rows, "osi"), col(rows, "rrt")
    denom = (1 - 2 * osi) * tawss
    defined = ~np.isnan(rrt)
    # Away from OSI = 1/2 the printed OSI gives 1 - 2 OSI to 1e-8 relative.
    well = defined & (1 - 2 * osi > 1e-2)
    err = np.max(np.abs(rrt[well] * denom[well] - 1), initial=0.0)
    assert err < 1e-6, f"rrt (1 - 2 osi) tawss - 1 = {err:.3e}"
    assert np.all(denom[~defined] <= 1e-9 * np.maximum(tawss[~defined], 1e-300)), "nan rrt"
    print(f"wall_shear.csv: {len(rows)} wall nodes, {well.sum()} checked for RRT "
          f"(max |RRT (1 - 2 OSI) TAWSS - 1| = {err:.2e}), {(~defined).sum()} undefined")


def check_summary(rows, summary):
    for s in summary:
        mine = [r for r in rows if r["patch"] == s["patch"]]
        a, tawss, osi, rrt, support = (col(mine, k) for k in ("area", "tawss", "osi", "rrt",
                                                               "support_fraction"))
        assert np.all((support >= 0) & (support <= 1 + 1e-12)), "support_fraction outside [0, 1]"
        fin = np.isfinite(rrt)
        clear = support == 0
        expect = {
            "area": a.sum(),
            "mean_tawss": (a * tawss).sum() / a.sum(),
            "max_tawss": tawss.max(),
            "mean_osi": (a * osi).sum() / a.sum(),
            "max_osi": osi.max(),
            "mean_rrt": (a[fin] * rrt[fin]).sum() / a[fin].sum() if fin.any() else math.nan,
            "rrt_area_fraction": a[fin].sum() / a.sum(),
            "clear_area_fraction": a[clear].sum() / a.sum(),
            "clear_mean_tawss": (a[clear] * tawss[clear]).sum() / a[clear].sum() if clear.any() else math.nan,
            "clear_max_tawss": tawss[clear].max() if clear.any() else math.nan,
        }
        for k, v in expect.items():
            got = float(s[k])
            ok = (math.isnan(v) and math.isnan(got)) or abs(got - v) <= CSV_RTOL * max(abs(v), 1e-12)
            assert ok, f"summary {s['patch']} {k}: {got} vs {v} from wall_shear.csv"
        assert float(s["window_start"]) <= float(s["window_end"]), s
        print(f"wall_shear_summary.csv {s['patch']}: " +
              ", ".join(f"{k} {float(s[k]):.6g}" for k in expect) + " (= wall_shear.csv)")


def read_surface(d):
    step = os.path.join(d, "wall_shear_surface_000000.h5")
    with h5py.File(os.path.join(d, "wall_shear_surface_mesh.h5"), "r") as m, h5py.File(step, "r") as f:
        out = {k: f[k][:] for k in ("tawss", "osi", "rrt", "support_fraction", "tau", "patch", "node")}
        out["coordinates"] = m["coordinates"][:]
        out["topology"] = m["topology"][:]
    return out


def check_surface(d, rows, names):
    s = read_surface(d)
    n = len(s["node"])
    by_key = {(names.index(r["patch"]), int(r["node"])): r for r in rows}
    keys = [(int(p), int(j)) for p, j in zip(s["patch"], s["node"])]
    assert set(keys) == set(by_key), "surface nodes differ from the wall nodes of wall_shear.csv"
    ref = [by_key[k] for k in keys]
    for k in ("tawss", "osi", "rrt", "support_fraction"):
        close(s[k], col(ref, k), CSV_RTOL, f"surface {k}")
    close(s["tau"], np.c_[col(ref, "tau_x"), col(ref, "tau_y"), col(ref, "tau_z")], CSV_RTOL,
          "surface tau")
    close(s["coordinates"], np.c_[col(ref, "x"), col(ref, "y"), col(ref, "z")], CSV_RTOL,
          "surface coordinates")
    codes = s["topology"]
    cells, pos = 0, 0
    while pos < len(codes):  # XDMF Mixed: code, then 3 (triangle) or 4 (quad) node ids
        assert codes[pos] in (4, 5), f"cell code {codes[pos]} is not a triangle or quad"
        pos += 1 + (3 if codes[pos] == 4 else 4)
        cells += 1
    assert pos == len(codes) and cells > 0
    print(f"wall_shear_surface: {n} nodes, {cells} faces, values = wall_shear.csv")
    return s


def compare(d, other, tol):
    a, b = read_csv(os.path.join(d, "wall_shear.csv")), read_csv(os.path.join(other, "wall_shear.csv"))
    assert [(r["patch"], r["node"]) for r in a] == [(r["patch"], r["node"]) for r in b]
    worst = 0.0
    for k in ("area", "tawss", "osi", "rrt", "tau_x", "tau_y", "tau_z", "support_fraction"):
        worst = max(worst, close(col(a, k), col(b, k), tol, f"wall_shear.csv {k}"))
    sa = read_csv(os.path.join(d, "wall_shear_summary.csv"))
    sb = read_csv(os.path.join(other, "wall_shear_summary.csv"))
    for k in sa[0]:
        if k != "patch":
            worst = max(worst, close(col(sa, k), col(sb, k), tol, f"summary {k}"))
    ha, hb = read_surface(d), read_surface(other)
    assert np.array_equal(ha["topology"], hb["topology"]), "surface topology differs"
    for k in ("tawss", "osi", "rrt", "support_fraction", "tau", "coordinates"):
        worst = max(worst, close(ha[k], hb[k], tol, f"surface {k}"))
    print(f"{d} vs {other}: largest relative difference {worst:.3e} (tolerance {tol:g})")


def main(d, other=None, tol=None):
    rows = read_csv(os.path.join(d, "wall_shear.csv"))
    summary = read_csv(os.path.join(d, "wall_shear_summary.csv"))
    names = [s["patch"] for s in summary]
    assert len(rows) > 100
    check_nodes(rows)
    check_summary(rows, summary)
    check_surface(d, rows, names)
    if other:
        compare(d, other, float(tol))


if __name__ == "__main__":
    main(*sys.argv[1:])
