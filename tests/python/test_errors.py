# SPDX-License-Identifier: GPL-3.0-or-later
"""Failure tier: bad input raises ValueError (dfchaos.InvalidParameter) with the CLI's one-line
message, or TypeError for what is not a real number; a computation that gives up raises
dfchaos.GaveUp (a RuntimeError) with the CLI's message. Nothing crashes, nothing is computed first.
"""
import numpy as np
import pytest

import dfchaos

pytestmark = pytest.mark.failure

P = dict(a=1.0, b=0.01, q=0.85)
P_ARGS = ["--a", "1", "--b", "0.01", "--q", "0.85"]
NAN, INF = float("nan"), float("inf")


def model(a=1.0, b=0.01, q=0.85):
    return dfchaos.Parameters(a, b, q)


def sim(**kw):
    """simulate with a valid start, some arguments replaced."""
    start = dict(x0=0.0, y0=0.0, v0=0.0, t0=4.0, t_end=50.0)
    start.update({k: v for k, v in kw.items() if k in start})
    options = {k: v for k, v in kw.items() if k not in start}
    return lambda: dfchaos.simulate(model(), *start.values(), **options)


SIM_CLI = ["simulate", *P_ARGS, "--x0", "0", "--y0", "0", "--v0", "0", "--t0", "4", "--t-end", "50"]


def sim_cli(**kw):
    args = list(SIM_CLI)
    for name, value in kw.items():
        flag = "--" + name.replace("_", "-")
        if flag in args:
            args[args.index(flag) + 1] = value
        else:
            args += [flag, value]
    if "sample" in kw:  # the tool writes samples to a file of their own (refused here before it is opened)
        args += ["--samples-out", "/nonexistent-dfchaos-dir/samples.tsv"]
    return args


# (the module's call, the CLI's arguments giving the same refusal, the parameter named)
CASES = [
    (lambda: model(a=NAN), ["map", "--a", "nan", "--b", "0.01", "--q", "0.85", "--theta", "4"], "a"),
    (lambda: model(a=INF), ["map", "--a", "inf", "--b", "0.01", "--q", "0.85", "--theta", "4"], "a"),
    (lambda: model(a=0.0), ["map", "--a", "0", "--b", "0.01", "--q", "0.85", "--theta", "4"], "a"),
    (lambda: model(a=-1.0), ["map", "--a", "-1", "--b", "0.01", "--q", "0.85", "--theta", "4"], "a"),
    (lambda: model(a=1e101), ["map", "--a", "1e101", "--b", "0.01", "--q", "0.85", "--theta", "4"], "a"),
    (lambda: model(b=0.0), ["map", "--a", "1", "--b", "0", "--q", "0.85", "--theta", "4"], "b"),
    (lambda: model(q=-2.0), ["map", "--a", "1", "--b", "0.01", "--q", "-2", "--theta", "4"], "q"),
    (lambda: dfchaos.T(model(b=0.5), 4.0), ["map", "--a", "1", "--b", "0.5", "--q", "0.85", "--theta", "4"], "b"),
    (lambda: dfchaos.T1(model(b=0.5), [4.0]), ["map", "--a", "1", "--b", "0.5", "--q", "0.85", "--theta", "4"], "b"),
    (lambda: dfchaos.step(model(b=0.3, q=0.5), 4.0), ["map", "--a", "1", "--b", "0.3", "--q", "0.5", "--theta", "4"], "q"),
    (lambda: dfchaos.T(model(b=1e-13), 4.0), ["map", "--a", "1", "--b", "1e-13", "--q", "0.85", "--theta", "4"], "b"),
    (lambda: dfchaos.orbit(model(b=0.7), 4.0, 3), ["orbit", "--a", "1", "--b", "0.7", "--q", "0.85", "--theta0", "4",
                                                     "--steps", "3"], "b"),
    (lambda: dfchaos.T(model(), 1.0), ["map", *P_ARGS, "--theta", "1.0"], "theta"),
    (lambda: dfchaos.T(model(), [4.0, 7.0]), ["map", *P_ARGS, "--theta", "4.0", "7.0"], "theta"),
    (lambda: dfchaos.T1(model(), np.array([[4.0], [7.0]])), ["map", *P_ARGS, "--theta", "4.0", "7.0"], "theta"),
    (lambda: dfchaos.step(model(), 7.0), ["map", *P_ARGS, "--theta", "7.0"], "theta"),
    (lambda: dfchaos.T(model(), NAN), ["map", *P_ARGS, "--theta", "nan"], "theta"),
    (lambda: dfchaos.T(model(), INF), ["map", *P_ARGS, "--theta", "inf"], "theta"),
    (lambda: dfchaos.orbit(model(), 6.5, 3), ["orbit", *P_ARGS, "--theta0", "6.5", "--steps", "3"], "theta0"),
    (lambda: dfchaos.orbit(model(), NAN, 3), ["orbit", *P_ARGS, "--theta0", "nan", "--steps", "3"], "theta0"),
    (lambda: dfchaos.orbit(model(), 4.0, 0), ["orbit", *P_ARGS, "--theta0", "4", "--steps", "0"], "steps"),
    (lambda: dfchaos.orbit(model(), 4.0, 10**8 + 1), ["orbit", *P_ARGS, "--theta0", "4", "--steps", "100000001"], "steps"),
    (sim(x0=1.0), sim_cli(x0="1"), "x0"),
    (sim(x0=NAN), sim_cli(x0="nan"), "x0"),
    (sim(v0=1e101), sim_cli(v0="1e101"), "v0"),
    (sim(t_end=3.0), sim_cli(t_end="3"), "t-end"),
    (sim(t0=-2e12), sim_cli(t0="-2e12"), "t0"),
    (sim(t_end=INF), sim_cli(t_end="inf"), "t-end"),
    (sim(sample=0.0), sim_cli(sample="0"), "sample"),
    (sim(sample=-1.0), sim_cli(sample="-1"), "sample"),
    (sim(sample=1e-6), sim_cli(sample="1e-6"), "sample"),
    (sim(max_events=0), sim_cli(max_events="0"), "max-events"),
]


@pytest.mark.parametrize("call,cli_args,name", CASES, ids=[" ".join(c[1]) for c in CASES])
def test_message_is_the_clis(cli, call, cli_args, name):
    expected = cli.error(*cli_args)
    with pytest.raises(ValueError) as info:
        call()
    e = info.value
    assert isinstance(e, dfchaos.InvalidParameter)
    assert str(e) == expected
    assert e.parameter == name
    assert "\n" not in str(e)


def test_gave_up_is_a_runtime_error_with_the_clis_message(cli):
    """b = 0.45, q = 0.95: the progression from t0 never ends in free flight (test_return_map)."""
    p = model(b=0.45, q=0.95)
    rc, _, err = cli.run("map", "--a", "1", "--b", "0.45", "--q", "0.95", "--theta", "4.5")
    assert rc == 1 and err.startswith("dfchaos: gave up: ")
    for call in (lambda: dfchaos.T(p, 4.5), lambda: dfchaos.T(p, [4.5]), lambda: dfchaos.step(p, 4.5),
                 lambda: dfchaos.orbit(p, 4.5, 10)):
        with pytest.raises(dfchaos.GaveUp) as info:
            call()
        assert isinstance(info.value, RuntimeError)
        assert str(info.value) == err.strip()[len("dfchaos: gave up: "):]


def test_event_limit_gives_up(cli):
    rc, _, err = cli.run(*sim_cli(t_end="1e4", max_events="5"))
    assert rc == 1
    with pytest.raises(dfchaos.GaveUp) as info:
        dfchaos.simulate(model(), 0.0, 0.0, 0.0, 4.0, 1e4, max_events=5)
    assert str(info.value) == err.strip()[len("dfchaos: gave up: "):]


@pytest.mark.parametrize("fn", [dfchaos.T, dfchaos.T1, dfchaos.step])
@pytest.mark.parametrize("bad", [NAN, INF, -INF])
def test_non_finite_element_is_named_with_its_index_before_any_work(fn, bad):
    """The first element is out of the arc, which the library would refuse on its own; the
    non-finite element further on is reported instead, so the check ran before the loop."""
    x = np.full((3, 4), 4.0)
    x[0, 0] = 1.0
    x[2, 1] = bad
    with pytest.raises(ValueError) as info:
        fn(model(), x)
    spelled = "nan" if np.isnan(bad) else ("inf" if bad > 0 else "-inf")
    assert str(info.value) == f"theta: must be a finite number (got '{spelled}' at flat index 9)"
    assert info.value.parameter == "theta"


@pytest.mark.parametrize("bad", ["4.0", ["4.0", "5.0"], None, [4.0, None], 4.0 + 1j, np.array([4.0 + 0j]),
                                 np.array([True]), {"theta": 4.0}, object()])
def test_not_real_numbers_raise_type_error(bad):
    with pytest.raises(TypeError) as info:
        dfchaos.T(model(), bad)
    assert "theta" in str(info.value)


def test_too_many_elements_refused_before_copying():
    huge = np.broadcast_to(4.0, (10**8 + 1,))  # a zero-stride view: copying it would take 800 MB
    with pytest.raises(ValueError) as info:
        dfchaos.T(model(), huge)
    assert str(info.value) == "theta: must satisfy number of elements <= 1e8 (got 100000001)"


def test_wrong_argument_types():
    with pytest.raises(TypeError):
        dfchaos.T((1.0, 0.01, 0.85), 4.0)       # not a Parameters
    with pytest.raises(TypeError):
        dfchaos.Parameters("1", 0.01, 0.85)
    with pytest.raises(TypeError):
        dfchaos.orbit(model(), 4.0, 2.5)        # steps is an integer


def test_parameters_are_immutable():
    p = model()
    with pytest.raises(AttributeError):
        p.b = 0.02
    assert p.b == 0.01


def test_covering_refuses_a_bad_interval():
    p = model()
    with pytest.raises(ValueError) as info:
        dfchaos.covering_segments(p, 4.0, 3.9)
    assert info.value.parameter == "lo, hi"
    with pytest.raises(ValueError) as info:
        dfchaos.covering_segments(model(b=0.6))
    assert info.value.parameter == "b"
