# SPDX-License-Identifier: GPL-3.0-or-later
"""What the sweep tests share (sweep_certified.py, sweep_region.py): one ok/FAIL line per check, the
tool run with its output returned, and its output read back with the column names."""
import subprocess
import sys


class Checks:
    """Counts checks and failures; each check prints one line."""

    def __init__(self, cli):
        self.cli = cli
        self.fails = 0
        self.count = 0

    def check(self, ok, what):
        self.count += 1
        print(("ok:   " if ok else "FAIL: ") + what)
        if not ok:
            self.fails += 1

    def sweep(self, *args):
        """stdout of `dfchaos sweep ARGS`; a failed run ends the test (exit 1)."""
        r = subprocess.run([self.cli, "sweep", *args], capture_output=True, text=True)
        if r.returncode != 0:
            print(f"FAIL: dfchaos sweep {' '.join(args)}: exit {r.returncode}: {r.stderr[:300]}")
            sys.exit(1)
        return r.stdout

    def finish(self):
        """Prints the totals and exits 1 if any check failed."""
        print(f"{self.count - self.fails} passed, {self.fails} failed")
        sys.exit(1 if self.fails else 0)


def parse(text):
    """(header comment lines, column names, rows as dicts) of a sweep output."""
    comments, rows, columns = [], [], None
    for line in text.splitlines():
        if line.startswith("#"):
            comments.append(line)
        elif columns is None:
            columns = line.split("\t")
        else:
            rows.append(dict(zip(columns, line.split("\t"))))
    return comments, columns, rows
