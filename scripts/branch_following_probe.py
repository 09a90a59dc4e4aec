#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""How far in b can the ends of a covering segment go: fixed in theta, or following their branch?

A sampled (floating-point) probe for the box prover of the certified region (docs/certified.md,
"Limits"): a box proof today keeps J0 and J1 fixed in theta over the whole box, so its width in b
is bounded by how fast the plateau T = t2 and the level 3 pi/2 move under a fixed theta. If instead
each end followed its branch of T1 (fixed in the branch coordinate phi = 2 theta - (a/b) cos theta,
whose odd multiples of pi are the jumps of T1, Eq. 14-16), how wide could the box be?

For each b/a given (a = 1, q/a = Q): the covering segments of the floating search (Lemma 4,
dfchaos.covering_segments) among the first six above t2, the one whose T rises highest; its t2 end
at the middle of the run where T == t2 exactly; its top end where T is nearest 3 pi/2 + min(0.3,
half its rise above 3 pi/2). Then, for relative steps d = 1e-9 * 1.25^n, whether at 8 values of
b in (b0, b0 (1 +- d)] the two ends still give T == t2 and T >= 3 pi/2:
  fixed      the ends at the same theta;
  following  the ends at the same phi, on the branch (theta solved from phi by bisection).
Printed: the largest d passed on both sides (a lower bound within a factor 1.25), and d / (b/a).
Only the two ends are checked, at sample points, in double precision: evidence about the box
width to aim for, not a proof (continuity inside J is not looked at).

Usage: PYTHONPATH=build/python /usr/bin/python3 scripts/branch_following_probe.py [--q Q] B [B ...]
"""
import argparse
import math
import sys

import numpy as np

import dfchaos


def phi(theta, b):
    """The branch coordinate at a = 1: T1 jumps where it is an odd multiple of pi."""
    return 2 * theta - math.cos(theta) / b


def theta_of_phi(target, b, lo, hi):
    """The theta in [lo, hi] with phi(theta, b) = target, or None (bisection; phi is monotone there)."""
    flo, fhi = phi(lo, b) - target, phi(hi, b) - target
    if flo * fhi > 0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fm = phi(mid, b) - target
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def ends_hold(q, b, theta_t2, theta_top):
    p = dfchaos.Parameters(1.0, b, q)
    if not p.t2 < min(theta_t2, theta_top):
        return False
    T = dfchaos.T(p, np.array([theta_t2, theta_top]))
    return T[0] == p.t2 and T[1] >= 1.5 * math.pi


def widest(b0, holds, sign, limit=0.5):
    """The largest d = 1e-9 * 1.25^n (< limit) with holds(b) at 8 values of b in (b0, b0 (1 + sign d)]."""
    ok, d = 0.0, 1e-9
    while d < limit:
        if all(holds(b) for b in b0 * (1 + sign * np.linspace(0, d, 9)[1:])):
            ok, d = d, d * 1.25
        else:
            break
    return ok


def probe(q, b0):
    p = dfchaos.Parameters(1.0, b0, q)
    segments = dfchaos.covering_segments(p)[:6]
    if not segments:
        return None

    def rise(s):
        return float(np.max(np.asarray(dfchaos.T(p, np.linspace(s["lo"], s["hi"], 2001)))))

    seg = max(segments, key=rise)
    xs = np.linspace(seg["lo"], seg["hi"], 4001)
    T = np.asarray(dfchaos.T(p, xs))
    # the t2 end: the middle of the run of T == t2 through the segment's t2 end (which runs on
    # beyond the segment: scanned on a window of the segment's length centred there)
    half = 0.5 * (seg["hi"] - seg["lo"])
    ys = np.linspace(seg["theta_at_t2"] - half, seg["theta_at_t2"] + half, 4001)
    Ty = np.asarray(dfchaos.T(p, ys))
    on = np.flatnonzero(Ty == p.t2)
    if on.size == 0:
        return None
    i = j = on[np.argmin(abs(ys[on] - seg["theta_at_t2"]))]
    while i > 0 and Ty[i - 1] == p.t2:
        i -= 1
    while j < len(ys) - 1 and Ty[j + 1] == p.t2:
        j += 1
    theta_t2, plateau = 0.5 * (ys[i] + ys[j]), ys[j] - ys[i]
    target = 1.5 * math.pi + min(0.3, 0.5 * (T.max() - 1.5 * math.pi))
    k = int(np.argmin(abs(T - target)))
    theta_top = xs[k]
    phi_t2, phi_top = phi(theta_t2, b0), phi(theta_top, b0)

    def fixed(b):
        return ends_hold(q, b, theta_t2, theta_top)

    def following(b):
        lo = math.pi + 1e-12
        e2, et = theta_of_phi(phi_t2, b, lo, 1.5 * math.pi), theta_of_phi(phi_top, b, lo, 1.5 * math.pi)
        return e2 is not None and et is not None and ends_hold(q, b, e2, et)

    d_fixed = min(widest(b0, fixed, +1), widest(b0, fixed, -1))
    d_follow = min(widest(b0, following, +1), widest(b0, following, -1))
    return seg["label"]["t1_branch"], T[k] - 1.5 * math.pi, plateau, d_fixed, d_follow


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--q", type=float, default=0.85, help="q/a (default 0.85)")
    ap.add_argument("b", type=float, nargs="+", help="values of b/a")
    args = ap.parse_args()
    print("b/a\tbranch\tT_top-3pi/2\tplateau_rad\tfixed_d\tfollowing_d\tfixed_d/(b/a)\tfollowing/fixed")
    for b0 in args.b:
        r = probe(args.q, b0)
        if r is None:
            print(f"{b0:g}\tno covering segment with a plateau")
            continue
        k, top, plateau, d_fixed, d_follow = r
        ratio = d_follow / d_fixed if d_fixed > 0 else math.inf
        print(f"{b0:g}\t{k}\t{top:.3f}\t{plateau:.2e}\t{d_fixed:.2e}\t{d_follow:.2e}\t{d_fixed / b0:.3g}\t{ratio:.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
