#!/usr/bin/env python3
"""Certificates of `dfchaos certify ... --certificate FILE`, re-verified by dfchaos-recheck (MPFI).

One CTest test per CASE: the tool writes a certificate, the checker accepts it (exit 0), or a
mutated copy of it is rejected with the exit status of its kind of damage (1: a step fails;
2: malformed). docs/certificates.md describes the format.

usage: recheck_certificates.py DFCHAOS DFCHAOS_RECHECK CASE
"""
import json
import os
import subprocess
import sys
import tempfile

# The requests whose certificates the cases use.
REQUESTS = {
    "vartheta0": ["vartheta0"],
    "lemma1_point": ["lemma1", "--a", "1", "--b", "0.001", "--q", "0.85"],
    # a box across which u(t2) is near 0 at the low q: the prover splits it into several sub-boxes
    "lemma1_box": ["lemma1", "--a", "1", "--b", "0.001:0.0035", "--q", "0.73:0.76"],
    "b0": ["b0", "--a", "1", "--q", "0.85"],
}


def write_certificate(cli, request, directory):
    """Runs the tool with --certificate; returns (path, record)."""
    path = os.path.join(directory, request + ".json")
    proc = subprocess.run([cli, "certify", *REQUESTS[request], "--certificate", path], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"FAIL: dfchaos certify {' '.join(REQUESTS[request])} --certificate: exit {proc.returncode}: {proc.stderr.strip()}")
    record = json.loads(proc.stdout)
    info = record.get("certificate", {})
    size = os.path.getsize(path)
    if info.get("bytes") != size or len(info.get("sha256", "")) != 64:
        sys.exit(f"FAIL: the record's certificate {info} does not match the file ({size} bytes)")
    print(f"ok:   {request}: certificate of {size} bytes, sha256 {info['sha256'][:16]}...")
    return path, record


def recheck(checker, path, want, why):
    proc = subprocess.run([checker, path], capture_output=True, text=True)
    line = (proc.stdout + proc.stderr).strip()
    if proc.returncode != want:
        sys.exit(f"FAIL: {why}: dfchaos-recheck exit {proc.returncode}, want {want}: {line}")
    print(f"ok:   {why}: exit {want}: {line}")


def mutate(path, out, change):
    """Writes to `out` the certificate at `path` after change(cert) (a function on the dict)."""
    with open(path) as f:
        cert = json.load(f)
    change(cert)
    with open(out, "w") as f:
        json.dump(cert, f, indent=1)
    return out


def next_double_hex(h, direction):
    """The hex float of the neighbour of the double `h` (direction +1 up, -1 down)."""
    import math
    return float.hex(math.nextafter(float.fromhex(h), direction * math.inf))


def main():
    if len(sys.argv) != 4:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    cli, checker, case = sys.argv[1:]
    with tempfile.TemporaryDirectory() as d:
        bad = os.path.join(d, "mutated.json")
        if case.startswith("accepts_"):
            path, _ = write_certificate(cli, case[len("accepts_"):], d)
            recheck(checker, path, 0, f"the {case[len('accepts_'):]} certificate")
        elif case == "rejects_gap":  # a sub-box deleted: the rest no longer covers the box
            path, _ = write_certificate(cli, "lemma1_box", d)
            with open(path) as f:
                n = len(json.load(f)["witnesses"]["sub_boxes"])
            if n < 2:
                sys.exit(f"FAIL: the lemma1 box proof used {n} sub-box(es); the case needs several")
            recheck(checker, mutate(path, bad, lambda c: c["witnesses"]["sub_boxes"].pop(n // 2)), 1, "a sub-box deleted")
        elif case == "rejects_outside":  # a sub-box moved outside the box (b shifted past b_hi)
            path, _ = write_certificate(cli, "lemma1_box", d)

            def move(c):
                s = c["witnesses"]["sub_boxes"][0]
                width = float.fromhex(s[1]) - float.fromhex(s[0])
                top = float.fromhex(c["parameters"]["b"]["hi"]["hex"])
                s[0], s[1] = float.hex(top + 1e-6), float.hex(top + 1e-6 + width)
            recheck(checker, mutate(path, bad, move), 1, "a sub-box moved outside the box")
        elif case == "rejects_bracket_off_root":  # the vartheta0 bracket moved beside the root
            path, _ = write_certificate(cli, "vartheta0", d)

            def off(c):
                br = c["witnesses"]["bracket"]
                br["lo"]["hex"], br["hi"]["hex"] = br["hi"]["hex"], float.hex(1.0)
            recheck(checker, mutate(path, bad, off), 1, "the vartheta0 bracket moved off its root")
        elif case == "rejects_parameter_last_bit":  # b_lo one ulp lower: the sub-boxes leave a gap at the edge
            path, _ = write_certificate(cli, "lemma1_box", d)

            def ulp(c):
                b = c["parameters"]["b"]["lo"]
                b["hex"] = next_double_hex(b["hex"], -1)
            recheck(checker, mutate(path, bad, ulp), 1, "parameter b_lo changed in its last bit")
        elif case == "rejects_truncated":
            path, _ = write_certificate(cli, "lemma1_point", d)
            with open(path, "rb") as f:
                data = f.read()
            with open(bad, "wb") as f:
                f.write(data[: len(data) // 2])
            recheck(checker, bad, 2, "a truncated certificate")
        elif case == "rejects_missing_field":
            path, _ = write_certificate(cli, "b0", d)
            recheck(checker, mutate(path, bad, lambda c: c["witnesses"].pop("b_low")), 2, "a missing field (b_low)")
        elif case == "rejects_inexact_number":
            path, _ = write_certificate(cli, "lemma1_point", d)

            def decimal(c):
                c["parameters"]["q"]["lo"]["hex"] = "0.85"
            recheck(checker, mutate(path, bad, decimal), 2, "a number that is not an exact hex float")
        elif case == "rejects_wrong_version":
            path, _ = write_certificate(cli, "vartheta0", d)
            recheck(checker, mutate(path, bad, lambda c: c.update(version=2)), 2, "a wrong format version")
        elif case == "unwritable":  # --certificate below a regular file (no directory can be made there): exit 2, no file
            with open(os.path.join(d, "plain"), "w") as f:
                f.write("a file, not a directory\n")
            target = os.path.join(d, "plain", "c.json")
            proc = subprocess.run([cli, "certify", "vartheta0", "--certificate", target], capture_output=True, text=True)
            lines = proc.stderr.strip().splitlines()
            if proc.returncode != 2 or proc.stdout or len(lines) != 1 or "certificate" not in lines[0]:
                sys.exit(f"FAIL: unwritable --certificate: exit {proc.returncode}, stdout {proc.stdout[:100]!r}, stderr {proc.stderr!r}")
            print(f"ok:   unwritable --certificate: exit 2: {lines[0]}")
            # a read-only directory (unless root, who may write anyway): exit 2 and nothing left in it
            ro = os.path.join(d, "ro")
            os.mkdir(ro, 0o555)
            proc = subprocess.run([cli, "certify", "lemma1", "--b", "0.001", "--q", "0.85", "--certificate", os.path.join(ro, "c.json")],
                                  capture_output=True, text=True)
            if os.geteuid() != 0 and (proc.returncode != 2 or os.listdir(ro)):
                sys.exit(f"FAIL: read-only directory: exit {proc.returncode}, left {os.listdir(ro)}")
            # an empty file name
            proc = subprocess.run([cli, "certify", "vartheta0", "--certificate", ""], capture_output=True, text=True)
            if proc.returncode != 2 or proc.stdout or len(proc.stderr.strip().splitlines()) != 1 or "certificate" not in proc.stderr:
                sys.exit(f"FAIL: --certificate '': exit {proc.returncode}, stderr {proc.stderr!r}")
            print(f"ok:   --certificate '': exit 2: {proc.stderr.strip()}")
            # a statement without a certificate format: bad input before any proof
            proc = subprocess.run([cli, "certify", "covering", "--b", "0.001", "--q", "0.85", "--certificate", os.path.join(d, "c.json")],
                                  capture_output=True, text=True)
            if proc.returncode != 2 or proc.stdout or os.path.exists(os.path.join(d, "c.json")) or "certificate" not in proc.stderr:
                sys.exit(f"FAIL: covering --certificate: exit {proc.returncode}, stderr {proc.stderr!r}")
            print(f"ok:   covering --certificate: exit 2: {proc.stderr.strip()}")
            # a statement not proved writes no certificate (exit 1)
            target = os.path.join(d, "not-proved.json")
            proc = subprocess.run([cli, "certify", "lemma1", "--b", "0.05", "--q", "0.73", "--certificate", target], capture_output=True, text=True)
            if proc.returncode != 1 or os.path.exists(target) or '"written": false' not in proc.stdout:
                sys.exit(f"FAIL: not proved: exit {proc.returncode}, file left: {os.path.exists(target)}, stdout {proc.stdout[:300]!r}")
            print("ok:   a statement not proved: exit 1, no certificate")
            leftovers = [f for f in os.listdir(d) if f not in ("ro", "plain")]
            if leftovers:
                sys.exit(f"FAIL: files left behind: {leftovers}")
        else:
            print(f"unknown case {case}", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
