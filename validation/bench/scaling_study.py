#!/usr/bin/python3
"""Scaling study (issue 19, target 6): parallel efficiency at 2 ranks and the measured inputs of
the scaling model in docs/performance.md. Opt-in, never in `make test`.

Measures, with the project's own binaries (bench_tgv_re1600 and `valsalva run`, the run loop users
run):
  1. cost per node-step and Poisson iterations against the mesh size: Taylor-Green Re 1600
     (central2, no model) at --sizes on 1 rank;
  2. efficiency at 2 ranks, wall and CPU time of the time loop: Taylor-Green at the largest size,
     and the valve scene (--valve-scene, e.g. scenes/valve_m1.toml) for --valve-steps steps;
  3. halo size (ghost nodes, values sent per exchange, neighbours) at 2, 4 and 8 ranks: the
     "halo:" line of `valsalva run` after one step (8 ranks oversubscribe this machine; only
     the partition is measured there);
  4. MPI operations per time step and rank: calls and bytes of each operation counted by
     libvalsalva_mpi_counts.so (validation/bench/mpi_counts.c, LD_PRELOAD), the difference of a
     long and a short run divided by the steps between them (so the set-up does not count).
Writes OUT/scaling.json (every measurement and the fitted model) and OUT/scaling.md.

Usage: validation/bench/scaling_study.py --build build --out bench-results/scaling
         [--sizes 24,32,48,64] [--t-end 10] [--valve-scene scenes/valve_m1.toml
         --valve-set mesh.file=... --valve-set structure.valve.file=...] [--valve-steps 40]
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import time
from pathlib import Path

MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
           "OMPI_MCA_hwloc_base_binding_policy": "none", "OMPI_MCA_rmaps_base_oversubscribe": "1"}
ROOT = Path(__file__).resolve().parents[2]


def run(cmd, log, env=None):
    """Runs cmd; returns (wall s, CPU s of it and its waited-for children, stdout)."""
    full_env = dict(os.environ, **MPI_ENV, **(env or {}))
    Path(log).parent.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()
    with open(log, "w") as out:
        proc = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT, env=full_env, cwd=ROOT)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - t0
    text = Path(log).read_text()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"scaling_study: {' '.join(map(str, cmd))} failed; see {log}:\n{text[-2000:]}")
    return wall, usage.ru_utime + usage.ru_stime, text


def mpi(ranks, cmd):
    return cmd if ranks == 1 else ["mpiexec", "-n", str(ranks)] + cmd


def tgv(args, n, ranks, out):
    """One bench_tgv_re1600 run; its summary.csv row."""
    bench = args.build / "bin" / "bench_tgv_re1600"
    cmd = mpi(ranks, [str(bench), "--n", str(n), "--t-end", str(args.t_end), "--out", str(out)])
    run(cmd, out / f"tgv_{n}_np{ranks}.log")
    rows = [r for r in csv.DictReader(open(out / "summary.csv"))
            if int(r["n"]) == n and int(r["ranks"]) == ranks and r["scheme"] == "central2"]
    return {k: float(v) for k, v in rows[-1].items() if k != "scheme"}


def tgv_scene_sets(n):
    return ["--set", f"mesh.box.cells=[{n}, {n}, {n}]", "--set", "flow.scheme=central2",
            "--set", "les.model=none", "--set", f"time.dt={0.5 * 2 * math.pi / n:.17g}"]


def scene(args, scene_file, sets, ranks, out_dir, steps, log, counts=None):
    """`valsalva run` for `steps` steps, one log.csv row per step; (wall, cpu, text, rows)."""
    cmd = mpi(ranks, [str(args.build / "bin" / "valsalva"), "run", str(scene_file), "--out",
                      str(out_dir), "--overwrite", "--set", f"time.max_steps={steps}",
                      "--set", "run.log_every=1", "--set", "run.progress=lines",
                      "--set", "output.interval=0"] + sets)
    env = None
    if counts:
        lib = args.build / "lib" / "libvalsalva_mpi_counts.so"
        env = {"LD_PRELOAD": str(lib), "VALSALVA_MPI_COUNTS": str(counts)}
    wall, cpu, text = run(cmd, log, env)
    rows = list(csv.DictReader(open(out_dir / "log.csv")))
    return wall, cpu, text, rows


def halo_line(text):
    m = re.search(r"halo: owned nodes per rank (\d+)\.\.(\d+); per rank at most (\d+) ghost "
                  r"nodes, (\d+) neighbours, (\d+) values sent", text)
    keys = ("owned_min", "owned_max", "ghosts_max", "neighbours_max", "sent_max")
    return dict(zip(keys, map(int, m.groups())))


def dual_nodes(text):
    return int(re.search(r"mesh: \d+ nodes \((\d+) dual nodes\)", text).group(1))


def setup_seconds(text):
    return float(re.search(r"set-up: ([0-9.]+) s", text).group(1))


def read_counts(prefix, ranks):
    """{operation: (calls, bytes)} of the busiest rank (max over ranks of each)."""
    total = {}
    for r in range(ranks):
        for rank, op, calls, nbytes in csv.reader(open(f"{prefix}.{r}")):
            c, b = total.get(op, (0, 0))
            total[op] = (max(c, int(calls)), max(b, int(nbytes)))
    return total


def per_step_counts(args, scene_file, sets, ranks, out, name, short, long):
    """MPI operations per step (long run minus short run) and Poisson iterations per step."""
    counts = {}
    its = {}
    for steps in (short, long):
        prefix = out / f"counts_{name}_np{ranks}_{steps}"
        for f in out.glob(prefix.name + ".*"):
            f.unlink()
        _, _, text, rows = scene(args, scene_file, sets, ranks, out / f"run_{name}_counts", steps,
                                 out / f"counts_{name}_np{ranks}_{steps}.log", counts=prefix)
        counts[steps] = read_counts(prefix, ranks)
        its[steps] = sum(float(r["poisson_iterations"]) for r in rows)
    steps = long - short
    per_step = {op: {"calls": (counts[long][op][0] - counts[short].get(op, (0, 0))[0]) / steps,
                     "bytes": (counts[long][op][1] - counts[short].get(op, (0, 0))[1]) / steps}
                for op in counts[long]}
    return {"operations": per_step, "poisson_iterations": (its[long] - its[short]) / steps,
            "halo": halo_line(text)}


def fit_line(x, y):
    """Least squares y = a + b x."""
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((xi - mx) ** 2 for xi in x)
    b = sum((xi - mx) * (yi - my) for xi, yi in zip(x, y)) / sxx if sxx > 0 else 0.0
    return my - b * mx, b


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", type=Path, default=ROOT / "build")
    ap.add_argument("--out", type=Path, default=ROOT / "bench-results" / "scaling")
    ap.add_argument("--sizes", default="24,32,48,64")
    ap.add_argument("--t-end", type=float, default=10.0)
    ap.add_argument("--valve-scene", type=Path)
    ap.add_argument("--valve-set", action="append", default=[])
    ap.add_argument("--valve-steps", type=int, default=40)
    ap.add_argument("--valve-ghost-layers", type=int, default=2,
                    help="partition.ghost_layers of the valve at 4 and 8 ranks (the kernels' "
                         "depth near the leaflets is added by distance, partition.ghost_distance)")
    ap.add_argument("--poisson-share", type=float, default=0.6,
                    help="share of the PCG + AMG solve in a 1-rank TGV step, from the profile of "
                         "validation/notes/flow_throughput.md: splits the cost per node-step")
    ap.add_argument("--skip", default="", help="comma list of parts to skip: size,tgv2,valve,halo,counts")
    args = ap.parse_args()
    args.build = args.build.resolve()
    args.out = args.out.resolve()
    args.out.mkdir(parents=True, exist_ok=True)
    skip = set(filter(None, args.skip.split(",")))
    sizes = [int(s) for s in args.sizes.split(",")]
    result_file = args.out / "scaling.json"
    res = json.loads(result_file.read_text()) if result_file.exists() else {}
    tgv_scene = ROOT / "validation" / "tgv_les" / "tgv_les.toml"
    valve_sets = [a for s in args.valve_set for a in ("--set", s)]

    if "size" not in skip:  # 1. cost per node-step and Poisson iterations against N
        res["size"] = []
        for n in sizes:
            r = tgv(args, n, 1, args.out / "tgv")
            res["size"].append({"n": n, "nodes": n ** 3, "steps": r["steps"], "cpu_s": r["cpu_s"],
                                "loop_wall_s": r["loop_wall_s"],
                                "poisson_its_mean": r["poisson_its_mean"],
                                "us_per_node_step": 1e6 * r["cpu_s"] / (n ** 3 * r["steps"])})
            print(f"size {n}^3: {res['size'][-1]}", flush=True)
        result_file.write_text(json.dumps(res, indent=1))

    if "tgv2" not in skip:  # 2a. efficiency at 2 ranks on the largest Taylor-Green
        n = sizes[-1]
        one = tgv(args, n, 1, args.out / "tgv2")
        two = tgv(args, n, 2, args.out / "tgv2")
        res["tgv_np2"] = {"n": n, "np1": one, "np2": two,
                          "efficiency_wall": one["loop_wall_s"] / (2 * two["loop_wall_s"]),
                          "efficiency_cpu": one["cpu_s"] / two["cpu_s"]}
        print(f"TGV {n}^3 at 2 ranks: wall efficiency {res['tgv_np2']['efficiency_wall']:.3f}, "
              f"CPU {res['tgv_np2']['efficiency_cpu']:.3f}", flush=True)
        result_file.write_text(json.dumps(res, indent=1))

    if args.valve_scene and "valve" not in skip:  # 2b. the valve scene at 1 and 2 ranks
        v = {}
        for ranks in (1, 2):
            wall, cpu, text, rows = scene(args, args.valve_scene, valve_sets, ranks,
                                          args.out / f"valve_np{ranks}", args.valve_steps,
                                          args.out / f"valve_np{ranks}.log")
            loop = [float(r["wall_per_step"]) for r in rows[1:]]  # step 1 builds the AMG
            v[f"np{ranks}"] = {"wall_s": wall, "cpu_s": cpu, "setup_s": setup_seconds(text),
                               "wall_per_step_s": sum(loop) / len(loop), "steps": len(rows),
                               "nodes": dual_nodes(text)}
        v["efficiency_wall"] = v["np1"]["wall_per_step_s"] / (2 * v["np2"]["wall_per_step_s"])
        v["efficiency_cpu_whole_run"] = v["np1"]["cpu_s"] / v["np2"]["cpu_s"]
        res["valve_np2"] = v
        print(f"valve at 2 ranks: wall efficiency per step {v['efficiency_wall']:.3f}, CPU "
              f"(whole run) {v['efficiency_cpu_whole_run']:.3f}", flush=True)
        result_file.write_text(json.dumps(res, indent=1))

    if "halo" not in skip:  # 3. halo size against nodes per rank
        res["halo"] = []
        cases = [("tgv", n, tgv_scene, tgv_scene_sets(n)) for n in sizes]
        if args.valve_scene:
            cases.append(("valve", 0, args.valve_scene, valve_sets))
        for name, n, scene_file, sets in cases:
            for ranks in (2, 4, 8):
                if name == "valve" and ranks > 2:
                    sets = valve_sets + ["--set",
                                         f"partition.ghost_layers={args.valve_ghost_layers}"]
                _, _, text, _ = scene(args, scene_file, sets, ranks, args.out / "run_halo", 1,
                                      args.out / f"halo_{name}{n}_np{ranks}.log")
                nodes = dual_nodes(text)
                res["halo"].append(dict(case=name, n=n, ranks=ranks, nodes=nodes,
                                        ghost_layers=int(re.search(r"(\d+) ghost layers",
                                                                   text).group(1)),
                                        **halo_line(text)))
                print(f"halo {res['halo'][-1]}", flush=True)
        result_file.write_text(json.dumps(res, indent=1))

    if "counts" not in skip:  # 4. MPI operations per step
        res["counts"] = {"tgv": per_step_counts(args, tgv_scene, tgv_scene_sets(32), 2, args.out,
                                                "tgv32", 5, 25)}
        if args.valve_scene:
            res["counts"]["valve"] = per_step_counts(args, args.valve_scene, valve_sets, 2,
                                                     args.out, "valve", 5, 15)
        print(f"counts {json.dumps(res['counts'])}", flush=True)
        result_file.write_text(json.dumps(res, indent=1))

    res["model"] = fit_model(res, args.poisson_share)
    result_file.write_text(json.dumps(res, indent=1))
    (args.out / "scaling.md").write_text(report(res))
    print((args.out / "scaling.md").read_text())


# Cluster figures the model assumes (not measured here: this machine has one node): an
# InfiniBand HDR-class network and a 2-socket node of 64 cores.
CLUSTER = {"latency_s": 2e-6, "bandwidth_B_per_s": 12e9, "allreduce_stage_s": 2e-6,
           "neighbours_at_scale": 14}


def fit_model(res, poisson_share):
    """T(N, p) = (a + b it(N)) N/p + exchanges + collectives; see docs/performance.md."""
    m = {"cluster": CLUSTER}
    if "size" in res and len(res["size"]) >= 2:
        # The cost per node-step grows with N (cache) far more than the iterations vary, so a fit
        # of it against the iterations is ill-posed: the largest size's cost is split by the
        # profile's Poisson share instead (validation/notes/flow_throughput.md).
        s = res["size"]
        big = max(s, key=lambda r: r["nodes"])
        u, its = big["us_per_node_step"], big["poisson_its_mean"]
        g, c = fit_line([math.log(r["nodes"]) for r in s],
                        [math.log(r["poisson_its_mean"]) for r in s])
        m.update(us_per_node_step_flow=(1 - poisson_share) * u,
                 us_per_node_step_per_poisson_it=poisson_share * u / its,
                 poisson_share=poisson_share, poisson_its_exponent=c,
                 poisson_its_constant=math.exp(g))
    if res.get("halo"):
        h = [r for r in res["halo"] if r["case"] == "tgv"]
        # values sent per exchange = k (N/p)^(2/3)
        ks = [r["sent_max"] / (r["nodes"] / r["ranks"]) ** (2 / 3) for r in h]
        m["halo_k_tgv"] = sum(ks) / len(ks)
        hv = [r for r in res["halo"] if r["case"] == "valve"]
        if hv:
            kv = [r["sent_max"] / (r["nodes"] / r["ranks"]) ** (2 / 3) for r in hv]
            m["halo_k_valve"] = sum(kv) / len(kv)
    if res.get("counts", {}).get("tgv"):
        ops = res["counts"]["tgv"]["operations"]
        send = ops.get("isend", {"calls": 0, "bytes": 0})
        halo = res["counts"]["tgv"]["halo"]
        m["messages_per_step_per_neighbour"] = send["calls"] / halo["neighbours_max"]
        m["scalar_exchanges_per_step"] = send["bytes"] / (8 * halo["sent_max"])
        m["allreduce_per_step"] = ops.get("allreduce", {"calls": 0})["calls"]
        m["poisson_its_in_count_runs"] = res["counts"]["tgv"]["poisson_iterations"]
    if all(k in m for k in ("us_per_node_step_flow", "halo_k_tgv", "allreduce_per_step")):
        m["predictions"] = predictions(m)
    return m


def step_time(m, nodes, ranks):
    its = m["poisson_its_constant"] * nodes ** m["poisson_its_exponent"]
    compute = 1e-6 * (m["us_per_node_step_flow"] + m["us_per_node_step_per_poisson_it"] * its) * (
        nodes / ranks)
    if ranks == 1:
        return compute, its
    c = m["cluster"]
    # Messages and collectives scale with the Poisson iterations measured in the count runs.
    scale = its / m["poisson_its_in_count_runs"]
    per_rank = nodes / ranks
    halo_bytes = 8 * m["scalar_exchanges_per_step"] * m["halo_k_tgv"] * per_rank ** (2 / 3)
    messages = m["messages_per_step_per_neighbour"] * scale * c["neighbours_at_scale"]
    exchange = messages * c["latency_s"] + halo_bytes * scale / c["bandwidth_B_per_s"]
    collective = m["allreduce_per_step"] * scale * c["allreduce_stage_s"] * math.log2(ranks)
    return compute + exchange + collective, its


def predictions(m):
    out = []
    for label, nodes in (("M1 valve root (85k nodes)", 84639), ("M2 (~680k nodes)", 680000),
                         ("10M nodes", 10_000_000), ("100M nodes", 100_000_000)):
        t1, its = step_time(m, nodes, 1)
        for ranks in (2, 16, 64, 256, 1000):
            tp, _ = step_time(m, nodes, ranks)
            out.append({"mesh": label, "nodes": nodes, "ranks": ranks,
                        "nodes_per_rank": nodes / ranks, "step_s": tp,
                        "efficiency": t1 / (ranks * tp), "poisson_its": its})
    return out


def report(res):
    lines = ["# scaling study (validation/bench/scaling_study.py)", ""]
    if "size" in res:
        lines += ["| TGV n^3 (1 rank, central2) | steps | CPU s | us per node-step | Poisson its |",
                  "|---|---|---|---|---|"]
        lines += [f"| {r['n']}^3 | {r['steps']:.0f} | {r['cpu_s']:.1f} | "
                  f"{r['us_per_node_step']:.3f} | {r['poisson_its_mean']:.2f} |"
                  for r in res["size"]]
        lines.append("")
    if "tgv_np2" in res:
        t = res["tgv_np2"]
        lines += [f"TGV {t['n']}^3 time loop: 1 rank {t['np1']['loop_wall_s']:.1f} s wall, "
                  f"{t['np1']['cpu_s']:.1f} s CPU; 2 ranks {t['np2']['loop_wall_s']:.1f} s wall, "
                  f"{t['np2']['cpu_s']:.1f} s CPU (both ranks): efficiency "
                  f"{t['efficiency_wall']:.3f} (wall), {t['efficiency_cpu']:.3f} (CPU).", ""]
    if "valve_np2" in res:
        v = res["valve_np2"]
        lines += [f"Valve scene, {v['np1']['nodes']} nodes, {v['np1']['steps']} steps: wall per "
                  f"step {v['np1']['wall_per_step_s']:.3f} s (1 rank), "
                  f"{v['np2']['wall_per_step_s']:.3f} s (2 ranks): efficiency "
                  f"{v['efficiency_wall']:.3f}; set-up {v['np1']['setup_s']:.1f} s / "
                  f"{v['np2']['setup_s']:.1f} s; CPU of the whole run {v['np1']['cpu_s']:.1f} s / "
                  f"{v['np2']['cpu_s']:.1f} s ({v['efficiency_cpu_whole_run']:.3f}).", ""]
    if res.get("halo"):
        lines += ["| case | ranks | ghost layers | nodes per rank | ghosts max | values sent max | "
                  "neighbours max |", "|---|---|---|---|---|---|---|"]
        lines += [f"| {r['case']} {r['n'] or ''} | {r['ranks']} | {r['ghost_layers']} | "
                  f"{r['nodes'] / r['ranks']:.0f} | "
                  f"{r['ghosts_max']} | {r['sent_max']} | {r['neighbours_max']} |"
                  for r in res["halo"]]
        lines.append("")
    for name, c in res.get("counts", {}).items():
        lines += [f"MPI operations per step, busiest rank, 2 ranks, {name} "
                  f"({c['poisson_iterations']:.1f} Poisson iterations per step):", "",
                  "| operation | calls | bytes |", "|---|---|---|"]
        lines += [f"| {op} | {v['calls']:.1f} | {v['bytes']:.0f} |"
                  for op, v in sorted(c["operations"].items()) if v["calls"] > 0]
        lines.append("")
    m = res.get("model", {})
    if "predictions" in m:
        lines += ["Model (docs/performance.md), assumed cluster: " + json.dumps(m["cluster"]), "",
                  "| mesh | ranks | nodes per rank | step s | efficiency |", "|---|---|---|---|---|"]
        lines += [f"| {p['mesh']} | {p['ranks']} | {p['nodes_per_rank']:.0f} | "
                  f"{p['step_s']:.3g} | {p['efficiency']:.3f} |" for p in m["predictions"]]
        lines.append("")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
