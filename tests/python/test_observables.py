# SPDX-License-Identifier: GPL-3.0-or-later
"""The observables of one parameter set and the sweep, against `dfchaos sweep`.

dfchaos.lyapunov, rate and period call the C++ function behind the sweep's columns
(sweep::plane_orbit), dfchaos.sweep the sweep's engine: each must equal the tool's TSV to the last
bit (the file has %.17g, which reads back to the same double). dfchaos.derivative is T', whose
logarithm the Lyapunov exponent averages. Bad input gives the tool's message.
"""
import math

import numpy as np
import pytest

import dfchaos

# (a, b/a, q/a): scenarios A to D, a chaotic and a periodic regime, a != 1.
ORBIT_SETS = [
    (1.0, 0.01, 0.85),
    (1.0, 0.1, 0.85),
    (1.0, 0.05, 0.7),
    (1.0, 1e-3, 0.8),
    (2.5, 0.012, 0.76),
    (1.0, 0.1, 0.95),
]


def one(x):
    return f"{x!r}:{x!r}:1"


def sweep_table(cli, *args):
    """The tool's sweep on stdout: (header text: the column line and the '#' lines after it, column
    names, rows)."""
    rc, out, err = cli.run("sweep", *args)
    assert rc == 0, err
    return split_sweep(out)


def split_sweep(text):
    lines = text.splitlines(keepends=True)
    k = next(i for i in range(1, len(lines)) if not lines[i].startswith("#"))  # the first row
    names = lines[0].rstrip("\n").split("\t")
    rows = [l.rstrip("\n").split("\t") for l in lines[k:] if not l.startswith("#")]
    return "".join(lines[:k]), names, rows


def model(a, b_over_a, q_over_a):
    """The parameters of a sweep's cell, made as the sweep makes them (q = (q/a) a, b = (b/a) a)."""
    return dfchaos.Parameters(a, b_over_a * a, q_over_a * a)


@pytest.mark.crossval
@pytest.mark.parametrize("abq", ORBIT_SETS)
@pytest.mark.parametrize("fraction", [0.5, 0.377])
def test_orbit_observables_equal_a_one_cell_sweep(cli, abq, fraction):
    a, bo, qo = abq
    _, names, rows = sweep_table(cli, "--a", repr(a), "--q-range", one(qo), "--b-range", one(bo), "--observables",
                                 "lyapunov,rate,period", "--theta0-fraction", repr(fraction), "--transient", "300", "--steps", "500",
                                 "--period-max", "40", "--period-tol", "1e-8")
    assert len(rows) == 1 and rows[0][names.index("status")] == "ok", rows
    row = dict(zip(names, rows[0]))
    p = model(a, bo, qo)
    theta0 = p.t2 + fraction * (p.t3 - p.t2)
    lyap = dfchaos.lyapunov(p, theta0, steps=500, transient=300)
    rate = dfchaos.rate(p, theta0=theta0, steps=500, transient=300)
    period = dfchaos.period(p, theta0, 500, 300, period_max=40, period_tol=1e-8)
    assert lyap == float(row["lyapunov"]), (lyap, row["lyapunov"])
    assert rate == float(row["rate"]), (rate, row["rate"])
    assert isinstance(period, int) and period == float(row["period"]), (period, row["period"])
    if fraction == 0.5:  # theta0=None is the sweep's default start
        assert dfchaos.lyapunov(p, steps=500, transient=300) == lyap
        assert dfchaos.rate(p, None, 500, 300) == rate
        assert dfchaos.period(p, steps=500, transient=300, period_max=40, period_tol=1e-8) == period


@pytest.mark.crossval
def test_orbit_observables_default_settings(cli):
    """The defaults of lyapunov, rate and period are the sweep's defaults."""
    _, names, rows = sweep_table(cli, "--q-range", one(0.85), "--b-range", one(0.01), "--observables", "lyapunov,rate,period")
    row = dict(zip(names, rows[0]))
    p = dfchaos.Parameters(1.0, 0.01, 0.85)
    assert dfchaos.lyapunov(p) == float(row["lyapunov"])
    assert dfchaos.rate(p) == float(row["rate"])
    assert dfchaos.period(p) == float(row["period"])


@pytest.mark.crossval
@pytest.mark.parametrize("abq", ORBIT_SETS)
def test_derivative_is_what_the_lyapunov_exponent_sums(cli, abq):
    """One averaged step: the tool's lyapunov is ln|T'(theta0)| (-inf where T' = 0, at a stop)."""
    a, bo, qo = abq
    p = model(a, bo, qo)
    seen = set()
    for fraction in (0.1, 0.45, 0.8, 0.97):
        _, names, rows = sweep_table(cli, "--a", repr(a), "--q-range", one(qo), "--b-range", one(bo), "--observables", "lyapunov",
                                     "--theta0-fraction", repr(fraction), "--transient", "0", "--steps", "1")
        tool = float(dict(zip(names, rows[0]))["lyapunov"])
        theta = p.t2 + fraction * (p.t3 - p.t2)
        d = dfchaos.derivative(p, theta)
        scenario = dfchaos.step(p, theta)["scenario"]
        seen.add(scenario)
        if scenario == "A":
            assert math.isfinite(d) and d != 0 and math.log(abs(d)) == tool, (theta, d, tool)
        elif scenario in ("B", "C", "D", "C'", "D'"):
            assert d == 0.0 and tool == -math.inf, (theta, d, tool)
        else:
            assert math.isnan(d)
    assert "A" in seen and seen & {"B", "C", "D"}, seen  # both kinds of step at each parameter set


def test_derivative_against_difference_quotients():
    """In scenario A, T' agrees with a central difference of T; with a stop it is exactly 0."""
    p = dfchaos.Parameters(1.0, 0.05, 0.7)
    theta = np.linspace(p.t2 + 0.01, p.t3 - 0.01, 200)
    s = dfchaos.step(p, theta)
    d = dfchaos.derivative(p, theta)
    assert d.shape == theta.shape and d.dtype == np.float64
    h = 1e-6
    checked = 0
    for x, dx, sc in zip(theta, d, s["scenario"]):
        lo, hi = dfchaos.step(p, x - h), dfchaos.step(p, x + h)
        if sc == "A" and lo["scenario"] == "A" and hi["scenario"] == "A" and abs(hi["T"] - lo["T"]) < 1:
            fd = (hi["T"] - lo["T"]) / (2 * h)
            assert abs(fd - dx) <= 1e-4 * max(1.0, abs(dx)), (x, fd, dx)
            checked += 1
        elif sc in ("B", "C", "D", "C'", "D'"):
            assert dx == 0.0
    assert checked >= 20
    assert dfchaos.derivative(p, float(theta[3])) == d[3]
    assert dfchaos.derivative(p=p, theta=[[theta[0], theta[1]]]).shape == (1, 2)


@pytest.mark.crossval
def test_sweep_equals_the_tool_file(cli, tmp_path):
    """A 3 x 4 grid with every observable, an inadmissible cell and error cells (a covering budget
    too small for b/a = 1e-3): every column, the error texts and the header, byte for byte. The
    region cells hold the uniform route (q/a below 1) and boxes (20 a cell)."""
    out = tmp_path / "s.tsv"
    args = ["--a", "2", "--q-range", "0.75:0.95:3", "--b-range", "1e-3:0.45:4:log", "--observables",
            "covering,superstable,lyapunov,rate,period,certified,region", "--max-branches", "60", "--superstable-scan", "50",
            "--theta0-fraction", "0.25", "--transient", "100", "--steps", "200", "--period-max", "20", "--period-tol", "1e-7",
            "--region-max-boxes", "20"]
    rc, _, err = cli.run("sweep", *args, "--out", out)
    assert rc == 0, err
    text = out.read_text()
    header, names, rows = split_sweep(text)
    cols, prov = dfchaos.sweep("0.75:0.95:3", (1e-3, 0.45, 4, "log"), a=2, observables=["covering", "superstable", "lyapunov",
                               "rate", "period", "certified", "region"], max_branches=60, superstable_scan=50, theta0_fraction=0.25,
                               transient=100, steps=200, period_max=20, period_tol=1e-7, region_max_boxes=20)
    assert list(cols) == names == prov["columns"]
    # The header names the build (version, git hash): rebuild both dfchaos_cli and dfchaos_python.
    assert prov["header"] == header, "the module and the tool are not of the same build?"
    assert prov["version"] == dfchaos.__version__ and prov["a"] == "2" and prov["steps"] == "200"
    assert prov["q_over_a"] == "0.75:0.95:3:lin"
    by_column = list(zip(*rows))
    statuses = set(by_column[names.index("status")])
    assert statuses == {"ok", "inadmissible", "error"}, statuses  # the test covers every kind of cell
    for j, name in enumerate(names):
        ours = cols[name]
        assert ours.shape == (12,), name
        if name == "index":
            assert ours.dtype == np.int64 and list(ours) == [int(x) for x in by_column[j]]
        elif name in ("status", "error"):
            assert list(ours) == list(by_column[j]), name
        else:
            theirs = np.array([float(x) for x in by_column[j]])
            same = (ours == theirs) | (np.isnan(ours) & np.isnan(theirs))
            assert same.all(), (name, ours, theirs)


@pytest.mark.crossval
def test_sweep_defaults_and_threads(cli):
    """The default observables and settings; the same values on 1 thread (OMP_NUM_THREADS=1 for the tool)."""
    import os
    import subprocess
    env = dict(os.environ, OMP_NUM_THREADS="1")
    r = subprocess.run([cli.path, "sweep", "--q-range", "0.8:0.9:2", "--b-range", "0.01:0.02:2"], capture_output=True, text=True,
                       env=env, timeout=300)
    assert r.returncode == 0, r.stderr
    lines = [l for l in r.stdout.splitlines() if not l.startswith("#")]
    names, rows = lines[0].split("\t"), [l.split("\t") for l in lines[1:]]
    cols, prov = dfchaos.sweep(q_range=(0.8, 0.9, 2), b_range="0.01:0.02:2")
    assert prov["observables"] == "covering,superstable,lyapunov,rate,period"
    for j, name in enumerate(names):
        if name in ("status", "error"):
            assert list(cols[name]) == [row[j] for row in rows]
        else:
            assert list(cols[name]) == [float(row[j]) for row in rows], name


def test_sweep_single_value_axes(cli):
    """One number is the axis x:x:1, as the tool's --q-range 0.85: the same columns as its spellings."""
    one, _ = dfchaos.sweep(0.85, 0.01, observables="covering,period", steps=50, transient=10)
    text, _ = dfchaos.sweep("0.85", "0.01:0.01:1", observables="covering,period", steps=50, transient=10)
    tup, _ = dfchaos.sweep((0.85, 0.85, 1), (0.01, 0.01, 1, "lin"), observables="covering,period", steps=50, transient=10)
    for name in one:
        assert list(one[name]) == list(text[name]) == list(tup[name]), name
    rc, out, err = cli.run("sweep", "--q-range", "0.85", "--b-range", "0.01", "--observables", "covering,period", "--steps", "50",
                           "--transient", "10")
    assert rc == 0, err
    row = [l for l in out.splitlines()[1:] if not l.startswith("#")][0].split("\t")
    assert float(row[5]) == one["period"][0] and float(row[4]) == one["covering"][0]


# ---- failures: the tool's messages -----------------------------------------------------------------
P = dfchaos.Parameters(1.0, 0.01, 0.85)
SWEEP = ["sweep", "--q-range", "0.85:0.85:1", "--b-range", "0.01:0.01:1"]
ORBIT_FAILURES = [
    (lambda: dfchaos.lyapunov(P, steps=0), [*SWEEP, "--steps", "0"], "steps"),
    (lambda: dfchaos.rate(P, steps=10**8 + 1), [*SWEEP, "--steps", "100000001"], "steps"),
    (lambda: dfchaos.lyapunov(P, transient=-1), [*SWEEP, "--transient", "-1"], "transient"),
    (lambda: dfchaos.period(P, transient=10**8 + 1), [*SWEEP, "--transient", "100000001"], "transient"),
    (lambda: dfchaos.period(P, period_max=0), [*SWEEP, "--period-max", "0"], "period-max"),
    (lambda: dfchaos.period(P, period_tol=1.0), [*SWEEP, "--period-tol", "1"], "period-tol"),
    (lambda: dfchaos.lyapunov(P, 1.0), ["orbit", "--a", "1", "--b", "0.01", "--q", "0.85", "--theta0", "1.0", "--steps", "5"],
     "theta0"),
    (lambda: dfchaos.rate(P, float("nan")), ["orbit", "--a", "1", "--b", "0.01", "--q", "0.85", "--theta0", "nan", "--steps", "5"],
     "theta0"),
    (lambda: dfchaos.lyapunov(dfchaos.Parameters(1, 0.3, 0.5)), ["map", "--a", "1", "--b", "0.3", "--q", "0.5", "--theta", "4"], "q"),
    (lambda: dfchaos.derivative(P, 1.0), ["map", "--a", "1", "--b", "0.01", "--q", "0.85", "--theta", "1.0"], "theta"),
    (lambda: dfchaos.derivative(dfchaos.Parameters(1, 1e-13, 0.85), 4.0), ["map", "--a", "1", "--b", "1e-13", "--q", "0.85",
                                                                           "--theta", "4"], "b"),
    (lambda: dfchaos.sweep("0.85:0.85", "0.01:0.01:1"), ["sweep", "--q-range", "0.85:0.85", "--b-range", "0.01:0.01:1"], "q-range"),
    (lambda: dfchaos.sweep("0.85:0.85:1", (0.01, 0.6, 3)), ["sweep", "--q-range", "0.85:0.85:1", "--b-range", "0.01:0.6:3"],
     "b-range"),
    (lambda: dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", observables="lyapunov,chaos"), [*SWEEP, "--observables", "lyapunov,chaos"],
     "observables"),
    (lambda: dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", a=0.0), [*SWEEP, "--a", "0"], "a"),
    (lambda: dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", theta0_fraction=1.0), [*SWEEP, "--theta0-fraction", "1"], "theta0-fraction"),
    (lambda: dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", steps=0), [*SWEEP, "--steps", "0"], "steps"),
    (lambda: dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", max_branches=0), [*SWEEP, "--max-branches", "0"], "max-branches"),
    (lambda: dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", superstable_scan=1), [*SWEEP, "--superstable-scan", "1"],
     "superstable-scan"),
    (lambda: dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", period_tol=0.1), [*SWEEP, "--period-tol", "0.1"], "period-tol"),
]


@pytest.mark.failure
@pytest.mark.parametrize("call,cli_args,parameter", ORBIT_FAILURES)
def test_bad_input_gives_the_tools_message(cli, call, cli_args, parameter):
    with pytest.raises(ValueError) as e:
        call()
    assert isinstance(e.value, dfchaos.InvalidParameter)
    assert e.value.parameter == parameter
    assert str(e.value) == cli.error(*cli_args)


@pytest.mark.failure
def test_wrong_types_and_keywords():
    with pytest.raises(TypeError):
        dfchaos.lyapunov(P, steps=1.5)
    with pytest.raises(TypeError):
        dfchaos.lyapunov(P, theta=4.0)  # the keyword is theta0
    with pytest.raises(TypeError):
        dfchaos.sweep("0.85:0.85:1", "0.01:0.01:1", theta0=0.5)  # a fraction: theta0_fraction
    with pytest.raises(TypeError):
        dfchaos.sweep([0.85], "0.01:0.01:1")  # one number is an axis (x:x:1); a list is not


def test_orbit_observables_from_threads():
    """lyapunov and sweep release the GIL: four Python threads at once give the serial values."""
    import threading
    sets = [dfchaos.Parameters(1.0, b, 0.85) for b in (0.005, 0.01, 0.02, 0.05)]
    ref = [dfchaos.lyapunov(p, steps=20000, transient=100) for p in sets]
    ref_sweep = dfchaos.sweep("0.8:0.9:3", "0.01:0.03:3", observables="lyapunov,period")[0]["lyapunov"]
    out, sweeps = [None] * 4, [None] * 4

    def work(k):
        out[k] = dfchaos.lyapunov(sets[k], steps=20000, transient=100)
        sweeps[k] = dfchaos.sweep("0.8:0.9:3", "0.01:0.03:3", observables="lyapunov,period")[0]["lyapunov"]
    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert out == ref
    for s in sweeps:
        assert np.array_equal(s, ref_sweep)
