#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every data file the experiments write loads with the documented one-call readers.

    pandas.read_csv(f, sep="\\t", comment="#", float_precision="round_trip")
    numpy.genfromtxt(f, names=True, delimiter="\\t", comments="#", dtype=None, encoding=None)

For each DIR/*.tsv (the experiments' data files, written through the kit's Output::table): the
first line is the column line; both readers give those names (pandas exactly, numpy as many) and
as many rows as the file has lines that are neither the column line nor '#' lines; every column
whose texts all read as numbers comes back from both readers as the same doubles as float(text).

Usage: data_files_load.py DIR   (CTest runs it on the smoke tests' output, build/smoke/data)
"""
import glob
import io
import math
import os
import sys
import warnings

import numpy as np
import pandas


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def check(path):
    text = open(path, encoding="utf-8").read()
    lines = text.splitlines()
    if not lines or lines[0].startswith("#"):
        return "the first line is not the column line"
    names = lines[0].split("\t")
    rows = [l.split("\t") for l in lines[1:] if not l.startswith("#")]
    frame = pandas.read_csv(io.StringIO(text), sep="\t", comment="#", float_precision="round_trip")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # numpy's own deprecation notes about its integer dtypes
        array = np.atleast_1d(np.genfromtxt(io.StringIO(text), names=True, delimiter="\t", comments="#", dtype=None, encoding=None))
    if list(frame.columns) != names:
        return f"pandas names {list(frame.columns)[:4]}... against {names[:4]}..."
    if len(array.dtype.names) != len(names):
        return f"numpy reads {len(array.dtype.names)} columns, the file has {len(names)}"
    if len(frame) != len(rows) or len(array) != len(rows):
        return f"rows: pandas {len(frame)}, numpy {len(array)}, file {len(rows)}"
    for k, name in enumerate(names):
        texts = [r[k] for r in rows]
        values = [number(t) for t in texts]
        if not rows or any(v is None for v in values):
            continue
        for label, got in (("pandas", frame[name].to_numpy(dtype=float)), ("numpy", array[array.dtype.names[k]].astype(float))):
            for v, g, t in zip(values, got, texts):
                if not (v == g or (math.isnan(v) and math.isnan(g))):
                    return f"column {name}: {label} read {g!r} from {t!r}"
    return ""


def main():
    files = sorted(glob.glob(os.path.join(sys.argv[1], "*.tsv")))
    if not files:
        sys.exit(f"data_files_load: no .tsv file in {sys.argv[1]} (the smoke tests write them)")
    bad = 0
    for f in files:
        problem = check(f)
        if problem:
            bad += 1
            print(f"FAIL: {f}: {problem}")
    print(f"data_files_load: {len(files)} data files, {bad} not read in one call")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
