# SPDX-License-Identifier: GPL-3.0-or-later
"""Failure tier (reliability): no object of the module exists in an unchecked state, and
every keyword argument of every function is checked before any work, with one line naming it and
the condition it breaks (dfchaos.InvalidParameter, a ValueError), or a TypeError for a wrong type.
"""
import math
import os
import pickle
import subprocess
import sys
import textwrap

import pytest

import dfchaos

pytestmark = pytest.mark.failure

P = dict(a=1.0, b=0.01, q=0.85)


def model():
    return dfchaos.Parameters(**P)


def unconstructed(cls=dfchaos.Parameters):
    """An object made by __new__ without __init__ (pybind11 allows it)."""
    return cls.__new__(cls)


# ---- item 9: Parameters.__new__ without __init__ ------------------------------------------------

def test_parameters_is_the_only_class_bound():
    """The checks below cover every class of the module bound to C++: a new class must be added to them.
    Interval and Certified are pure Python types (a tuple and a dict subclass): they hold no C++ state."""
    classes = {name for name, obj in vars(dfchaos).items()
               if isinstance(obj, type) and not issubclass(obj, BaseException)}
    assert classes == {"Parameters", "Interval", "Certified"}
    for name in ("Interval", "Certified"):
        assert not issubclass(vars(dfchaos)[name], dfchaos.Parameters.__mro__[1]), name  # not a pybind11 object


def periodic_orbit_01(p):
    """periodic_orbit at p; at the model's b/a = 0.01 no covering is found (InvalidParameter): the call
    got past the check of the Parameters, which is what is tested here."""
    try:
        return dfchaos.periodic_orbit(p, "01")
    except dfchaos.InvalidParameter:
        return None


def follow_orbit_01(p):
    """follow_orbit at p, as periodic_orbit_01 (its start is periodic_orbit)."""
    try:
        return dfchaos.follow_orbit(p, "01", 0.0101)
    except dfchaos.InvalidParameter:
        return None


# Every use of a Parameters: its properties, its methods, pickling, every function taking one.
USES = {
    **{f"property {name}": (lambda name: lambda p: getattr(p, name))(name)
       for name, attr in vars(dfchaos.Parameters).items() if isinstance(attr, property)},
    "F": lambda p: p.F(1.0),
    "require_return_map": lambda p: p.require_return_map(),
    "require_eq2": lambda p: p.require_eq2(),
    "describe": lambda p: p.describe(),
    "pickle": lambda p: pickle.dumps(p),
    "T": lambda p: dfchaos.T(p, 4.0),
    "T array": lambda p: dfchaos.T(p, [4.0, 4.5]),
    "T1": lambda p: dfchaos.T1(p, 4.0),
    "step": lambda p: dfchaos.step(p, 4.0),
    "orbit": lambda p: dfchaos.orbit(p, 4.0, 3),
    "simulate": lambda p: dfchaos.simulate(p, 0.0, 0.0, 0.0, 4.0, 10.0),
    "covering_segments": lambda p: dfchaos.covering_segments(p, method="branchwise"),
    "lemma4_covering": lambda p: dfchaos.lemma4_covering(p, method="branchwise"),
    "_bench_T": lambda p: dfchaos._bench_T(p, [4.0]),
    "lyapunov": lambda p: dfchaos.lyapunov(p, 4.0, 3, 0),
    "rate": lambda p: dfchaos.rate(p, steps=3, transient=0),
    "period": lambda p: dfchaos.period(p, steps=3, transient=0),
    "derivative": lambda p: dfchaos.derivative(p, 4.0),
    "periodic_orbit": periodic_orbit_01,
    "follow_orbit": follow_orbit_01,
    "certify at a Parameters": lambda p: dfchaos.certify("covering", p),
}


def test_every_use_is_listed():
    """Every property of Parameters and every function of the module taking one is in USES."""
    assert {f"property {n}" for n in ("a", "b", "q", "c", "t0", "t1", "t2", "t3", "assumptions")} <= set(USES)
    functions = {name for name, f in vars(dfchaos).items() if callable(f) and not isinstance(f, type)}
    # sweep and orbit_diagram take axes, not a Parameters; certify takes one in its second form (listed
    # above under its own name)
    assert functions - {"certify", "sweep", "orbit_diagram"} == {k for k in USES if k in functions}


@pytest.mark.parametrize("cls", [dfchaos.Parameters, type("Sub", (dfchaos.Parameters,), {})], ids=["Parameters", "subclass"])
@pytest.mark.parametrize("use", list(USES), ids=list(USES))
def test_unconstructed_parameters_refused_everywhere(cls, use):
    u = unconstructed(cls)
    with pytest.raises(TypeError) as info:
        USES[use](u)
    assert "never initialised" in str(info.value) and "Parameters(a, b, q)" in str(info.value)
    assert "\n" not in str(info.value)


def test_unconstructed_parameters_repr_and_later_init():
    u = unconstructed()
    assert repr(u) == "<dfchaos.Parameters, not initialised>"
    u.__init__(**P)  # what unpickling does after __new__
    assert repr(u) == repr(model()) and dfchaos.T(u, 4.0) == dfchaos.T(model(), 4.0)
    assert pickle.loads(pickle.dumps(u)).b == P["b"]


def test_constructed_parameters_still_work():
    for call in USES.values():
        call(model())


# ---- item 10: every keyword argument checked ---------------------------------------------------

def refusal(call, name):
    """The InvalidParameter raised by call(), which must name `name` and its condition, in one line."""
    with pytest.raises(ValueError) as info:
        call()
    e = info.value
    assert isinstance(e, dfchaos.InvalidParameter)
    assert e.parameter == name and str(e).startswith(f"{name}: must "), str(e)
    assert "\n" not in str(e) and "nan" not in str(e).split("(got")[0]
    return str(e)


SEARCHES = [dfchaos.covering_segments, dfchaos.lemma4_covering]
SEARCH_IDS = ["covering_segments", "lemma4_covering"]


@pytest.mark.parametrize("method", ["dense", "branchwise"])
@pytest.mark.parametrize("search", SEARCHES, ids=SEARCH_IDS)
@pytest.mark.parametrize("recheck", [-1, 0, 1, 3, 10**8 + 1])
def test_recheck_that_would_not_recheck_is_refused(search, method, recheck):
    """recheck < 2 used to mark segments rechecked=True with no re-check run (< 4: no jump test)."""
    msg = refusal(lambda: search(model(), method=method, recheck=recheck), "recheck")
    assert msg == f"recheck: must satisfy 4 <= recheck <= 1e8 (got {recheck})"


@pytest.mark.parametrize("search", SEARCHES, ids=SEARCH_IDS)
@pytest.mark.parametrize("refine", [0, -1, 10**8 + 1])
def test_refine_is_checked(search, refine):
    """refine = 0 used to fail deep inside, naming theta and -nan."""
    msg = refusal(lambda: search(model(), refine=refine), "refine")
    assert msg == f"refine: must satisfy 1 <= refine <= 1e8 (got {refine})"


@pytest.mark.parametrize("search", SEARCHES, ids=SEARCH_IDS)
@pytest.mark.parametrize("name,value,condition", [
    ("scan", 1, "scan >= 2"),
    ("scan", 10**8 + 1, "scan <= 1e8"),
    ("uniform", -1, "uniform >= 0"),
    ("uniform", 10**8 + 1, "uniform <= 1e8"),
    ("max_segments", -1, "max_segments >= 0 (0: all)"),
    ("max_branches", 0, "max_branches >= 1"),
])
def test_search_counts_are_checked(search, name, value, condition):
    msg = refusal(lambda: search(model(), **{name: value}), name)
    assert msg == f"{name}: must satisfy {condition} (got {value})"


@pytest.mark.parametrize("search", SEARCHES, ids=SEARCH_IDS)
def test_covering_work_budget_gives_up_before_any_work(search):
    """At b/a = 1e-8, [t2, 3 pi/2] holds 1.6e7 branches of T1, more than the default
    budget: GaveUp at once, naming it; a larger max_branches is accepted (not run here)."""
    p = dfchaos.Parameters(1.0, 1e-8, 0.85)
    with pytest.raises(dfchaos.GaveUp, match="max_branches"):
        search(p, method="branchwise")
    with pytest.raises(dfchaos.GaveUp, match="budget of 10 "):
        search(dfchaos.Parameters(1.0, 1e-4, 0.85), method="branchwise", max_branches=10)


@pytest.mark.parametrize("search", SEARCHES, ids=SEARCH_IDS)
@pytest.mark.parametrize("descend", [0, 1, None, "yes"])
def test_descend_must_be_a_bool(search, descend):
    with pytest.raises(TypeError):
        search(model(), descend=descend)


@pytest.mark.parametrize("top", [1.0, "t2", "t3", 6.3, math.nan, math.inf])
def test_top_lies_in_the_arc(top):
    """T takes values in [t2, t3): another top gives no segment, or segments of zero length."""
    p = model()
    top = {"t2": p.t2, "t3": p.t3}.get(top, top)
    msg = refusal(lambda: dfchaos.covering_segments(p, top=top), "top")
    if math.isfinite(top):
        assert msg.startswith("top: must satisfy t2 < top < t3 = (3.16")
    else:
        assert msg.startswith("top: must be a finite number")


def test_smallest_accepted_values_run():
    p = model()
    segs = dfchaos.covering_segments(p, method="branchwise", recheck=4, max_segments=0)
    assert all(s["rechecked"] is True for s in segs)
    r = dfchaos.lemma4_covering(p, method="branchwise", refine=1, recheck=4, scan=2, uniform=0, max_segments=0, descend=False)
    assert r["holds"] in (True, False)


@pytest.mark.parametrize("t", [math.nan, math.inf, -math.inf])
def test_F_wants_a_finite_t(t):
    refusal(lambda: model().F(t), "t")


def test_max_events_bound_is_the_tools(cli):
    args = ["simulate", "--a", "1", "--b", "0.01", "--q", "0.85", "--x0", "0", "--y0", "0", "--v0", "0", "--t0", "4",
            "--t-end", "50", "--max-events", str(10**8 + 1)]
    expected = cli.error(*args)
    with pytest.raises(dfchaos.InvalidParameter) as info:
        dfchaos.simulate(model(), 0.0, 0.0, 0.0, 4.0, 50.0, max_events=10**8 + 1)
    assert str(info.value) == expected


# ---- std::bad_alloc becomes MemoryError ----------------------------------------------------------

@pytest.mark.skipif("asan" in os.environ.get("LD_PRELOAD", ""), reason="an address-space limit breaks the sanitizer")
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS as on Linux")
def test_bad_alloc_is_memory_error():
    """simulate's 5e6 samples (about 200 MB in a std::vector) under an address-space limit 64 MB
    above what the interpreter already maps: the library's std::bad_alloc reaches Python as
    MemoryError. In a child process, so that the limit binds nothing else."""
    code = textwrap.dedent("""
        import resource, dfchaos
        with open("/proc/self/statm") as f:
            mapped = int(f.read().split()[0]) * resource.getpagesize()
        limit = mapped + 64 * 2**20
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        try:
            dfchaos.simulate(dfchaos.Parameters(1.0, 0.01, 0.85), 0.0, 0.0, 0.0, 4.0, 4.0 + 499.0, sample=1e-4)
        except MemoryError as e:
            print("MemoryError", type(e).__name__)
        else:
            print("no error")
    """)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["MemoryError", "MemoryError"]
