#!/usr/bin/python3
"""analysis/plot_valve.py on tests/data/plot_valve: PNGs with a PNG header, the instants where the
design note puts them, and a missing column named with its file and line."""
import json, os, shutil, subprocess, sys, tempfile

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
    print("plot_valve script: ok")
finally:
    shutil.rmtree(out)
