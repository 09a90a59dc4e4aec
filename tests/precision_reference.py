#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Independent 40-digit reference for T1 (Eq. 11) and T (Eq. 17, Lemma 3), and the precision test.

Written from the paper's formulas alone, in mpmath (mp.dps = 40), with absolute times t as
40-digit numbers (no split into turns and phase, no long double, nothing shared with the C++
library). Inputs are the exact binary values of the doubles a, b, q, theta.

  * T1: first zero t > theta of G1(theta, t) = b s^2 - a sin t + a cos(theta) s + a sin(theta),
    s = t - theta (Eq. 11), written without cancellation near s = 0 as
    G1 = b s^2 + 2 a sin(theta) sin^2(s/2) + a cos(theta) (s - sin s).
    G1'' = F(t) = a sin t + 2b changes sign only at t2, t3 (mod 2 pi), so G1 is concave on
    [t2 + 2 pi k, t3 + 2 pi k] and convex on [t3 + 2 pi k, t2 + 2 pi (k+1)]. Scanning these pieces
    in order, a convex piece holds an up-crossing iff G1 >= 0 at its end, and a concave piece iff
    G1 >= 0 at its end or at its maximum (the zero of G1'): the FIRST root cannot be skipped.
    Where U(s) = b s^2 + a cos(theta) s + a sin(theta) + a < 0, G1 <= U < 0: those pieces are
    jumped over, so a flight of 10^7 time units costs a few pieces at each end.
  * theta2: first zero after T1 of the progression velocity (Eq. 17)
    V(t) = v1 + 2c (t - T1) - a cos t + a cos T1, v1 = dG1/dt at T1; V' = F - q changes sign only
    at t0, t1 (mod 2 pi), so the same piece scan finds its first zero.
  * Lemma 3 and Section 3: theta2 mod 2 pi in [t2, t3): T = theta2 (A); in [t1, t2): stop until
    t2, T = t2 (B); otherwise stop until t0, progress from rest (Eq. 7) until t4, then T = t4 (D)
    or T = t2 (C) by the same rule; a second stop before t0 repeats for ever (no T).

Usage:
  precision_reference.py eval A B Q THETA...     print theta, T1, T, scenario, elapsed (reference)
  precision_reference.py check DFCHAOS [--ratios R,R,...] [--random N] [--seed S]
        run `DFCHAOS map` at random phases and at phases at relative distances 1e-11, 1e-9, 1e-7
        on both sides of discontinuities of T1 (the symmetric tangencies, closed form
        2z - (a/b) cos z = (2k+1) pi), compare with the reference, print the maximal errors,
        exit 1 if a tolerance below is exceeded (CTest: precision_reference).
  precision_reference.py measure DFCHAOS R,R,...  print the error table for these b/a (no
        thresholds; used to choose the b/a floor of docs/accuracy.md).
"""
import math
import random
import subprocess
import sys

from mpmath import mp, mpf, sin, cos, asin, floor, pi as mpi

mp.dps = 40

# Tolerances of the accuracy contract (docs/accuracy.md), checked for b/a >= 1e-7.
# Tolerances of the accuracy contract (docs/accuracy.md), checked for b/a >= 1e-12 (the floor).
TOL_T_RANDOM = 1e-11        # |T - T_ref| (on the circle) at random phases
TOL_T_NEAR_DISC = 1e-9      # |T - T_ref| at relative distance >= 1e-11 from a discontinuity of T1
TOL_T1_ABS = 1e-11          # |T1 - T1_ref| and |elapsed - elapsed_ref| at random phases, beyond
TOL_T1_ROUNDING = 2.0 ** -52  #   the rounding of a number up to 1e12 to a double: + this times it
TOL_NEAR_T3 = 1e-15         # |T - T_ref|, |T1 - T1_ref| on the last doubles below t3 (T = t2 there)
REL_DISTANCES = (1e-11, 1e-9, 1e-7)
RATIOS = "1e-12,1e-10,1e-7,1e-6,1e-5,1e-3,1e-2,0.1"
Q_OVER_A = (0.85, 0.75, 0.6)

MAX_PIECES = 100000


class NoReturn(Exception):
    """The motion never flies again (eternal stick-slip)."""


def solve_up(g, lo, hi, glo, ghi, tol):
    """Zero of g on [lo, hi] with g(lo) < 0 <= g(hi) and a single sign change (Illinois method)."""
    side = 0
    for _ in range(400):
        if hi - lo <= tol:
            break
        x = hi - ghi * (hi - lo) / (ghi - glo)
        if not (lo < x < hi):
            x = (lo + hi) / 2
        gx = g(x)
        if gx < 0:
            lo, glo = x, gx
            if side == -1:
                ghi /= 2
            side = -1
        else:
            hi, ghi = x, gx
            if side == 1:
                glo /= 2
            side = 1
    return hi


class Ref:
    def __init__(self, a, b, q):
        self.a, self.b, self.q = mpf(a), mpf(b), mpf(q)
        self.c2 = 2 * self.b - self.q  # 2c
        w = asin(2 * self.b / self.a)
        self.t2, self.t3 = mpi + w, 2 * mpi - w
        u = asin((self.q - 2 * self.b) / self.a)
        self.p0, self.p1 = u, mpi - u  # the paper's t0, t1
        self.twopi = 2 * mpi

    def phase(self, t):
        return t - self.twopi * floor(t / self.twopi)

    # ---- T1: first zero of G1 -------------------------------------------------------------
    def first_hit(self, theta):
        a, b = self.a, self.b
        st, ct = sin(theta), cos(theta)
        G = lambda s: b * s * s + 2 * a * st * sin(s / 2) ** 2 + a * ct * (s - sin(s))
        dG = lambda s: 2 * b * s + a * st * sin(s) + 2 * a * ct * sin(s / 2) ** 2
        # Skip window of U(s) = b s^2 + a ct s + a st + a and root bound of L = U - 2a.
        def roots(k):
            disc = (a * ct) ** 2 - 4 * b * k
            if disc < 0:
                return None
            r = mp.sqrt(disc)
            return ((-a * ct - r) / (2 * b), (-a * ct + r) / (2 * b))
        win = roots(a * st + a)
        bound = roots(a * st - a)[1]
        tol = mpf(10) ** (-30) * (1 + abs(bound))
        # Piece boundaries in s: t2 + 2 pi k (start of a concave piece) and t3 + 2 pi k.
        # The first piece [theta, t3] is concave with G1(0) = G1'(0) = 0 and G1' decreasing: G1 < 0.
        sa = self.t3 - theta
        concave = False  # the next piece [t3, t2 + 2 pi] is convex
        for _ in range(MAX_PIECES):
            if win is not None and win[0] < sa < win[1]:
                # jump to the piece containing win[1] if it starts later (G1 <= U < 0 up to there)
                t = theta + win[1]
                tc = self.t2 + self.twopi * floor((t - self.t2) / self.twopi)  # concave piece start <= t
                if t >= tc + (self.t3 - self.t2):
                    nsa, nconc = tc + (self.t3 - self.t2) - theta, False
                else:
                    nsa, nconc = tc - theta, True
                if nsa > sa:
                    sa, concave = nsa, nconc
            length = (self.t3 - self.t2) if concave else (self.t2 + self.twopi - self.t3)
            sb = sa + length
            ga, gb = G(sa), G(sb)
            if ga >= 0:
                raise RuntimeError("reference: G1 >= 0 at a piece start (root skipped)")
            if gb >= 0:
                s1 = solve_up(G, sa, sb, ga, gb, tol)
                return s1, dG(s1)
            if concave:
                da, db = dG(sa), dG(sb)
                if da > 0 and db < 0:
                    # tangent lines bound the maximum from above
                    u = (gb - db * sb - ga + da * sa) / (da - db)
                    if min(ga + da * (u - sa), gb + db * (u - sb)) >= 0:
                        m = solve_up(lambda s: -dG(s), sa, sb, -da, -db, tol)
                        gm = G(m)
                        if gm >= 0:
                            s1 = solve_up(G, sa, m, ga, gm, tol)
                            return s1, dG(s1)
            if sa > bound + 10:
                raise RuntimeError("reference: no root before the bound")
            sa, concave = sb, not concave
        raise RuntimeError("reference: too many pieces")

    # ---- first zero of a progression velocity ---------------------------------------------
    def progression_end(self, t_start, v_start):
        """First zero after t_start of V(t) = v_start + 2c (t - t_start) - a cos t + a cos t_start."""
        a = self.a
        sn, cs = sin(t_start), cos(t_start)
        V = lambda u: v_start + self.c2 * u + 2 * a * cs * sin(u / 2) ** 2 + a * sn * sin(u)
        # Breaks: p0, p1 (mod 2 pi); V increasing on (p0, p1), decreasing elsewhere.
        ph = self.phase(t_start)
        base = t_start - ph
        breaks = []
        for k in range(0, 64):
            for p in (self.p0, self.p1):
                t = base + self.twopi * k + p
                if t > t_start + mpf(10) ** -25 * (1 + abs(t_start)):  # (not t_start itself, rounded)
                    breaks.append(t)
        breaks.sort()
        ua = mpf(0)
        va = V(ua)
        for t in breaks:
            ub = t - t_start
            vb = V(ub)
            if vb <= 0:
                # V is monotone on [ua, ub] and V(ua) > 0 (or V(0) = 0 with V increasing on the first
                # piece, which then ends with V > 0): the first zero lies in (ua, ub].
                return t_start + solve_up(lambda u: -V(u), ua, ub, -va, -vb, mpf(10) ** -32)
            ua, va = ub, vb
        raise RuntimeError("reference: progression does not stop within 64 periods")

    def F(self, t):
        return self.a * sin(t) + 2 * self.b

    def in_arc(self, phi, lo, hi):
        return lo <= phi < hi

    def next_at(self, t, p):
        """First instant >= t with phase p."""
        k = floor((t - p) / self.twopi)
        x = p + self.twopi * k
        while x < t:
            x += self.twopi
        return x

    # ---- T ---------------------------------------------------------------------------------
    def step(self, theta):
        """Returns (T1, T, scenario, elapsed) for the start at rest at phase theta."""
        theta = mpf(theta)
        start = theta
        if theta < self.t2:  # the double t2 below the real t2: at rest until t2, then flight
            start = self.t2
        if start >= self.t3:  # F >= 0: the mass stays at rest (degenerate scenario C')
            th1, chain, th2 = start, ["f", "s"], start
        else:
            s1, v1 = self.first_hit(start)
            th1 = start + s1
            if v1 <= 0:
                raise RuntimeError("reference: zero-velocity contact")
            th2 = self.progression_end(th1, v1)
            chain = ["f", "p"]
        ph2 = self.phase(th2)
        if chain[-1] == "p" and self.in_arc(ph2, self.t2, self.t3):
            return th1, ph2, "A", th2 - theta
        if chain[-1] == "p" and self.in_arc(ph2, self.p1, self.t2):
            return th1, self.t2, "B", self.next_at(th2, self.t2) - theta
        if chain[-1] == "p":
            chain.append("s")
        t0n = self.next_at(th2, self.p0)
        if t0n == th2:
            t0n += self.twopi
        t4 = self.progression_end(t0n, mpf(0))
        ph4 = self.phase(t4)
        tag = "" if chain == ["f", "p", "s"] else "'"
        if self.in_arc(ph4, self.t2, self.t3):
            return th1, ph4, "D" + tag, t4 - theta
        if self.in_arc(ph4, self.p1, self.t2):
            return th1, self.t2, "C" + tag, self.next_at(t4, self.t2) - theta
        raise NoReturn()

    def tangency(self, k):
        """The solution z of h(z) = 2z - (a/b) cos z = (2k+1) pi in (t2, 3 pi/2) (h decreasing)."""
        r = self.a / self.b
        target = (2 * k + 1) * mpi
        lo, hi = self.t2, 3 * mpi / 2
        h = lambda z: 2 * z - r * cos(z)
        for _ in range(400):
            m = (lo + hi) / 2
            if h(m) >= target:
                lo = m
            else:
                hi = m
            if hi - lo < mpf(10) ** -38:
                break
        return (lo + hi) / 2

    def k_range(self):
        r = self.a / self.b
        h = lambda z: 2 * z - r * cos(z)
        k_hi = int(floor((h(self.t2) / mpi - 1) / 2))
        k_lo = int(mp.ceil((h(3 * mpi / 2) / mpi - 1) / 2))
        return k_lo, k_hi


def circle_distance(x, y):
    d = abs(x - y) % (2 * mpi)
    return min(d, 2 * mpi - d)


def run_cli(cli, a, b, q, thetas):
    """Rows (theta, T1, T, scenario, elapsed) of `dfchaos map`; None for a phase where it gives up
    (exit 1: no return to free flight)."""
    def call(ths):
        args = [cli, "map", "--a", repr(a), "--b", repr(b), "--q", repr(q), "--theta"] + [repr(t) for t in ths]
        return subprocess.run(args, capture_output=True, text=True)
    out = call(thetas)
    if out.returncode == 1 and len(thetas) > 1:
        return [run_cli(cli, a, b, q, [t])[0] for t in thetas]
    if out.returncode == 1:
        return [None]
    if out.returncode != 0:
        raise RuntimeError("dfchaos map failed (%d): %s" % (out.returncode, out.stderr.strip()))
    rows = [line.split("\t") for line in out.stdout.strip().split("\n")[1:] if not line.startswith("#")]
    return [(float(r[0]), float(r[1]), float(r[2]), r[3], float(r[4])) for r in rows]


def lib_phases(cli, a, b, q):
    """The doubles t2, t3 as dfchaos computes them (its map accepts theta in [t2, t3))."""
    out = subprocess.run([cli, "info", "--a", repr(a), "--b", repr(b), "--q", repr(q)], capture_output=True, text=True, check=True)
    rows = dict(line.split("\t", 1) for line in out.stdout.strip().split("\n") if not line.startswith("#"))
    return float(rows["t2"]), float(rows["t3"])


def cases(cli, ratio, qa, n_random, seed):
    """(theta, kind) pairs: random phases, the last doubles below t3, phases near discontinuities of T1."""
    a, b, q = 1.0, float(ratio), float(qa)
    ref = Ref(a, b, q)
    rng = random.Random(seed)
    t2, t3 = lib_phases(cli, a, b, q)
    out = []
    for _ in range(n_random):
        th = t2 + (t3 - t2) * rng.random()
        if t2 <= th < t3:
            out.append((th, "random"))
    # the last doubles below t3, and phases 1e-15 .. 1e-9 below it (the t3 edge)
    th = t3
    for i in range(1, 7):
        th = math.nextafter(th, 0.0)
        if i in (1, 2, 6):
            out.append((th, "near t3"))
    for d in (1e-14, 1e-13, 1e-12, 1e-9):
        out.append((t3 - d, "near t3"))
    k_lo, k_hi = ref.k_range()
    ks = sorted({k_lo + 1, k_hi - 1, rng.randint(k_lo + 1, k_hi - 1)}) if k_hi - k_lo > 3 else []
    for k in ks:
        z = ref.tangency(k)
        for d in REL_DISTANCES:
            for sgn in (-1, 1):
                out.append((float(z * (1 + sgn * mpf(d))), "disc %+g" % (sgn * d)))
    return (a, b, q), ref, out


def compare(cli, ratios, qa, n_random, seed, verbose=True):
    """Returns rows (ratio, kind, max |T err|, max rel T1 err, scenario mismatches, count)."""
    table = []
    for ratio in ratios:
        (a, b, q), ref, cs = cases(cli, ratio, qa, n_random, seed)
        lib = run_cli(cli, a, b, q, [t for t, _ in cs])
        worst = {}
        for (th, kind), row in zip(cs, lib):
            try:
                r_T1, r_T, r_scen, r_el = ref.step(th)
            except NoReturn:
                if row is not None:
                    raise RuntimeError("dfchaos returned T where the motion never flies again: theta=%r" % th)
                continue
            if row is None:
                raise RuntimeError("dfchaos gave up where the reference returns: theta=%r" % th)
            th_out, T1, T, scen, elapsed = row
            assert th_out == th, (th_out, th)
            eT = float(circle_distance(mpf(T), r_T))
            # error of T1 beyond the rounding of the printed double (T1 is an instant up to 1e12)
            eT1 = max(0.0, float(abs(mpf(T1) - r_T1)) - TOL_T1_ROUNDING * abs(T1))
            # the same for the elapsed time of the step (T-hat - theta)
            eT1 = max(eT1, float(abs(mpf(elapsed) - r_el)) - TOL_T1_ROUNDING * abs(elapsed))
            group = kind if not kind.startswith("disc") else "disc %g" % abs(float(kind.split()[1]))
            w = worst.setdefault(group, [0.0, 0.0, 0, 0, None])
            if eT > w[0]:
                w[0], w[4] = eT, th
            w[1] = max(w[1], eT1)
            w[2] += scen.rstrip("'") != r_scen.rstrip("'")
            w[3] += 1
        for group, w in sorted(worst.items()):
            table.append((ratio, group, w[0], w[1], w[2], w[3], w[4]))
            if verbose:
                print("b/a=%-7g q/a=%-5g %-12s n=%-3d max|T-Tref|=%.3e  max|T1-T1ref|,|el-elref| (beyond rounding)=%.3e  scenario mismatches=%d  (worst theta %r)"
                      % (ratio, qa, group, w[3], w[0], w[1], w[2], w[4]), flush=True)
    return table


def main(argv):
    if len(argv) >= 2 and argv[1] == "eval":
        a, b, q = (float(x) for x in argv[2:5])
        ref = Ref(a, b, q)
        print("theta\tT1\tT\tscenario\telapsed")
        for x in argv[5:]:
            th = float(x)
            try:
                T1, T, scen, el = ref.step(th)
                print("%r\t%s\t%s\t%s\t%s" % (th, mp.nstr(T1, 25), mp.nstr(T, 25), scen, mp.nstr(el, 25)))
            except NoReturn:
                print("%r\tno return to free flight" % th)
        return 0
    if len(argv) >= 4 and argv[1] == "measure":
        compare(argv[2], [float(x) for x in argv[3].split(",")], 0.85, 16, 7)
        return 0
    if len(argv) >= 3 and argv[1] == "check":
        cli = argv[2]
        opts = dict(zip(argv[3::2], argv[4::2]))
        ratios = [float(x) for x in opts.get("--ratios", RATIOS).split(",")]
        n_random = int(opts.get("--random", "12"))
        seed = int(opts.get("--seed", "20130214"))
        failures = 0
        checks = 0
        for qa in Q_OVER_A:
            for row in compare(cli, ratios, qa, n_random, seed + int(qa * 100)):
                ratio, group, eT, eT1, mism, n, worst = row
                tol = {"random": TOL_T_RANDOM, "near t3": TOL_NEAR_T3}.get(group, TOL_T_NEAR_DISC)
                tol1 = {"random": TOL_T1_ABS, "near t3": TOL_NEAR_T3}.get(group)
                checks += 1
                bad = []
                if eT > tol:
                    bad.append("max|T-Tref| %.3e > %.0e" % (eT, tol))
                if tol1 is not None and eT1 > tol1:
                    bad.append("T1 or elapsed error %.3e > %.0e" % (eT1, tol1))
                if mism:
                    bad.append("%d scenario mismatches" % mism)
                if bad:
                    failures += 1
                    print("FAIL b/a=%g q/a=%g %s: %s (worst theta %r)" % (ratio, qa, group, "; ".join(bad), worst))
        print("%d passed, %d failed" % (checks - failures, failures))
        return 1 if failures else 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
