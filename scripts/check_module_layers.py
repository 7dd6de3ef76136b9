#!/usr/bin/env python3
"""Fails when a module of core imports one in a higher layer.

Every top-level module of core/src (a folder or a lib-level file) has a layer in LAYERS; a module
may import its own layer (peers: they only have to stay acyclic, files and folders alike, which
`check_module_cycles.py` checks) and the layers below it, never one above. Imports are found as
that script finds them (`crate::` paths, use trees, `super::`, a folder's children, exported
macros), so test modules may look up as they may there. A top-level module without a layer, or a
layer naming no module, fails too, and so does CONTRIBUTING.md when its copy of the table (between
its `layers:begin` and `layers:end` markers) differs from `--markdown`.

    check_module_layers.py [REPO]      check REPO (default: this script's repository)
    check_module_layers.py --markdown  the table as CONTRIBUTING.md prints it
    check_module_layers.py --self-test a fake tree with upward imports must be refused
"""
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from check_module_cycles import Scan, core_src, fake_core  # noqa: E402

# The layers, lowest first: (top-level modules, what they are). The one place they are written.
LAYERS = [
    (["params", "checks", "signals", "numerics", "as_printed", "geometry"],
     "leaves: the parameter declarations and their checks, the trace's signals, numerical methods, "
     "the thesis' as-printed switches, the hull's offsets and sections"),
    (["plant", "ship", "sea", "control"],
     "the subsystems, peers: the power plant, the hull and its maneuvering, the seaway and "
     "seakeeping, the controllers and their design toolkit"),
    (["scenario"], "a scenario: every subsystem's parameters, the presets, the file format"),
    (["sim"], "the simulator: the plant assembled from a scenario, stepped, recorded and checked"),
    (["studies"], "the studies that run the simulator or the subsystems' models"),
    (["output"], "what a display or report of runs and studies needs"),
]

# Upward imports that are known and on their way out: (from, to) -> why. An entry that no longer
# occurs fails the check, so this list only shrinks.
LEAVING = {}


def layer_of(layers):
    return {m: i for i, (mods, _) in enumerate(layers) for m in mods}


def check(src, layers, leaving):
    """Every problem with `src`'s layers, as printable lines (none: the layers hold)."""
    scan = Scan(src)
    level = layer_of(layers)
    top = sorted({m.split("::")[0] for m in scan.modules})
    problems = [f"core/src/{m}: a top-level module with no layer (add it to LAYERS in {pathlib.Path(__file__).name})"
                for m in top if m not in level]
    problems += [f"LAYERS names {m}, which core/src does not have" for m in sorted(level) if m not in top]
    seen, used = set(), set()
    for name in sorted(scan.modules):
        a = level.get(name.split("::")[0])
        lines = scan.modules[name].read_text().split("\n")
        # One report a line and module imported, by the longest path that names it there.
        for target, line, path in sorted(scan.sites[name], key=lambda s: (s[1], s[0], -len(s[2]))):
            b = level.get(target.split("::")[0])
            if a is None or b is None or b <= a or (name, line, target) in seen:
                continue
            seen.add((name, line, target))
            if (name, target) in leaving:
                used.add((name, target))
                continue
            rel = scan.modules[name].relative_to(src.parent.parent)
            problems.append(f"{rel}:{line}: {name} (layer {a}) imports {target} (layer {b}) by `{path}`: "
                            f"{lines[line - 1].strip()}")
    problems += [f"LEAVING lists {a} -> {b}, which no longer occurs: remove it" for a, b in sorted(set(leaving) - used)]
    return problems


def markdown(layers):
    rows = ["| layer | modules | what |", "|---|---|---|"]
    rows += [f"| {i} | {', '.join(f'`{m}`' for m in mods)} | {what} |" for i, (mods, what) in enumerate(layers)]
    return "\n".join(rows) + "\n"


def contributing_problems(repo):
    path = repo / "CONTRIBUTING.md"
    text = path.read_text()
    begin, end = "<!-- layers:begin -->\n", "<!-- layers:end -->"
    if begin not in text or end not in text:
        return [f"{path.name}: no {begin.strip()} ... {end} block for the layer table"]
    shown = text.split(begin, 1)[1].split(end, 1)[0]
    if shown != markdown(LAYERS):
        return [f"{path.name}: the layer table differs from LAYERS; paste `python3 scripts/check_module_layers.py --markdown` "
                f"between its layers markers"]
    return []


def self_test():
    """A fake core with five upward imports (a path in code, a use tree, super::super::, what lib.rs
    re-exports, code after the test module) and two allowed ones (a test module, a lower layer), a
    module with no layer, and a stale exception."""
    files = {
        "lib.rs": "pub mod params;\npub mod plant;\npub mod sim;\npub mod stray;\npub use sim::{run};\n",
        "params.rs": "pub struct P;\n",
        "plant/mod.rs": "pub mod motor;\nuse crate::params::P;\n",
        "plant/motor.rs": "use crate::params::P;\n\npub fn f() {\n    crate::sim::run();\n}\n"
                          "use crate::{params, sim::{run as go}};\nfn g() {\n    super::super::sim::run();\n}\n"
                          "fn h() {\n    crate::run();\n}\n"
                          "#[cfg(test)]\nmod tests {\n    use crate::sim::run;\n}\n"
                          "fn k() {\n    crate::sim::run();\n}\n",
        "sim/mod.rs": "use crate::plant::motor;\npub fn run() {}\n",
        "stray.rs": "",
    }
    layers = [(["params"], "leaf"), (["plant"], "subsystem"), (["sim"], "simulator")]
    with tempfile.TemporaryDirectory() as root:
        got = check(fake_core(root, files), layers, {("sim", "params"): "stale"})
    want = [
        "core/src/stray: a top-level module with no layer",
        "core/src/plant/motor.rs:4: plant::motor (layer 1) imports sim (layer 2) by `sim::run`: crate::sim::run();",
        "core/src/plant/motor.rs:6: plant::motor (layer 1) imports sim (layer 2) by `sim::run`: use crate::{params, sim::{run as go}};",
        "core/src/plant/motor.rs:8: plant::motor (layer 1) imports sim (layer 2) by `sim::run`: super::super::sim::run();",
        "core/src/plant/motor.rs:11: plant::motor (layer 1) imports sim (layer 2) by `run`: crate::run();",
        "core/src/plant/motor.rs:18: plant::motor (layer 1) imports sim (layer 2) by `sim::run`: crate::sim::run();",
        "LEAVING lists sim -> params, which no longer occurs",
    ]
    ok = len(got) == len(want) and all(g.startswith(w) for g, w in zip(got, want))
    for line in got:
        print("  " + line)
    if not ok:
        print("layer check self-test FAILED: expected, in order:\n  " + "\n  ".join(want), file=sys.stderr)
        sys.exit(1)
    print("layer check self-test: the fake tree's five upward imports, its module with no layer and its stale "
          "exception are refused; its test module's and its downward imports are not")


def main():
    if "--self-test" in sys.argv:
        return self_test()
    if "--markdown" in sys.argv:
        return print(markdown(LAYERS), end="")
    src = core_src(sys.argv)
    problems = check(src, LAYERS, LEAVING) + contributing_problems(src.parent.parent)
    if problems:
        print("core's modules break their layers:\n" + "\n".join(problems), file=sys.stderr)
        sys.exit(1)
    chain = " <- ".join("{" + ", ".join(mods) + "}" for mods, _ in LAYERS)
    print(f"core's layers hold (no module imports a layer above its own): {chain}")
    for (a, b), why in LEAVING.items():
        print(f"  known until it leaves: {a} -> {b}: {why}")


if __name__ == "__main__":
    main()
