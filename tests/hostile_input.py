#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Hostile input to the checker and the tool, CTest `hostile_input`
(label failure). The Python items (4, 6) are in tests/python/test_budgets.py, the certificate
mutations (3) in tests/recheck_certificates.py and tests/recheck_paper_construction.sh.

    hostile_input.py DFCHAOS DFCHAOS_RECHECK DOCS_DIR

Each check prints ok/FAIL; exit 1 if any failed.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

cli, checker, docs = (os.path.abspath(a) for a in sys.argv[1:4])
tmp = tempfile.mkdtemp(prefix="dfchaos-hostile-")
os.chdir(tmp)
fails = 0


def check(ok, what, detail=""):
    global fails
    print(("ok:   " if ok else "FAIL: ") + what + (f"  [{detail}]" if detail and not ok else ""), flush=True)
    if not ok:
        fails += 1


def run(args, timeout=60, **kw):
    return subprocess.run(args, capture_output=True, text=True, timeout=timeout, **kw)


def one_line_refusal(r, word):
    """exit 2, nothing on stdout, one line on stderr that names `word`."""
    lines = r.stderr.strip().splitlines()
    return r.returncode == 2 and r.stdout == "" and len(lines) == 1 and word in lines[0]


# A good certificate to mix with bad names.
r = run([cli, "certify", "vartheta0", "--certificate", "good.json"])
assert r.returncode == 0, r.stderr

# ---- 1. the checker: anything but a regular file is refused, the other files still checked ----------
r = run([checker, "good.json", "/tmp", "good.json"])
lines = r.stdout.splitlines()
check(r.returncode == 2 and len(lines) == 3 and lines[0].startswith("OK good.json:") and lines[2].startswith("OK good.json:")
      and lines[1].startswith("MALFORMED /tmp: is a directory"), "recheck good /tmp good: exit 2, three verdicts, the directory named",
      f"exit {r.returncode}: {r.stdout!r} {r.stderr!r}")
os.mkfifo("fifo")
try:
    r = run([checker, "fifo", "good.json"], timeout=20)
    lines = r.stdout.splitlines()
    check(r.returncode == 2 and len(lines) == 2 and lines[0].startswith("MALFORMED fifo: is a FIFO") and lines[1].startswith("OK good.json"),
          "recheck FIFO good: refused at once, not read (no writer needed), the next file checked", f"exit {r.returncode}: {r.stdout!r}")
except subprocess.TimeoutExpired:
    check(False, "recheck FIFO: blocked for 20 s")
r = run([checker, "/dev/null"])
check(r.returncode == 2 and "is a device" in r.stdout, "recheck /dev/null: a device, refused", r.stdout)
r = run([checker, "no-such-file.json"])
check(r.returncode == 2 and "cannot be opened: No such file" in r.stdout, "recheck a missing file: exit 2, says why", r.stdout)
os.symlink("/tmp", "link-to-dir")
r = run([checker, "link-to-dir"])
check(r.returncode == 2 and "is a directory" in r.stdout, "recheck a symlink to a directory: refused", r.stdout)
# A file over the checker's size limit: refused without being parsed.
with open("big.json", "wb") as f:
    f.truncate((256 << 20) + 1)
r = run([checker, "big.json"])
check(r.returncode == 2 and "larger than 256 MiB" in r.stdout, "recheck a 256 MiB + 1 byte file: refused by size", r.stdout)
os.remove("big.json")

# Each verdict is flushed as soon as it is decided: the first line arrives while the checker is still
# reading a second, large file (about 200 MB of blanks, then not JSON).
with open("slow.json", "w") as f:
    f.write(" " * (200 << 20) + "x")
p = subprocess.Popen([checker, "good.json", "slow.json"], stdout=subprocess.PIPE, text=True)
first = p.stdout.readline()
running = p.poll() is None
rest = p.stdout.read()
p.wait()
check(first.startswith("OK good.json") and running, "the first verdict is written before the next file is read",
      f"first {first!r}, still running {running}")
check(p.returncode == 2 and rest.startswith("MALFORMED slow.json: not JSON"), "the large file: not JSON", rest[:200])
os.remove("slow.json")

# ---- 2. usage, version, names ------------------------------------------------------------------------
r = run([checker, "--help"])
check(r.returncode == 0 and r.stdout.startswith("usage: dfchaos-recheck") and "Exit status" in r.stdout and r.stderr == "",
      "recheck --help: usage on stdout, exit 0", r.stdout[:200])
r = run([checker, "--version"])
check(r.returncode == 0 and r.stdout.startswith("dfchaos-recheck ") and "MPFI" in r.stdout, "recheck --version", r.stdout)
for flag in ("--help", "-h", "--version"):  # exit 0 means "every file verified": never with files beside it
    r = run([checker, "good.json", "missing.json", flag])
    check(one_line_refusal(r, flag), f"recheck FILES {flag}: exit 2, nothing checked, one line", r.stderr + r.stdout)
r = run([checker, "--frobnicate", "good.json"])
check(one_line_refusal(r, "--frobnicate"), "recheck an unknown option: exit 2, one line naming it", r.stderr)
r = run([checker])
check(one_line_refusal(r, "no FILE"), "recheck without a file: exit 2, one line", r.stderr)
shutil.copy("good.json", "-dash.json")
r = run([checker, "--", "-dash.json"])
check(r.returncode == 0 and r.stdout.startswith("OK -dash.json:"), "recheck -- -dash.json: a file after --", r.stdout)
weird = "two\nlines \"q\".json"
shutil.copy("good.json", weird)
r = run([checker, weird, "good.json"])
lines = r.stdout.splitlines()
check(r.returncode == 0 and len(lines) == 2 and lines[0].startswith('OK "two\\nlines \\"q\\".json": vartheta0'),
      "a name with a newline and quotes: quoted with C escapes, one line per file", repr(r.stdout))

# ---- 5. sweep: a cell outside the model's range is refused up front, not answered by error rows ------
r = run([cli, "sweep", "--a", "1e-90", "--q-range", "0.85", "--b-range", "1e-12:1e-11:2:log", "--observables", "covering"])
check(one_line_refusal(r, "b-range"), "sweep --a 1e-90 at b/a 1e-12: refused (b-range), no rows", r.stderr)
r = run([cli, "sweep", "--a", "1.5e-100", "--q-range", "0.85", "--b-range", "1e-3", "--observables", "covering"])
check(one_line_refusal(r, "range"), "sweep --a 1.5e-100 at b/a 1e-3: refused, no rows", r.stderr)
r = run([cli, "sweep", "--a", "1e-95", "--q-range", "0.85", "--b-range", "1e-3", "--observables", "covering"])
rows = [l for l in r.stdout.splitlines()[1:] if not l.startswith("#")]
check(r.returncode == 0 and len(rows) == 1 and "\tok\t" in rows[0], "sweep --a 1e-95 at b/a 1e-3 (b = 1e-98): computed", r.stderr + r.stdout[-300:])
r = run([cli, "sweep", "--help"])
with open(os.path.join(docs, "cluster.md"), encoding="utf-8") as f:
    cluster = f.read()
check("1e-100 <= a <= 1e+100" in r.stdout or "1e-100 <= a <= 1e100" in r.stdout, "sweep --help states 1e-100 <= a <= 1e100",
      [l for l in r.stdout.splitlines() if "--a" in l])
check("10⁻¹⁰⁰ ≤ a ≤ 10¹⁰⁰" in cluster and "10⁻¹⁵⁰" not in cluster, "docs/cluster.md states the same range of a")

# ---- 7. messages of --certificate ---------------------------------------------------------------------
# A relative name in a directory where nothing can be created (/proc, even for root): the message names
# the relative file, not a file at the root.
r = run([cli, "certify", "vartheta0", "--certificate", "rel.json"], cwd="/proc")
check(one_line_refusal(r, "rel.json") and " /rel.json" not in r.stderr and "current directory" in r.stderr,
      "--certificate rel.json where nothing can be created: names rel.json in the current directory", r.stderr)
# /dev/stdout on a pipe: a pipe is not a file (formerly /proc/self/fd/pipe:[N].tmp)
r = run([cli, "certify", "vartheta0", "--certificate", "/dev/stdout"])
check(one_line_refusal(r, "pipe") and "/proc/self" not in r.stderr and "pipe:[" not in r.stderr,
      "--certificate /dev/stdout into a pipe: 'a pipe or FIFO, not a file'", r.stderr)

# ---- 8. the proofs of a certified or region sweep are bounded before any work ------------------------
big = ["--q-range", "0.8:0.9:10000", "--b-range", "1e-3:1e-2:10000:log"]
for obs in ("region", "certified", "covering,certified"):
    t = time.monotonic()
    r = run([cli, "sweep", *big, "--observables", obs])
    check(one_line_refusal(r, "max-proofs") and "--max-proofs" in r.stderr and time.monotonic() - t < 10,
          f"sweep of 1e4 x 1e4 cells with {obs}: refused at once, naming --max-proofs", r.stderr)
small = ["--q-range", "0.85", "--b-range", "1e-3:2e-3:2:log", "--observables", "certified"]
r = run([cli, "sweep", *small, "--max-proofs", "1"])
check(one_line_refusal(r, "max-proofs"), "2 certified cells with --max-proofs 1: refused", r.stderr)
r = run([cli, "sweep", *small, "--max-proofs", "2"], timeout=300)
check(r.returncode == 0, "2 certified cells with --max-proofs 2: computed", r.stderr)
r = run([cli, "sweep", *small, "--max-proofs", "0"])
check(one_line_refusal(r, "max-proofs"), "--max-proofs 0: refused", r.stderr)

shutil.rmtree(tmp, ignore_errors=True)
print(f"{fails} failed" if fails else "all passed")
sys.exit(1 if fails else 0)
