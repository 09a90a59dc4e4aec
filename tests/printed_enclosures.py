#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every ball that `dfchaos certify` prints must contain the quantity it names.

    printed_enclosures.py DFCHAOS

A printed ball is {"mid": decimal string, "rad": decimal string}: the claim is |x - mid| <= rad for
the true value x. The midpoint is printed with a few dozen digits, so the radius must cover the
rounding of the midpoint as well as the ball's own radius. This test recomputes the quantities
independently, in mpmath, from the paper's formulas (the reference of tests/precision_reference.py
for T and the stop of the progression; a root of Eq. 1 for vartheta0), and checks each printed ball
against them, exactly, in decimal arithmetic:
  - vartheta0 and sin(vartheta0) (80 digits; the reference is good to 1e-75);
  - at (a, b, q) = (1, 0.001, 0.85), every covering segment's T_there and theta2_phase_there (the
    reference is good to about 1e-25 here: its root tolerance is 1e-30 times the flight time, ~1e3;
    the check allows that, and nothing more).
Exit status 0 when every ball encloses, 1 otherwise (each failure named on one line).
"""
import json
import os
import subprocess
import sys

from mpmath import mp, mpf, cot, sin, findroot, pi as mpi

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import precision_reference  # noqa: E402  (the 40-digit reference of T, written from the paper)

failures = []
checked = 0


def check(name, ball, exact, ref_error):
    """|exact - mid| <= rad + ref_error, computed in mpmath at the working precision."""
    global checked
    checked += 1
    mid, rad = mpf(ball["mid"]), mpf(ball["rad"])
    err = abs(exact - mid)
    if err > rad + ref_error:
        failures.append(f"{name}: printed {ball['mid']} +- {ball['rad']}, but the value is "
                        f"{mp.nstr(exact, 30)} (off by {mp.nstr(err, 3)}, more than the radius)")


def certify(cli, *args):
    r = subprocess.run([cli, "certify", *args], capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        sys.exit(f"printed_enclosures: dfchaos certify {' '.join(args)} exited {r.returncode}: {r.stderr.strip()}")
    return json.loads(r.stdout)


def main(argv):
    if len(argv) != 2:
        sys.exit("usage: printed_enclosures.py DFCHAOS")
    cli = argv[1]

    # Eq. (1): pi - x = cot(x/2) on (0, pi/2].
    mp.dps = 80
    v = certify(cli, "vartheta0")
    theta0 = findroot(lambda x: mpi - x - cot(x / 2), mpf("0.81"))
    check("vartheta0", v["vartheta0"], theta0, mpf(10) ** -75)
    check("sin_vartheta0", v["sin_vartheta0"], sin(theta0), mpf(10) ** -75)

    # Lemma 4 at (1, 0.001, 0.85): T at the point where T >= 3 pi / 2 and the stop phase of the
    # progression at the point where T = t2, on each covering segment.
    mp.dps = precision_reference.mp.dps = 40
    a, b, q = 1.0, 0.001, 0.85
    cov = certify(cli, "covering", "--a", str(a), "--b", str(b), "--q", str(q))
    ref = precision_reference.Ref(a, b, q)
    ref_error = mpf(10) ** -25
    segments = [x for x in _walk(cov) if "T_there" in x]
    if not segments:
        sys.exit("printed_enclosures: the covering record holds no segment with T_there")
    for i, s in enumerate(segments):
        _, T, _, _ = ref.step(mpf(s["theta_T_ge_3pi_2"]))
        check(f"covering segment {i} T_there", s["T_there"], T, ref_error)
        theta = mpf(s["theta_T_eq_t2"])
        s1, v1 = ref.first_hit(theta)
        th2 = ref.progression_end(theta + s1, v1)
        check(f"covering segment {i} theta2_phase_there", s["theta2_phase_there"], ref.phase(th2), ref_error)

    for f in failures:
        print("printed_enclosures: FAIL " + f)
    print(f"printed_enclosures: {checked} printed balls checked, {len(failures)} do not enclose their value")
    return 1 if failures else 0


def _walk(node):
    """Every JSON object inside node, depth first."""
    if isinstance(node, dict):
        yield node
        for v in node.values():
            yield from _walk(v)
    elif isinstance(node, list):
        for v in node:
            yield from _walk(v)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
