#!/usr/bin/env python3
"""Seeded, repeatable fuzz campaign over every subcommand of the `aes-sim` binary.

Lists the subcommands from `aes-sim --help` (and the nested ones of `design` and `ips`), the
flags of each from `aes-sim CMD --help`, and the scenario parameters from `aes-sim params
--json`; then generates N cases that mix valid arguments with hostile ones (NaN, inf, huge and
negative numbers, empty strings, control characters, long strings, unknown paths, files that
are empty, binary, huge, a directory or /dev/null, a closed standard output). Each case runs in
a fresh working folder with a time-out, and is judged:

- exit status 0, 1 or 2 (101 is a panic; a signal is a crash, except SIGPIPE on a closed
  standard output, which is what a pipe reader that leaves does);
- standard error under 2 kB with no raw control character, and not empty on a refusal;
- no NaN or infinity in the output (JSON or text), no raw control character in text output,
  no `null` under a key that names a unit (a number was expected there);
- no file left in the working folder but the ones the case named;
- an impossible number (NaN, infinity, or outside the range `aes-sim params` declares) given
  and exit status 0: accepted;
- within the time-out (60 s): no unbounded work. A refusal for being long (`--allow-long`)
  is a clean refusal.

Prints a summary line and writes every finding, shrunk to the fewest arguments that still
show it, to target/fuzz/cli-findings.json (and the per-command counts beside it).

    python3 scripts/fuzz-cli.py --cases 1000 --seed 1 [--jobs 2] [--bin target/release/aes-sim]
"""

import argparse
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f\x80-\x9f]")
NONFINITE_TEXT = re.compile(r"(?<![A-Za-z_])(NaN|nan|-?inf|-?Infinity)(?![A-Za-z_])")
UNIT_KEY = re.compile(
    r"_(s|m|kn|w|j|pu|deg|kg|hz|rad|n|nm|v|a|rpm|m2|m3|mj|mw|kw|kj|per_h|per_nm|m_s|rad_s|pct|frac)$"
)
# Keys whose null is a deliberate "none" (an Option in the code): no wave sums to time on a calm
# preset, a signal that never settles or recovers in the run, fuel per mile at 0 kn, a
# sensitivity with one turbine online, the excess energy of a study that does not collect it, an
# arrival rate with no exposure (every event at the start), one seed's spread.
NULL_MEANS_NONE = {"wave_sums_s", "settling_time_s", "bus_recovery_s", "turbine_recovery_s",
                   "fuel_per_nmi_j", "sensitivity_w_per_n", "excess_energy_mj", "excess_vs_calm_mj",
                   "phase_crossover_rad_s", "gain_crossover_rad_s", "kg_per_nmi_std", "rate_per_s"}
TIMEOUT_S = 60.0
WEIGHTS = {"validate": 0.15}
# The valid span of each numeric flag (values outside it come from the hostile list), and of each
# list flag with its most entries and whether they are whole numbers.
NUMBER_RANGES = {
    "duration-s": (5, 30), "from": (0.01, 10), "to": (10, 1000), "level": (0.2, 1.5),
    "brute-force": (0.001, 0.01), "vfd": (0.01, 100), "load": (0.01, 100), "torque": (0.01, 100),
    "mu": (0.001, 10), "omega-p": (0.001, 10), "q": (0.001, 10), "turbine-weight": (0.001, 10),
    "speed-kn": (5, 30), "beam": (5, 30), "draft": (2, 10), "area-coeff": (0.5, 1.0), "kg": (3, 10),
    "kxx": (3, 10), "kyy": (20, 50), "kzz": (20, 50), "heading-deg": (0, 360),
    "roll-wave-amplitude": (0.1, 3), "mass": (3e6, 1e7), "diameter-m": (1, 6), "rpm": (50, 300),
    "depth-m": (2, 10), "at-j": (0.1, 1.2), "hub-ratio": (0.1, 0.3),
}
LIST_RANGES = {
    "speeds": (0, 30, 3, False), "headings": (0, 360, 3, False), "sea-states": (2, 6, 3, True),
    "omega": (0.2, 2.0, 3, False), "energy-mj": (1, 100, 2, False), "power-mw": (1, 100, 2, False),
}
STDERR_MAX = 2048

HOSTILE_NUMBERS = [
    ("nan", True), ("NaN", True), ("inf", True), ("-inf", True), ("1e308", None), ("-1e308", None),
    ("1e999", True), ("1e-320", None), ("0", None), ("-0", None), ("-1", None), ("-5", None),
    ("1e9", None), ("99999999999999999999", None), ("0x10", None), ("1,5", None), ("", None),
    (" ", None), ("abc", None), ("\x1b[31mred", None), ("5\x07", None), ("\r", None), ("1e", None),
    ("--", None), ("9" * 5000, None), ("-9" + "9" * 400, None), ("1.5.2", None), ("\u202e12", None),
]
HOSTILE_TEXT = [
    "", " ", "\x1b]0;title\x07", "a\rb", "line\nbreak", "\t", "x" * 5000, "../../etc/passwd",
    "preset:", "preset:nope", "preset:\x1b[2J", "\u00e9\u00e8", "%s%n", "{}", "null", "-", "--help",
]


def help_text(binary, args):
    out = subprocess.run([binary, *args, "--help"], capture_output=True, text=True, timeout=30)
    return out.stdout


def list_commands(binary, prefix=()):
    """The leaf subcommands under `prefix`, from the `Commands:` section of the help."""
    text = help_text(binary, list(prefix))
    if "Commands:" not in text:
        return [tuple(prefix)]
    section = text.split("Commands:", 1)[1].split("\n\n", 1)[0]
    leaves = []
    for line in section.splitlines():
        m = re.match(r"^\s{2}([a-z][a-z0-9-]*)\s", line)
        if m and m.group(1) != "help":
            leaves += list_commands(binary, (*prefix, m.group(1)))
    return leaves


def list_flags(binary, command):
    """(flags, positionals, required): each flag with whether it takes a value, each positional's
    name, and the flags the usage line requires."""
    text = help_text(binary, list(command))
    flags, positionals = {}, []
    usage = re.search(r"Usage: .*", text)
    required = re.findall(r"--([a-z][a-z0-9-]*) <", usage.group(0)) if usage else []
    for line in text.splitlines():
        m = re.match(r"^\s+(?:-\w, )?--([a-z][a-z0-9-]*)(?: <([^>]+)>(\.\.\.)?)?", line)
        if m and m.group(1) not in ("help", "version"):
            flags[m.group(1)] = m.group(2) is not None
            continue
        m = re.match(r"^\s{2}([<\[])([A-Z_]+)[>\]](\.\.\.)?\s", line)
        if m:
            positionals.append((m.group(2), m.group(1) == "<", bool(m.group(3))))
    return flags, positionals, required


class Gen:
    """Argument generators: valid most of the time, hostile the rest."""

    def __init__(self, rng, params, presets, fixtures):
        self.rng = rng
        self.params = params
        self.numeric = [p for p in params if p["kind"] in ("number", "integer")]
        self.presets = presets
        self.fx = fixtures

    def chance(self, p):
        return self.rng.random() < p

    def hostile_number(self):
        value, impossible = self.rng.choice(HOSTILE_NUMBERS)
        return value, ("non-finite number" if impossible else None)

    def number(self, lo, hi, integer=False):
        if self.chance(0.8):
            x = self.rng.uniform(lo, hi)
            return (str(int(round(x))) if integer else f"{x:.6g}"), None
        return self.hostile_number()

    def num_list(self, lo, hi, n_max=3, integer=False):
        if self.chance(0.15):
            return self.rng.choice(["", ",", "1,,2", "a,b", "nan,1", "1e308", "-1," + "5," * 3000 + "5"]), (
                None)
        vals, bad = [], None
        for _ in range(self.rng.randint(1, n_max)):
            v, b = self.number(lo, hi, integer)
            vals.append(v)
            bad = bad or b
        return ",".join(vals), bad

    def text(self):
        return self.rng.choice(HOSTILE_TEXT)

    def param_value(self, p):
        """A value for a registry parameter, and why it is impossible if it is."""
        kind = p["kind"]
        if kind in ("number", "integer"):
            lo, hi = p.get("min"), p.get("max")
            r = self.rng.random()
            if r < 0.55 and lo is not None and hi is not None:
                span_hi = min(hi, lo + 1e6) if hi - lo > 1e6 else hi
                x = self.rng.uniform(lo, span_hi)
                return (str(int(round(x))) if kind == "integer" else f"{x:.6g}"), None
            if r < 0.7 and lo is not None:
                x = lo - abs(lo) * 0.5 - 1.0
                return f"{x:.6g}", f"below its minimum {lo}"
            if r < 0.8 and hi is not None:
                x = hi * 2 + 1.0
                return f"{x:.6g}", f"above its maximum {hi}"
            return self.hostile_number()
        if kind == "choice" or p.get("choices"):
            choices = [c["value"] if isinstance(c, dict) else c for c in p.get("choices", [])]
            if choices and self.chance(0.75):
                return str(self.rng.choice(choices)), None
            return self.text(), None
        if kind == "switch":
            return self.rng.choice(["true", "false", "1", "0", "yes", "maybe", ""]), None
        return self.text(), None

    def set_arg(self):
        r = self.rng.random()
        if r < 0.8:
            p = self.rng.choice(self.params)
            v, bad = self.param_value(p)
            return f"{p['path']}={v}", bad
        p = self.rng.choice(self.params)["path"]
        return self.rng.choice([
            f"={self.rng.randint(0, 9)}", p, f"{p}.x=5", f"{p}==5", "no.such.path=1", f"{p}=",
            f" {p} = 5", f"{p}\x1b[1m=5", f"{'a.' * 2000}b=1", "=",
        ]), None

    def scenario_file(self):
        """A FILE argument: a preset mostly, otherwise a hostile file, and the stdin to feed."""
        r = self.rng.random()
        if r < 0.7:
            return f"preset:{self.rng.choice(self.presets)}", None
        if r < 0.8:
            return "-", self.rng.choice(self.fx["stdin"])
        if r < 0.95:
            return self.rng.choice(self.fx["files"]), None
        return self.text(), None

    def trial_range(self):
        return self.rng.choice(["0..1", "0..2", "1..2", "2..1", "0..0", "a..b", "0..999999999", "-1..2",
                                "0..", "..3", "0...2"])


def bounded(gen, cmd, args):
    """Small sizes most of the time for the heavy studies: the point is inputs, not long runs.
    Returns the arguments and whether they were made small."""
    c = cmd[0]
    small = gen.chance(0.9)
    if not small:
        return args, False
    extra = []
    if c in ("run", "mc", "rare", "fuel-per-mile", "bench", "stability-map", "maneuvers", "fuel",
             "storage-sizing", "operability", "schedule"):
        if c in ("run", "mc", "rare", "fuel-per-mile", "bench", "storage-sizing"):
            extra += ["--set", f"sim.duration_s={gen.rng.choice([2, 5, 10, 20])}"]
    has = set(a.split("=", 1)[0] for a in args if a.startswith("--"))
    if c in ("mc", "rare") and "--trials" not in has:
        extra += ["--trials", str(gen.rng.randint(1, 4))]
    if c in ("mc", "rare", "operability", "fuel-per-mile", "storage-sizing", "stability-map") and "--threads" not in has:
        extra += ["--threads", "1"]
    if c in ("mc", "rare", "operability", "fuel-per-mile", "storage-sizing", "stability-map") and "--quiet" not in has and gen.chance(0.7):
        extra += ["--quiet"]
    if c == "operability":
        for f, v in (("--speeds", "12"), ("--headings", "180,90"), ("--sea-states", "4")):
            if f not in has:
                extra += [f, v]
    if c == "fuel-per-mile":
        for f, v in (("--speeds", "15"), ("--seeds", "1")):
            if f not in has:
                extra += [f, v]
    if c == "storage-sizing":
        for f, v in (("--energy-mj", "50"), ("--power-mw", "5"), ("--duration-s", "20")):
            if f not in has:
                extra += [f, v]
    if c == "fuel" and "--omega" not in has:
        extra += ["--omega", "0.6,0.9"]
    if c == "bench" and "--repeat" not in has:
        extra += ["--repeat", "1"]
    if c == "validate" and "--trials" not in has:
        extra += ["--trials", "2"]
    if c == "ips" and len(cmd) > 1 and cmd[1] == "bode" and "--points" not in has:
        extra += ["--points", "20"]
    return args + extra, True


def flag_value(gen, cmd, flag, outputs):
    """The value of one flag, its stdin if any, and why it is impossible if it is."""
    g, rng = gen, gen.rng
    c = cmd[0]
    if flag == "set":
        if c == "ips":
            name = rng.choice(["l_md", "r_s", "l_ls", "j", "c_dc", "nope", "", "r_fd"])
            v, bad = g.number(1e-4, 1.0)
            return f"{name}={v}", None, bad
        v, bad = g.set_arg()
        return v, None, bad
    if flag in ("out", "partial"):
        name = rng.choice(["out.csv", "shard.bin", "o.json"])
        if g.chance(0.15):
            bad = rng.choice(["", "/dev/null", "missing_dir/x.csv", ".", "/proc/nope", "a\x1bb"])
            if bad == "a\x1bb":
                outputs.add(bad)  # an odd name, but the one named: it may be written
            return bad, None, None
        outputs.add(name)
        return name, None, None
    if flag == "figures":
        outputs.add("figs")
        return ("figs" if g.chance(0.9) else "/dev/null"), None, None
    if flag == "check":
        return rng.choice([g.fx["empty"], g.fx["binary"], "docs/validation.md", "missing.md"]), None, None
    if flag == "merge" or flag == "files-from":
        return rng.choice(g.fx["shards"] + g.fx["files"]), None, None
    if flag == "trial-range":
        return g.trial_range(), None, None
    if flag == "trials":
        v, _ = g.number(1, 5, integer=True)
        return v, None, None
    if flag in ("seed",):
        return rng.choice(["0", "1", "42", "-1", "18446744073709551615", "18446744073709551616", "1.5", "x"]), None, None
    if flag == "threads":
        return rng.choice(["1", "1", "2", "0", "-1", "100000", "x"]), None, None
    if flag == "seas":
        return rng.choice(["2:8", "2:8,4:10", "0:8", "-1:5", "4:0", "nan:8", "2", "2:8:9", "1e308:10"]), None, None
    if flag == "scatter":
        return rng.choice(["none", "core/data/iacs_rec34_north_atlantic.csv"] + g.fx["files"]), None, None
    if flag in LIST_RANGES and not (c == "ips" and flag == "omega"):
        lo, hi, n_max, integer = LIST_RANGES[flag]
        v, bad = g.num_list(lo, hi, n_max, integer)
        return v, None, bad
    if flag == "seeds":
        return rng.choice(["1", "2", "0", "-1", "1000000000", "x"]), None, None
    if flag == "points":
        return rng.choice(["2", "10", "20", "1", "0", "10001", "1e9", "x"]), None, None
    if flag == "event":
        return rng.choice(["ventilation", "emergence", "level", "nope", ""]), None, None
    if flag == "shaft":
        return rng.choice(["port", "starboard", "both", ""]), None, None
    if flag == "threshold":
        name = rng.choice(["min_bus_voltage_pu", "nope", "", "min_bus_voltage_pu.x"])
        v, bad = g.number(0, 2)
        return f"{name}={v}", None, bad
    if flag == "against":
        return g.scenario_file()[0] if g.chance(0.3) else "preset:head-seas-ss6-storage", None, None
    if flag == "repeat":
        return rng.choice(["1", "2", "0", "-1", "x"]), None, None
    if flag == "hull":
        return rng.choice(["wigley", "dtmb5415", "nope", "core/data/dtmb5415_offsets.csv"] + g.fx["files"]), None, None
    if flag == "value" or flag == "before":
        if flag == "before" and g.chance(0.3):
            return "default", None, None
        controls = [c for cs in g.fx["controls"].values() for c in cs]
        path = rng.choice(controls) if g.chance(0.8) else rng.choice(["nope", "=5", "", "sea.sea_state.x"])
        p = next((q for q in g.params if q["path"] == path), None)
        v, bad = g.param_value(p) if p else g.number(0, 6)
        return f"{path}={v}", None, bad
    if flag == "answer":
        return rng.choice(["1", "2", "3", "0", "-1", "99", "x"]), None, None
    if flag in ("x", "y"):
        p = rng.choice(g.numeric)
        lo, hi = p.get("min"), p.get("max")
        if lo is not None and hi is not None and g.chance(0.7):
            a = rng.uniform(lo, min(hi, lo + 1e6))
            b = rng.uniform(a, min(hi, a + 1e6))
            n = rng.randint(1, 3)
            return f"{p['path']}={a:.6g}:{b:.6g}:{n}", None, None
        return rng.choice([
            f"{p['path']}=0:1:2", f"{p['path']}=nan:1:2", f"{p['path']}=1:0:2", f"{p['path']}=0:1:0",
            f"{p['path']}=0:1:100000", f"{p['path']}=0:1", "nope=0:1:2", f"{p['path']}\x1b=0:1:2",
            f"{'x' * 3000}=0:1:2",
        ]), None, None
    if flag == "side":
        return rng.choice(["generator", "motor", "both"]), None, None
    if flag in ("loop",):
        return rng.choice(["open", "closed", "x"]), None, None
    if flag == "plant":
        return rng.choice(["aes", "nope", ""]), None, None
    if flag in NUMBER_RANGES or flag == "omega":
        v, bad = g.number(*NUMBER_RANGES.get(flag, (1, 5000)))
        return v, None, bad
    if flag == "form":
        return rng.choice(["auto", "lewis", "bulb", "x"]), None, None
    if flag == "scenario":
        return g.scenario_file()[0], None, None
    if flag == "blades":
        return rng.choice(["3", "4", "5", "0", "1", "100", "-1", "x"]), None, None
    if flag == "water":
        return rng.choice(["fresh", "sea", "x"]), None, None
    if flag == "j":
        return rng.choice(["0:1.2:5", "0.1:1:3", "1:0:5", "0:1:0", "0:1:1000000", "nan:1:2", "0:1"]), None, None
    v, bad = g.number(0, 10)
    return v, None, bad


def positional_value(gen, cmd, name):
    g, rng = gen, gen.rng
    c = cmd[0]
    if c == "preset":
        return (rng.choice(g.presets) if g.chance(0.8) else g.text()), None
    if c == "lesson":
        return (rng.choice(["power", "waves", "turn", "braking", "bus", "engines", "sign", "battery"])
                if g.chance(0.85) else g.text()), None
    if c == "bench":
        return rng.choice(["startup", "seakeeping", "propeller", "turn-45", "nope"]), None
    if c == "propeller":
        r = rng.random()
        if r < 0.6:
            return rng.choice(["core/data/dtmb4119_geometry.csv", "core/data/b4_70_geometry.csv",
                               "preset:startup", "preset:head-seas-ss6"]), None
        if r < 0.7:
            return "-", rng.choice(g.fx["stdin"])
        return rng.choice(g.fx["files"]), None
    if c == "merge":
        return rng.choice(g.fx["shards"]), None
    if c == "design":
        r = rng.random()
        if r < 0.5:
            return g.fx["lqg"], None
        if r < 0.6:
            return "-", rng.choice(g.fx["stdin"])
        return rng.choice(g.fx["files"]), None
    return g.scenario_file()


def make_case(gen, commands, flags_of):
    # `validate` runs the whole validation report (about 25 s a case): drawn rarely.
    cmd = gen.rng.choices(commands, weights=[WEIGHTS.get(c[0], 1.0) for c in commands])[0]
    flags, positionals, required_flags = flags_of[cmd]
    rng = gen.rng
    args, stdin, outputs, impossible = [], None, set(), []
    for name, required, many in positionals:
        if required or gen.chance(0.7):
            for _ in range(rng.randint(1, 3) if many else 1):
                v, s = positional_value(gen, cmd, name)
                args.append(v)
                stdin = stdin or s
    names = list(flags)
    chosen = rng.sample(names, k=min(len(names), rng.randint(0, 4)))
    chosen += [f for f in required_flags if f not in chosen and gen.chance(0.95)]
    for flag in chosen:
        if flag == "allow-long" and gen.chance(0.8):
            continue
        if not flags[flag]:
            args.append(f"--{flag}")
            continue
        for _ in range(rng.randint(1, 3) if flag in ("set", "value", "threshold") else 1):
            v, s, bad = flag_value(gen, cmd, flag, outputs)
            # `--flag=value` mostly: clap takes a value that starts with '-' for a flag otherwise.
            args += [f"--{flag}={v}"] if gen.chance(0.8) else [f"--{flag}", v]
            stdin = stdin or s
            if bad:
                impossible.append({"value": v, "why": f"--{flag} {v[:60]!r}: {bad}"})
    if gen.chance(0.03):
        args.append(rng.choice(["--nope", "extra", "--", "-x"]))
    args, sized = bounded(gen, cmd, args)
    closed = gen.chance(0.04)
    return {"cmd": list(cmd), "args": args, "stdin": stdin, "outputs": sorted(outputs),
            "impossible": impossible, "closed_stdout": closed, "sized": sized}


def walk_json(value, path, problems, check_null):
    if isinstance(value, dict):
        # No numbers where there is nothing to measure: an inadmissible option of the schedule (the
        # set cannot carry the load), a cell whose reserve no set meets, a fuel-per-mile row of a
        # merge that lacks its runs (the merge warns).
        check_null = (check_null and value.get("admissible") is not False and value.get("reserve_unmet") is not True
                      and value.get("seeds") != 0)
        for k, v in value.items():
            if v is None and check_null and UNIT_KEY.search(str(k)) and k not in NULL_MEANS_NONE:
                problems.append(f"null at {path}.{k}")
            walk_json(v, f"{path}.{k}", problems, check_null)
    elif isinstance(value, list):
        for i, v in enumerate(value[:100000]):
            walk_json(v, f"{path}[{i}]", problems, check_null)
    elif isinstance(value, float) and not math.isfinite(value):
        problems.append(f"{value} at {path}")


def run_case(binary, case, fixtures_dir):
    work = tempfile.mkdtemp(prefix="case-", dir=os.path.join(fixtures_dir, "..", "work"))
    argv = [binary, *case["cmd"], *case["args"]]
    # Relative input paths (core/data/...) resolve from the repository: link its folders in.
    for d in ("core", "docs"):
        os.symlink(os.path.join(ROOT, d), os.path.join(work, d))
    stdin_data = None
    if case["stdin"] is not None:
        with open(case["stdin"], "rb") as f:
            stdin_data = f.read()
    t0 = time.monotonic()
    rfd = wfd = None
    if case["closed_stdout"]:
        rfd, wfd = os.pipe()
        os.close(rfd)
    try:
        proc = subprocess.Popen(argv, cwd=work, stdin=subprocess.PIPE if stdin_data is not None else subprocess.DEVNULL,
                                stdout=wfd if wfd is not None else subprocess.PIPE, stderr=subprocess.PIPE,
                                start_new_session=True)
    except (OSError, ValueError) as e:
        shutil.rmtree(work, ignore_errors=True)
        return {"kind": "skip", "why": str(e)}
    if wfd is not None:
        os.close(wfd)
    timed_out = False
    try:
        out, err = proc.communicate(stdin_data, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
    except BrokenPipeError:
        out, err = proc.communicate()
    elapsed = time.monotonic() - t0
    out = out or b""
    problems = []
    rc = proc.returncode
    err_text = err.decode("utf-8", "replace")
    if timed_out and not case["sized"]:
        # A study at its own full size that the program estimated under its hour-long budget and
        # accepted: long, not unbounded. Counted apart (the campaign is about inputs).
        shutil.rmtree(work, ignore_errors=True)
        return {"kind": "long", "rc": None, "elapsed_s": round(elapsed, 3), "problems": [], "stderr": err_text[:300]}
    if timed_out:
        problems.append(("timeout", f"no answer in {TIMEOUT_S:.0f} s"))
    elif rc < 0:
        if not (case["closed_stdout"] and rc == -signal.SIGPIPE):
            problems.append(("signal", f"killed by signal {-rc}"))
    elif rc == 101:
        problems.append(("panic", err_text[-400:]))
    elif rc not in (0, 1, 2):
        problems.append(("exit_code", f"exit status {rc}"))
    if len(err) > STDERR_MAX:
        problems.append(("long_stderr", f"{len(err)} bytes of stderr"))
    m = CONTROL.search(err_text)
    if m:
        problems.append(("control_char_stderr", f"{m.group(0)!r} in stderr: {err_text[max(0, m.start() - 60):m.start() + 20]!r}"))
    if rc in (1, 2) and not err_text.strip() and not timed_out:
        problems.append(("silent_refusal", "exit status %d with nothing on stderr" % rc))
    if rc == 0 and not timed_out:
        text = out.decode("utf-8", "replace")
        parsed, is_json = None, False
        if text.lstrip()[:1] in ("{", "["):
            try:
                parsed = json.loads(text, parse_constant=lambda c: float(c))
                is_json = True
            except ValueError:
                pass
        if is_json:
            found = []
            walk_json(parsed, "$", found, case["cmd"][0] not in ("preset", "params"))
            for f in found[:3]:
                problems.append(("null_number" if f.startswith("null") else "nan_json", f))
        else:
            m = NONFINITE_TEXT.search(text)
            if m:
                problems.append(("nan_text", text[max(0, m.start() - 80):m.end() + 20]))
            m = CONTROL.search(text)
            if m:
                problems.append(("control_char_stdout", f"{m.group(0)!r}: {text[max(0, m.start() - 60):m.start() + 20]!r}"))
        if case["impossible"]:
            problems.append(("accepted_impossible", "; ".join(i["why"] for i in case["impossible"])))
        for name in case["outputs"]:
            p = os.path.join(work, name)
            if os.path.isfile(p) and name.endswith((".csv", ".json")):
                with open(p, "rb") as f:
                    head = f.read(4 << 20).decode("utf-8", "replace")
                m = NONFINITE_TEXT.search(head)
                if m:
                    problems.append(("nan_file", f"{name}: {head[max(0, m.start() - 80):m.end() + 20]!r}"))
    allowed = set(case["outputs"]) | {"core", "docs"}
    for entry in os.listdir(work):
        if entry not in allowed:
            problems.append(("stray_file", f"left behind: {entry!r}"))
    shutil.rmtree(work, ignore_errors=True)
    if problems:
        kind = "finding"
    elif timed_out:
        kind = "finding"
    elif rc == 0:
        kind = "success"
    else:
        kind = "refusal"
    return {"kind": kind, "rc": rc, "elapsed_s": round(elapsed, 3), "problems": problems,
            "stderr": err_text[:300]}


def shrink(binary, case, kinds, fixtures_dir, budget=12):
    """Drop flags (with their values) one at a time while the same kinds of finding remain."""
    best = dict(case)
    i = 0
    tries = 0
    while tries < budget:
        args = best["args"]
        # Argument groups: a flag and its value, or one positional.
        groups, j = [], 0
        while j < len(args):
            if args[j].startswith("--") and j + 1 < len(args) and not args[j + 1].startswith("--"):
                groups.append((j, j + 2))
                j += 2
            else:
                groups.append((j, j + 1))
                j += 1
        if i >= len(groups):
            break
        a, b = groups[i]
        kept = args[:a] + args[b:]
        impossible = [i for i in best["impossible"] if any(i["value"] in x for x in kept)]
        trial = dict(best, args=kept, impossible=impossible)
        tries += 1
        res = run_case(binary, trial, fixtures_dir)
        if res["kind"] == "finding" and kinds <= {p[0] for p in res["problems"]}:
            best = trial
        else:
            i += 1
    return best


def make_fixtures(binary, d, rng):
    os.makedirs(d, exist_ok=True)
    fx = {"files": [], "stdin": [], "shards": []}

    def put(name, data):
        p = os.path.join(d, name)
        with open(p, "wb") as f:
            f.write(data)
        return p

    fx["empty"] = put("empty.json", b"")
    fx["binary"] = put("binary.bin", bytes(rng.getrandbits(8) for _ in range(4096)))
    huge = put("huge.json", b"[" + b"1e308," * (4 << 20) + b"1]")
    deep = put("deep.json", b"[" * 100000 + b"]" * 100000)
    ctl = put("control.json", b'{"name": "\\u001b[31m\\u0007x\\r\\n", "description": "\\u001b]0;t\\u0007"}')
    os.makedirs(os.path.join(d, "a_dir"), exist_ok=True)
    fx["files"] += [fx["empty"], fx["binary"], huge, deep, ctl, os.path.join(d, "a_dir"), "/dev/null",
                    os.path.join(d, "missing.json")]
    # Scenarios: each preset, and each with one field made hostile.
    presets = subprocess.run([binary, "presets"], capture_output=True, text=True).stdout
    names = [line.split()[0] for line in presets.splitlines() if line.strip()]
    scen = json.loads(subprocess.run([binary, "preset", "head-seas-ss6"], capture_output=True, text=True).stdout)
    fx["stdin"].append(put("scenario.json", json.dumps(scen).encode()))
    bad_values = [1e308, -1.0, 0.0, "x", None, [], {}, 1e-320, -1e308, "\u001b[2J"]
    for k in range(12):
        s = json.loads(json.dumps(scen))
        node = s
        keys = []
        while isinstance(node, dict) and node:
            key = rng.choice(sorted(node))
            keys.append(key)
            if not isinstance(node[key], dict):
                node[key] = rng.choice(bad_values)
                break
            node = node[key]
        raw = json.dumps(s).encode()
        if k % 4 == 3:
            raw = raw.replace(b"0.0", b"NaN", 1)
        p = put(f"mutated{k}.json", raw)
        fx["files"].append(p)
        fx["stdin"].append(p)
    fx["stdin"] += [fx["empty"], fx["binary"], ctl]
    fx["lqg"] = put("lqg.json", json.dumps({"a": [[-1, 0], [0, -2]], "b": [[1, 0], [0, 1]], "c": [[1, 0], [0, 1]],
                                            "d": [[0, 0], [0, 0]], "mu": 0.005, "omega_p": 3.0, "q": 1000.0}).encode())
    fx["files"].append(put("lqg_bad.json", json.dumps({"a": [[float("1e308")]], "b": [[0]], "c": [[1]], "d": [[0]]}).encode()))
    # Shards of each study, and damaged copies.
    studies = [
        ["mc", "preset:mc-wigley", "--trials", "2", "--set", "sim.duration_s=5"],
        ["rare", "--trials", "2", "--set", "sim.duration_s=5"],
        ["operability", "--speeds", "12,15", "--headings", "180", "--sea-states", "4"],
        ["fuel-per-mile", "--speeds", "15,18", "--seeds", "1", "--set", "sim.duration_s=20"],
        ["storage-sizing", "--energy-mj", "50", "--power-mw", "5", "--duration-s", "20"],
    ]
    for k, s in enumerate(studies):
        p = os.path.join(d, f"shard{k}.bin")
        r = subprocess.run([binary, *s, "--trial-range", "0..1", "--partial", p, "--quiet", "--threads", "1"],
                           capture_output=True, timeout=300)
        if r.returncode != 0 or not os.path.exists(p):
            print(f"fixture shard {s[0]} not made: {r.stderr[:200]!r}", file=sys.stderr)
            continue
        fx["shards"].append(p)
        data = bytearray(open(p, "rb").read())
        for m in range(3):
            dam = bytearray(data)
            if m == 0:
                dam = dam[: len(dam) // 2]
            else:
                for _ in range(4):
                    dam[rng.randrange(len(dam))] = rng.getrandbits(8)
            fx["shards"].append(put(f"shard{k}_damaged{m}.bin", bytes(dam)))
    # Each lesson's controls, from the refusal of an empty path that names them.
    fx["controls"] = {}
    for lesson in ("power", "waves", "turn", "braking", "bus", "engines", "sign", "battery"):
        r = subprocess.run([binary, "lesson", lesson, "--value", "=1"], capture_output=True, text=True)
        m = re.search(r"its controls are (.*)", r.stderr)
        fx["controls"][lesson] = [c.strip() for c in m.group(1).split(",")] if m else []
    listing = put("shards.txt", ("\n".join(fx["shards"][:4]) + "\n").encode())
    fx["shards"] += [listing, fx["empty"], "/dev/null"]
    return fx, names


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cases", type=int, default=5000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--bin", default=os.path.join(ROOT, "target", "release", "aes-sim"))
    ap.add_argument("--out", default=os.path.join(ROOT, "target", "fuzz"))
    ap.add_argument("--only", help="run only this subcommand (e.g. `maneuvers`)")
    args = ap.parse_args()
    args.out = os.path.abspath(args.out)
    binary = os.path.abspath(args.bin)
    rng = random.Random(args.seed)
    os.makedirs(os.path.join(args.out, "work"), exist_ok=True)
    fixtures_dir = os.path.join(args.out, "fixtures")
    fx, presets = make_fixtures(binary, fixtures_dir, random.Random(0))
    params = json.loads(subprocess.run([binary, "params", "--json"], capture_output=True, text=True).stdout)
    commands = list_commands(binary)
    if args.only:
        commands = [c for c in commands if " ".join(c).startswith(args.only)]
    flags_of = {c: list_flags(binary, c) for c in commands}
    gen = Gen(rng, params, presets, fx)
    cases = [make_case(gen, commands, flags_of) for _ in range(args.cases)]
    t0 = time.monotonic()
    per_cmd, findings, counts = {}, [], {"success": 0, "refusal": 0, "finding": 0, "skip": 0, "long": 0}
    by_kind = {}
    log = open(os.path.join(args.out, f"cli-cases-seed{args.seed}.jsonl"), "w")
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = pool.map(lambda c: (c, run_case(binary, c, fixtures_dir)), cases)
        for n, (case, res) in enumerate(results, 1):
            name = " ".join(case["cmd"])
            pc = per_cmd.setdefault(name, {"cases": 0, "success": 0, "refusal": 0, "finding": 0, "skip": 0, "long": 0})
            pc["cases"] += 1
            log.write(json.dumps({"argv": [*case["cmd"], *case["args"]], "rc": res.get("rc"),
                                  "s": res.get("elapsed_s"), "stderr": res.get("stderr", "")[:200]}) + "\n")
            pc[res["kind"]] += 1
            counts[res["kind"]] += 1
            if res["kind"] == "finding":
                for kind, _ in res["problems"]:
                    by_kind[kind] = by_kind.get(kind, 0) + 1
                findings.append({"case": case, "result": res})
            if n % 250 == 0:
                print(f"  {n}/{len(cases)} cases, {time.monotonic() - t0:.0f} s", file=sys.stderr)
    # Shrink the first few findings of each kind and command.
    seen = {}
    for f in findings:
        kinds = frozenset(p[0] for p in f["result"]["problems"])
        key = (tuple(f["case"]["cmd"]), kinds)
        seen[key] = seen.get(key, 0) + 1
        if seen[key] <= 2:
            small = shrink(binary, f["case"], set(kinds), fixtures_dir)
            f["minimal"] = {"argv": ["aes-sim", *small["cmd"], *small["args"]], "stdin": small["stdin"],
                            "closed_stdout": small["closed_stdout"]}
    elapsed = time.monotonic() - t0
    report = {"seed": args.seed, "cases": len(cases), "elapsed_s": round(elapsed, 1), "counts": counts,
              "findings_by_kind": by_kind, "per_command": per_cmd, "findings": findings}
    path = os.path.join(args.out, f"cli-findings-seed{args.seed}.json")
    with open(path, "w") as f:
        json.dump(report, f, indent=1, default=str)
    print(f"fuzz-cli: {len(cases)} cases over {len(commands)} commands in {elapsed:.0f} s (seed {args.seed}): "
          f"{counts['refusal']} clean refusals, {counts['success']} successes, {counts['long']} full-size runs past "
          f"{TIMEOUT_S:.0f} s, {counts['finding']} with findings "
          f"{json.dumps(by_kind, sort_keys=True)}; details in {os.path.relpath(path, ROOT)}")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
