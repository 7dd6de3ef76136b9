#!/usr/bin/env python3
"""Fails when core's modules import each other in a cycle, looking inside folders.

Every file is a module (`plant/motor.rs` is `plant::motor`, `sim/mod.rs` is `sim`). An edge X -> Y
is a path that names Y from X: `crate::a::b` (resolved to the longest module it names), a
`use crate::{...}` tree, `super::` paths (`super::super::` goes two folders up), a folder's
`child::` paths, a `crate::params!`-style macro defined in Y, and an item lib.rs re-exports from Y
(`crate::run`). Test modules (`#[cfg(test)] mod`) may look up, and a file may use its own folders'
mod.rs (the hub that declares it). The modules must form an acyclic order; prints it, or the cycle.

Folders too: inside every folder (core/src itself included) its entries, files and sub-folders,
each taken whole, must import each other without a cycle, so `ship/hull.rs -> sea/strip.rs` and
`sea/strip.rs -> ship/sections.rs` fail although the files alone are acyclic, and so do peers of
one layer in a ring (plant -> control -> sea -> plant). An import from a folder's mod.rs into its
own files, or back, is the folder's business and no edge between entries.

    check_module_cycles.py [REPO]      check REPO (default: this script's repository)
    check_module_cycles.py --self-test fake trees with a file cycle, a folder pair and a folder ring must be refused

`Scan` is shared with `check_module_layers.py`, which holds the folders to their layers.
"""
import pathlib
import re
import sys


class Scan:
    """Core's modules, their files and every import between them, with where it is written."""

    def __init__(self, src):
        self.src = pathlib.Path(src)
        self.modules = {}
        for p in sorted(self.src.rglob("*.rs")):
            rel = p.relative_to(self.src)
            if str(rel) == "lib.rs":
                continue
            parts = list(rel.parts)
            parts[-1] = parts[-1][:-3]
            if parts[-1] == "mod":
                parts.pop()
            self.modules["::".join(parts)] = p
        self.is_folder = {m: p.name == "mod.rs" for m, p in self.modules.items()}
        self.macro_home = {}
        for name, f in self.modules.items():
            for m in re.finditer(r"#\[macro_export\]\s*macro_rules!\s*(\w+)", f.read_text()):
                self.macro_home[m.group(1)] = name
        # What lib.rs re-exports (`pub use sim::{run, ..};`): `crate::run` names `sim`.
        lib = self.src / "lib.rs"
        for m in re.finditer(r"pub use ([^;]+);", re.sub(r"//[^\n]*", "", lib.read_text() if lib.exists() else "")):
            out = []
            use_tree("", m.group(1), out)
            for p in out:
                home, _, item = p.strip(":").rpartition("::")
                self.macro_home[item] = home
        # edges[X] = the modules X imports; sites[X] = (Y, line, path as written) for each.
        self.edges = {m: set() for m in self.modules}
        self.sites = {m: [] for m in self.modules}
        for name in self.modules:
            self._scan(name)

    def resolve(self, path):
        """The longest module that a `::` path names (or the home of what lib.rs re-exports), or None."""
        segs = path.split("::")
        if len(segs) == 1 and segs[0] in self.macro_home:
            return self.macro_home[segs[0]]
        for n in range(len(segs), 0, -1):
            cand = "::".join(segs[:n])
            if cand in self.modules:
                return cand
        # `crate::Scenario::default()`: an item lib.rs re-exports, and a path inside it.
        return self.macro_home.get(segs[0])

    def _scan(self, name):
        f = self.modules[name]
        # Comments go, and so do test modules (tests may look up); line breaks stay, so positions
        # keep their line numbers.
        text = re.sub(r"//[^\n]*", "", f.read_text())
        for m in reversed(list(re.finditer(r"#\[cfg\(test\)\]\s*mod \w+ \{", text))):
            body = braced(text, m.end())
            end = m.end() + len(body) + 1
            text = text[:m.start()] + "\n" * text.count("\n", m.start(), end) + text[end:]
        is_folder = self.is_folder[name]
        paths = []  # (position in text, path from the crate root)
        for m in re.finditer(r"(?:\$?crate)::((?:\w+::)*\w+)", text):
            paths.append((m.start(), m.group(1)))
        for m in re.finditer(r"use (?:\$?crate)::((?:\w+::)*)\{", text):
            out = []
            use_tree(m.group(1).rstrip(":"), braced(text, m.end()), out)
            paths += [(m.start(), p.lstrip(":")) for p in out]
        # super:: is the parent of a file's module (a folder's mod.rs: the folder's parent), and
        # each further super:: one folder up.
        def up(supers):
            return "::".join(name.split("::")[:-supers.count("super")])

        for m in re.finditer(r"\b((?:super::)+)((?:\w+::)*\w+)", text):
            base = up(m.group(1))
            paths.append((m.start(), (base + "::" if base else "") + m.group(2)))
        for m in re.finditer(r"use ((?:super::)+)\{", text):
            out = []
            use_tree(up(m.group(1)), braced(text, m.end()), out)
            paths += [(m.start(), p.lstrip(":")) for p in out]
        if is_folder:
            # A folder's own children named without `crate::` (`use plant::NX;`, `plant::run(..)`).
            depth = name.count("::") + 1
            for child in [m for m in self.modules if m.startswith(name + "::") and m.count("::") == depth]:
                short = child.split("::")[-1]
                m = re.search(r"(?<![\w:])" + short + r"::", text)
                if m:
                    paths.append((m.start(), child))
        for pos, p in paths:
            target = self.resolve(p)
            # A folder's mod.rs is the hub of its files: a file may use what its folders declare.
            if target and target != name and not name.startswith(target + "::"):
                self.edges[name].add(target)
                self.sites[name].append((target, text.count("\n", 0, pos) + 1, p))


def braced(text, start):
    """The text from `start` to the brace that closes the one just before it."""
    depth, i = 1, start
    while i < len(text) and depth:
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return text[start:i - 1]


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


def core_src(argv):
    """core/src of the repository given as the first argument, or of this script's."""
    root = argv[1] if len(argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    return pathlib.Path(root) / "core" / "src"


def find_cycle(edges):
    """(None, the nodes leaves first) when `edges` is acyclic, else (a cycle as a node list, None)."""
    state, stack, order = {}, [], []

    def visit(n):
        state[n] = 1
        stack.append(n)
        for m in sorted(edges.get(n, ())):
            if state.get(m) == 1:
                return stack[stack.index(m):] + [m]
            if m not in state:
                found = visit(m)
                if found:
                    return found
        stack.pop()
        state[n] = 2
        order.append(n)
        return None

    for n in sorted(edges):
        if n not in state:
            found = visit(n)
            if found:
                return found, None
    return None, order


def entry_edges(scan):
    """{entry: {entry}} between the entries of each folder (a file or a sub-folder, taken whole),
    and one import site for each such edge: (module, line, path as written)."""
    edges, sites = {}, {}
    for name, targets in scan.sites.items():
        for target, line, path in targets:
            a, b = name.split("::"), target.split("::")
            i = 0
            while i < min(len(a), len(b)) and a[i] == b[i]:
                i += 1
            if i == len(a) or i == len(b):
                continue  # a folder's mod.rs and its own files
            x, y = "::".join(a[:i + 1]), "::".join(b[:i + 1])
            edges.setdefault(x, set()).add(y)
            sites.setdefault((x, y), (name, line, path))
    return edges, sites


def check(src):
    """The problem with `src`'s imports as printable lines (none: no cycle), and the modules' order."""
    scan = Scan(src)
    cycle, order = find_cycle(scan.edges)
    if cycle:
        return ["import cycle between core modules: " + " -> ".join(cycle)], None
    edges, sites = entry_edges(scan)
    cycle, _ = find_cycle(edges)
    if cycle:
        folder = cycle[0].rpartition("::")[0] or "core/src"
        lines = [f"import cycle between the entries of {folder}: " + " -> ".join(cycle)]
        for x, y in zip(cycle, cycle[1:]):
            name, line, path = sites[(x, y)]
            lines.append(f"  {x} -> {y}: {scan.modules[name].relative_to(src.parent.parent)}:{line} names `{path}`")
        return lines, None
    return [], order


def fake_core(root, files):
    """Writes `files` ({path under core/src: text}) under `root`; returns that core/src."""
    src = pathlib.Path(root) / "core" / "src"
    for rel, body in files.items():
        (src / rel).parent.mkdir(parents=True, exist_ok=True)
        (src / rel).write_text(body)
    return src


def self_test():
    """Fake trees: files in a cycle; two folders whose files are acyclic but which import each other;
    three folders in a ring; and one that passes (a folder's hub and its files both ways, a test
    module looking up, folders one way)."""
    import tempfile

    base = {"lib.rs": "pub mod ship;\npub mod sea;\npub mod plant;\n",
            "plant/mod.rs": "pub mod motor;\n", "plant/motor.rs": "",
            "ship/mod.rs": "pub mod hull;\npub mod sections;\nuse hull::Hull;\n",
            "ship/hull.rs": "use crate::sea::strip::Ship;\nuse super::sections;\nuse crate::ship::Thing;\n",
            "ship/sections.rs": "#[cfg(test)]\nmod tests {\n    use crate::ship::hull::Hull;\n}\n",
            "sea/mod.rs": "pub mod strip;\n", "sea/strip.rs": "use crate::plant::motor;\n"}
    cases = [
        ("files in a cycle", {"plant/motor.rs": "use crate::sea::strip::Ship;\n"},
         "import cycle between core modules: plant::motor -> sea::strip -> plant::motor"),
        ("two folders", {"sea/strip.rs": "use crate::ship::sections::HullOffsets;\n"},
         "import cycle between the entries of core/src: sea -> ship -> sea"),
        ("a ring of three", {"plant/motor.rs": "fn f() {\n    crate::ship::sections::g();\n}\n"},
         "import cycle between the entries of core/src: plant -> ship -> sea -> plant"),
        ("one way", {}, None),
    ]
    failed = []
    for what, change, want in cases:
        with tempfile.TemporaryDirectory() as root:
            got, _ = check(fake_core(root, {**base, **change}))
        print(f"  {what}: " + ("\n    ".join(got) if got else "no cycle"))
        if (got[0] if got else None) != want:
            failed.append(f"{what}: expected {want!r}")
    if failed:
        print("cycle check self-test FAILED:\n  " + "\n  ".join(failed), file=sys.stderr)
        sys.exit(1)
    print("cycle check self-test: a file cycle, a pair of folders and a ring of three are refused; "
          "a folder's hub with its files, a test module looking up and one-way folders are not")


def main():
    if "--self-test" in sys.argv:
        return self_test()
    problems, order = check(core_src([a for a in sys.argv if not a.startswith("--")]))
    if problems:
        print("\n".join(problems), file=sys.stderr)
        sys.exit(1)
    print("core modules, no import cycle between files or between the entries of a folder (leaves first): "
          + " ".join(order))


if __name__ == "__main__":
    main()
