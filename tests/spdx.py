#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every source, script and figure file carries the licence line in its first 3 lines.

The project is GPL-3.0-or-later (LICENSE). A file of a covered kind must have, in its first 3 lines,
the line `<comment> SPDX-License-Identifier: GPL-3.0-or-later` with the comment marker of its
language (after a shebang when there is one). Exempt kinds carry no such line:
  *.md                  prose (README, docs/): the README and LICENSE state the licence
  *.json, *.cff         metadata; JSON has no comments, and CITATION.cff states the licence in its
                        own `license` field
  .gitignore, LICENSE   a list of ignore patterns; the licence text itself
Any other kind of file fails the test, so that a new kind is classified here rather than slipping
through unchecked.

The files checked are those of `git ls-files` when SOURCE_DIR is a git checkout; otherwise (an
unpacked `make dist` archive) every file under it, except build directories (build, build-*) and
caches. The mode used is printed. Before the tree, the checker is run on a small made-up tree with a
missing line, a line below line 3 and a wrong licence, and must find exactly those: the test cannot
pass by finding nothing.

usage: spdx.py SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

TAG = "SPDX-License-Identifier: GPL-3.0-or-later"
HEAD_LINES = 3

C_LIKE = {".cpp", ".hpp", ".h"}
HASH = {".py", ".sh", ".gp", ".cmake", ".yml", ".yaml", ".toml"}
TEX = {".tex", ".sty"}
HASH_NAMES = {"CMakeLists.txt", "Makefile", "run", ".clang-format", ".clang-tidy"}  # run: .ci/run; .clang-* are YAML
EXEMPT_SUFFIXES = {".md", ".json", ".cff"}
EXEMPT_NAMES = {".gitignore", "LICENSE"}


def comment_marker(rel):
    """The comment marker of a covered file, "" for an exempt one, None for an unknown kind."""
    p = Path(rel)
    if p.name in EXEMPT_NAMES or p.suffix in EXEMPT_SUFFIXES:
        return ""
    if p.suffix in C_LIKE:
        return "//"
    if p.suffix in TEX:
        return "%"
    if p.suffix in HASH or p.name.endswith(".cmake.in") or (p.name in HASH_NAMES and (p.name != "run" or p.parent.name == ".ci")):
        return "#"
    return None


def listed_files(root):
    """(mode, relative paths): git ls-files in a git checkout, else a walk of the tree."""
    try:
        top = subprocess.run(["git", "-C", str(root), "rev-parse", "--show-toplevel"], capture_output=True, text=True)
        is_checkout = top.returncode == 0 and Path(top.stdout.strip()).resolve() == root.resolve()
    except FileNotFoundError:  # no git on this machine
        is_checkout = False
    if is_checkout:
        out = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True, check=True).stdout
        files = [f for f in out.decode().split("\0") if f and (root / f).is_file()]
        return "git ls-files", files
    files = []
    for d, dirs, names in os.walk(root):
        rel_d = Path(d).relative_to(root)
        dirs[:] = sorted(x for x in dirs if not (x.startswith(".") and x != ".ci") and x != "__pycache__"
                         and not (rel_d == Path(".") and (x == "build" or x.startswith("build-"))))
        files += [str(rel_d / n) for n in sorted(names) if not n.endswith((".swp", ".pyc"))]
    return "a walk of the tree: not a git checkout", files


def problems(root, files):
    found = []
    for rel in files:
        marker = comment_marker(rel)
        if marker is None:
            found.append(f"{rel}: a kind of file this test does not know: classify it in tests/spdx.py")
            continue
        if marker == "":
            continue
        with open(root / rel, encoding="utf-8", errors="replace") as f:
            head = [f.readline().strip() for _ in range(HEAD_LINES)]
        if f"{marker} {TAG}" not in head:
            found.append(f"{rel}: no '{marker} {TAG}' in its first {HEAD_LINES} lines")
    return found


def self_test():
    """The checker finds what it must on a made-up tree (walked, not a git checkout)."""
    cases = {
        "good.cpp": f"// {TAG}\nint x;\n",
        "good.sh": f"#!/bin/sh\n# {TAG}\necho\n",
        "doc.md": "# no licence line needed\n",
        "missing.hpp": "// a header without the line\n",
        "too_low.py": f'"""doc"""\n\n\n# {TAG}\n',
        "wrong.gp": "# SPDX-License-Identifier: MIT\n",
        "odd.xyz": "?\n",
    }
    with tempfile.TemporaryDirectory() as d:
        for name, text in cases.items():
            Path(d, name).write_text(text)
        mode, files = listed_files(Path(d))
        got = sorted(p.split(":")[0] for p in problems(Path(d), files))
    want = ["missing.hpp", "odd.xyz", "too_low.py", "wrong.gp"]
    if got != want:
        print(f"spdx: self-test: the checker flagged {got}, expected {want}", file=sys.stderr)
        sys.exit(1)


def main():
    if len(sys.argv) != 2 or not Path(sys.argv[1]).is_dir():
        print("usage: spdx.py SOURCE_DIR (an existing directory)", file=sys.stderr)
        sys.exit(2)
    self_test()
    root = Path(sys.argv[1])
    mode, files = listed_files(root)
    found = problems(root, files)
    for p in found:
        print("spdx: " + p, file=sys.stderr)
    if found:
        print(f"spdx: {len(found)} of {len(files)} files ({mode}) lack the licence line or are of an unknown kind",
              file=sys.stderr)
        sys.exit(1)
    covered = sum(1 for f in files if comment_marker(f))
    print(f"spdx: {covered} covered files of {len(files)} ({mode}) carry '{TAG}'; the others are exempt kinds")


if __name__ == "__main__":
    main()
