#!/usr/bin/env python3
"""The default time.cfl from an error-against-CPU study (issue 19, target 8). Opt-in, not a test.

Runs, in one go on one rank (so that CPU ratios come from the same machine state):
  - bench_tgv_re1600 (Taylor-Green Re 1600, no model, central2) at 32^3, 48^3, 64^3 for each CFL
    number, and central4 + the 4th-order operators at 32^3: the max -dE/dt error against the
    512^3 spectral reference, and the CPU time of the time loop;
  - bench_womersley_study (inlet-driven Womersley pipe, Wo 17, D/10 Gmsh Delaunay tetrahedra):
    the max and L2 velocity errors against the exact solution over the sampled period, and the
    run's wall time.
A run that blows up (or fails) at some CFL ends that series: its largest stable CFL is the last
one that ran. Writes OUT/cfl_study.csv and OUT/cfl_study.png (error against CPU, one curve per
mesh, the CFL numbers on the points).

Usage: validation/bench/cfl_study.py [--bin build/bin] [--out bench-results/cfl_study]
                                     [--cfl 0.25,0.5,1,1.5,2,2.5,3] [--sizes 32,48,64]
                                     [--womersley 0] [--plot-only]
"""
import argparse
import csv
import pathlib
import re
import resource
import subprocess
import sys

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--bin", default="build/bin", help="folder of the bench executables")
parser.add_argument("--out", default="bench-results/cfl_study", help="output folder")
parser.add_argument("--cfl", default="0.25,0.5,1,1.5,2,2.5,3", help="CFL numbers, ascending")
parser.add_argument("--sizes", default="32,48,64", help="Taylor-Green cells per side (central2)")
parser.add_argument("--womersley", default="1", help="0: leave the pipe out")
parser.add_argument("--plot-only", action="store_true", help="redraw OUT/cfl_study.png from its CSV")
args = parser.parse_args()
out = pathlib.Path(args.out)
out.mkdir(parents=True, exist_ok=True)
bindir = pathlib.Path(args.bin)
cfls = [float(c) for c in args.cfl.split(",")]
rows = []


def run(cmd):
    """Runs cmd; returns (stdout, CPU seconds of the child) or (None, cpu) when it failed."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if p.returncode != 0:
        sys.stdout.write(f"  failed ({p.returncode}): {(p.stderr or p.stdout).strip()[-300:]}\n")
        return None, cpu
    return p.stdout, cpu


def tgv_series(label, n, extra):
    tgv_out = out / "tgv"
    for cfl in cfls:
        print(f"TGV {label} {n}^3 cfl {cfl}", flush=True)
        text, cpu = run([str(bindir / "bench_tgv_re1600"), "--n", str(n), "--cfl", str(cfl),
                         "--out", str(tgv_out)] + extra)
        if text is None:
            rows.append(dict(case="tgv", variant=label, size=n, cfl=cfl, stable=0, cpu_s=cpu))
            return
        loop_cpu = float(re.search(r"CPU ([0-9.eE+-]+) s \(time loop\)", text).group(1))
        err = float(re.search(r"max error ([0-9.eE+-]+) of", text).group(1))
        steps = int(re.search(r": (\d+) steps of dt", text).group(1))
        rows.append(dict(case="tgv", variant=label, size=n, cfl=cfl, stable=1, steps=steps,
                         cpu_s=loop_cpu, error=err, error_name="max |-dE/dt error| / peak"))
        print(f"  {steps} steps, CPU {loop_cpu:.1f} s, error {err:.4f}", flush=True)


def womersley_series():
    for cfl in cfls:
        print(f"Womersley Wo 17 D/10 cfl {cfl}", flush=True)
        text, cpu = run([str(bindir / "bench_womersley_study"), "--cfl", str(cfl)])
        if text is None:
            rows.append(dict(case="womersley", variant="central2", size=10, cfl=cfl, stable=0,
                             cpu_s=cpu))
            return
        m = re.search(r"(\d+) steps dt [0-9.eE+-]+, max ([0-9.]+) L2 ([0-9.]+)", text)
        steps, worst, l2 = int(m.group(1)), float(m.group(2)), float(m.group(3))
        rows.append(dict(case="womersley", variant="central2", size=10, cfl=cfl, stable=1,
                         steps=steps, cpu_s=cpu, error=l2, error_max=worst,
                         error_name="L2 velocity error / u_peak"))
        print(f"  {steps} steps, CPU {cpu:.1f} s, L2 {l2:.4f} max {worst:.4f}", flush=True)


fields = ["case", "variant", "size", "cfl", "stable", "steps", "cpu_s", "error", "error_max",
          "error_name"]
if args.plot_only:
    for r in csv.DictReader(open(out / "cfl_study.csv")):
        for key in ["size", "stable"]:
            r[key] = int(r[key])
        for key in ["cfl", "cpu_s", "error"]:
            r[key] = float(r[key]) if r[key] else None
        rows.append(r)
else:
    for n in [int(s) for s in args.sizes.split(",")]:
        tgv_series("central2", n, [])
    tgv_series("central4+op4", 32, ["--scheme", "central4", "--operators", "order4"])
    if args.womersley != "0":
        womersley_series()
    with open(out / "cfl_study.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    print(f"-> {out / 'cfl_study.csv'}")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("no matplotlib: the CSV is written; redraw with --plot-only where it is installed")
fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
for ax, case in zip(axes, ["tgv", "womersley"]):
    series = sorted({(r["variant"], r["size"]) for r in rows if r["case"] == case})
    for variant, size in series:
        pts = [r for r in rows if r["case"] == case and r["variant"] == variant
               and r["size"] == size and r["stable"]]
        if not pts:
            continue
        ax.loglog([p["cpu_s"] for p in pts], [p["error"] for p in pts], "o-",
                  label=f"{variant} {size}" + ("^3" if case == "tgv" else " nodes/D"))
        for p in pts:
            ax.annotate(f"{p['cfl']:g}", (p["cpu_s"], p["error"]), fontsize=7)
    ax.set_xlabel("CPU s (1 rank)")
    ax.set_ylabel(pts[0]["error_name"] if pts else "error")
    ax.set_title("Taylor-Green Re 1600, t 0-10" if case == "tgv" else "Womersley Wo 17 pipe")
    ax.legend(fontsize=8)
fig.suptitle("Error against CPU time for time.cfl (labels on the points)")
fig.tight_layout()
fig.savefig(out / "cfl_study.png", dpi=110)
print(f"-> {out / 'cfl_study.png'}")
