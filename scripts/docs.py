#!/usr/bin/env python3
"""Regenerates the book's generated tables (docs/), each between its `<!-- NAME:begin -->` and
`<!-- NAME:end -->` markers:

  docs/reference/parameters.md  params   `aes-sim params --markdown` (the parameter registry)
  docs/reference/health.md      health   `aes-sim health --markdown` (core/src/sim/health.rs)
  docs/reference/signals.md     signals  a table of `aes-sim signals --json` (core/src/signals.rs)
  docs/architecture.md          modules  one line per module of core/src and www/js: the first
                                         sentence of its first doc comment (`//!` in Rust, the
                                         leading `//` comment in JS)

Usage: python3 scripts/docs.py [--check]. With --check nothing is written: it fails (exit 1) naming
every stale table, and every module without a first doc line. The command is
target/release/aes-sim unless AES_SIM names another (`./build.sh docs` builds it first)."""
import json
import os
import re
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
AES_SIM = os.environ.get("AES_SIM", os.path.join(ROOT, "target", "release", "aes-sim"))


def aes_sim(*args):
    if not os.path.exists(AES_SIM):
        sys.exit(f"docs.py: {AES_SIM} is missing: build it first (cargo build --release -p aes-cli)")
    return subprocess.check_output([AES_SIM, *args], text=True)


def cell(text):
    """A Markdown table cell: one line, its pipes escaped."""
    return " ".join(text.split()).replace("|", "\\|")


def signals_table():
    rows = ["| signal | unit | label | what it is |", "|---|---|---|---|"]
    for s in json.loads(aes_sim("signals", "--json")):
        rows.append(f"| `{s['name']}` | {cell(s['unit'])} | {cell(s['label'])} | {cell(s['description'])} |")
    return "\n".join(rows) + "\n"


def first_sentence(comment_lines):
    """The first sentence of a comment's first paragraph. A full stop ends it only before a
    capital or a backtick, so `ch. 2.5` and `eqs. 2.2-2.4` do not."""
    para = []
    for line in comment_lines:
        if not line.strip():
            if para:
                break
            continue
        para.append(line.strip())
    text = " ".join(para)
    m = re.search(r"[.!?](?=\s+[A-Z`])", text)
    return text[: m.end()] if m else text


def doc_line(path):
    """The first sentence of a module's doc comment, or None."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    prefix = "//!" if path.endswith(".rs") else "//"
    comment = []
    for line in lines:
        s = line.strip()
        if not comment and (s.startswith("#!") or (not s and prefix == "//!")):
            continue  # a shebang, or blank lines before a Rust module's doc
        if s.startswith(prefix) and not (prefix == "//" and s.startswith("///")):
            comment.append(s[len(prefix):])
        else:
            break
    sentence = first_sentence(comment)
    return sentence or None


def modules(missing):
    out = []
    for top, ext in (("core/src", ".rs"), ("www/js", ".js")):
        files = []
        for dirpath, dirnames, filenames in os.walk(os.path.join(ROOT, top)):
            dirnames[:] = [d for d in dirnames if not d.startswith(".")]
            files += [os.path.join(dirpath, n) for n in filenames if n.endswith(ext)]
        out += [f"| module of `{top}` | what it is |", "|---|---|"]
        for path in sorted(files, key=lambda p: os.path.relpath(p, ROOT)):
            rel = os.path.relpath(path, ROOT).replace(os.sep, "/")
            line = doc_line(path)
            if line is None:
                missing.append(rel)
                line = "(no doc line)"
            out.append(f"| `{rel[len(top) + 1:]}` | {cell(line)} |")
        out.append("")
    return "\n".join(out).rstrip("\n") + "\n"


def main():
    check = sys.argv[1:] == ["--check"]
    if sys.argv[1:] not in ([], ["--check"]):
        sys.exit(__doc__)
    missing = []
    targets = [
        ("docs/reference/parameters.md", "params", lambda: aes_sim("params", "--markdown")),
        ("docs/reference/health.md", "health", lambda: aes_sim("health", "--markdown")),
        ("docs/reference/signals.md", "signals", signals_table),
        ("docs/architecture.md", "modules", lambda: modules(missing)),
    ]
    stale = []
    for rel, marker, make in targets:
        path = os.path.join(ROOT, rel)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        begin, end = f"<!-- {marker}:begin -->\n", f"<!-- {marker}:end -->"
        if begin not in text or end not in text:
            sys.exit(f"docs.py: {rel} has no {begin.strip()} ... {end} markers")
        a = text.index(begin) + len(begin)
        b = text.index(end, a)
        table = make().rstrip("\n") + "\n"
        if text[a:b] == table:
            continue
        stale.append(f"{rel}: the {marker} table is stale")
        if not check:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text[:a] + table + text[b:])
    for rel in missing:
        print(f"docs.py: {rel} has no first doc line (`//!` in Rust, a leading `//` in JS)", file=sys.stderr)
    if check:
        for s in stale:
            print(f"docs.py: {s}: run ./build.sh docs", file=sys.stderr)
        if stale or missing:
            sys.exit(1)
        print("docs.py: every generated table in docs/ is current")
    else:
        print("\n".join(f"docs.py: regenerated {s.split(':')[0]}" for s in stale) or "docs.py: nothing to regenerate")
        if missing:
            sys.exit(1)


if __name__ == "__main__":
    main()
