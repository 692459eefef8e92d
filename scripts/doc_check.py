#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
"""The paths and make targets the docs name, against the tree (ctest docs_paths_exist).

    scripts/doc_check.py [FILE.md ...]     (default: README.md and docs/**/*.md)

- a path: a token that starts with one of the repository's top folders (rtl/, sw_ref/,
  sim/, tests/, ...) or is a top-level file (Makefile, README.md, ...), or the target of a
  Markdown link (relative to the doc's folder); trailing punctuation, a `:line` and a
  link's #anchor are stripped. It must exist. A glob (`*`, `?`, `[...]`) must match
  something, and a `<...>` placeholder (`formal/<block>_props.sv`) counts as `*`. build/
  paths are outputs and are not checked, nor are URLs, nor the links of a template (a doc
  with {{...}} placeholders: its links are relative to the page rendered from it);
- a make target: `make <target>` inside a code span or a code block (prose says "make the
  loader wait"); the target must be a rule of the Makefile (`name:`) or in its .PHONY.
CHANGELOG.md is history and is not read. Exits 1 naming each file:line and what it names.
"""
import glob
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# The top folders a path in the docs starts with, and the top-level files (a bare name
# of one of these kinds is one of them: README.md, CMakeLists.txt, mcadsw.core, ...).
TOP_DIRS = ("rtl", "sw_ref", "sim", "tests", "scripts", "flow", "docs", "constraints",
            "driver", "data", "bench", "formal", ".ci")
TOP_FILE = re.compile(r"(?:Makefile|LICENSE|[A-Z][A-Za-z0-9_-]*\.(?:md|txt|cff|toml)"
                      r"|[a-z][a-z0-9_-]*\.(?:core|xml|conf)|requirements\.txt)")
# Characters that end a path token (Markdown and prose around it).
STOP = r"\s`'\"()\[\]{},;|"
PATH = re.compile(r"(?<![\w./<>-])((?:%s)/[^%s]*)" % ("|".join(re.escape(d) for d in TOP_DIRS), STOP))
BARE = re.compile(r"(?<![\w./<>-])(%s)(?![\w/-]|\.\w)" % TOP_FILE.pattern)
LINK = re.compile(r"\]\(([^()\s]+)\)")
MAKE = re.compile(r"\bmake\s+([a-z][\w-]*)\b(?!=)")
CODE = re.compile(r"^ *```.*?^ *```|``.+?``|`[^`]+`", re.S | re.M)


def make_targets():
    text = (ROOT / "Makefile").read_text()
    names = set()
    for m in re.finditer(r"^([A-Za-z0-9_.-]+(?:[ \t]+[A-Za-z0-9_.-]+)*)[ \t]*::?(?!=)", text, re.M):
        names.update(n for n in m.group(1).split() if not n.startswith("."))
    for m in re.finditer(r"^\.PHONY[ \t]*:(.*)$", text, re.M):
        names.update(m.group(1).split())
    return names


def exists(path, base):
    """path (repository-relative, or relative to base for a link) exists, as a file,
    a folder or a glob that matches."""
    p = re.sub(r"<[^<>]*>", "*", path)
    if "<" in p or ">" in p:
        return True  # an unclosed placeholder: not a path
    full = (base / p) if not p.startswith("/") else pathlib.Path(p)
    if any(c in p for c in "*?["):
        return bool(glob.glob(str(full), recursive=True))
    return full.exists()


def check(doc, targets):
    rel = doc.relative_to(ROOT) if doc.is_relative_to(ROOT) else doc
    text = doc.read_text()
    line_of = lambda off: text.count("\n", 0, off) + 1
    bad = []
    for m in PATH.finditer(text):
        tok = m.group(1).split("#", 1)[0]
        tok = re.sub(r":\d[\d.:-]*$", "", tok)  # file:line
        tok = re.sub(r"[.,:;!?]+$", "", tok)
        if tok.startswith("build/") or not tok:
            continue
        if not exists(tok, ROOT):
            bad.append((line_of(m.start()), "path", tok))
    for m in BARE.finditer(text):
        if not exists(m.group(1), ROOT) and not exists(m.group(1), doc.parent):
            bad.append((line_of(m.start()), "path", m.group(1)))
    # A template ({{...}} placeholders: docs/datasheet/template.md) has its links relative
    # to the page a generator renders from it, which is checked itself.
    links = [] if re.search(r"\{\{[^{}\n]+\}\}", text) else LINK.finditer(text)
    for m in links:
        tok = m.group(1).split("#", 1)[0]
        if not tok or re.match(r"[a-z]+:", tok):
            continue  # an anchor in the same page, a URL
        if not exists(tok, doc.parent):
            bad.append((line_of(m.start()), "link", m.group(1)))
    for c in CODE.finditer(text):
        for m in MAKE.finditer(c.group(0)):
            if m.group(1) not in targets:
                bad.append((line_of(c.start() + m.start()), "make target", m.group(1)))
    return [f"{rel}:{ln}: {kind} {name} does not exist" for ln, kind, name in sorted(set(bad))]


def main(argv):
    if argv:
        docs = [pathlib.Path(a).resolve() for a in argv]
    else:
        docs = [ROOT / "README.md"] + sorted(p for p in (ROOT / "docs").rglob("*.md"))
    docs = [d for d in docs if d.name != "CHANGELOG.md"]
    targets = make_targets()
    problems = [p for d in docs for p in check(d, targets)]
    for p in problems:
        print(p)
    if problems:
        print(f"doc_check: {len(problems)} names in the docs that the tree does not have", file=sys.stderr)
        return 1
    print(f"doc_check: the paths and make targets of {len(docs)} docs exist")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
