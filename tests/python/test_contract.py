# SPDX-License-Identifier: GPL-3.0-or-later
"""Unit tier: the contract of the return map T (Section 3, Lemma 3) over every way the module gives T.

The same property suite as the C++ typed tests (tests/test_T_contract.cpp): T(theta) lies in
[t2, t3); T has a plateau at t2; T is continuous away from the jumps of the closed form; T agrees
with a direct integration of the motion (here the classical Runge-Kutta method in numpy, written
from Eqs. 3-5 and the stop rule of Section 2 alone); T is unchanged when a, b, q are scaled
together. The implementations: dfchaos.T on a float and on an array, the T of dfchaos.step, and
the second element of dfchaos.orbit.
"""
import functools
import math

import numpy as np
import pytest

import dfchaos

PARAMETERS = [(0.05, 0.85), (0.03, 0.9)]   # (b/a, q/a) with a = 1, as in the C++ suite
N_PHASES = 40

IMPLEMENTATIONS = {
    "T": lambda p, th: dfchaos.T(p, th),
    "T_array": lambda p, th: float(dfchaos.T(p, np.array([th]))[0]),
    "step": lambda p, th: dfchaos.step(p, th)["T"],
    "orbit": lambda p, th: float(dfchaos.orbit(p, th, 2)["theta"][1]),
}
impl = pytest.mark.parametrize("T", IMPLEMENTATIONS.values(), ids=IMPLEMENTATIONS.keys())
params = pytest.mark.parametrize("bq", PARAMETERS, ids=[f"b={b},q={q}" for b, q in PARAMETERS])


def phases(p):
    """N_PHASES phases spread over [t2, t3) by the golden ratio (as the C++ suite)."""
    return [p.t2 + (p.t3 - p.t2) * math.fmod(0.5 + i * 0.6180339887498949, 1.0) for i in range(N_PHASES)]


def away_from_jumps(p, theta, width=1e-5):
    """The steps at theta -+ width follow the same scenario, T1 does not jump between them, and T
    stays away from t3 (where it wraps to t2)."""
    if theta - width < p.t2 or theta + width >= p.t3:
        return False
    left, right = dfchaos.step(p, theta - width), dfchaos.step(p, theta + width)
    return (left["scenario"] == right["scenario"] and abs(left["T1"] - right["T1"]) < 1e-2
            and p.t3 - left["T"] > 1e-3 and p.t3 - right["T"] > 1e-3)


# ---- direct integration -------------------------------------------------------------------------

H = 2e-3  # Runge-Kutta step (time units): global error ~1e-9 over the flights here


def rk4(a, k2, t, x, v, h):
    """One classical Runge-Kutta step of x'' = a sin t + k2 (k2 = 2b in flight, Eq. 3; 2b - q in
    progression, Eq. 4)."""
    f0, f1, f2 = a * math.sin(t) + k2, a * math.sin(t + h / 2) + k2, a * math.sin(t + h) + k2
    return x + h * (v + h * (f0 + 2 * f1) / 6), v + h * (f0 + 4 * f1 + f2) / 6


def integrate_until(a, k2, t, x, v, crossed, t_max=1e4):
    """Steps from (t, x, v) until crossed(x, v) holds, then bisects the step size to 1e-13 in time;
    returns the state there."""
    while t < t_max:
        xn, vn = rk4(a, k2, t, x, v, H)
        if crossed(xn, vn):
            lo, hi = 0.0, H
            while hi - lo > 1e-13:
                mid = 0.5 * (lo + hi)
                if crossed(*rk4(a, k2, t, x, v, mid)):
                    hi = mid
                else:
                    lo = mid
            xn, vn = rk4(a, k2, t, x, v, hi)
            return t + hi, xn, vn
        t, x, v = t + H, xn, vn
    raise RuntimeError("no event")


@functools.lru_cache(maxsize=None)
def integrated_T(a, b, q, theta):
    """T(theta) by integrating the motion: free flight from rest at the delimiter (Eq. 10) until the
    mass hits it, progression with it until the velocity vanishes, then the rule of Section 2 for a
    mass at rest: it flies where F < 0, progresses where F > q, else stays until one of the two."""
    two_pi = 2 * math.pi
    t2 = math.pi + math.asin(2 * b / a)
    t0 = math.asin((q - 2 * b) / a)
    # flight: the gap x - y < 0 until the contact
    t, _, v = integrate_until(a, 2 * b, theta, 0.0, 0.0, lambda x, v: x >= 0)
    for _ in range(4):
        # progression: until the velocity vanishes
        t, _, v = integrate_until(a, 2 * b - q, t, 0.0, v, lambda x, v: v <= 0)
        phase = math.fmod(t, two_pi)
        if a * math.sin(phase) + 2 * b < 0:
            return phase                        # flies at once (scenario A)
        to_t2, to_t0 = (t2 - phase) % two_pi, (t0 - phase) % two_pi
        if to_t2 < to_t0:
            return t2                           # waits for t2 (scenarios B, C)
        t, v = t + to_t0, 0.0                   # waits for t0, progresses from rest (Eq. 7)
    raise RuntimeError("no return to free flight")


# ---- the properties -----------------------------------------------------------------------------

@impl
@params
def test_phase_lies_in_the_arc(T, bq):
    p = dfchaos.Parameters(1.0, *bq)
    for th in phases(p):
        assert p.t2 <= T(p, th) < p.t3, th


@impl
@params
def test_plateau_at_t2(T, bq):
    """Some phase and its neighbours at distance 1e-5 all go to t2 exactly (a stop arc)."""
    p = dfchaos.Parameters(1.0, *bq)
    assert any(all(T(p, x) == p.t2 for x in (th - 1e-5, th, th + 1e-5)) for th in phases(p))


@impl
@params
def test_continuous_away_from_the_jumps(T, bq):
    """Away from the jumps, a step of 1e-7 moves T by far less than any jump (>= 0.1 here)."""
    p = dfchaos.Parameters(1.0, *bq)
    checked = [th for th in phases(p) if away_from_jumps(p, th)]
    assert len(checked) >= N_PHASES // 2
    for th in checked:
        assert abs(T(p, th + 1e-7) - T(p, th)) < 1e-3, th


@impl
@params
def test_agrees_with_direct_integration(T, bq):
    p = dfchaos.Parameters(1.0, *bq)
    checked = [th for th in phases(p)[::5] if away_from_jumps(p, th)]
    assert len(checked) >= 3
    for th in checked:
        assert T(p, th) == pytest.approx(integrated_T(1.0, *bq, th), abs=1e-6), th


@impl
@params
@pytest.mark.parametrize("scale", [0.25, 3.0, 1e3, 1e-7])
def test_invariant_under_scaling_a_b_q(T, bq, scale):
    """Only b/a and q/a matter (Section 2): the rounding of scale*b, scale*q moves T by ~1e-16 |T'|."""
    b, q = bq
    p, ps = dfchaos.Parameters(1.0, b, q), dfchaos.Parameters(scale, scale * b, scale * q)
    checked = [th for th in phases(p)[::2] if ps.t2 <= th < ps.t3 and away_from_jumps(p, th)]
    assert len(checked) >= N_PHASES // 4
    for th in checked:
        assert T(ps, th) == pytest.approx(T(p, th), abs=1e-10), th
