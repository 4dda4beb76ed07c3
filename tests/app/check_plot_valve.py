#!/usr/bin/python3
"""analysis/plot_valve.py on tests/data/plot_valve: PNGs with a PNG header, the instants where the
design note puts them, a missing column named with its file and line, and the per-cycle figures of
a lumped circulation (circulation_cycles.csv) against their closed forms on a made-up outlets.csv."""
import csv, json, math, os, shutil, subprocess, sys, tempfile

script, data = sys.argv[1], sys.argv[2]
out = tempfile.mkdtemp()
try:
    subprocess.run(["/usr/bin/python3", script, data, out, "--cycle-offset", "-0.1"], check=True)
    for name in ("tpg.png", "flow_rate.png", "opening_area.png", "tips.png"):
        with open(os.path.join(out, name), "rb") as f:
            assert f.read(8) == b"\x89PNG\r\n\x1a\n", name
    rep = json.load(open(os.path.join(out, "plotted.json")))
    # data span 0 .. 0.078 s; cycle starting at -0.1 s: only t1 (0.15 into the cycle) = 0.05 s
    assert [n for n, _ in rep["instants"]] == ["t1 opening"], rep["instants"]
    assert abs(rep["instants"][0][1] - 0.05) < 1e-12, rep["instants"]
    assert rep["plots"]["tpg.png"]["tpg_mmHg"][1] > 1.0, rep["plots"]["tpg.png"]
    bad = os.path.join(out, "bad")
    os.mkdir(bad)
    lines = open(os.path.join(data, "valve.csv")).read().splitlines()
    open(os.path.join(bad, "valve.csv"), "w").write(
        "\n".join([lines[0].replace("tpg_mmHg", "tpg")] + lines[1:5]) + "\n")
    r = subprocess.run(["/usr/bin/python3", script, bad, bad], capture_output=True, text=True)
    assert r.returncode != 0 and "valve.csv:1: missing column 'tpg_mmHg'" in r.stderr, r.stderr
    open(os.path.join(bad, "valve.csv"), "w").write(lines[0] + "\n")
    r = subprocess.run(["/usr/bin/python3", script, bad, bad], capture_output=True, text=True)
    assert r.returncode != 0 and "0 data rows" in r.stderr, r.stderr
    # Line statistics of the PIV profiles (statistics/p1.csv): bins 20 and 26 of 100 sampled
    # (phases 0.205 and 0.265 s, nearest ES and PS), three points each; MS and LS have none.
    prof = os.path.join(out, "prof")
    os.makedirs(os.path.join(prof, "statistics"))
    shutil.copy(os.path.join(data, "valve.csv"), prof)
    with open(os.path.join(prof, "statistics", "p1.csv"), "w") as f:
        f.write("bin,phase_time,s,x,y,z,samples,mean_w,rms_w\n")
        for b in range(100):
            for j, y in enumerate((-0.01, 0.0, 0.01)):
                n = 5 if b in (20, 26) else 0
                f.write(f"{b},{(b + 0.5) / 100},{j * 0.01},0,{y},0.02,{n},{b / 10 + j},{0.01 * j}\n")
    subprocess.run(["/usr/bin/python3", script, prof, prof], check=True)
    with open(os.path.join(prof, "profiles.png"), "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    rows = open(os.path.join(prof, "profiles.csv")).read().splitlines()
    assert rows[0].startswith("line,phase,phase_time_s,y_m,mean_w_m_s"), rows[0]
    assert [r.split(",")[1] for r in rows[1:]] == ["ES"] * 3 + ["PS"] * 3, rows
    assert abs(float(rows[4].split(",")[4]) - 2.6) < 1e-12, rows[4]  # bin 26, first point
    plotted = json.load(open(os.path.join(prof, "plotted.json")))["plots"]["profiles.png"]
    assert sorted(plotted) == ["p1_ES_mean_w", "p1_PS_mean_w"], plotted
    # A made-up circulation, 2.5 periods of 1 s sampled every 1e-4 s: the inlet's outward flux
    # -A sin(2 pi t) in systole (t mod 1 < 0.5) and -B sin(2 pi t) (> 0, backward) in diastole,
    # so per cycle the forward volume is A / pi, the regurgitant one B / pi and the mean flow
    # over 0.6-1 s B (1 + cos(0.2 pi)) / (0.8 pi); the aorta at P0 + P1 cos(2 pi t), the
    # ventricle at V0 + V1 sin(2 pi t). Expected: two complete cycles, each with those figures.
    A, B, P0, P1, V0, V1, mmhg = 3e-4, 2e-6, 1.2e4, 2.5e3, 8e3, 6e3, 133.322387415
    circ = os.path.join(out, "circ")
    os.mkdir(circ)
    shutil.copy(os.path.join(data, "valve.csv"), circ)
    with open(os.path.join(circ, "outlets.csv"), "w") as f:
        f.write("step,time,flux_inlet,pressure_inlet,volume_inlet,flux_outlet,pressure_outlet\n")
        for k in range(25001):
            t = k * 1e-4
            q = -(A if t % 1.0 < 0.5 else B) * math.sin(2 * math.pi * t)
            f.write(f"{k},{t!r},{q!r},{V0 + V1 * math.sin(2 * math.pi * t)!r},1e-4,{-q!r},"
                    f"{P0 + P1 * math.cos(2 * math.pi * t)!r}\n")
    subprocess.run(["/usr/bin/python3", script, circ, circ], check=True)
    with open(os.path.join(circ, "circulation.png"), "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    cycles = list(csv.DictReader(open(os.path.join(circ, "circulation_cycles.csv"))))
    assert len(cycles) == 2, cycles
    # Tolerance: the trapezoidal rule on 1e-4 s samples errs by pi^2 h^2 / 3 = 3.3e-8 relative
    # on a half sine's integral (Euler-Maclaurin); the extremes are samples (t = 0, 0.25).
    expected = {"forward_volume_mL": A / math.pi * 1e6, "regurgitant_volume_mL": B / math.pi * 1e6,
                "regurgitant_fraction": B / A,
                "aorta_max_mmHg": (P0 + P1) / mmhg, "aorta_min_mmHg": (P0 - P1) / mmhg,
                "aorta_mean_mmHg": P0 / mmhg, "ventricle_max_mmHg": (V0 + V1) / mmhg,
                "diastolic_mean_flow_mL_s": B * (1 + math.cos(0.2 * math.pi)) / (0.8 * math.pi) * 1e6}
    for row in cycles:
        for key, value in expected.items():
            got = float(row[key])
            assert abs(got - value) <= 1e-7 * abs(value), (row["cycle"], key, got, value)
    assert abs(float(cycles[1]["net_volume_change_mL"])) < 1e-9, cycles[1]
    lines = open(os.path.join(circ, "outlets.csv")).read().splitlines()
    lines[3] = lines[3].replace(",", ",x", 1)
    open(os.path.join(circ, "outlets.csv"), "w").write("\n".join(lines) + "\n")
    r = subprocess.run(["/usr/bin/python3", script, circ, circ], capture_output=True, text=True)
    assert r.returncode != 0 and "outlets.csv:4: column 'time'" in r.stderr, r.stderr
    print("plot_valve script: ok")
finally:
    shutil.rmtree(out)
