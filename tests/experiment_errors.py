#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Bad-input battery for every experiment, generated from the experiments' own declarations.

For each experiment of BIN_DIR, `--describe` lists its options with their type and admissible
range. For every option, a non-number, an empty string, NaN, infinities, a value just outside each
end of the range and (for counts) a non-integer must give exit status 2, exactly one line on stderr
naming the option, nothing on stdout, and no output file at all. So must an unknown option, and an
output root that is a regular file or lies below /proc.

Usage: experiment_errors.py BIN_DIR
"""
import json
import os
import subprocess
import sys
import tempfile


def below(opt):
    lo = opt["min"]
    if opt["type"] == "count":
        return str(lo - 1)
    return repr(lo / 2 if lo > 0 else (lo * 2 if lo < 0 else -1e-3))


def above(opt):
    hi = opt["max"]
    if opt["type"] == "count":
        return str(hi + 1)
    return repr(hi * 2 if hi > 0 else (hi / 2 if hi < 0 else 1e-3))


def main():
    bin_dir = sys.argv[1]
    failures = []
    checks = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name in sorted(os.listdir(bin_dir)):
            exe = os.path.join(bin_dir, name)
            desc = json.loads(subprocess.run([exe, "--describe"], capture_output=True, text=True, check=True).stdout)
            cases = []
            for opt in desc["options"]:
                flag = "--" + opt["name"]
                values = ["x", "", "nan", "inf", "-inf", "1e999", below(opt), above(opt)]
                if opt["type"] == "count":
                    values.append("1.5")
                cases += [([flag, v], opt["name"]) for v in values]
            cases.append((["--no-such-option", "1"], "no-such-option"))
            regular = os.path.join(tmp, "a-regular-file")
            open(regular, "w").close()
            for args, must_name in cases + [([], "out")]:
                checks += 1
                out = os.path.join(tmp, "out-" + name)
                out_args = ["--out", out] if args else ["--out", regular]
                r = subprocess.run([exe, "--fast"] + out_args + args, capture_output=True, text=True, timeout=120)
                files = sum(len(f) for _, _, f in os.walk(out)) if os.path.isdir(out) else 0
                lines = r.stderr.splitlines()
                ok = r.returncode == 2 and not r.stdout and len(lines) == 1 and files == 0 and must_name in r.stderr
                if not ok:
                    failures.append(f"{name} {' '.join(args) or '--out <regular file>'} -> rc={r.returncode}, "
                                    f"stdout {len(r.stdout)} bytes, stderr {len(lines)} lines, {files} files: {r.stderr[:300]!r}")
            # an output root below /proc cannot be created
            checks += 1
            r = subprocess.run([exe, "--fast", "--out", "/proc/dfchaos-cannot-be-here"], capture_output=True, text=True, timeout=120)
            if r.returncode != 2 or len(r.stderr.splitlines()) != 1 or "out" not in r.stderr:
                failures.append(f"{name} --out /proc/... -> rc={r.returncode}: {r.stderr[:300]!r}")
    for f in failures:
        print("FAIL:", f)
    print(f"{checks - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
