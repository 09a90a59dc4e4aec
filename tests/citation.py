#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""CITATION.cff and codemeta.json: valid, of the project's version, under its licence.

  CITATION.cff   valid YAML (Debian's python3-yaml); cff-version 1.2.0 with the fields the format
                 requires (message, title, authors); the authors are "The dfchaos developers";
                 version is the string VERSION (a bare 1.0 would be read as a number); license is
                 GPL-3.0-or-later; a reference names the paper by Begun and Kryzhevich with its
                 arXiv id.
  codemeta.json  valid JSON with a codemeta context; name dfchaos; version VERSION; license the
                 SPDX URL of GPL-3.0-or-later; every software requirement or suggestion is a
                 Debian package that scripts/install-deps.sh installs (so the two cannot drift).
VERSION is CMake's project version, passed by tests/CMakeLists.txt: the one place it is written.

usage: citation.py SOURCE_DIR VERSION
"""
import json
import re
import sys
from pathlib import Path

LICENSE = "GPL-3.0-or-later"
PAPER_TITLE = "One-dimensional chaos in a system with dry friction: analytical approach"
ARXIV = "1302.3377"


def cff_problems(path, version):
    try:
        import yaml
    except ImportError:
        return ["python3-yaml is not installed (scripts/install-deps.sh build installs it)"]
    try:
        cff = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as e:
        return [f"{path.name}: not readable as YAML: {' '.join(str(e).split())}"]
    if not isinstance(cff, dict):
        return [f"{path.name}: not a YAML mapping"]
    p = []
    if cff.get("cff-version") != "1.2.0":
        p.append(f"{path.name}: cff-version is {cff.get('cff-version')!r}, expected '1.2.0'")
    for key in ("message", "title", "authors"):
        if not cff.get(key):
            p.append(f"{path.name}: the required field {key} is missing or empty")
    if [a.get("name") for a in cff.get("authors") or [] if isinstance(a, dict)] != ["The dfchaos developers"]:
        p.append(f"{path.name}: authors must be the one entity 'The dfchaos developers'")
    if cff.get("version") != version:
        p.append(f"{path.name}: version is {cff.get('version')!r}, CMake's project version is {version!r}")
    if cff.get("license") != LICENSE:
        p.append(f"{path.name}: license is {cff.get('license')!r}, expected {LICENSE!r}")
    refs = list(cff.get("references") or []) + ([cff["preferred-citation"]] if cff.get("preferred-citation") else [])
    paper = [r for r in refs if isinstance(r, dict) and r.get("title") == PAPER_TITLE]
    if not paper:
        p.append(f"{path.name}: no reference or preferred-citation titled '{PAPER_TITLE}'")
    elif ARXIV not in json.dumps(paper[0]):
        p.append(f"{path.name}: the paper's entry does not give its arXiv id {ARXIV}")
    return p


def debian_packages(install_deps):
    """Every package named in the *_pkgs=( ... ) arrays of scripts/install-deps.sh."""
    text = install_deps.read_text(encoding="utf-8")
    names = set()
    for body in re.findall(r"^\w+_pkgs=\((.*?)\)", text, flags=re.S | re.M):
        names.update(body.split())
    return names


def codemeta_problems(path, version, packages):
    try:
        meta = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        return [f"{path.name}: not readable as JSON: {e}"]
    if not isinstance(meta, dict):
        return [f"{path.name}: not a JSON object"]
    p = []
    if "codemeta" not in json.dumps(meta.get("@context")):
        p.append(f"{path.name}: @context is not a codemeta context: {meta.get('@context')!r}")
    if meta.get("name") != "dfchaos":
        p.append(f"{path.name}: name is {meta.get('name')!r}, expected 'dfchaos'")
    if meta.get("version") != version:
        p.append(f"{path.name}: version is {meta.get('version')!r}, CMake's project version is {version!r}")
    if meta.get("license") != "https://spdx.org/licenses/" + LICENSE:
        p.append(f"{path.name}: license is {meta.get('license')!r}, expected https://spdx.org/licenses/{LICENSE}")
    reqs = list(meta.get("softwareRequirements") or []) + list(meta.get("softwareSuggestions") or [])
    if not meta.get("softwareRequirements"):
        p.append(f"{path.name}: softwareRequirements is missing or empty")
    unknown = [r for r in reqs if r not in packages]
    if unknown:
        p.append(f"{path.name}: requirements not installed by scripts/install-deps.sh: {', '.join(map(str, unknown))}")
    if ARXIV not in json.dumps(meta.get("referencePublication")):
        p.append(f"{path.name}: referencePublication does not give the paper's arXiv id {ARXIV}")
    return p


def main():
    if len(sys.argv) != 3 or not Path(sys.argv[1]).is_dir() or not re.fullmatch(r"\d+(\.\d+){0,3}", sys.argv[2]):
        print("usage: citation.py SOURCE_DIR VERSION (an existing directory, a version such as 1.2.3)", file=sys.stderr)
        sys.exit(2)
    root, version = Path(sys.argv[1]), sys.argv[2]
    packages = debian_packages(root / "scripts/install-deps.sh")
    if not packages:
        print("citation: no package lists found in scripts/install-deps.sh", file=sys.stderr)
        sys.exit(1)
    found = cff_problems(root / "CITATION.cff", version) + codemeta_problems(root / "codemeta.json", version, packages)
    for p in found:
        print("citation: " + p, file=sys.stderr)
    if found:
        sys.exit(1)
    print(f"citation: CITATION.cff and codemeta.json are valid, of version {version}, licensed {LICENSE}")


if __name__ == "__main__":
    main()
