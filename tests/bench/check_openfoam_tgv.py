#!/usr/bin/python3
"""Checks of validation/bench/peers/openfoam_tgv that need neither OpenFOAM nor a run: the case it
writes (initial field on blockMesh's cell order, cyclic patches), the -dE/dt measurement both
codes go through (exact on an exponential decay up to the central difference's known error), the
energy file reader, the time step, and the equal-error comparison.
Usage: check_openfoam_tgv.py SCRIPT"""
import importlib.machinery
import importlib.util
import math
import pathlib
import sys
import tempfile

script = pathlib.Path(sys.argv[1])
loader = importlib.machinery.SourceFileLoader("openfoam_tgv", str(script))
spec = importlib.util.spec_from_loader("openfoam_tgv", loader)
tgv = importlib.util.module_from_spec(spec)
loader.exec_module(tgv)

failures = []


def check(name, ok, detail):
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {detail}")
    if not ok:
        failures.append(name)


def numbers(text, start, count):
    """The `count` entries after the line `count` following `start` in an OpenFOAM list."""
    lines = text[text.index(start):].split("\n")
    assert int(lines[1]) == count and lines[2] == "("
    return [[float(v) for v in line.strip("()").split()] for line in lines[3:3 + count]]


with tempfile.TemporaryDirectory() as tmp:
    # The case: n = 4, the velocity at cell (i, j, k) is the TGV field at its centre, in
    # blockMesh's order (x fastest); 12 significant digits are written, so 1e-11 is round-off.
    n = 4
    case = pathlib.Path(tmp) / "case"
    tgv.write_case(case, n, "WALE", 0.1, 1.0)
    velocity = numbers((case / "0/U").read_text(), "List<vector>", n ** 3)
    h = 2 * math.pi / n
    worst = 0.0
    for k in range(n):
        for j in range(n):
            for i in range(n):
                exact = tgv.tgv_velocity((i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h)
                got = velocity[i + n * j + n * n * k]
                worst = max(worst, max(abs(a - b) for a, b in zip(got, exact)))
    check("initial velocity on blockMesh's cell order", worst < 1e-11, f"max deviation {worst:.2e}")
    energy = sum(0.5 * (u * u + v * v + w * w) for u, v, w in velocity) / n ** 3
    check("initial mean kinetic energy 0.125 (the reader's E(0))", abs(energy - 0.125) < 1e-12,
          f"{energy:.15f}")
    mesh = (case / "system/blockMeshDict").read_text()
    cyclic = sum(mesh.count(f"{p} {{ type cyclic; neighbourPatch {q};")
                 for p, q in (("x0", "x1"), ("x1", "x0"), ("y0", "y1"), ("y1", "y0"),
                              ("z0", "z1"), ("z1", "z0")))
    check("six cyclic patches in pairs", cyclic == 6, f"{cyclic} of 6")
    check("WALE selected", "LESModel WALE;" in (case / "constant/turbulenceProperties").read_text(),
          "constant/turbulenceProperties")

    # The energy reader: comment lines skipped, E = volAverage(|U|^2) / 2, E(0) prepended.
    post = case / "postProcessing/energy/0"
    post.mkdir(parents=True)
    (post / "volFieldValue.dat").write_text(
        "# Region : all\n# Time\tvolAverage(magSqrU)\n0.1\t0.24\n0.2\t0.2\n")
    times, energies = tgv.read_openfoam_energy(case)
    check("energy file", times == [0.0, 0.1, 0.2] and energies == [0.125, 0.12, 0.1],
          f"{times} {energies}")

# -dE/dt of E = E0 exp(-lambda t) sampled every dt, against the exact rate lambda E: the central
# difference gives lambda E sinh(x) / x with x = lambda dt, so the largest error (at the first
# interior sample, where the rate is largest) is exp(-x) (sinh(x) / x - 1) of the reference
# peak lambda E0 (at t = 0), and the peak error exp(-x) sinh(x) / x - 1.
lam, dt, e0 = 0.5, 0.01, 0.125
times = [i * dt for i in range(1001)]
series = [e0 * math.exp(-lam * t) for t in times]
reference = [(t, e, lam * e) for t, e in zip(times, series)]
result = tgv.errors(tgv.dissipation(times, series), reference, 10.0)
x = lam * dt
expected = math.exp(-x) * (math.sinh(x) / x - 1)
# Tolerance: the difference of E over 2 dt carries a round-off of about 1e-16 E0 / (2 dt), 1e-15
# in a rate error of 2.6e-7 (lambda E0 4e-6): 4e-9 relative.
check("max error of the curve", abs(result["error_max"] - expected) < 1e-8 * expected,
      f"{result['error_max']:.10e} against {expected:.10e}")
check("laminar-phase error equals it here", result["error_max_laminar"] == result["error_max"],
      f"{result['error_max_laminar']:.10e}")
expected_peak = math.exp(-x) * math.sinh(x) / x - 1
check("peak error", abs(result["peak_error"] - expected_peak) < 1e-9,
      f"{result['peak_error']:.10e} against {expected_peak:.10e}")
check("peak time", abs(result["peak_time"] - dt) < 1e-12 and
      abs(result["peak_time_error"] - dt) < 1e-12, f"{result['peak_time']}")

# The time step both codes use: dt = t_end / ceil(t_end / (CFL h)), h = 2 pi / 64: 204 steps.
check("time step", abs(tgv.time_step(64, 0.5, 10.0) - 10.0 / 204) < 1e-15,
      f"{tgv.time_step(64, 0.5, 10.0)!r}")

# Equal error: the cheapest valsalva run at or below OpenFOAM's error, and not reached.
openfoam = [{"label": "pimpleFoam laminar", "n": 64, "cpu_s": 100.0, "error_max": 0.2},
            {"label": "pimpleFoam laminar", "n": 128, "cpu_s": 900.0, "error_max": 0.05}]
valsalva = [{"label": "valsalva central2", "n": n, "cpu_s": c, "error_max": e}
            for n, c, e in ((32, 3.0, 0.3), (48, 20.0, 0.15), (64, 60.0, 0.1))]
rows = tgv.equal_error(openfoam, valsalva, "error_max")
check("equal error: 48^3 at 0.2 of the CPU",
      rows[0]["valsalva_run"] == "48^3" and abs(rows[0]["cpu_ratio"] - 0.2) < 1e-15,
      f"{rows[0]['valsalva_run']} {rows[0]['cpu_ratio']}")
check("equal error: not reached", rows[1]["valsalva_run"] == "not reached" and
      math.isnan(rows[1]["cpu_ratio"]), f"{rows[1]['valsalva_run']}")

# The peak counts with its time: 24^3 has the smaller peak error but a later peak than OpenFOAM's.
openfoam = [{"label": "pimpleFoam WALE", "n": 64, "cpu_s": 150.0, "peak_error": -0.07,
             "peak_time_error": -3.4}]
valsalva = [{"label": "valsalva central4+sigma", "n": n, "cpu_s": c, "peak_error": e,
             "peak_time_error": dt_peak}
            for n, c, e, dt_peak in ((24, 2.0, -0.03, -3.5), (48, 45.0, -0.06, -1.0))]
rows = tgv.equal_error(openfoam, valsalva, "peak")
check("equal peak: value and time", rows[0]["valsalva_run"] == "48^3" and
      abs(rows[0]["cpu_ratio"] - 0.3) < 1e-15, f"{rows[0]['valsalva_run']} {rows[0]['cpu_ratio']}")

sys.exit(1 if failures else 0)
