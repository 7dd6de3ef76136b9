#!/usr/bin/env python3
"""Fails when core's top-level modules import each other in a cycle.

The modules must form an acyclic chain: subsystems <- scenario <- sim <- studies (Monte Carlo,
fuel) <- {cli, web}. An edge X -> Y is any `crate::Y` path (use or inline) in X's files, or a
`crate::for_each_signal!`-style macro defined in Y. Prints the order it found, or the cycle.
"""
import pathlib
import re
import sys

src = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent) / "core" / "src"
modules = {}
for p in sorted(src.iterdir()):
    if p.name in ("lib.rs", "main.rs"):
        continue
    name = p.stem if p.suffix == ".rs" else p.name
    files = [p] if p.suffix == ".rs" else sorted(p.rglob("*.rs"))
    modules.setdefault(name, []).extend(files)

# Exported macros and `pub use` re-exports live at the crate root; map each to its module.
macro_home = {}
for m in re.finditer(r"pub use (\w+)::(?:\{([^}]*)\}|(\w+));", (src / "lib.rs").read_text()):
    for item in re.findall(r"\w+", m.group(2) or m.group(3)):
        macro_home[item] = m.group(1)
for name, files in modules.items():
    for f in files:
        for m in re.finditer(r"#\[macro_export\]\s*macro_rules!\s*(\w+)", f.read_text()):
            macro_home[m.group(1)] = name

edges = {name: set() for name in modules}
for name, files in modules.items():
    for f in files:
        text = re.sub(r"//[^\n]*", "", f.read_text())
        text = re.sub(r"#\[cfg\(test\)\]\s*mod tests \{.*", "", text, flags=re.S)  # tests may look up
        for m in re.finditer(r"crate::(\w+)", text):
            target = m.group(1)
            target = macro_home.get(target, target)
            if target in modules and target != name:
                edges[name].add(target)
        for use in re.finditer(r"use crate::\{([^;]*)\};", text, flags=re.S):
            for part in re.findall(r"(?:^|,)\s*(\w+)", use.group(1)):
                part = macro_home.get(part, part)
                if part in modules and part != name:
                    edges[name].add(part)

# Depth-first search for a cycle.
state = {}
stack = []
order = []


def visit(n):
    state[n] = 1
    stack.append(n)
    for m in sorted(edges[n]):
        if state.get(m) == 1:
            cycle = stack[stack.index(m):] + [m]
            print("import cycle between core modules: " + " -> ".join(cycle), file=sys.stderr)
            sys.exit(1)
        if m not in state:
            visit(m)
    stack.pop()
    state[n] = 2
    order.append(n)


for n in sorted(modules):
    if n not in state:
        visit(n)
print("core modules, no import cycle (leaves first): " + " ".join(order))
