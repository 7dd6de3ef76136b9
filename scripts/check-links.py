#!/usr/bin/env python3
"""Fails when a relative link or image of README.md, CONTRIBUTING.md or docs/**/*.md does not
resolve: the file (or folder) must be in the repository, and a `#anchor` must name a heading of
the target Markdown file by GitHub's rules (lower case, punctuation dropped, spaces as hyphens, a
repeated heading's slug followed by -1, -2, ...) or an HTML id/name in it. Links to other sites
(http:, https:, mailto:) are not followed; code spans and fenced blocks are not read.

Usage: python3 scripts/check-links.py [--self-test]. --self-test feeds it pages with a broken link,
a broken anchor and a broken image, and fails unless each is caught and the good links pass."""
import glob
import os
import re
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# [text](target "title") and ![alt](target): the target up to a space or the closing parenthesis,
# one level of parentheses allowed inside it.
INLINE = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?((?:[^()\s<>]|\([^()\s]*\))*)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$", re.M)
HTML = re.compile(r"<(?:a|img)\b[^>]*?\b(?:href|src)\s*=\s*\"([^\"]*)\"", re.I)
HTML_ID = re.compile(r"<[a-z]+\b[^>]*?\b(?:id|name)\s*=\s*\"([^\"]*)\"", re.I)


def strip_code(text, spans=True):
    """The text with fenced blocks (and code spans) blanked, line numbers kept."""
    out, fence = [], None
    for line in text.split("\n"):
        m = re.match(r"^\s{0,3}(`{3,}|~{3,})", line)
        if fence:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence):
                fence = None
            out.append("")
            continue
        if m:
            fence = m.group(1)
            out.append("")
            continue
        out.append(re.sub(r"(`+)(?:(?!\1).)+?\1", lambda c: " " * len(c.group(0)), line) if spans else line)
    return "\n".join(out)


def slug(heading):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text only
    text = re.sub(r"<[^>]+>", "", text)  # HTML tags
    text = text.strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", "-")


def anchors(path, cache={}):
    """Every anchor a Markdown file defines."""
    if path not in cache:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        found, seen = set(), {}
        # Headings outside fenced blocks; a code span's text is part of its heading's slug.
        for line in strip_code(text, spans=False).split("\n"):
            m = re.match(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$", line)
            if m:
                base = slug(m.group(2))
                n = seen.get(base, 0)
                seen[base] = n + 1
                found.add(base if n == 0 else f"{base}-{n}")
        found.update(HTML_ID.findall(text))
        cache[path] = found
    return cache[path]


def targets(text):
    """(line, target) of every link and image of a Markdown text."""
    plain = strip_code(text)
    out = []
    for pattern in (INLINE, REFERENCE, HTML):
        for m in pattern.finditer(plain):
            out.append((plain.count("\n", 0, m.start()) + 1, m.group(1)))
    return out


def check(root, files):
    """The problems of the given Markdown files, as 'file:line: ...' lines."""
    problems = []
    for path in files:
        rel = os.path.relpath(path, root)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for line, target in targets(text):
            if not target or re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I) or target.startswith("//"):
                continue  # another site, or mailto:
            where, _, anchor = target.partition("#")
            dest = path if not where else os.path.normpath(os.path.join(os.path.dirname(path), where))
            if where.startswith("/") or not os.path.abspath(dest).startswith(os.path.abspath(root) + os.sep):
                problems.append(f"{rel}:{line}: {target}: outside the repository (write a relative link)")
                continue
            if not os.path.exists(dest):
                problems.append(f"{rel}:{line}: {target}: no such file")
                continue
            if anchor:
                if not dest.endswith(".md"):
                    problems.append(f"{rel}:{line}: {target}: an anchor into a file that is not Markdown")
                elif anchor not in anchors(dest):
                    problems.append(f"{rel}:{line}: {target}: no heading #{anchor} in {os.path.relpath(dest, root)}")
    return problems


def book(root):
    files = [os.path.join(root, "README.md"), os.path.join(root, "CONTRIBUTING.md")]
    files += sorted(glob.glob(os.path.join(root, "docs", "**", "*.md"), recursive=True))
    return [f for f in files if os.path.exists(f)]


def self_test():
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs", "studies"))
        pages = {
            "README.md": "# Title\n\n![shot](docs/shot.png) [book](docs/README.md) [site](https://example.org)\n"
            "[gone](docs/gone.md)\n`[not a link](docs/nothing.md)`\n```\n[nor](this.md)\n```\n",
            "docs/README.md": "# The book\n\n## A `code` heading, with (punctuation)!\n\n## Twice\n\n## Twice\n\n"
            "[ok](studies/a.md#the-study) [ok](#a-code-heading-with-punctuation) [ok](#twice-1)\n"
            "[bad anchor](studies/a.md#no-such-heading)\n![missing](missing.svg)\n[up](../README.md#title)\n",
            "docs/studies/a.md": "# The study\n\n[back](../README.md#twice) [outside](../../../etc/passwd)\n",
        }
        for rel, text in pages.items():
            with open(os.path.join(root, rel), "w", encoding="utf-8") as f:
                f.write(text)
        open(os.path.join(root, "docs", "shot.png"), "wb").close()
        problems = check(root, book(root))
        want = ["README.md:4: docs/gone.md", "docs/README.md:10: studies/a.md#no-such-heading",
                "docs/README.md:11: missing.svg", "docs/studies/a.md:3: ../../../etc/passwd"]
        caught = [w for w in want if any(p.startswith(w + ":") for p in problems)]
        extra = [p for p in problems if not any(p.startswith(w + ":") for w in want)]
        if caught != want or extra:
            print("check-links.py --self-test: FAILED", file=sys.stderr)
            print("  not caught: " + ", ".join(w for w in want if w not in caught), file=sys.stderr)
            print("  wrongly refused: " + ", ".join(extra), file=sys.stderr)
            sys.exit(1)
    print(f"check-links.py --self-test: the {len(want)} broken links are caught, the good ones pass")


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if sys.argv[1:]:
        sys.exit(__doc__)
    files = book(ROOT)
    problems = check(ROOT, files)
    if problems:
        print(f"check-links.py: {len(problems)} broken link(s):\n  " + "\n  ".join(problems), file=sys.stderr)
        sys.exit(1)
    print(f"check-links.py: every relative link and anchor of {len(files)} Markdown files resolves")


if __name__ == "__main__":
    main()
