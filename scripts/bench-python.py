#!/usr/bin/env python3
"""A sweep of 20 runs from Python against the same 20 runs of the command line, side by side.

    python3 scripts/bench-python.py [--cli target/release/aes-sim] [--rounds 3] [--preset startup]

The sweep: the preset with its ordered speed at 20 values from 10 to 29 kn (`commands.0.speed_kn`),
one run after another on each side. Python: `aes_sim.run` on each, keeping the summary and the trace
as numpy arrays. The command line: `aes-sim run preset:NAME --set commands.0.speed_kn=V` as a
process, its summary read as JSON; once without the trace, once with it written (`--out`, CSV, not
read back). The rounds alternate the sides so that both see the same machine; the ratio is of the
medians. Issue 58 asks Python to cost no more than 1.1x the command line.
"""

import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import aes_sim

ROOT = pathlib.Path(__file__).resolve().parents[1]
SPEEDS_KN = [10.0 + 1.0 * k for k in range(20)]


def sweep_python(base):
    finals = []
    for v in SPEEDS_KN:
        r = aes_sim.run(base.copy().set("commands.0.speed_kn", v))
        finals.append(r.trace["ship_speed_kn"][-1])
    return finals


def sweep_cli(exe, preset, out_dir=None):
    finals = []
    for k, v in enumerate(SPEEDS_KN):
        cmd = [exe, "run", f"preset:{preset}", "--set", f"commands.0.speed_kn={v}"]
        if out_dir:
            cmd += ["--out", os.path.join(out_dir, f"run{k}.csv")]
        p = subprocess.run(cmd, capture_output=True, text=True, check=True)
        finals.append(json.loads(p.stdout)["final_time_s"])
    return finals


def timed(f, *args):
    t0 = time.perf_counter()
    f(*args)
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", default=str(ROOT / "target" / "release" / "aes-sim"))
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--preset", default="startup")
    a = ap.parse_args()
    if a.rounds < 1:
        sys.exit("--rounds: at least 1")
    base = aes_sim.Scenario.from_preset(a.preset)
    py, cli, cli_out = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(a.rounds):
            py.append(timed(sweep_python, base))
            cli.append(timed(sweep_cli, a.cli, a.preset))
            cli_out.append(timed(sweep_cli, a.cli, a.preset, tmp))
    m_py, m_cli, m_out = (statistics.median(x) for x in (py, cli, cli_out))
    print(f"20 runs of preset {a.preset} (ordered speed 10 to 29 kn), median of {a.rounds} rounds:")
    print(f"  Python (aes_sim.run, trace as numpy):       {m_py:7.3f} s")
    print(f"  command line, summary only:                  {m_cli:7.3f} s")
    print(f"  command line, summary and trace CSV (--out): {m_out:7.3f} s")
    print(f"  ratio Python / command line (summary only): {m_py / m_cli:.3f}x (target <= 1.1x)")
    print(f"  ratio Python / command line (with --out):   {m_py / m_out:.3f}x")
    return 0 if m_py <= 1.1 * m_cli else 1


if __name__ == "__main__":
    sys.exit(main())
