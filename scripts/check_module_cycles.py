#!/usr/bin/env python3
"""Fails when core's modules import each other in a cycle, looking inside folders.

Every file is a module (`plant/motor.rs` is `plant::motor`, `sim/mod.rs` is `sim`). An edge X -> Y
is a path that names Y from X: `crate::a::b` (resolved to the longest module it names), a
`use crate::{...}` tree, `super::` paths, a folder's `child::` paths, and a `crate::params!`-style
macro defined in Y. Test modules may look up, and a file may use its own folders' mod.rs (the hub
that declares it). The modules must form an acyclic order; prints it, or the cycle.
"""
import pathlib
import re
import sys

src = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent) / "core" / "src"
modules = {}
for p in sorted(src.rglob("*.rs")):
    rel = p.relative_to(src)
    if str(rel) == "lib.rs":
        continue
    parts = list(rel.parts)
    parts[-1] = parts[-1][:-3]
    if parts[-1] == "mod":
        parts.pop()
    modules["::".join(parts)] = p
is_folder = {m: p.name == "mod.rs" for m, p in modules.items()}

macro_home = {}
for name, f in modules.items():
    for m in re.finditer(r"#\[macro_export\]\s*macro_rules!\s*(\w+)", f.read_text()):
        macro_home[m.group(1)] = name
for m in re.finditer(r"pub use ([\w:]+)::(\w+);", (src / "lib.rs").read_text()):
    macro_home[m.group(2)] = m.group(1)


def resolve(path):
    """The longest module that a `::` path names, or None."""
    segs = path.split("::")
    if len(segs) == 1 and segs[0] in macro_home:
        return macro_home[segs[0]]
    for n in range(len(segs), 0, -1):
        cand = "::".join(segs[:n])
        if cand in modules:
            return cand
    return None


def use_tree(prefix, body, out):
    """Expands `a::{b, c::{d}}` into full paths under `prefix`."""
    depth, cur, items = 0, "", []
    for ch in body:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        if ch == "," and depth == 0:
            items.append(cur)
            cur = ""
        else:
            cur += ch
    items.append(cur)
    for it in items:
        it = re.sub(r"\s+", "", it)
        if not it:
            continue
        m = re.match(r"([\w:]*?)(?:::)?\{(.*)\}$", it)
        if m:
            use_tree(prefix + ("::" + m.group(1) if m.group(1) else ""), m.group(2), out)
        else:
            out.append(prefix + "::" + re.sub(r"as\w+$", "", it))


edges = {m: set() for m in modules}
for name, f in modules.items():
    text = re.sub(r"//[^\n]*", "", f.read_text())
    text = re.sub(r"#\[cfg\(test\)\]\s*mod tests \{.*", "", text, flags=re.S)
    parent = name if is_folder[name] else "::".join(name.split("::")[:-1])
    grand = "::".join(parent.split("::")[:-1]) if parent else ""
    paths = []
    for m in re.finditer(r"(?:\$?crate)::((?:\w+::)*\w+)", text):
        paths.append(m.group(1))
    for m in re.finditer(r"use (?:\$?crate)::((?:\w+::)*)\{", text):
        start = m.end()
        depth, i = 1, start
        while i < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        out = []
        use_tree(m.group(1).rstrip(":"), text[start:i - 1], out)
        paths += [p.lstrip(":") for p in out]
    # super:: is the parent of a file's module (a folder's mod.rs: the folder's parent).
    base = grand if is_folder[name] else parent
    for m in re.finditer(r"\bsuper::((?:\w+::)*\w+)", text):
        paths.append((base + "::" if base else "") + m.group(1))
    for m in re.finditer(r"use super::\{", text):
        start = m.end()
        depth, i = 1, start
        while i < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        out = []
        use_tree(base, text[start:i - 1], out)
        paths += [p.lstrip(":") for p in out]
    if is_folder[name]:
        # A folder's own children named without `crate::` (`use plant::NX;`, `plant::run(..)`).
        for child in [m for m in modules if m.startswith(name + "::") and m.count("::") == name.count("::") + 1]:
            short = child.split("::")[-1]
            if re.search(r"(?<![\w:])" + short + r"::", text):
                edges[name].add(child)
    for p in paths:
        target = resolve(p)
        # A folder's mod.rs is the hub of its files: a file may use what its folders declare.
        if target and target != name and not name.startswith(target + "::"):
            edges[name].add(target)

state, stack, order = {}, [], []


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
