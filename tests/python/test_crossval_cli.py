# SPDX-License-Identifier: GPL-3.0-or-later
"""Cross-validation: the module gives the numbers of the dfchaos tool to the last bit.

The tool prints %.17g, which reads back to the same double; every comparison is float(text) == value
(no tolerance). Phases are passed to the tool as Python's repr, which also reads back exactly.
"""
import math

import numpy as np
import pytest

import dfchaos

pytestmark = pytest.mark.crossval

# (a, b, q): b/a from 0.1 to 1e-8, q/a above and below sin(vartheta0), a != 1; together they
# produce the scenarios A, B, C and D.
PARAMETER_SETS = [
    (1.0, 0.1, 0.85),
    (1.0, 0.01, 0.85),
    (1.0, 0.05, 0.7),
    (1.0, 1e-4, 0.85),
    (1.0, 1e-8, 0.6),
    (2.5, 0.03, 1.9),
]


def args(a, b, q):
    return ["--a", repr(a), "--b", repr(b), "--q", repr(q)]


def floats(column):
    return np.array([float(x) for x in column])


def assert_bits(name, ours, theirs):
    """Equal as doubles, element by element (NaN never occurs: the tool refuses it)."""
    ours, theirs = np.asarray(ours, dtype=float), np.asarray(theirs, dtype=float)
    assert ours.shape == theirs.shape, f"{name}: shape {ours.shape} against {theirs.shape}"
    bad = np.flatnonzero(ours != theirs)
    assert bad.size == 0, (f"{name}: {bad.size} of {ours.size} differ, first at {bad[0]}: "
                           f"{ours[bad[0]]!r} against {theirs[bad[0]]!r}")


def random_phases(p, n, seed):
    rng = np.random.default_rng(seed)
    return p.t2 + (p.t3 - p.t2) * rng.random(n)


@pytest.mark.parametrize("abq", PARAMETER_SETS)
def test_map_over_the_arc(cli, abq):
    """`dfchaos map --arc N`: every column, for T, T1 and step on the tool's own phases."""
    p = dfchaos.Parameters(*abq)
    header, rows = cli.table("map", *args(*abq), "--arc", 2000)
    assert header == ["theta", "T1", "T", "scenario", "elapsed", "penetration"]
    col = list(zip(*rows))
    theta = floats(col[0])
    s = dfchaos.step(p, theta)
    assert_bits("theta", s["theta"], theta)
    assert_bits("T1", s["T1"], floats(col[1]))
    assert_bits("T", s["T"], floats(col[2]))
    assert list(s["scenario"]) == list(col[3])
    assert_bits("elapsed", s["elapsed"], floats(col[4]))
    assert_bits("penetration", s["penetration"], floats(col[5]))
    assert_bits("dfchaos.T", dfchaos.T(p, theta), floats(col[2]))
    assert_bits("dfchaos.T1", dfchaos.T1(p, theta), floats(col[1]))


@pytest.mark.parametrize("abq", PARAMETER_SETS)
def test_map_at_random_phases_scalar_and_array(cli, abq):
    """`dfchaos map --theta X ...` at random phases given as repr: scalar calls and one array call."""
    p = dfchaos.Parameters(*abq)
    theta = random_phases(p, 60, seed=17)
    _, rows = cli.table("map", *args(*abq), "--theta", *[repr(float(x)) for x in theta])
    col = list(zip(*rows))
    assert_bits("theta", floats(col[0]), theta)
    for i, x in enumerate(theta):
        one = dfchaos.step(p, float(x))
        assert (one["T1"], one["T"], one["scenario"], one["elapsed"], one["penetration"]) == (
            float(col[1][i]), float(col[2][i]), col[3][i], float(col[4][i]), float(col[5][i])), f"theta={x!r}"
        assert dfchaos.T(p, float(x)) == float(col[2][i])
        assert dfchaos.T1(p, float(x)) == float(col[1][i])
    assert_bits("T", dfchaos.T(p, theta), floats(col[2]))


def test_the_comparison_covers_several_scenarios(cli):
    """The sets above are not all scenario A: the comparison meets B, C and D too."""
    seen = set()
    for abq in PARAMETER_SETS:
        _, rows = cli.table("map", *args(*abq), "--arc", 2000)
        seen |= {r[3] for r in rows}
    assert {"A", "B", "C", "D"} <= seen, seen


@pytest.mark.parametrize("abq,theta0,steps", [
    ((1.0, 0.01, 0.85), 3.5, 500),
    ((1.0, 0.1, 0.85), 4.0, 300),
    ((1.0, 1e-4, 0.85), 5.0, 200),
    ((2.5, 0.03, 1.9), 4.4, 300),
])
def test_orbit(cli, abq, theta0, steps):
    """`dfchaos orbit`: row n is element n of every column (element 0 the first row)."""
    p = dfchaos.Parameters(*abq)
    header, rows = cli.table("orbit", *args(*abq), "--theta0", repr(theta0), "--steps", steps)
    assert header == ["n", "theta", "scenario", "elapsed", "penetration", "time", "y"]
    col = list(zip(*rows))
    o = dfchaos.orbit(p, theta0, steps)
    assert [int(n) for n in col[0]] == list(range(steps))
    assert o["theta"][0] == theta0 == float(col[1][0])
    assert_bits("theta", o["theta"], floats(col[1]))
    assert list(o["scenario"]) == list(col[2])
    assert_bits("elapsed", o["elapsed"], floats(col[3]))
    assert_bits("penetration", o["penetration"], floats(col[4]))
    assert_bits("time", o["time"], floats(col[5]))
    assert_bits("y", o["y"], floats(col[6]))


def parse_simulate(out, samples_text=None):
    """The tool's simulate output: the column line, the provenance lines, the initial regime, event
    rows, the final state; the sample rows from their own file (--samples-out), which has the
    provenance lines too."""
    lines = out.split("\n")
    assert lines[0].split("\t") == ["t", "phase", "before", "after", "kind", "x", "y", "v_before", "v_after"]
    assert lines[1] == "# dfchaos simulate: the event log of the full system" and lines[2].startswith("# dfchaos ")
    head = [l for l in lines[3:] if l.startswith("# ") and " = " in l and not l.startswith("# final")]
    assert [l.split(" = ")[0] for l in head][:3] == ["# a", "# b", "# q"]
    start = 3 + len(head)
    assert lines[start].startswith("# initial regime: ")
    initial = lines[start].split(": ")[1]
    events = [l.split("\t") for l in lines[start + 1:] if l and not l.startswith("#")]
    assert lines[-2].startswith("# final state: ") and lines[-1] == ""
    samples = []
    if samples_text is not None:
        s = samples_text.split("\n")
        assert s[0] == "t\tx\ty\tv\tregime" and s[1] == "# dfchaos simulate: the state every sample time units"
        samples = [l.split("\t") for l in s[1:] if l and not l.startswith("#")]
    return initial, events, samples


@pytest.mark.parametrize("abq,start,t_end,sample", [
    ((1.0, 0.01, 0.85), (0.0, 0.0, 0.0, 4.0), 300.0, 0.7),
    ((1.0, 0.1, 0.85), (-0.5, 0.25, 1.5, -3.0), 120.0, 0.25),
    ((1.0, 0.7, 0.5), (-1.0, 0.0, -2.0, 0.0), 60.0, 1.0),   # outside the assumptions: b > a/2, q < 2b
    ((1.0, 0.2, 1.5), (-1.0, 0.0, -2.0, 0.0), 60.0, 0.3),   # q > a
    ((2.5, 0.03, 1.9), (0.0, 0.0, 2.0, 1.0), 200.0, None),
])
def test_simulate(cli, abq, start, t_end, sample, tmp_path):
    """`dfchaos simulate`: the initial regime, every event column, every sample column."""
    p = dfchaos.Parameters(*abq)
    x0, y0, v0, t0 = start
    samples_file = tmp_path / "samples.tsv"
    extra = ["--sample", repr(sample), "--samples-out", samples_file] if sample else []
    rc, out, err = cli.run("simulate", *args(*abq), "--x0", repr(x0), "--y0", repr(y0), "--v0", repr(v0),
                           "--t0", repr(t0), "--t-end", repr(t_end), *extra)
    assert rc == 0, err
    initial, events, samples = parse_simulate(out, samples_file.read_text() if sample else None)
    r = dfchaos.simulate(p, x0, y0, v0, t0, t_end, sample=sample)
    assert r["initial_regime"] == initial
    final = dict(kv.split(" = ") for kv in out.split("\n")[-2][len("# final state: "):].split(", "))
    assert final["regime"] == r["final"]["regime"]
    for name in ("t", "phase", "x", "y", "v"):
        assert float(final[name]) == r["final"][name], name
    ev = r["events"]
    assert len(events) > 0 and len(ev["t"]) == len(events)
    col = list(zip(*events))
    for k, name in enumerate(["t", "phase", "before", "after", "kind", "x", "y", "v_before", "v_after"]):
        if name in ("before", "after", "kind"):
            assert list(ev[name]) == list(col[k]), name
        else:
            assert_bits(name, ev[name], floats(col[k]))
    sm = r["samples"]
    if sample:
        assert len(samples) == len(sm["t"]) == math.floor((t_end - t0) / sample) + 1
        col = list(zip(*samples))
        for k, name in enumerate(["t", "x", "y", "v", "regime"]):
            if name == "regime":
                assert list(sm[name]) == list(col[k])
            else:
                assert_bits("sample " + name, sm[name], floats(col[k]))
    else:
        assert samples == [] and len(sm["t"]) == 0


@pytest.mark.parametrize("abq", PARAMETER_SETS + [(1.0, 0.7, 0.5), (1.0, 0.1, 1.5)])
def test_parameters_against_info(cli, abq):
    """t0..t3 and vartheta0 against `dfchaos info` (None where info prints no value)."""
    p = dfchaos.Parameters(*abq)
    _, rows = cli.table("info", *args(*abq))
    info = {r[0]: r[1] for r in rows if len(r) == 2}
    for name in ("a", "b", "q"):
        assert getattr(p, name) == float(info[name])
    for name in ("t0", "t1", "t2", "t3"):
        ours = getattr(p, name)
        if ours is None:
            assert name not in info or not _is_number(info[name]), (name, info.get(name))
        else:
            assert ours == float(info[name]), name
    assert p.vartheta0 == dfchaos.vartheta0 == float(info["vartheta0"])
    assert p.a * dfchaos.sin_vartheta0 == float(info["a*sin(vartheta0)"])
    assert p.assumptions["describe"] == info["assumptions"]


def _is_number(text):
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


@pytest.mark.crossval
def test_orbit_diagram_equals_the_tool(cli):
    """dfchaos.orbit_diagram and `dfchaos orbit-diagram`: the same cells, phases
    and marks to the last bit, with the defaults of both (one C++ function and one set of defaults)
    and with settings given; the q/a axis reaches cells whose orbit stops (lyapunov -inf, a return of t2)."""
    q = [0.8, 0.96705685618729098]
    b = [0.003, 0.01, 0.05]
    for kw, opts in (({}, []), (dict(transient=40, steps=30, keep=7, theta0_fraction=0.25),
                                ["--transient", 40, "--steps", 30, "--keep", 7, "--theta0-fraction", 0.25])):
        d = dfchaos.orbit_diagram(q, b, **kw)
        keep = d["theta"].shape[1]
        for qi in q:
            for bi in b:
                header, rows = cli.table("orbit-diagram", "--q-range", repr(qi), "--b-range", repr(bi), *map(str, opts))
                assert header == ["q_over_a", "b_over_a", "k", "theta", "lyapunov", "period_of_t2", "superstable"]
                i = [j for j in range(len(d["q_over_a"])) if d["q_over_a"][j] == qi and d["b_over_a"][j] == bi]
                assert len(i) == 1 and len(rows) == keep
                i = i[0]
                assert_bits("theta", d["theta"][i], floats([r[3] for r in rows]))
                assert_bits("lyapunov", [d["lyapunov"][i]], floats([rows[0][4]]))
                assert int(rows[0][5]) == d["period_of_t2"][i] and (rows[0][6] == "1") == bool(d["superstable"][i])
        if not kw:  # with the defaults, the cell (0.967..., 0.01) stops and returns to t2
            assert (d["lyapunov"] == -np.inf).any() and (d["period_of_t2"] > 0).any()


@pytest.mark.failure
@pytest.mark.parametrize("kw,opts", [
    (dict(q_over_a=0.85, b_over_a=[0.01, 0.6]), ["--q-range", "0.85", "--b-range", "0.01:0.6:2"]),
    (dict(q_over_a=0.85, b_over_a=0.01, steps=10, keep=11), ["--q-range", "0.85", "--b-range", "0.01", "--steps", "10", "--keep", "11"]),
    (dict(q_over_a=0.85, b_over_a=0.01, theta0_fraction=1.0), ["--q-range", "0.85", "--b-range", "0.01", "--theta0-fraction", "1"]),
])
def test_orbit_diagram_refuses_as_the_tool(cli, kw, opts):
    with pytest.raises(dfchaos.InvalidParameter) as e:
        dfchaos.orbit_diagram(**kw)
    assert str(e.value) == cli.error("orbit-diagram", *opts)


@pytest.mark.crossval
@pytest.mark.parametrize("word", ["0011", "1", "0111010"])
def test_periodic_orbit_of_any_itinerary_equals_the_tool_and_its_proof(cli, word):
    """dfchaos.periodic_orbit equals `dfchaos periodic --word` to the last bit, and
    dfchaos.certify("periodic", p, word=...) proves the orbit of that itinerary, the floating points
    within their precision floor of the certified balls."""
    p = dfchaos.Parameters(1.0, 0.003, 0.85)
    o = dfchaos.periodic_orbit(p, word)
    header, rows = cli.table("periodic", "--b", "0.003", "--q", "0.85", "--word", word)
    assert header == ["j", "letter", "x", "T"] and "".join(r[1] for r in rows) == word == o["word"]
    assert_bits("x", o["x"], floats([r[2] for r in rows]))
    assert_bits("T", o["T"], floats([r[3] for r in rows]))
    c = dfchaos.certify("periodic", p, word=word)
    assert c["proved"] is True and c["itinerary"] == word and c["period"] == len(word)
    for x, ball in zip(o["x"], c["orbit"]):
        assert abs(x - float(ball["mid"])) <= o["precision_floor"] + float(ball["rad"])


@pytest.mark.failure
def test_periodic_orbit_refuses_as_the_tool(cli):
    p = dfchaos.Parameters(1.0, 0.003, 0.85)
    for word in ("0101", "012"):
        with pytest.raises(dfchaos.InvalidParameter) as e:
            dfchaos.periodic_orbit(p, word)
        assert str(e.value) == cli.error("periodic", "--b", "0.003", "--q", "0.85", "--word", word)
    with pytest.raises(dfchaos.InvalidParameter, match="word"):
        dfchaos.certify("periodic", p, word="0101")
    with pytest.raises(dfchaos.InvalidParameter, match="word"):
        dfchaos.certify("covering", p, word="01")
    # word is keyword-only: the arguments before it keep their places (segment is the sixth)
    assert "on L2" in dfchaos.certify("discontinuities", 1.0, 0.01, None, 0, "L2")["statement"]


@pytest.mark.crossval
def test_follow_orbit_equals_the_tool_and_ends_where_it_says(cli):
    """dfchaos.follow_orbit equals `dfchaos continue` to the last bit, every step's
    interval is proved (--certify), and the end is a border collision located to --min-step."""
    p = dfchaos.Parameters(1.0, 0.003, 0.85)
    # (up to 0.00307: nearer to where this orbit ends, at b/a = 0.0030889, its multiplier falls and
    # the steps are no longer all proved)
    f = dfchaos.follow_orbit(p, "011", 0.00307, certify=True)
    rc, out, err = cli.run("continue", "--b", "0.003", "--q", "0.85", "--word", "011", "--to", "0.00307", "--certify")
    assert rc == 0, err
    lines = out.splitlines()
    header = lines[0].split("\t")
    rows = [l.split("\t") for l in lines[1:] if not l.startswith("#")]
    assert header == ["b", "certified", "log_multiplier", "residual", "x0", "x1", "x2"]
    assert_bits("b", f["b"], floats([r[0] for r in rows]))
    assert_bits("log_multiplier", f["log_multiplier"], floats([r[2] for r in rows]))
    for j in range(3):
        assert_bits(f"x{j}", f["x"][:, j], floats([r[4 + j] for r in rows]))
    assert [r[1] for r in rows] == ["-"] + ["1"] * (len(rows) - 1) and list(f["certified"]) == [-1] + [1] * (len(rows) - 1)
    assert f["end"] == "range_end" and "# end = range_end" in lines and f["b"][-1] == 0.00307
    # followed far up in b, the orbit ends in a border collision, named, located to 1e-12 relative
    g = dfchaos.follow_orbit(p, "011", 0.2)
    assert g["end"] in ("plateau", "reaches_t2", "reaches_t3", "grazing", "fold"), g["detail"]
    assert abs(g["b_lost"] - g["b"][-1]) <= 1e-12 * g["b"][-1] * (1 + 1e-12)
    _, out, _ = cli.run("continue", "--b", "0.003", "--q", "0.85", "--word", "011", "--to", "0.2")
    assert f"# end = {g['end']}" in out.splitlines()
    # the end is real: just past it the continued cycle is lost (its point's step is no longer smooth on
    # its branch), and the last row is a cycle of T to its residual
    last = dfchaos.Parameters(1.0, g["b"][-1], 0.85)
    x = g["x"][-1]
    for j in range(3):
        assert abs(dfchaos.T(last, x[j]) - x[(j + 1) % 3]) <= 1e-9


@pytest.mark.failure
def test_follow_orbit_refuses_as_the_tool(cli):
    p = dfchaos.Parameters(1.0, 0.003, 0.85)
    for kw, opts in (({"step": 0.5}, ["--step", "0.5"]), ({"min_step": 1.0}, ["--min-step", "1"]), ({"max_steps": 0}, ["--max-steps", "0"])):
        with pytest.raises(dfchaos.InvalidParameter) as e:
            dfchaos.follow_orbit(p, "01", 0.004, **kw)
        assert str(e.value) == cli.error("continue", "--b", "0.003", "--q", "0.85", "--word", "01", "--to", "0.004", *opts)
    for word in ("0101", "0" * 65):
        with pytest.raises(dfchaos.InvalidParameter) as e:
            dfchaos.follow_orbit(p, word, 0.004)
        assert str(e.value) == cli.error("continue", "--b", "0.003", "--q", "0.85", "--word", word, "--to", "0.004")
    with pytest.raises(dfchaos.InvalidParameter) as e:
        dfchaos.follow_orbit(p, "01", 0.6)
    assert str(e.value) == cli.error("continue", "--b", "0.003", "--q", "0.85", "--word", "01", "--to", "0.6")
