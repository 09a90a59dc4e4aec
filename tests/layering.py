#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The layers only point down: core <- certified, kit <- certify, sweep <- cli, python, experiments.

Three checks, each able to fail:
  1. includes: every quoted #include of a file in a lower layer resolves to a header of the same or a
     lower layer (core: src/dfchaos but its certified/ folder; certified: src/dfchaos/certified, the
     ball-arithmetic layer over the core; kit: src/kit; certify: src/certify; sweep: src/sweep; the
     tool: src/cli). A header is looked up as the compiler would: beside the including file, then in each
     layer's include directory.
  2. links: the direct link libraries of each library target (written by CMake at generate time into
     the file given as the second argument, one `target=lib;lib;...` a line), followed transitively,
     never reach a target of a higher or sibling layer; the Python module links no CLI library.
  3. the independent checker src/recheck (dfchaos-recheck) includes nothing of src/ outside its own
     folder (quoted or angle includes, looked up beside the file and in every layer's include
     directory) and links no library of the project.

usage: layering.py SOURCE_DIR LINKS_FILE
"""
import re
import sys
from pathlib import Path

# Layer of each source folder and its include directory (relative to src/), lowest first.
# (certified lies inside core's folder, dfchaos/certified: layer_of() tells it apart.)
LAYERS = {"core": "dfchaos", "certified": "dfchaos/certified", "kit": "kit", "certify": "certify", "sweep": "sweep", "cli": "cli"}
INCLUDE_DIRS = {"core": "", "kit": "kit", "certify": "certify", "sweep": "sweep", "cli": "cli"}
# What each layer may use (itself included).
ALLOWED = {
    "core": {"core"},
    "certified": {"core", "certified"},
    "kit": {"core", "kit"},
    "certify": {"core", "certified", "kit", "certify"},
    "sweep": {"core", "certified", "kit", "sweep"},
}
# The CMake targets of each layer, and what each may link (transitively) among the project's targets.
TARGET_LAYER = {
    "dfchaos": "core", "dfchaos_certified": "certified", "dfchaos_kit": "kit", "dfchaos_certify": "certify",
    "dfchaos_sweep": "sweep", "dfchaos_cli_core": "cli", "dfchaos_python": "python",
}
TARGET_ALLOWED = dict(ALLOWED, cli={"core", "certified", "kit", "certify", "sweep", "cli"},
                      python={"core", "certified", "kit", "certify", "sweep", "python"})

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def layer_of(path, src):
    rel = path.relative_to(src)
    if rel.parts[:2] == ("dfchaos", "certified"):
        return "certified"
    for layer, folder in LAYERS.items():
        if rel.parts[0] == folder:
            return layer
    return None


def resolve(name, including, src):
    """The file a quoted include names, looked up beside the including file, then in each include directory."""
    candidates = [including.parent / name] + [src / d / name for d in INCLUDE_DIRS.values()]
    for c in candidates:
        if c.is_file():
            return c.resolve()
    return None


def check_includes(src):
    problems = []
    for layer, folder in LAYERS.items():
        if layer not in ALLOWED:
            continue
        for f in sorted((src / folder).rglob("*")):
            if f.suffix not in (".hpp", ".cpp", ".h") or layer_of(f, src) != layer:
                continue  # (core's folder holds the certified layer's: each is checked as its own)
            for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = resolve(m.group(1), f, src)
                if target is None:
                    continue  # generated or third-party headers
                used = layer_of(target, src)
                if used is not None and used not in ALLOWED[layer]:
                    problems.append(f"{f.relative_to(src.parent)}:{n}: the {layer} layer includes "
                                    f"\"{m.group(1)}\" of the {used} layer")
    return problems


def check_links(links_file):
    direct = {}
    for line in Path(links_file).read_text().splitlines():
        if "=" in line:
            target, libs = line.split("=", 1)
            direct[target] = [lib for lib in libs.split(";") if lib]
    missing = [t for t in ("dfchaos", "dfchaos_kit", "dfchaos_certify", "dfchaos_sweep") if t not in direct]
    if missing:
        return [f"{links_file}: no link libraries written for {', '.join(missing)}"]
    problems = []
    for target, layer in TARGET_LAYER.items():
        if target not in direct:
            continue
        seen, todo = set(), list(direct[target])
        while todo:
            lib = todo.pop()
            name = lib.split("::")[-1] if lib.startswith("dfchaos::") else lib
            name = {"dfchaos": "dfchaos", "kit": "dfchaos_kit", "sweep": "dfchaos_sweep"}.get(name, name)
            if name in seen:
                continue
            seen.add(name)
            todo += direct.get(name, [])
            used = TARGET_LAYER.get(name)
            if used is not None and used not in TARGET_ALLOWED[layer]:
                problems.append(f"target {target} ({layer} layer) links {name} ({used} layer)")
    return problems


ANY_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]')
PROJECT_PREFIXES = ("dfchaos/", "kit/", "certify/", "sweep/", "cli/", "recheck/")


def check_recheck(src, links_file):
    """src/recheck shares no code with the prover: no include of src/ outside it, no project library."""
    folder = src / "recheck"
    problems = []
    files = [f for f in sorted(folder.rglob("*")) if f.suffix in (".hpp", ".cpp", ".h")]
    if not files:
        return [f"{folder}: no sources found"]
    for f in files:
        for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
            m = ANY_INCLUDE.match(line)
            if not m:
                continue
            target = resolve(m.group(1), f, src)
            outside = target is not None and folder.resolve() not in target.parents
            if outside or m.group(1).startswith(PROJECT_PREFIXES):
                problems.append(f"{f.relative_to(src.parent)}:{n}: the independent checker includes \"{m.group(1)}\" of the project")
    direct = {}
    for line in Path(links_file).read_text().splitlines():
        if "=" in line:
            target, libs = line.split("=", 1)
            direct[target] = [lib for lib in libs.split(";") if lib]
    if "dfchaos_recheck" not in direct:
        return problems + [f"{links_file}: no link libraries written for dfchaos_recheck"]
    for lib in direct["dfchaos_recheck"]:
        name = lib.split("::")[-1]
        if lib.startswith("dfchaos") or name in TARGET_LAYER or name in ("kit", "sweep", "certify", "certified"):
            problems.append(f"target dfchaos_recheck (the independent checker) links {lib} of the project")
    return problems


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    src = Path(sys.argv[1]).resolve() / "src"
    problems = check_includes(src) + check_links(sys.argv[2]) + check_recheck(src, sys.argv[2])
    for p in problems:
        print("FAIL:", p)
    if problems:
        return 1
    print("ok: includes of src/dfchaos, src/dfchaos/certified, src/kit, src/certify, src/sweep and the link libraries point down; "
          "src/recheck includes and links nothing of the project")
    return 0


if __name__ == "__main__":
    sys.exit(main())
