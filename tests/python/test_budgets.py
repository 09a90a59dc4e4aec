# SPDX-License-Identifier: GPL-3.0-or-later
"""Long calls of the module are bounded and interruptible.

- certify has the tool's budgets (max_seconds, max_memory; defaults 60 s and 2 GiB, the tool's
  --max-seconds and --max-memory) and gives up with the tool's wording, naming the keyword;
- Ctrl-C (SIGINT) during certify, sweep, lyapunov, rate and period raises KeyboardInterrupt
  promptly, instead of after the whole computation (formerly 108-145 s for discontinuities at
  b = 1e-9); the latency is printed. The bound asserted here (INTERRUPT_BOUND) is generous: this is
  a check of behaviour, not a timing test;
- dfchaos.Interval refuses reversed or NaN ends, and from_ball a negative or non-finite radius or
  mid, with ValueError naming lo, hi, mid or rad.
"""
import math
import os
import signal
import subprocess
import sys
import textwrap
import time
from fractions import Fraction

import pytest

import dfchaos

pytestmark = pytest.mark.failure

# Seconds allowed between SIGINT and the end of the child process (the target is 1 s; measured
# here 25-60 ms). The module's watcher checks for the signal every 0.1 s and the library polls its
# stop token at every step, box, branch or cell; the rest of this bound is for a loaded machine and
# the sanitizers. A check of behaviour, not a timing test: the calls below ran for 20 s or more after
# the signal before the stop token.
INTERRUPT_BOUND = 3.0
# Seconds the child runs before the signal: well inside each call below (each would run for minutes).
RUN_BEFORE_SIGNAL = 1.5


def test_certify_budgets_have_the_tools_defaults(cli):
    # pybind11's signature lines (one per overload: numbers or a Parameters) show the defaults the
    # binding was given (kit/budget.hpp's constants); the tool's help shows its own.
    signatures = [l for l in dfchaos.certify.__doc__.splitlines() if "certify(what: str," in l]
    assert len(signatures) == 2, dfchaos.certify.__doc__
    for signature in signatures:
        assert "max_seconds: float = 60.0" in signature and "max_memory: float = 2.0" in signature, signature
    _, out, _ = cli.run("certify", "covering", "--help")
    assert "--max-seconds S=60 " in out and "--max-memory G=2 " in out, out


@pytest.mark.parametrize("kw, name", [({"max_seconds": 0}, "max-seconds"), ({"max_seconds": -1}, "max-seconds"),
                                      ({"max_seconds": float("nan")}, "max-seconds"), ({"max_seconds": 2e6}, "max-seconds"),
                                      ({"max_memory": 0.1}, "max-memory"), ({"max_memory": float("inf")}, "max-memory"),
                                      ({"max_memory": 1e5}, "max-memory")])
def test_certify_refuses_a_bad_budget_before_any_work(kw, name):
    t = time.monotonic()
    with pytest.raises(dfchaos.InvalidParameter) as e:
        dfchaos.certify("discontinuities", b=1e-9, **kw)
    assert str(e.value).startswith(name + ":"), str(e.value)
    assert time.monotonic() - t < 5, "refused only after work"


def test_certify_time_budget_gives_up_with_the_tools_wording():
    t = time.monotonic()
    with pytest.raises(dfchaos.GaveUp) as e:
        dfchaos.certify("discontinuities", b=1e-9, max_seconds=1)
    took = time.monotonic() - t
    print(f"time budget of 1 s: gave up after {took:.2f} s")
    assert str(e.value) == "gave up: the time budget of 1 s ran out (max_seconds raises it)"
    assert took < 1 + INTERRUPT_BOUND


def test_certify_memory_budget_gives_up_with_the_tools_wording():
    # At b = 1e-12 the enumeration of Lemma 2's tangencies grows without bound (formerly a MemoryError
    # at 2.1 GB); with a quarter of a GiB allowed it gives up long before.
    t = time.monotonic()
    with pytest.raises(dfchaos.GaveUp) as e:
        dfchaos.certify("discontinuities", b=1e-12, max_memory=0.25, max_seconds=300)
    print(f"memory budget of 0.25 GiB: gave up after {time.monotonic() - t:.2f} s")
    assert str(e.value) == "gave up: the memory budget of 0.25 GiB ran out (max_memory raises it)"


def test_certify_within_its_budget_answers_as_the_tool_does(cli):
    # The proof on the module's worker thread, watched, against the tool's own process.
    import json
    r = dfchaos.certify("covering", b=0.001, q=0.85, max_seconds=120, max_memory=4)
    rc, out, err = cli.run("certify", "covering", "--b", "0.001", "--q", "0.85")
    assert rc == 0, err
    tool = json.loads(out)
    assert r.proved is True
    assert {k: v for k, v in r.items() if k != "seconds"} == {k: v for k, v in tool.items() if k != "seconds"}


def test_certificate_not_written_when_the_budget_runs_out(tmp_path):
    path = tmp_path / "c.json"
    with pytest.raises(dfchaos.GaveUp):
        dfchaos.certify("discontinuities", b=1e-9, max_seconds=0.5, certificate=str(path))
    assert os.listdir(tmp_path) == []


CALLS = {
    "certify": "dfchaos.certify('discontinuities', b=1e-9, max_seconds=600)",
    "sweep": "dfchaos.sweep('0.75:0.95:40', '1e-6:1e-3:40:log', observables='certified')",
    # one cell that runs for tens of seconds (10^8 tangencies to bisect): a stop between cells is not enough
    "sweep_one_cell": "dfchaos.sweep('0.85', '1e-8', observables='covering', max_branches=10**9)",
    "lemma4_covering": "dfchaos.lemma4_covering(dfchaos.Parameters(1, 1e-8, 0.85), max_branches=10**9)",
    "covering_segments": "dfchaos.covering_segments(dfchaos.Parameters(1, 1e-8, 0.85), max_branches=10**9)",
    "lyapunov": "dfchaos.lyapunov(dfchaos.Parameters(1, 0.01, 0.85), steps=100_000_000)",
    "rate": "dfchaos.rate(dfchaos.Parameters(1, 0.01, 0.85), steps=100_000_000)",
    "period": "dfchaos.period(dfchaos.Parameters(1, 0.01, 0.85), transient=100_000_000)",
}


@pytest.mark.parametrize("name", sorted(CALLS))
def test_ctrl_c_raises_keyboard_interrupt_promptly(name, tmp_path):
    code = textwrap.dedent(f"""
        import sys, dfchaos
        print("started", flush=True)
        try:
            {CALLS[name]}
        except KeyboardInterrupt:
            print("KeyboardInterrupt", flush=True)
            sys.exit(0)
        print("finished without interruption", flush=True)
        sys.exit(1)
    """)
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(RUN_BEFORE_SIGNAL)
        assert child.poll() is None, f"{name} ended before the signal: {child.stdout.read()} {child.stderr.read()}"
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=INTERRUPT_BOUND + 60)
        latency = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    print(f"{name}: KeyboardInterrupt {latency:.3f} s after SIGINT")
    assert child.returncode == 0 and out.strip() == "KeyboardInterrupt", (child.returncode, out, err)
    assert latency < INTERRUPT_BOUND, f"{name}: {latency:.1f} s from SIGINT to the end"


@pytest.mark.parametrize("lo, hi, names", [(2.0, 1.0, "lo, hi"), (math.nan, 1.0, "lo"), (0.0, math.nan, "hi"), ("x", 1.0, "lo"), (0.0, None, "hi"),
                                            ("0.1", 1.0, "lo"), (True, 2.0, "lo"), (Fraction(1, 10), 1.0, "lo"), (0.0, 2**53 + 1, "hi"),
                                            (0.0, 2**1024, "hi")])
def test_interval_refuses_bad_ends(lo, hi, names):
    with pytest.raises(ValueError) as e:
        dfchaos.Interval(lo, hi)
    assert str(e.value).startswith(names + ":"), str(e.value)


def test_interval_accepts_good_ends():
    assert dfchaos.Interval(1, 2) == (1.0, 2.0)
    assert dfchaos.Interval(-math.inf, 0.5).lo == -math.inf
    assert dfchaos.Interval(3.0, 3.0).width == 0
    with pytest.raises(ValueError):
        dfchaos.Interval._make([2.0, 1.0])


@pytest.mark.parametrize("ball, name", [({"mid": "1", "rad": "-1"}, "rad"), ({"mid": "nan", "rad": "1e-9"}, "mid"),
                                        ({"mid": "1", "rad": "inf"}, "rad"), ({"mid": "one", "rad": "0"}, "mid"),
                                        ({"mid": "1"}, "rad"), ({"mid": "1", "rad": "NaN"}, "rad"), ({"mid": "1e400", "rad": "0"}, "mid, rad")])
def test_from_ball_refuses_bad_balls(ball, name):
    with pytest.raises(ValueError) as e:
        dfchaos.Interval.from_ball(ball)
    assert str(e.value).startswith(name + ":"), str(e.value)


def test_from_ball_still_rounds_outward():
    i = dfchaos.Interval.from_ball({"mid": "0.1", "rad": "0"})  # 1/10 is no double: two neighbours
    assert i.lo < i.hi and 0.1 in i
