# SPDX-License-Identifier: GPL-3.0-or-later
"""Parameters.from_physical (docs/units.md): a drilling model in physical units to (a, b, q), its
worked example, each term's scaling checked by another route (the physical free flight integrated
by hand in seconds and metres against the paper's x(t) in the scaled time), the tool's
`info --physical`, and the readable repr and pickling of Parameters."""
import math
import pickle
import re
import random

import pytest

import dfchaos

# docs/units.md, worked example: m = 0.5 kg, omega = 100 rad/s, F0 = 5000 N, P = 100 N, Q = 4250 N.
EXAMPLE = dict(mass=0.5, omega=100.0, amplitude=5000.0, static_force=100.0, friction=4250.0)


def test_worked_example():
    """m omega^2 = 5000 N/m: a = 5000/5000 = 1 m, b = 100/(2 * 5000) = 0.01 m, q = 4250/5000 = 0.85 m."""
    p = dfchaos.Parameters.from_physical(**EXAMPLE)
    assert (p.a, p.b, p.q) == (1.0, 0.01, 0.85)
    assert repr(p) == "dfchaos.Parameters(a=1, b=0.01, q=0.85)"
    assert dfchaos.Parameters.from_physical(0.5, 100, 5000, 100, 4250).q == 0.85  # positional, ints


def physical_free_flight(m, w, F0, P, tau0, X0, V0, tau):
    """X(tau) solving m X'' = F0 sin(w tau) + P from X(tau0) = X0, X'(tau0) = V0 (integrated twice by hand)."""
    return (-F0 / (m * w * w) * math.sin(w * tau) + P / (2 * m) * (tau - tau0) ** 2
            + (V0 + F0 / (m * w) * math.cos(w * tau0)) * (tau - tau0) + X0 + F0 / (m * w * w) * math.sin(w * tau0))


def paper_free_flight(p, theta0, x0, x1, t):
    """The paper's solution of Eq. (3) (Section 2): x(t) = -a sin t + b (t - theta0)^2 + (x1 + a cos theta0)(t - theta0) + x0 + a sin theta0."""
    return (-p.a * math.sin(t) + p.b * (t - theta0) ** 2 + (p.a * math.cos(theta0) + x1) * (t - theta0) + x0
            + p.a * math.sin(theta0))


@pytest.mark.parametrize("seed", range(5))
def test_each_term_scales_as_derived(seed):
    """For random physical models: the physical motion in seconds equals the scaled one at t = omega tau
    (velocities scaled by omega), and each force divided by the mass is omega^2 times its term."""
    rng = random.Random(seed)
    m, w = 10 ** rng.uniform(-1, 2), 10 ** rng.uniform(0, 3)
    F0 = m * w * w * 10 ** rng.uniform(-3, 1)
    P, Q = F0 * rng.uniform(1e-3, 0.2), F0 * rng.uniform(0.75, 0.95)
    p = dfchaos.Parameters.from_physical(m, w, F0, P, Q)
    close = lambda x, y: math.isclose(x, y, rel_tol=1e-12, abs_tol=1e-12 * p.a)
    for _ in range(20):
        tau = rng.uniform(0, 10) / w
        assert close((F0 * math.sin(w * tau) + P) / m, w * w * p.F(w * tau))            # Eq. (3)
        assert close((F0 * math.sin(w * tau) + P - Q) / m, w * w * (p.F(w * tau) - p.q))  # Eq. (4)
    tau0, X0, V0 = rng.uniform(0, 1) / w, rng.uniform(-1, 1) * p.a, rng.uniform(-1, 1) * p.a * w
    for _ in range(20):
        tau = tau0 + rng.uniform(0, 20) / w
        X = physical_free_flight(m, w, F0, P, tau0, X0, V0, tau)
        x = paper_free_flight(p, w * tau0, X0, V0 / w, w * tau)
        assert math.isclose(X, x, rel_tol=1e-9, abs_tol=1e-9 * p.a), (X, x)


@pytest.mark.crossval
def test_info_physical_equals_from_physical(cli):
    header, rows = cli.table("info", "--physical", "0.5", "100", "5000", "100", "4250")
    values = dict(rows)
    p = dfchaos.Parameters.from_physical(**EXAMPLE)
    assert (float(values["a"]), float(values["b"]), float(values["q"])) == (p.a, p.b, p.q)
    args = ("2.5", "157.07963267948966", "1e5", "1234.5", "8.5e4")
    _, rows = cli.table("info", "--physical", *args)
    values = dict(rows)
    p = dfchaos.Parameters.from_physical(*map(float, args))
    assert (float(values["a"]), float(values["b"]), float(values["q"]), float(values["t2"])) == (p.a, p.b, p.q, p.t2)


@pytest.mark.failure
@pytest.mark.parametrize("k,value", [(0, 0.0), (1, -100.0), (2, float("inf")), (3, 0.0), (4, float("nan")), (1, 1e200)])
def test_from_physical_bad_input_gives_the_tools_message(cli, k, value):
    args = [0.5, 100.0, 5000.0, 100.0, 4250.0]
    args[k] = value
    with pytest.raises(ValueError) as e:
        dfchaos.Parameters.from_physical(*args)
    assert str(e.value) == cli.error("info", "--physical", *[repr(x) for x in args])


@pytest.mark.failure
def test_from_physical_keywords():
    with pytest.raises(TypeError):
        dfchaos.Parameters.from_physical(mass=0.5, omega=100, amplitude=5000, static=100, friction=4250)
    with pytest.raises(TypeError):
        dfchaos.Parameters.from_physical(0.5, 100, 5000, 100)


@pytest.mark.parametrize("abq", [(1.0, 0.01, 0.85), (1.0, 0.1 + 0.2, 0.85), (2.5, 1e-5, 1.9), (1e-100, 3e-100, 1e100),
                                 (3.0000000000000004, 0.1, 2.2)])
def test_repr_is_shortest_and_round_trips(abq):
    p = dfchaos.Parameters(*abq)
    text = repr(p)
    # Python's repr is the shortest round-trip decimal too; "1.0" is written "1", and the exponent
    # without its leading zeros and "+" ("1e-5", "1e100", not Python's "1e-05", "1e+100").
    def shortest(x):
        return re.sub(r"e([-+]?)0*(\d)", lambda m: "e" + m.group(1).replace("+", "") + m.group(2), repr(x).removesuffix(".0"))
    assert text == "dfchaos.Parameters(a={}, b={}, q={})".format(*(shortest(x) for x in abq))
    back = eval(text, {"dfchaos": dfchaos})
    assert (back.a, back.b, back.q) == abq
    r = pickle.loads(pickle.dumps(p, protocol=pickle.HIGHEST_PROTOCOL))
    assert (r.a, r.b, r.q, r.t0, r.t2, r.t3) == (p.a, p.b, p.q, p.t0, p.t2, p.t3)
    # Equal (and of equal hash) exactly when a, b, q are the same doubles.
    assert back == p and r == p and hash(r) == hash(p) and len({p, r, back}) == 1
    assert p != dfchaos.Parameters(abq[0], math.nextafter(abq[1], 1.0), abq[2])
    assert p != abq and (p == "p") is False


PHYS = ["--physical", "0.5", "100", "5000", "100", "4250"]   # the worked example: a = 1 m, b = 0.01 m, q = 0.85 m
SCALED = ["--a", "1", "--b", "0.01", "--q", "0.85"]


def columns(cli, *args):
    header, rows = cli.table(*args)
    return {name: [r[k] for r in rows] for k, name in enumerate(header)}


@pytest.mark.crossval
@pytest.mark.parametrize("command,extra,times,lengths,velocities,phases", [
    ("map", ["--theta", "3.3", "4", "5.5"], ["T1", "elapsed"], ["penetration"], [], ["theta", "T"]),
    ("orbit", ["--theta0", "3.5", "--steps", "20"], ["elapsed", "time"], ["penetration", "y"], [], ["theta"]),
])
def test_physical_output_is_the_scaled_one_in_seconds_and_metres(cli, command, extra, times, lengths, velocities, phases):
    """--physical: the worked example of docs/units.md gives the rows of a = 1,
    b = 0.01, q = 0.85 with every time divided by omega = 100 (column name_s), lengths the same
    numbers in metres (name_m) and phases unchanged; the table says so in its '#' lines."""
    phys, scaled = columns(cli, command, *PHYS, *extra), columns(cli, command, *SCALED, *extra)
    for name in times:
        assert [float(x) for x in phys[name + "_s"]] == [float(x) / 100 for x in scaled[name]], name
    for name in lengths:
        assert phys[name + "_m"] == scaled[name], name
    for name in phases:
        assert phys[name] == scaled[name], name
    _, out, _ = cli.run(command, *PHYS, *extra)
    assert "# units = times in seconds (t / omega), lengths in metres, velocities in m/s" in out


@pytest.mark.crossval
def test_physical_simulate_takes_and_gives_seconds_metres_and_metres_per_second(cli, tmp_path):
    """simulate --physical: t0, t-end, the sample step and v0 in seconds and m/s are the scaled run's
    t0 = 100 t0_s, ...; its events and samples come back in seconds, metres and m/s."""
    s1, s2 = tmp_path / "phys.tsv", tmp_path / "scaled.tsv"
    rc, phys, err = cli.run("simulate", *PHYS, "--x0", "0", "--y0", "0", "--v0", "0.5", "--t0", "0.04", "--t-end", "1",
                            "--sample", "0.01", "--samples-out", s1)
    assert rc == 0, err
    rc, scaled, err = cli.run("simulate", *SCALED, "--x0", "0", "--y0", "0", "--v0", "0.005", "--t0", "4", "--t-end", "100",
                              "--sample", "1", "--samples-out", s2)
    assert rc == 0, err
    def table(text):
        lines = text.splitlines()
        return lines[0].split("\t"), [l.split("\t") for l in lines[1:] if not l.startswith("#")]
    (hp, rp), (hs, rs) = table(phys), table(scaled)
    assert hp == ["t_s", "phase", "before", "after", "kind", "x_m", "y_m", "v_before_m_per_s", "v_after_m_per_s"]
    assert len(rp) == len(rs) >= 3
    for a, b in zip(rp, rs):
        assert float(a[0]) == pytest.approx(float(b[0]) / 100, rel=1e-14)      # seconds
        assert float(a[1]) == pytest.approx(float(b[1]), abs=1e-12) and a[2:5] == b[2:5]  # phase; regimes, kind
        assert float(a[5]) == pytest.approx(float(b[5]), rel=1e-12, abs=1e-14)  # metres
        assert float(a[7]) == pytest.approx(float(b[7]) * 100, rel=1e-12, abs=1e-12)  # m/s
    (hp, rp), (hs, rs) = table(s1.read_text()), table(s2.read_text())
    assert hp == ["t_s", "x_m", "y_m", "v_m_per_s", "regime"] and len(rp) == len(rs) == 97
    assert phys.splitlines()[-1].startswith("# final state: t_s = 1, ")
    # the limits and messages are in the units given
    for args, name in ((["--t0", "1", "--t-end", "0.5"], "t-end: must satisfy t-end >= t0 = 1 "),
                       (["--t0", "0", "--t-end", "1e11"], "t-end: must satisfy |t-end| x OMEGA <= 1e12 (in seconds"),
                       (["--t0", "0", "--t-end", "1", "--sample", "1e-320", "--samples-out", str(tmp_path / "s.tsv")], "sample: ")):
        assert cli.error("simulate", *PHYS, "--x0", "0", "--y0", "0", "--v0", "0", *args).startswith(name)


SWEEP = ["--q-range", "0.8:0.95:3", "--b-range", "1e-3:0.02:3:log", "--observables", "superstable,lyapunov,rate,period",
         "--transient", "50", "--steps", "50"]


@pytest.mark.crossval
@pytest.mark.parametrize("mass,omega,amplitude", [(0.5, 100.0, 5000.0), (0.7, 123.0, 4321.0)])
def test_physical_sweep_is_the_scaled_one_with_rate_in_metres_per_second(cli, mass, omega, amplitude):
    """sweep --physical MASS OMEGA AMPLITUDE: the rows of the sweep at
    a = AMPLITUDE/(MASS OMEGA^2) (computed here, in the same order of rounding), the rate times omega
    (column rate_m_per_s) and each cell's forces Q = (q/a) F0, P = 2 (b/a) F0 in newtons; the Python
    module's physical= gives the same columns."""
    a = amplitude / (mass * omega * omega)
    phys = columns(cli, "sweep", "--physical", repr(mass), repr(omega), repr(amplitude), *SWEEP)
    scaled = columns(cli, "sweep", "--a", repr(a), *SWEEP)
    assert list(phys) == ["index", "q_over_a", "b_over_a", "status", "superstable", "epsilon", "lyapunov", "rate_m_per_s",
                          "period", "friction_N", "static_N", "error"]
    for name in ("index", "q_over_a", "b_over_a", "status", "superstable", "epsilon", "lyapunov", "period", "error"):
        assert phys[name] == scaled[name], name
    assert [float(x) for x in phys["rate_m_per_s"]] == [omega * float(x) for x in scaled["rate"]]
    assert [float(x) for x in phys["friction_N"]] == [float(q) * amplitude for q in scaled["q_over_a"]]
    assert [float(x) for x in phys["static_N"]] == [2 * float(b) * amplitude for b in scaled["b_over_a"]]
    _, out, _ = cli.run("sweep", "--physical", repr(mass), repr(omega), repr(amplitude), *SWEEP)
    assert f"# a = {a!r}".removesuffix(".0") in out.splitlines()
    assert any(l.startswith("# units = rate_m_per_s = omega rate (m/s)") for l in out.splitlines())
    cols, prov = dfchaos.sweep("0.8:0.95:3", "1e-3:0.02:3:log", observables="superstable,lyapunov,rate,period", transient=50,
                               steps=50, physical=(mass, omega, amplitude))
    assert list(cols) == list(phys)
    assert tuple(float(x) for x in prov["physical"].split("  ")[0].split()) == (mass, omega, amplitude)
    for name in ("rate_m_per_s", "friction_N", "static_N", "lyapunov"):
        assert [float(x) for x in phys[name]] == [float(x) for x in cols[name]], name


@pytest.mark.failure
def test_physical_sweep_bad_input(cli):
    """--physical excludes --a; each quantity must be finite and positive, named; Python says the same."""
    assert "--a excludes --physical" in cli.error("sweep", "--physical", "0.5", "100", "5000", "--a", "2", *SWEEP) or \
        "--physical excludes --a" in cli.error("sweep", "--physical", "0.5", "100", "5000", "--a", "2", *SWEEP)
    for k, name in enumerate(("mass", "omega", "amplitude")):
        args = ["0.5", "100", "5000"]
        args[k] = "-1"
        message = cli.error("sweep", "--physical", *args, *SWEEP)
        assert message.startswith(f"{name}: must satisfy 0 < {name} < inf"), message
        with pytest.raises(ValueError) as e:
            dfchaos.sweep("0.85", "0.01", physical=tuple(float(x) for x in args))
        assert str(e.value) == message
    with pytest.raises(ValueError, match="^a: give a or physical"):
        dfchaos.sweep("0.85", "0.01", a=2.0, physical=(0.5, 100.0, 5000.0))
