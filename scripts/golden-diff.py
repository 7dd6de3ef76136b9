#!/usr/bin/env python3
"""How far every preset's summary moved against the golden records of a git revision.

    scripts/golden-diff.py [REV]        (default HEAD: the committed records vs the working tree's)

Run `./build.sh golden` first (it rewrites tests/golden/ from the code as it is), then this. Prints,
per preset, the largest change of the quantities the tolerances are stated for: h/R (largest
absolute change of its min, mean, max, final), shaft speed (rpm, relative), power (motor, turbine,
ship, inverter, generator: relative to the signal's largest magnitude; all four statistics and the
mean alone), the energy books (relative
to the turbine energy) and their relative residual, and the largest relative change of any other
summary number (signals relative to their largest magnitude; settling times left out).
"""
import json
import subprocess
import sys
from pathlib import Path

rev = sys.argv[1] if len(sys.argv) > 1 else "HEAD"
root = Path(__file__).resolve().parent.parent
golden = root / "tests" / "golden"


def old(name):
    text = subprocess.run(["git", "-C", str(root), "show", f"{rev}:tests/golden/{name}"],
                          capture_output=True, text=True, check=True).stdout
    return json.loads(text)


def flat(x, path=""):
    if isinstance(x, dict):
        for k, v in x.items():
            yield from flat(v, f"{path}.{k}" if path else k)
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from flat(v, f"{path}[{i}]")
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        yield path, float(x)


POWER = ["p_motor_w", "p_turbine_w", "p_ship_w", "p_inverter_w", "p_generator_w"]
RPM = ["prop_rpm", "prop_rpm_1", "prop_rpm_2"]
STATS = ["min", "mean", "max", "final"]

worst = {"h_over_r": 0.0, "rpm": 0.0, "power": 0.0, "power_mean": 0.0, "energy": 0.0, "residual": 0.0, "any": 0.0}
print(f"{'preset':26} {'h/R abs':>9} {'rpm rel':>9} {'power rel':>9} {'p mean':>9} {'energy rel':>10} {'resid abs':>9} "
      f"{'any rel':>9}  (largest relative change, where)")
for f in sorted(golden.glob("*.json")):
    a, b = old(f.name), json.loads(f.read_text())
    sa, sb = a["summary"], b["summary"]
    sig_a, sig_b = sa.get("signals", {}), sb.get("signals", {})
    row = {}
    if "h_over_r" in sig_a:
        row["h_over_r"] = max(abs(sig_a["h_over_r"][k] - sig_b["h_over_r"][k]) for k in STATS)
    rpm = 0.0
    for s in RPM:
        if s in sig_a:
            scale = max(abs(sig_a[s][k]) for k in STATS) or 1.0
            rpm = max(rpm, max(abs(sig_a[s][k] - sig_b[s][k]) / scale for k in STATS))
    row["rpm"] = rpm
    pw, pm = 0.0, 0.0
    for s in POWER:
        if s in sig_a:
            scale = max(abs(sig_a[s][k]) for k in STATS) or 1.0
            pw = max(pw, max(abs(sig_a[s][k] - sig_b[s][k]) / scale for k in STATS))
            pm = max(pm, abs(sig_a[s]["mean"] - sig_b[s]["mean"]) / scale)
    row["power"] = pw
    row["power_mean"] = pm
    ea, eb = sa.get("energy_j", {}), sb.get("energy_j", {})
    if ea:
        scale = abs(ea.get("turbine", 0.0)) or max(abs(v) for v in ea.values()) or 1.0
        row["energy"] = max(abs(ea[k] - eb[k]) / scale for k in ea if k not in ("relative_residual", "residual"))
        row["residual"] = abs(ea["relative_residual"] - eb["relative_residual"])
    fa, fb = dict(flat(a)), dict(flat(b))
    anyrel, where = 0.0, ""
    for k, va in fa.items():
        if k.startswith("trace_fingerprints") or k not in fb or k.endswith("settling_time_s"):
            continue
        # Relative to the signal's largest magnitude (a mean near zero is not a large change).
        scale = abs(va)
        if k.startswith("summary.signals."):
            name = k.split(".")[2]
            scale = max(abs(sig_a[name][s]) for s in STATS)
        d = abs(va - fb[k]) / max(scale, 1e-300) if va != fb[k] else 0.0
        if d > anyrel:
            anyrel, where = d, k
    row["any"] = anyrel
    for k, v in row.items():
        worst[k] = max(worst[k], v)
    print(f"{f.stem:26} {row.get('h_over_r', 0):9.2e} {row['rpm']:9.2e} {row['power']:9.2e} {row['power_mean']:9.2e} "
          f"{row.get('energy', 0):10.2e} {row.get('residual', 0):9.2e} {anyrel:9.2e}  {where}")
print(f"{'largest':26} {worst['h_over_r']:9.2e} {worst['rpm']:9.2e} {worst['power']:9.2e} {worst['power_mean']:9.2e} "
      f"{worst['energy']:10.2e} {worst['residual']:9.2e} {worst['any']:9.2e}")
