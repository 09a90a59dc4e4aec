#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Reliability of the tool's files, signals and budgets (docs/reliability.md), CTest `reliability` (label failure).

    reliability.py DFCHAOS [--sanitized] [--experiment EXPERIMENT]

Part 1 runs one regression check per case of the contract in docs/reliability.md.
Part 2 is the harness over files and processes, with the counts it printed:
  - a sweep file cut at every byte offset, then --resume: refused (exit 2, file untouched) or finished
    byte-identical to the full run; never "complete" with other bytes;
  - one byte changed at every offset of a shard file (sweep-merge), of a finished file (--resume)
    and of a checkpoint chunk (--resume): refused, never a changed row accepted;
  - SIGINT, SIGTERM, SIGHUP at random instants during --out and --resume runs: no temporary left,
    the output absent or whole (and after --resume, byte-identical once finished);
  - a full disk (a small tmpfs when this process may mount one, else /dev/full for stdout);
  - concurrent writers of one --out file and of one --resume file.
Every check prints ok/FAIL; exit 1 if any failed. With --sanitized (AddressSanitizer build) the memory
budget is not enforced by the tool, so its check is skipped (said so). --experiment names one built
experiment executable, whose stdout must be checked as the tool's is.
"""
import hashlib
import resource
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

cli = os.path.abspath(sys.argv[1])
sanitized = "--sanitized" in sys.argv[2:]
experiment = os.path.abspath(sys.argv[sys.argv.index("--experiment") + 1]) if "--experiment" in sys.argv else None
if experiment and not os.path.exists(experiment):
    print(f"skip: the experiment's stdout check ({experiment} not built)")
    experiment = None
tmp = tempfile.mkdtemp(prefix="dfchaos-reliability-")
os.chdir(tmp)
fails = 0
checks = 0
rng = random.Random(28)  # seeded: the same offsets and instants at every run
# Every byte offset; every 5th under the sanitizers (each run is several times slower there).
stride = 5 if sanitized else 1

S = ["--q-range", "0.8:0.9:2", "--b-range", "1e-3:1e-2:2:log", "--observables", "covering"]
# A sweep that lasts about a second, for signals and concurrency.
K = ["--q-range", "0.6:0.98:8", "--b-range", "2e-3:0.45:8:log", "--transient", "2000", "--steps", "2000"]


def check(ok, what):
    global fails, checks
    checks += 1
    print(("ok:   " if ok else "FAIL: ") + what, flush=True)
    if not ok:
        fails += 1


def run(*args, stdin=None, timeout=120, **kw):
    return subprocess.run([cli, *args], capture_output=True, timeout=timeout, stdin=stdin, **kw)


def one_line_error(r, rc, needle):
    err = r.stderr.decode(errors="replace")
    return r.returncode == rc and err.count("\n") == 1 and needle in err


def read(path):
    with open(path, "rb") as f:
        return f.read()


def write(path, data):
    with open(path, "wb") as f:
        f.write(data)


def leftovers(prefix):
    return [n for n in os.listdir(".") if n.startswith(prefix) and ".tmp." in n]


def resealed(data):
    """The file with its seal recomputed over its (changed) body: what a forger, not damage, makes."""
    body = data[: data.rindex(b"# end: ")]
    rows = int(data[data.rindex(b"# end: ") + 7:].split(b" ")[0])
    return body + b"# end: %d rows, sha256 %s (of every byte above this line)\n" % (rows, hashlib.sha256(body).hexdigest().encode())


def limited(resource_id, limit):
    return lambda: resource.setrlimit(resource_id, (limit, limit))


def changed_byte(b):
    return (b + 1) % 256 if b != 0x0A else 0x0B  # any other byte; a newline becomes a vertical tab


# ---- reference outputs -------------------------------------------------------------------------------
r = run("sweep", *S, "--out", "full.tsv")
check(r.returncode == 0, "the small sweep runs")
full = read("full.tsv")
check(full.endswith(b"\n") and b"\n# end: 4 rows, sha256 " in full, "a sweep file ends in its seal")
for i in range(3):
    run("sweep", *S, "--shard", f"{i}/3", "--out", f"s{i}.tsv")
shards = [read(f"s{i}.tsv") for i in range(3)]
r = run("sweep-merge", "s0.tsv", "s1.tsv", "s2.tsv")
check(r.returncode == 0 and r.stdout == full, "3 shards merge into the unsharded bytes")
kfull = run("sweep", *K).stdout

# ---- part 1: the cases of the contract (docs/reliability.md) ----------------------------------------
# 1. A truncated file, a header-only file, a header with garbage rows: never "already complete".
header = full[: full.index(b"\n0\t") + 1]
for name, data in [("truncated by two lines", b"\n".join(full.split(b"\n")[:-3]) + b"\n"), ("header only", header),
                   ("header and garbage rows", header + b"0\tx\ty\n1\tz\n")]:
    write("cut.tsv", data)
    r = run("sweep", *S, "--resume", "cut.tsv")
    check(one_line_error(r, 2, "no seal") and read("cut.tsv") == data, f"28.1 resume of a file {name}: refused (no seal), exit 2")
# 2. One changed value in a shard; a checkpoint chunk with ok -> XX.
for what, old, new in [("covering 1 -> 7", b"\tok\t1\t", b"\tok\t7\t"), ("a q_over_a digit", b"\t0.8000", b"\t0.8001"),
                       ("a status word", b"\tok\t", b"\tXX\t"), ("a NUL byte", b"\tok\t", b"\to\0\t")]:
    i = next(k for k in range(3) if old in shards[k])
    write("bad.tsv", shards[i].replace(old, new, 1))
    files = [f"s{k}.tsv" if k != i else "bad.tsv" for k in range(3)]
    r = run("sweep-merge", *files)
    check(one_line_error(r, 2, "damaged") and r.stdout == b"", f"28.2 sweep-merge of a shard with {what}: refused (damaged)")
    # The same change with the seal recomputed (a forgery, not damage): the field checks refuse it.
    write("bad.tsv", resealed(shards[i].replace(old, new, 1)))
    r = run("sweep-merge", *files)
    check(one_line_error(r, 2, "not a valid row") and r.stdout == b"", f"28.2 {what} with the seal recomputed: sweep-merge refuses the row")
write("forged.tsv", resealed(full.replace(b"\tok\t1\t", b"\tok\t7\t", 1)))
r = run("sweep", *S, "--resume", "forged.tsv")
check(one_line_error(r, 2, "not a valid row"), "28.2 a finished file with covering 7 and its seal recomputed: --resume refuses the row")
shutil.rmtree("ck.tsv.chunks", ignore_errors=True)
r = run("sweep", *S, "--resume", "ck.tsv", "--chunk", "2", "--max-chunks", "1")
chunk = os.path.join("ck.tsv.chunks", "chunk-000000000000-000000000002.tsv")
check(r.returncode == 3 and os.path.exists(chunk), "a run stopped by --max-chunks keeps its chunk")
good_chunk = read(chunk)
write(chunk, good_chunk.replace(b"\tok\t", b"\tXX\t", 1))
r = run("sweep", *S, "--resume", "ck.tsv")
check(one_line_error(r, 2, "damaged") and not os.path.exists("ck.tsv"), "28.2 a chunk with ok -> XX: resume refuses it")
write(chunk, resealed(good_chunk.replace(b"\tok\t", b"\tXX\t", 1)))
r = run("sweep", *S, "--resume", "ck.tsv")
check(one_line_error(r, 2, "not a valid row") and not os.path.exists("ck.tsv"), "28.2 a chunk with ok -> XX and its seal recomputed: refused")
# A chunk of another run (another q-range) put among this run's chunks.
S_other = ["--q-range", "0.5:0.6:2"] + S[2:]
run("sweep", *S_other, "--resume", "other.tsv", "--chunk", "2", "--max-chunks", "1")
shutil.copy(os.path.join("other.tsv.chunks", "chunk-000000000000-000000000002.tsv"), chunk)
r = run("sweep", *S, "--resume", "ck.tsv")
check(one_line_error(r, 2, "another run") and not os.path.exists("ck.tsv"), "28.2 a chunk of another run: refused")
write(chunk, good_chunk)
r = run("sweep", *S, "--resume", "ck.tsv")
check(r.returncode == 0 and read("ck.tsv") == full, "the chunk restored: resume finishes byte-identical")
# FIFOs as inputs: refused at once, never waited on.
os.mkfifo("in.fifo")
for what, args in [("--resume of a FIFO", ["sweep", *S, "--resume", "in.fifo"]), ("sweep-merge of a FIFO", ["sweep-merge", "s0.tsv", "in.fifo", "s2.tsv"])]:
    try:
        r = run(*args, timeout=20)
        check(one_line_error(r, 2, "not a regular file"), f"28.3 {what}: refused at once")
    except subprocess.TimeoutExpired:
        check(False, f"28.3 {what}: hangs")
shutil.rmtree("ck.tsv.chunks", ignore_errors=True)
os.remove("ck.tsv")
run("sweep", *S, "--resume", "ck.tsv", "--chunk", "2", "--max-chunks", "1")
os.mkfifo(os.path.join("ck.tsv.chunks", "chunk-000000000002-000000000004.tsv"))
try:
    r = run("sweep", *S, "--resume", "ck.tsv", timeout=20)
    check(one_line_error(r, 2, "not a regular file"), "28.3 a FIFO among the chunks: refused at once")
except subprocess.TimeoutExpired:
    check(False, "28.3 a FIFO among the chunks: hangs")
# 3. --out: a device, a FIFO and a directory are refused and left as they were; a symlink is written through.
os.mkfifo("fifo")
r = run("sweep", *S, "--out", "fifo")
check(one_line_error(r, 2, "FIFO") and os.path.exists("fifo") and not os.path.isfile("fifo"), "28.3 --out a FIFO: refused, still a FIFO")
os.mkdir("dir")
r = run("sweep", *S, "--out", "dir")
check(one_line_error(r, 2, "directory") and os.path.isdir("dir"), "28.3 --out a directory: refused")
try:
    os.mknod("nulldev", 0o666 | 0o020000, os.makedev(1, 3))
    r = run("sweep", *S, "--out", "nulldev")
    check(one_line_error(r, 2, "device") and not os.path.isfile("nulldev"), "28.3 --out a device node: refused, still a device")
    r = run("sweep-merge", "s0.tsv", "s1.tsv", "s2.tsv", "--out", "nulldev")
    check(one_line_error(r, 2, "device") and not os.path.isfile("nulldev"), "28.3 sweep-merge --out a device node: refused")
except PermissionError:
    print("skip: 28.3 --out a device node (mknod is not permitted here)")
os.symlink("target.tsv", "link.tsv")
r = run("sweep", *S, "--out", "link.tsv")
check(r.returncode == 0 and os.path.islink("link.tsv") and read("target.tsv") == full, "28.3 --out a symlink: written through, the link kept")
r = run("sweep-merge", "s0.tsv", "s1.tsv", "s2.tsv", "--out", "link.tsv")
check(r.returncode == 0 and os.path.islink("link.tsv") and read("target.tsv") == full, "28.3 sweep-merge --out a symlink: written through")
# A file-size limit (ulimit -f): a failed write, not a death by SIGXFSZ that leaves the temporary.
r = run("sweep", "--q-range", "0.8:0.9:10", "--b-range", "1e-3:1e-2:10:log", "--observables", "covering", "--out", "fsize.tsv",
        preexec_fn=limited(resource.RLIMIT_FSIZE, 1024))
check(r.returncode == 1 and r.stderr.count(b"\n") == 1 and not os.path.exists("fsize.tsv") and not leftovers("fsize.tsv"),
      "28.4 a file-size limit under --out: exit 1, one line, no temporary left")
# 5. A write failure is never a success: /dev/full and a closed stdout.
with open("/dev/full", "wb") as devfull:
    for args in [["certify", "vartheta0"], ["certify", "covering", "--b", "0.001", "--q", "0.85"], ["--help"], ["--version"],
                 ["info", "--a", "1", "--b", "0.01", "--q", "0.85"], ["sweep", *S]]:
        r = subprocess.run([cli, *args], stdout=devfull, stderr=subprocess.PIPE, timeout=120)
        check(r.returncode == 1 and r.stderr.decode().count("\n") == 1 and b"cannot write" in r.stderr,
              f"28.5 dfchaos {' '.join(args[:2])} > /dev/full: exit 1, one line")
if experiment:
    with open("/dev/full", "wb") as devfull:
        r = subprocess.run([experiment, "--describe"], stdout=devfull, stderr=subprocess.PIPE, timeout=60)
    check(r.returncode == 1 and b"cannot write" in r.stderr, f"28.5 {os.path.basename(experiment)} --describe > /dev/full: exit 1")
for args in [["certify", "vartheta0"], ["--version"]]:
    r = subprocess.run([cli, *args], stderr=subprocess.PIPE, timeout=60, preexec_fn=lambda: os.close(1))
    check(r.returncode == 1 and b"cannot write" in r.stderr, f"28.5 dfchaos {args[0]} with stdout closed: exit 1")
# 6. Work without bound: a time budget, a memory budget, a covering budget per sweep cell.
t = time.monotonic()
# (Lemma 2 on L0 at b/a = 1e-9: some 1e8 discontinuities to prove, so time and memory grow with
# the work; a covering proof no longer does at small b/a, bench_certified.)
r = run("certify", "discontinuities", "--a", "1", "--b", "1e-9", "--max-seconds", "2")
dt = time.monotonic() - t
check(one_line_error(r, 1, "time budget of 2 s") and r.stdout == b"" and dt < 10,
      f"28.6 certify discontinuities at b/a = 1e-9 with --max-seconds 2: gave up after {dt:.1f} s, exit 1, one line")
if sanitized:
    print("skip: 28.6 the memory budget (not enforced under AddressSanitizer)")
else:
    # (--max-seconds 600: the memory budget runs out after some 40 s alone, later on a busy machine,
    # and must be what ends the run, not the default time budget of 60 s)
    r = run("certify", "discontinuities", "--a", "1", "--b", "1e-9", "--max-memory", "0.25", "--max-seconds", "600", timeout=700)
    check(one_line_error(r, 1, "memory budget of 0.25 GiB") and r.stdout == b"",
          "28.6 certify discontinuities at b/a = 1e-9 with --max-memory 0.25: gave up, exit 1, one line")
    # (--max-seconds 600 here too: on a busy machine the default time budget of 60 s could end the run
    # before the address space runs out. 96 MiB: the run starts with some 45 MiB mapped and grows by
    # about 2.5 MiB/s, so the limit is reached in some 20 s rather than the 45 s of 256 MiB.)
    r = run("certify", "discontinuities", "--a", "1", "--b", "1e-9", "--max-seconds", "600", timeout=700,
            preexec_fn=limited(resource.RLIMIT_AS, 96 << 20))
    check(one_line_error(r, 1, "set outside dfchaos") and r.stdout == b"", "28.6 under a lower ulimit -v: the give-up line names that limit")
    # Memory running out in a sweep cell ends the run (exit 1), never a sealed 'error' cell.
    r = run("sweep", "--q-range", "0.85:0.85:1", "--b-range", "1e-8:1e-8:1", "--observables", "covering", "--max-branches", "100000000",
            "--out", "oom.tsv", preexec_fn=limited(resource.RLIMIT_AS, 300 << 20))
    check(one_line_error(r, 1, "out of memory") and not os.path.exists("oom.tsv") and not leftovers("oom.tsv"),
          "28.6 memory running out in a sweep cell: exit 1, one line, no file (not an error cell)")
for opt, val in [("--max-seconds", "0"), ("--max-seconds", "nan"), ("--max-memory", "0.1"), ("--max-memory", "x")]:
    r = run("certify", "vartheta0", opt, val)
    check(one_line_error(r, 2, opt[2:]), f"bad budget {opt} {val}: exit 2")
t = time.monotonic()
r = run("sweep", "--q-range", "0.85:0.85:1", "--b-range", "1e-8:1e-8:1", "--observables", "covering")
dt = time.monotonic() - t
row = [l for l in r.stdout.decode().split("\n") if l.startswith("0\t")]
check(r.returncode == 0 and len(row) == 1 and "\terror\t" in row[0] and "max_branches" in row[0] and dt < 10,
      f"28.6 a covering cell at b/a = 1e-8: an error cell naming its budget after {dt:.1f} s")
r = run("sweep", "--q-range", "0.8:0.9:2", "--b-range", "1e-13:1e-12:2:log", "--observables", "covering")
check(one_line_error(r, 2, "b-range"), "28.6/28.8 b/a below the 1e-12 floor: refused up front")
# 8. a outside the model's range; info names the floor.
r = run("sweep", "--a", "1e-150", *S)
check(one_line_error(r, 2, "a:"), "28.8 sweep --a 1e-150: refused (the model's range)")
r = run("info", "--a", "1", "--b", "1e-13", "--q", "0.85")
check(r.returncode == 0 and b"return_map\tnot computed" in r.stdout and b"1e-12" in r.stdout, "28.8 info at b/a = 1e-13 names the floor")
# 11. Smaller ones.
r = run("sweep", *S, "--out", "x" * 300)
check(one_line_error(r, 2, "out"), "28.11 a 300-character --out name: exit 2")
r = run("sweep", "--q-range", "1e-320:1e-320:1", "--b-range", "1e-3:1e-3:1")
check(one_line_error(r, 2, "q-range"), "28.11 a subnormal q-range is blamed on q-range")
r = run("sweep", "--q-range", "0.8\n:0.9:3", "--b-range", "1e-3:1e-3:1")
check(r.returncode == 2 and r.stderr.count(b"\n") == 1, "28.11 a newline inside a value: the error stays one line")
r = subprocess.run(["bash", "-c", f'"{cli}" sweep-merge <(cat s0.tsv) s1.tsv s2.tsv'], capture_output=True, timeout=60)
check(one_line_error(r, 2, "not a regular file"), "28.11 sweep-merge of a pipe: 'not a regular file', not 'cut short'")

# ---- part 2: the harness -----------------------------------------------------------------------------
# Truncation at every byte offset of a finished file, then --resume.
counts = {"refused": 0, "finished": 0, "accepted-wrong": 0}
for k in range(0, len(full), stride):
    write("cut.tsv", full[:k])
    r = run("sweep", *S, "--resume", "cut.tsv")
    now = read("cut.tsv") if os.path.exists("cut.tsv") else None
    if r.returncode == 2 and now == full[:k] and not os.path.exists("cut.tsv.chunks"):
        counts["refused"] += 1
    elif r.returncode == 0 and now == full:
        counts["finished"] += 1
    else:
        counts["accepted-wrong"] += 1
        print(f"  offset {k}: exit {r.returncode}, {r.stderr[:200]!r}")
    shutil.rmtree("cut.tsv.chunks", ignore_errors=True)
check(counts["accepted-wrong"] == 0, f"truncation at each of {len(range(0, len(full), stride))} offsets, then --resume: {counts}")

# One changed byte at every offset: sweep-merge of a shard, --resume of a finished file.
merge_refused = resume_refused = wrong = 0
for k in range(0, len(shards[1]), stride):
    bad = bytearray(shards[1])
    bad[k] = changed_byte(bad[k])
    write("bad.tsv", bytes(bad))
    r = run("sweep-merge", "s0.tsv", "bad.tsv", "s2.tsv")
    if r.returncode == 2 and r.stdout == b"":
        merge_refused += 1
    else:
        wrong += 1
        print(f"  merge, offset {k}: exit {r.returncode}")
check(wrong == 0, f"one changed byte at each of {len(range(0, len(shards[1]), stride))} offsets of a shard: sweep-merge refused {merge_refused}, accepted {wrong}")
wrong = 0
for k in range(0, len(full), stride):
    bad = bytearray(full)
    bad[k] = changed_byte(bad[k])
    write("flip.tsv", bytes(bad))
    r = run("sweep", *S, "--resume", "flip.tsv")
    if r.returncode == 2 and read("flip.tsv") == bytes(bad):
        resume_refused += 1
    else:
        wrong += 1
        print(f"  resume, offset {k}: exit {r.returncode}")
    shutil.rmtree("flip.tsv.chunks", ignore_errors=True)
check(wrong == 0, f"one changed byte at each of {len(range(0, len(full), stride))} offsets of a finished file: --resume refused {resume_refused}, accepted {wrong}")

# A checkpoint chunk cut at every offset and changed at every offset: refused or finished identically.
# The stopped run's directory is made once and copied before each trial (the run is deterministic, so
# a fresh run would write the same bytes; the copy halves the processes started).
shutil.rmtree("h0.tsv.chunks", ignore_errors=True)
run("sweep", *S, "--resume", "h0.tsv", "--chunk", "2", "--max-chunks", "1")
check(not os.path.exists("h0.tsv") and read(os.path.join("h0.tsv.chunks", "chunk-000000000000-000000000002.tsv")) == good_chunk,
      "a run stopped after one chunk leaves that chunk (the harness's starting point)")
outcomes = {"refused": 0, "finished": 0, "accepted-wrong": 0}
for mode in ("cut", "flip"):
    for k in range(0, len(good_chunk), stride):
        shutil.rmtree("h.tsv.chunks", ignore_errors=True)
        if os.path.exists("h.tsv"):
            os.remove("h.tsv")
        shutil.copytree("h0.tsv.chunks", "h.tsv.chunks")
        path = os.path.join("h.tsv.chunks", "chunk-000000000000-000000000002.tsv")
        data = bytearray(read(path))
        if mode == "cut":
            data = data[:k]
        else:
            data[k] = changed_byte(data[k])
        write(path, bytes(data))
        r = run("sweep", *S, "--resume", "h.tsv")
        if r.returncode == 2 and not os.path.exists("h.tsv"):
            outcomes["refused"] += 1
        elif r.returncode == 0 and read("h.tsv") == full:
            outcomes["finished"] += 1
        else:
            outcomes["accepted-wrong"] += 1
            print(f"  chunk {mode} at {k}: exit {r.returncode}")
check(outcomes["accepted-wrong"] == 0, f"a checkpoint chunk cut and changed at each of {len(range(0, len(good_chunk), stride))} offsets, then --resume: {outcomes}")

# Signals at random instants.
sig_counts = {"killed": 0, "finished": 0, "bad": 0}
for trial in range(12):
    sig = [signal.SIGINT, signal.SIGTERM, signal.SIGHUP][trial % 3]
    for stale in ["sig.tsv"] + leftovers("sig.tsv"):
        if os.path.exists(stale):
            os.remove(stale)
    p = subprocess.Popen([cli, "sweep", *K, "--out", "sig.tsv"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(rng.uniform(0.02, 0.6))
    p.send_signal(sig)
    rc = p.wait(timeout=120)
    left = leftovers("sig.tsv")
    whole = not os.path.exists("sig.tsv") or read("sig.tsv") == kfull
    if left or not whole:
        sig_counts["bad"] += 1
        print(f"  {signal.Signals(sig).name}: exit {rc}, left {left}, output whole: {whole}")
    elif rc == -sig:
        sig_counts["killed"] += 1
    else:
        sig_counts["finished"] += 1
check(sig_counts["bad"] == 0 and sig_counts["killed"] > 0, f"SIGINT/SIGTERM/SIGHUP at random instants during --out: {sig_counts}")
interrupted = 0
shutil.rmtree("rs.tsv.chunks", ignore_errors=True)
for trial in range(8):
    p = subprocess.Popen([cli, "sweep", *K, "--resume", "rs.tsv", "--chunk", "1"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(rng.uniform(0.05, 0.4))
    p.send_signal([signal.SIGINT, signal.SIGTERM][trial % 2])
    if p.wait(timeout=120) < 0:
        interrupted += 1
    if os.path.isdir("rs.tsv.chunks") and any(".tmp." in n for n in os.listdir("rs.tsv.chunks")):
        check(False, "a signalled --resume run left a chunk temporary")
r = run("sweep", *K, "--resume", "rs.tsv")
check(r.returncode == 0 and read("rs.tsv") == kfull and interrupted > 0,
      f"--resume interrupted {interrupted} times by signals, then finished: byte-identical")

# A full disk.
os.mkdir("small")
mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=4k", "tmpfs", "small"], capture_output=True).returncode == 0
if mounted:
    try:
        r = run("sweep", *K, "--out", "small/out.tsv")
        check(r.returncode == 1 and r.stderr.count(b"\n") == 1 and os.listdir("small") == [],
              "a full disk (4 kB tmpfs) under --out: exit 1, one line, nothing left")
        r = run("sweep", *K, "--resume", "small/res.tsv", "--chunk", "4")
        check(r.returncode == 1 and r.stderr.count(b"\n") == 1 and not os.path.exists("small/res.tsv"),
              "a full disk under --resume: exit 1, one line, no output file")
    finally:
        subprocess.run(["umount", "small"])
else:
    print("skip: a full tmpfs (mount is not permitted here); /dev/full below")
with open("/dev/full", "wb") as devfull:
    r = subprocess.run([cli, "sweep", *K], stdout=devfull, stderr=subprocess.PIPE, timeout=120)
check(r.returncode == 1 and r.stderr.count(b"\n") == 1, "a full device as stdout of a sweep: exit 1, one line")

# Concurrent writers.
ps = [subprocess.Popen([cli, "sweep", *K, "--out", "conc.tsv"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE) for _ in range(2)]
rcs = [p.wait(timeout=300) for p in ps]
check(rcs == [0, 0] and read("conc.tsv") == kfull and not leftovers("conc.tsv"), "two concurrent --out writers of one file: both finish, the file whole")
ps = [subprocess.Popen([cli, "sweep", *K, "--resume", "cres.tsv", "--chunk", "4"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE) for _ in range(2)]
outs = [p.communicate(timeout=300) for p in ps]
rcs = sorted(p.returncode for p in ps)
check(rcs in ([0, 0], [0, 2]) and read("cres.tsv") == kfull and (rcs == [0, 0] or any(b"in use" in e for _, e in outs)),
      f"two concurrent --resume runs of one file: exits {rcs} (the second refused while the first holds it), the file whole")

os.chdir("/")
shutil.rmtree(tmp, ignore_errors=True)
print(f"{checks - fails} passed, {fails} failed")
sys.exit(1 if fails else 0)
