#!/usr/bin/python3
"""io/plot_valve.py on tests/data/plot_valve: PNGs with a PNG header, the instants where the
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
    print("plot_valve script: ok")
finally:
    shutil.rmtree(out)
