# SPDX-License-Identifier: GPL-3.0-or-later
"""Every table the tool writes loads with one standard call.

The documented one-liners (README, docs/cluster.md, each command's --help):

    pandas.read_csv(f, sep="\\t", comment="#", float_precision="round_trip")
    numpy.genfromtxt(f, names=True, delimiter="\\t", comments="#", dtype=None, encoding=None)

Both need the column line to be the file's first line and every other non-row line to start with
'#'. pandas needs float_precision="round_trip": its default parser can miss the double a %.17g text
stands for by an ulp (seen here: 3.8244289057122183 read as 3.8244289057122174). Each test writes a
real output, loads it both ways and checks the names, the number of rows and that a numeric column
is read back to the same doubles as the text. The experiments' data files, all of them, are checked
the same way by the CTest data_files_load (tests/data_files_load.py, on the smoke runs' output).
"""
import io
import math

import numpy as np
import pandas
import pytest

P = ["--a", "1", "--b", "0.02", "--q", "0.85"]


def load_both(text):
    """(pandas frame, numpy structured array, column names, rows as lists of strings) of a table."""
    lines = text.splitlines()
    assert lines and not lines[0].startswith("#"), "the first line must be the column line"
    names = lines[0].split("\t")
    rows = [l.split("\t") for l in lines[1:] if not l.startswith("#")]
    frame = pandas.read_csv(io.StringIO(text), sep="\t", comment="#", float_precision="round_trip")
    array = np.genfromtxt(io.StringIO(text), names=True, delimiter="\t", comments="#", dtype=None, encoding=None)
    array = np.atleast_1d(array)
    assert list(frame.columns) == names
    assert len(frame) == len(rows) and len(array) == len(rows)
    assert len(array.dtype.names) == len(names)
    return frame, array, names, rows


def same_doubles(values, texts):
    for v, t in zip(values, texts):
        x = float(t)
        assert (math.isnan(x) and math.isnan(v)) or v == x, f"{v!r} read back from {t!r}"


def check_column(text, column):
    frame, array, names, rows = load_both(text)
    k = names.index(column)
    texts = [r[k] for r in rows]
    same_doubles(frame[column].to_numpy(dtype=float), texts)
    same_doubles(array[array.dtype.names[k]].astype(float), texts)
    return frame


def test_map(cli):
    rc, out, err = cli.run("map", *P, "--arc", "50")
    assert rc == 0, err
    check_column(out, "T")


def test_orbit(cli):
    rc, out, err = cli.run("orbit", *P, "--theta0", "3.5", "--steps", "40")
    assert rc == 0, err
    check_column(out, "theta")


def test_info(cli):
    rc, out, err = cli.run("info", *P)
    assert rc == 0, err
    frame, _, names, _ = load_both(out)
    assert names == ["quantity", "value"]
    assert "t2" in list(frame["quantity"])


def test_simulate_and_its_samples(cli, tmp_path):
    samples = tmp_path / "samples.tsv"
    rc, out, err = cli.run("simulate", *P, "--x0", "0", "--y0", "0", "--v0", "0", "--t0", "0", "--t-end", "40",
                           "--sample", "0.5", "--samples-out", samples)
    assert rc == 0, err
    check_column(out, "t")
    assert out.splitlines()[1] == "# dfchaos simulate: the event log of the full system"
    assert [l for l in out.splitlines() if l.startswith("# initial regime: ")]
    assert out.splitlines()[-1].startswith("# final state: t = 40, ")
    frame = check_column(samples.read_text(), "x")
    assert len(frame) == 81 and frame["t"].iloc[-1] == 40


def test_sweep_and_merged_shards(cli, tmp_path):
    grid = ["--q-range", "0.8:0.9:3", "--b-range", "0.01:0.03:2", "--steps", "50", "--transient", "10"]
    whole = tmp_path / "whole.tsv"
    rc, _, err = cli.run("sweep", *grid, "--out", whole)
    assert rc == 0, err
    frame = check_column(whole.read_text(), "lyapunov")
    assert len(frame) == 6 and list(frame["status"]) == ["ok"] * 6
    shards = []
    for i in range(2):
        shards.append(tmp_path / f"shard{i}.tsv")
        rc, _, err = cli.run("sweep", *grid, "--shard", f"{i}/2", "--out", shards[-1])
        assert rc == 0, err
        check_column(shards[-1].read_text(), "rate")
    rc, merged, err = cli.run("sweep-merge", *shards)
    assert rc == 0, err
    assert merged == whole.read_text()


def provenance(text):
    """The '#' lines between the column line and the first row: the title, the build and the
    settings as a dict."""
    lines = text.splitlines()
    head = []
    for l in lines[1:]:
        if not l.startswith("#"):
            break
        head.append(l)
    assert len(head) >= 2, f"no provenance lines after the column line: {lines[:3]}"
    settings = dict(l[2:].split(" = ", 1) for l in head[2:] if " = " in l)
    return head[0], head[1], settings


@pytest.mark.parametrize("command,extra,settings", [
    ("info", [], {}),
    ("map", ["--arc", "5"], {"arc": "5  (t2 + (t3 - t2) i / N, i = 0..N-1)"}),
    ("map", ["--grid", "3.5:4.5:3"], {"grid": "3.5:4.5:3:lin"}),
    ("orbit", ["--theta0", "3.5", "--steps", "4"], {"theta0": "3.5", "steps": "4"}),
    ("simulate", ["--x0", "0", "--y0", "0", "--v0", "0", "--t0", "0", "--t-end", "5"],
     {"x0": "0", "y0": "0", "v0": "0", "t0": "0", "t-end": "5", "max-events": "1000000"}),
])
def test_every_table_says_where_it_came_from(cli, command, extra, settings):
    """The tool's tables carry the sweep's header: what made them, with which build, at which
    settings."""
    rc, out, err = cli.run(command, *P, *extra)
    assert rc == 0, err
    title, build, got = provenance(out)
    assert title.startswith(f"# dfchaos {command}: ")
    _, sweep_build, _ = provenance(cli.run("sweep", "--q-range", "0.8:0.9:2", "--b-range", "0.01:0.02:2",
                                           "--observables", "covering")[1])
    assert build == sweep_build and build.startswith("# dfchaos ")
    assert {k: got[k] for k in ("a", "b", "q")} == {"a": "1", "b": "0.02", "q": "0.85"}
    for k, v in settings.items():
        assert got[k] == v, (k, got)


@pytest.mark.parametrize("command,extra", [
    ("info", []), ("map", ["--theta", "4"]), ("orbit", ["--theta0", "3.5", "--steps", "3"]),
    ("simulate", ["--x0", "0", "--y0", "0", "--v0", "0", "--t0", "0", "--t-end", "5"]),
])
def test_a_defaults_to_one_as_in_sweep_and_certify(cli, command, extra):
    """One rule for a in every command: left out, it is 1."""
    rc1, out1, err1 = cli.run(command, "--b", "0.02", "--q", "0.85", *extra)
    rc2, out2, err2 = cli.run(command, *P, *extra)
    assert rc1 == 0 and rc2 == 0, (err1, err2)
    assert out1 == out2
