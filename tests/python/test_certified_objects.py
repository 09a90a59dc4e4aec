# SPDX-License-Identifier: GPL-3.0-or-later
"""dfchaos.certify's answer as a Python object: a dfchaos.Certified (the tool's JSON record as a dict)
whose attributes give proved, the statement, J0 and J1 as dfchaos.Interval, every enclosure as an
Interval rounded outward, and the certificate when asked for."""
import json
import math
import pickle
from decimal import Decimal
from fractions import Fraction

import pytest

import dfchaos


def untimed(x):
    if isinstance(x, dict):
        return {k: untimed(v) for k, v in x.items() if k != "seconds"}
    if isinstance(x, list):
        return [untimed(v) for v in x]
    return x


@pytest.mark.crossval
def test_covering_as_an_object_equals_the_tool(cli):
    r = dfchaos.certify("covering", a=1.0, b=0.001, q=0.85)
    rc, out, err = cli.run("certify", "covering", "--a", "1", "--b", "0.001", "--q", "0.85")
    assert rc == 0, err
    tool = json.loads(out)
    assert isinstance(r, dict) and isinstance(r, dfchaos.Certified) and untimed(r) == untimed(tool)
    assert r.what == "covering" and r.proved is True and r.statement == tool["statement"]
    assert r.failed_step is None and r.detail is None
    assert r.J0 == dfchaos.Interval(*tool["J0"]) and r.J1 == dfchaos.Interval(*tool["J1"])
    assert r.J0.lo < r.J0.hi < r.J1.lo < r.J1.hi  # disjoint, J0 left of J1
    assert r.J0.lo in r.J0 and r.J1.lo not in r.J0 and math.isclose(r.J0.width, r.J0.hi - r.J0.lo)
    assert r.certificate is None
    assert repr(r).startswith("<dfchaos.Certified covering: proved=True, J0=Interval(lo=")
    back = pickle.loads(pickle.dumps(r))
    assert type(back) is dfchaos.Certified and back == r and back.what == "covering" and back.J1 == r.J1


@pytest.mark.crossval
def test_not_proved_is_an_answer_with_its_step(cli):
    r = dfchaos.certify("covering", b=0.02, q=0.85)
    rc, out, _ = cli.run("certify", "covering", "--a", "1", "--b", "0.02", "--q", "0.85")
    tool = json.loads(out)
    assert r.proved is False and r.failed_step == tool["failed_step"] and r.detail == tool["detail"]
    assert r.refuted == tool["refuted"]
    assert "failed_step=" in repr(r)


def test_enclosures_are_intervals_rounded_outward():
    v = dfchaos.certify("vartheta0")
    e = v.enclosures
    assert set(e) == {"vartheta0", "sin_vartheta0"}
    assert dfchaos.vartheta0 in e["vartheta0"] and dfchaos.sin_vartheta0 in e["sin_vartheta0"]
    for name, iv in e.items():
        ball = v[name]
        mid, rad = Fraction(Decimal(ball["mid"])), Fraction(Decimal(ball["rad"]))
        assert Fraction(iv.lo) <= mid - rad and mid + rad <= Fraction(iv.hi), name
        # the smallest such interval: one ulp less on either side would cut the ball
        assert Fraction(math.nextafter(iv.lo, math.inf)) > mid - rad, name
        assert Fraction(math.nextafter(iv.hi, -math.inf)) < mid + rad, name
    lemma1 = dfchaos.certify("lemma1", b=0.001, q=0.85).enclosures
    assert lemma1["u_at_t2"].hi < 0  # Eq. (8): the progression's velocity at t2 is negative


def test_interval_from_ball_by_hand():
    tenth = dfchaos.Interval.from_ball({"mid": "0.1", "rad": "0"})
    assert 0.1 in tenth
    assert Fraction(tenth.lo) < Fraction(1, 10) < Fraction(tenth.hi)  # 1/10 is not a double
    assert math.nextafter(tenth.lo, 1) == tenth.hi
    assert dfchaos.Interval.from_ball({"mid": "1", "rad": "0"}) == (1.0, 1.0)
    assert dfchaos.Interval.from_ball({"mid": "-2", "rad": "0.5"}) == (-2.5, -1.5)


def test_certificate_when_asked(tmp_path):
    path = tmp_path / "c.json"
    r = dfchaos.certify("lemma1", b=0.001, q=0.85, certificate=str(path))
    assert r.proved and r.certificate["path"] == str(path) and len(r.certificate["sha256"]) == 64
    assert r.certificate["bytes"] == path.stat().st_size
    not_proved = dfchaos.certify("lemma1", b=0.05, q=0.73, certificate=str(tmp_path / "d.json"))
    assert not_proved.certificate["written"] is False


@pytest.mark.failure
def test_certificate_in_a_missing_directory_is_refused_before_the_proof(tmp_path):
    target = tmp_path / "nodir" / "c.json"
    with pytest.raises(OSError, match="certificate: cannot create a file beside"):
        dfchaos.certify("covering", b=0.001, q=0.85, certificate=str(target))
    assert not target.parent.exists()  # nothing created
