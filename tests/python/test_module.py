# SPDX-License-Identifier: GPL-3.0-or-later
"""Unit tier: the module's values, shapes and identities (no CLI needed)."""
import math
import pickle
import threading

import numpy as np
import pytest

import dfchaos

P = dfchaos.Parameters(1.0, 0.01, 0.85)


def phases(p, n, seed=1):
    return p.t2 + (p.t3 - p.t2) * np.random.default_rng(seed).random(n)


# ---- module and Parameters -------------------------------------------------------------------

def test_module_metadata():
    assert isinstance(dfchaos.__version__, str) and dfchaos.__version__.count(".") == 2
    assert dfchaos.scenario_names == ("A", "B", "C", "D", "C'", "D'", "G", "other")
    assert dfchaos.min_parameter == 1e-100 and dfchaos.max_parameter == 1e100
    assert dfchaos.min_map_ratio == 1e-12 and dfchaos.max_simulation_time == 1e12
    assert dfchaos.max_elements == 10**8
    assert issubclass(dfchaos.InvalidParameter, ValueError) and issubclass(dfchaos.GaveUp, RuntimeError)
    for f in (dfchaos.T, dfchaos.T1, dfchaos.step, dfchaos.orbit, dfchaos.simulate, dfchaos.covering_segments,
              dfchaos.lyapunov, dfchaos.rate, dfchaos.period, dfchaos.derivative, dfchaos.sweep):
        assert len(f.__doc__) > 200, f.__name__


def test_help_is_a_short_guide():
    """help(dfchaos): the docstring names every public function and both exceptions once; pydoc shows
    no inherited exception methods (the exceptions are left out of __all__, documented in the guide)."""
    import pydoc
    text = pydoc.render_doc(dfchaos, renderer=pydoc.plaintext)
    assert "inherited from builtins.BaseException" not in text
    assert len(text.splitlines()) < 450, len(text.splitlines())
    public = {n for n in vars(dfchaos) if not n.startswith("_")}
    assert set(dfchaos.__all__) == public - {"InvalidParameter", "GaveUp", "Interval", "Certified"}
    for name in public:
        assert name in dfchaos.__doc__, name
    assert dfchaos.__doc__.count("InvalidParameter ") == 1 and dfchaos.__doc__.count("GaveUp ") == 1
    assert len(dfchaos.__doc__.splitlines()) < 45


def test_vartheta0_solves_eq1():
    v = dfchaos.vartheta0
    assert 0 < v <= math.pi / 2
    assert abs(math.pi - v - 1 / math.tan(v / 2)) < 1e-15
    assert P.vartheta0 == v and dfchaos.sin_vartheta0 == pytest.approx(math.sin(v), abs=2e-16)


def test_phases_in_closed_form():
    a, b, q = 2.0, 0.1, 1.5
    p = dfchaos.Parameters(a, b, q)
    assert (p.a, p.b, p.q, p.c) == (a, b, q, b - q / 2)
    assert p.t0 == pytest.approx(math.asin((q - 2 * b) / a), abs=1e-15)
    assert p.t1 == pytest.approx(math.pi - math.asin((q - 2 * b) / a), abs=1e-15)
    assert p.t2 == pytest.approx(math.pi + math.asin(2 * b / a), abs=1e-15)
    assert p.t3 == pytest.approx(2 * math.pi - math.asin(2 * b / a), abs=1e-15)
    for t in (p.t2, p.t3):
        assert abs(p.F(t)) < 1e-15
    for t in (p.t0, p.t1):
        assert abs(p.F(t) - q) < 1e-15


def test_undefined_phases_are_none():
    p = dfchaos.Parameters(1.0, 0.7, 0.5)       # b > a/2: F never vanishes
    assert p.t2 is None and p.t3 is None and p.t0 is not None
    p = dfchaos.Parameters(1.0, 0.1, 1.5)       # q - 2b > a: F never reaches q
    assert p.t0 is None and p.t1 is None and p.t2 is not None


def test_assumptions_and_requirements():
    assert P.assumptions["eq2"] and P.assumptions["progression_ends"]
    P.require_return_map()
    P.require_eq2()
    low = dfchaos.Parameters(1.0, 0.01, 0.6)    # q below a sin(vartheta0): (2) fails, the map exists
    assert not low.assumptions["q_above_threshold"]
    low.require_return_map()
    with pytest.raises(ValueError):
        low.require_eq2()


def test_repr_and_pickle():
    p = dfchaos.Parameters(1.0, 0.1 + 0.2, 0.85)
    assert repr(p) == "dfchaos.Parameters(a=1, b=0.30000000000000004, q=0.85)"
    assert eval(repr(p), {"dfchaos": dfchaos}).b == p.b
    r = pickle.loads(pickle.dumps(p))
    assert (r.a, r.b, r.q, r.t2, r.t3) == (p.a, p.b, p.q, p.t2, p.t3)
    assert p.describe().startswith("a=1 b=0.30000000000000004")


# ---- T, T1: vectorized, shapes -----------------------------------------------------------------

@pytest.mark.parametrize("fn", [dfchaos.T, dfchaos.T1])
def test_scalars_give_floats(fn):
    for x in (4.0, 4, np.float64(4.0), np.float32(4.0), np.array(4.0), np.int64(4)):
        y = fn(P, x)
        assert type(y) is float, type(x)
        assert y == fn(P, float(x))


@pytest.mark.parametrize("fn", [dfchaos.T, dfchaos.T1])
@pytest.mark.parametrize("shape", [(0,), (1,), (7,), (2, 3), (2, 0), (3, 1, 2)])
def test_arrays_keep_their_shape_and_equal_scalar_calls(fn, shape):
    x = phases(P, int(np.prod(shape))).reshape(shape)
    y = fn(P, x)
    assert isinstance(y, np.ndarray) and y.dtype == np.float64 and y.shape == shape
    assert all(y.flat[i] == fn(P, float(x.flat[i])) for i in range(x.size))


def test_any_array_like():
    x = phases(P, 12)
    ref = dfchaos.T(P, x)
    assert np.array_equal(dfchaos.T(P, list(x)), ref)
    assert np.array_equal(dfchaos.T(P, tuple(x)), ref)
    assert np.array_equal(dfchaos.T(P, x[::2]), ref[::2])                    # non-contiguous
    m = x.reshape(3, 4)
    assert np.array_equal(dfchaos.T(P, np.asfortranarray(m)), ref.reshape(3, 4))
    assert np.array_equal(dfchaos.T(P, m.T), ref.reshape(3, 4).T)            # transposed view
    f32 = x.astype(np.float32)
    assert np.array_equal(dfchaos.T(P, f32), dfchaos.T(P, f32.astype(np.float64)))
    assert np.array_equal(dfchaos.T(P, np.array([4, 5])), dfchaos.T(P, [4.0, 5.0]))  # integers
    before = x.copy()
    dfchaos.T(P, x)
    assert np.array_equal(x, before)                                          # input untouched


def test_T_in_the_arc_and_T1_after_theta():
    x = phases(P, 2000)
    T = dfchaos.T(P, x)
    T1 = dfchaos.T1(P, x)
    assert np.all((T >= P.t2) & (T < P.t3))
    assert np.all(T1 > x)


# ---- step ---------------------------------------------------------------------------------------

ARRAY_KEYS = {"theta", "T1", "theta2", "T", "scenario", "elapsed", "penetration"}


def test_step_scalar_keys_and_types():
    s = dfchaos.step(P, 4.0)
    assert set(s) == ARRAY_KEYS | {"chain", "progressions", "hit_velocity"}
    assert s["theta"] == 4.0 and s["scenario"] in dfchaos.scenario_names
    assert s["chain"] == "f>p>f" and s["scenario"] == "A" and s["progressions"] == 1
    assert s["T1"] <= s["theta2"] and s["elapsed"] > 0 and s["penetration"] > 0 and s["hit_velocity"] > 0


@pytest.mark.parametrize("shape", [(5,), (2, 3), (0,)])
def test_step_array_equals_scalar_steps(shape):
    x = phases(P, int(np.prod(shape)), seed=5).reshape(shape)
    s = dfchaos.step(P, x)
    assert set(s) == ARRAY_KEYS
    for k in ARRAY_KEYS:
        assert s[k].shape == shape, k
    assert s["scenario"].dtype.kind == "U"
    for i in range(x.size):
        one = dfchaos.step(P, float(x.flat[i]))
        for k in ARRAY_KEYS:
            assert s[k].flat[i] == one[k], k


def test_step_identities():
    """T, T1 as from dfchaos.T and dfchaos.T1; Lemma 3: T = t2 exactly after a stop (B, C);
    theta2 mod 2 pi = T in scenario A (Eq. 17: the progression ends the step)."""
    x = np.linspace(P.t2, P.t3, 4001)[:-1]
    s = dfchaos.step(P, x)
    assert np.array_equal(s["T"], dfchaos.T(P, x))
    assert np.array_equal(s["T1"], dfchaos.T1(P, x))
    assert set(np.unique(s["scenario"])) <= set(dfchaos.scenario_names)
    stop = np.isin(s["scenario"], ["B", "C"])
    assert stop.sum() > 10 and np.all(s["T"][stop] == P.t2)
    a = s["scenario"] == "A"
    assert np.allclose(np.mod(s["theta2"][a], 2 * np.pi), s["T"][a], atol=1e-9)
    assert np.allclose(s["elapsed"][a], s["theta2"][a] - x[a], rtol=1e-14, atol=1e-11)


# ---- orbit --------------------------------------------------------------------------------------

def test_orbit_iterates_T():
    o = dfchaos.orbit(P, 3.5, 400)
    assert set(o) == {"theta", "scenario", "elapsed", "penetration", "time", "y"}
    assert all(v.shape == (400,) for v in o.values())
    assert o["theta"][0] == 3.5 and o["time"][0] == 3.5 and o["y"][0] == 0.0
    assert np.array_equal(o["theta"][1:], dfchaos.T(P, o["theta"][:-1]))
    s = dfchaos.step(P, o["theta"])
    for k in ("scenario", "elapsed", "penetration"):
        assert np.array_equal(o[k], s[k])
    assert np.allclose(np.diff(o["time"]), o["elapsed"][:-1], rtol=1e-12)
    assert np.allclose(np.diff(o["y"]), o["penetration"][:-1], rtol=1e-9, atol=1e-12)
    assert len(dfchaos.orbit(P, 3.5, 1)["theta"]) == 1


# ---- simulate -----------------------------------------------------------------------------------

def test_simulate_structure():
    r = dfchaos.simulate(P, 0.0, 0.0, 0.0, 4.0, 600.0, sample=0.5)
    assert r["initial_regime"] in ("f", "p", "s")
    ev, sm = r["events"], r["samples"]
    assert set(ev) == {"t", "phase", "before", "after", "kind", "x", "y", "v_before", "v_after"}
    n = len(ev["t"])
    assert n > 5 and all(len(v) == n for v in ev.values())
    assert np.all(np.diff(ev["t"]) >= 0) and np.all((ev["phase"] >= 0) & (ev["phase"] < 2 * np.pi))
    assert set(ev["kind"]) <= {"fp", "is"} and set(ev["before"]) | set(ev["after"]) <= {"f", "p", "s"}
    assert np.all(ev["after"][:-1] == ev["before"][1:])       # the regimes chain up
    assert len(sm["t"]) == 1193 and np.allclose(np.diff(sm["t"]), 0.5)
    assert np.all(sm["x"] <= sm["y"] + 1e-9)                  # the mass never passes the delimiter
    assert np.all(np.diff(sm["y"]) >= -1e-12)                 # the delimiter only advances
    assert r["final"]["t"] == 600.0 and r["final"]["regime"] in ("f", "p", "s")
    none = dfchaos.simulate(P, 0.0, 0.0, 0.0, 4.0, 600.0)
    assert len(none["samples"]["t"]) == 0 and np.array_equal(none["events"]["t"], ev["t"])


def test_simulate_agrees_with_the_map():
    """Section 3: from rest at the delimiter at theta in [t2, t3), the first return to free flight
    of the full system happens at the instant theta + elapsed, with phase T(theta)."""
    theta = 4.0
    s = dfchaos.step(P, theta)
    r = dfchaos.simulate(P, 0.0, 0.0, 0.0, theta, theta + s["elapsed"] + 1.0)
    ev = r["events"]
    back = np.flatnonzero(ev["after"] == "f")
    assert back.size >= 1
    assert ev["phase"][back[0]] == pytest.approx(s["T"], abs=1e-10)
    assert ev["t"][back[0]] == pytest.approx(theta + s["elapsed"], abs=1e-9)


# ---- covering ------------------------------------------------------------------------------------

def test_covering_segments_cover():
    p = dfchaos.Parameters(1.0, 0.002, 0.85)
    segs = dfchaos.covering_segments(p)
    assert len(segs) >= 2
    top = 1.5 * np.pi
    for j, s in enumerate(segs):
        assert p.t2 <= s["lo"] < s["hi"] <= top and s["rechecked"]
        assert s["lo"] <= s["theta_at_t2"] <= s["hi"] and s["lo"] <= s["theta_at_top"] <= s["hi"]
        assert dfchaos.T(p, s["theta_at_t2"]) == p.t2
        assert dfchaos.T(p, s["theta_at_top"]) == s["T_at_top"] >= top
        assert set(s["label"]) == {"t1_branch", "t3_passed", "scenario_d"}
        if j:
            assert segs[j - 1]["hi"] < s["lo"]
    l4 = dfchaos.lemma4_covering(p)
    assert l4["holds"] and l4["segments_found"] == 2
    assert (l4["J0"]["lo"], l4["J1"]["lo"]) == (segs[0]["lo"], segs[1]["lo"])
    assert len(dfchaos.covering_segments(p, max_segments=1)) == 1


def test_covering_branchwise_agrees_with_dense():
    top = 1.5 * np.pi
    for b, q in [(0.002, 0.85), (1e-4, 0.8), (0.05, 0.9)]:
        p = dfchaos.Parameters(1.0, b, q)
        bw = dfchaos.lemma4_covering(p, method="branchwise")
        assert bw["holds"] == dfchaos.lemma4_covering(p)["holds"]
        for s in dfchaos.covering_segments(p, method="branchwise", max_segments=2):
            assert s["rechecked"] and dfchaos.T(p, s["theta_at_t2"]) == p.t2
            assert dfchaos.T(p, s["theta_at_top"]) >= top
    with pytest.raises(ValueError, match="method"):
        dfchaos.lemma4_covering(dfchaos.Parameters(1.0, 0.002, 0.85), method="fast")


# ---- threads: the GIL is released and the library is reentrant ----------------------------------

def test_threads_give_the_same_values():
    x = phases(P, 4000, seed=9)
    ref = dfchaos.T(P, x)
    parts = np.array_split(x, 4)
    out = [None] * 4

    def work(k):
        out[k] = dfchaos.T(P, parts[k])

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert np.array_equal(np.concatenate(out), ref)


def test_ctrl_c_stops_a_long_call():
    """The loop runs without the GIL but looks for signals every 2^14 elements: an interrupt
    (as from Ctrl-C) stops a call of about 10 s within a fraction of a second."""
    import _thread
    import time

    x = np.full(4_000_000, 4.0)
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            dfchaos.T(P, x)
    finally:
        timer.cancel()
    assert time.perf_counter() - start < 3.0


@pytest.mark.crossval
def test_certify_writes_the_certificate_of_the_cli(cli, tmp_path):
    """certificate= writes the same bytes as `dfchaos certify --certificate`, and dfchaos-recheck accepts them."""
    import os
    import subprocess
    mine, theirs = tmp_path / "py.json", tmp_path / "cli.json"
    rec = dfchaos.certify("lemma1", b=(0.001, 0.0035), q=(0.73, 0.76), certificate=str(mine))
    rc, out, err = cli.run("certify", "lemma1", "--b", "0.001:0.0035", "--q", "0.73:0.76", "--certificate", str(theirs))
    assert rc == 0, err
    assert mine.read_bytes() == theirs.read_bytes()
    assert rec["certificate"]["bytes"] == os.path.getsize(mine) and len(rec["certificate"]["sha256"]) == 64
    checker = os.path.join(os.path.dirname(cli.path), "dfchaos-recheck")
    proc = subprocess.run([checker, str(mine)], capture_output=True, text=True)
    assert proc.returncode == 0 and proc.stdout.startswith("OK "), proc.stdout + proc.stderr
    # the covering (Lemma 4), Theorem 2's conclusion and a periodic orbit (Sections 6-7), likewise
    for what, args, kw in (("covering", ["--b", "0.001", "--q", "0.85"], dict(b=0.001, q=0.85)),
                           ("superstable", ["--b", "0.0641", "--q", "0.85"], dict(b=0.0641, q=0.85)),
                           ("periodic", ["--b", "0.001", "--q", "0.85", "--period", "3"], dict(b=0.001, q=0.85, period=3))):
        mine, theirs = tmp_path / f"py-{what}.json", tmp_path / f"cli-{what}.json"
        dfchaos.certify(what, certificate=str(mine), **kw)
        rc, out, err = cli.run("certify", what, *args, "--certificate", str(theirs))
        assert rc == 0, err
        assert mine.read_bytes() == theirs.read_bytes(), what
        proc = subprocess.run([checker, str(mine)], capture_output=True, text=True)
        assert proc.returncode == 0 and proc.stdout.startswith(f"OK {mine}: {what}"), proc.stdout + proc.stderr


@pytest.mark.failure
def test_certify_certificate_refusals(tmp_path):
    """No certificate for a statement not proved, InvalidParameter for an empty path, OSError for a bad path."""
    rec = dfchaos.certify("lemma1", b=0.05, q=0.73, certificate=str(tmp_path / "c.json"))
    assert rec["proved"] is False and rec["certificate"]["written"] is False
    with pytest.raises(dfchaos.InvalidParameter, match="certificate"):
        dfchaos.certify("vartheta0", certificate="")
    (tmp_path / "plain").write_text("a file\n")
    with pytest.raises(OSError, match="certificate"):
        dfchaos.certify("vartheta0", certificate=str(tmp_path / "plain" / "c.json"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plain"]


@pytest.mark.crossval
def test_certify_matches_the_cli_and_refuses_bad_input(cli):
    """dfchaos.certify gives the record of `dfchaos certify`, as a dict."""
    import json
    rec = dfchaos.certify("covering", a=1.0, b=0.001, q=0.85)
    rc, out, err = cli.run("certify", "covering", "--a", "1", "--b", "0.001", "--q", "0.85")
    assert rc == 0, err
    def untimed(x):  # the records carry the time the proof took, which differs between runs
        if isinstance(x, dict):
            return {k: untimed(v) for k, v in x.items() if k != "seconds"}
        if isinstance(x, list):
            return [untimed(v) for v in x]
        return x
    assert untimed(rec) == untimed(json.loads(out))
    assert rec["proved"] is True
    # at the point of a Parameters, as the module's other functions take it; the
    # tool's a defaults to 1 as the module's does
    assert untimed(dfchaos.certify("covering", dfchaos.Parameters(1.0, 0.001, 0.85))) == untimed(rec)
    rc, out, err = cli.run("certify", "covering", "--b", "0.001", "--q", "0.85")
    assert rc == 0 and untimed(json.loads(out)) == untimed(rec), err
    v = dfchaos.certify("vartheta0")
    assert v["proved"] is True
    # a box in b; a false statement is not proved (exit 1 in the CLI), not an error
    assert dfchaos.certify("covering", b=(0.003, 0.00300001), q=0.85)["proved"] is True
    assert dfchaos.certify("covering", b=0.02, q=0.85)["proved"] is False
    with pytest.raises(dfchaos.InvalidParameter, match="b:"):
        dfchaos.certify("covering", b=0.6, q=0.85)
    with pytest.raises(dfchaos.InvalidParameter, match="b:"):
        dfchaos.certify("covering", b=float("nan"), q=0.85)
