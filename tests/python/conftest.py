# SPDX-License-Identifier: GPL-3.0-or-later
"""pytest configuration for the dfchaos Python module (tests/python).

Run by CTest (tests/CMakeLists.txt) with PYTHONPATH=build/python and DFCHAOS_CLI=build/bin/dfchaos,
one pytest run per tier:  -m unit, -m crossval (against the CLI), -m failure (bad input), -m timing.
By hand:  PYTHONPATH=build/python DFCHAOS_CLI=build/bin/dfchaos /usr/bin/python3 -m pytest -q tests/python
A test without a tier marker is a unit test.
"""
import os
import pathlib
import subprocess

import pytest

TIERS = {
    "unit": "known values, shapes and identities of single functions",
    "crossval": "the module against the dfchaos tool (build/bin/dfchaos): equal to the last bit",
    "failure": "bad input is rejected with the CLI's one-line message",
    "timing": "the cost of a vectorized call against the bare C++ loop (reported, not asserted)",
}


def pytest_configure(config):
    for name, text in TIERS.items():
        config.addinivalue_line("markers", f"{name}: {text}")


def pytest_collection_modifyitems(config, items):
    for item in items:
        if not any(item.get_closest_marker(t) for t in ("crossval", "failure", "timing")):
            item.add_marker(pytest.mark.unit)


class Cli:
    """The dfchaos tool: runs it and parses its tab-separated output."""

    def __init__(self, path):
        self.path = path

    def run(self, *args):
        r = subprocess.run([self.path, *map(str, args)], capture_output=True, text=True, timeout=300)
        return r.returncode, r.stdout, r.stderr

    def table(self, *args):
        """The rows of a successful call, as lists of strings, without the header; and the header.
        The '#' lines after the column line (provenance, settings) are checked and left out."""
        rc, out, err = self.run(*args)
        assert rc == 0, f"dfchaos {' '.join(map(str, args))} failed: {err}"
        lines = out.splitlines()
        assert lines[1].startswith("# dfchaos ") and lines[2].startswith("# dfchaos "), f"no provenance lines after the column line: {lines[:3]}"
        return lines[0].split("\t"), [l.split("\t") for l in lines[1:] if not l.startswith("#")]

    def error(self, *args):
        """The message of a refused call (the CLI prints 'dfchaos: error: <message>', exit 2)."""
        rc, out, err = self.run(*args)
        assert rc == 2 and out == "", f"dfchaos {' '.join(map(str, args))}: rc={rc}, stdout={out!r}"
        lines = err.splitlines()
        assert len(lines) == 1 and lines[0].startswith("dfchaos: error: "), err
        return lines[0][len("dfchaos: error: "):]


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("DFCHAOS_CLI")
    if not path:
        path = str(pathlib.Path(__file__).resolve().parents[2] / "build" / "bin" / "dfchaos")
    if not os.access(path, os.X_OK):
        pytest.fail(f"the dfchaos tool is not at {path}: set DFCHAOS_CLI (CTest does)")
    return Cli(path)
