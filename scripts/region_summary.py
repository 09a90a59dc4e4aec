#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The summary of `make certify-region`: how much of the plane where the sampled search finds a
covering carries a proof over area, read from the sweep's output.

usage: region_summary.py SWEEP.tsv SECONDS WORKERS OUTDIR

SWEEP.tsv is the output of `dfchaos sweep --observables covering,region` (or of dfchaos-sweep-mpi);
its seal ('# end: N rows, sha256 HEX') is checked first, and a file cut short, damaged or of another
spec is refused (exit 2, nothing written). SECONDS is the run's wall time, WORKERS how it ran (e.g.
"2 MPI ranks"). Writes OUTDIR/certify-region.tex (LaTeX macros \\dfcCertRegion...) and
OUTDIR/certify-region-columns.tsv (one row per q/a column), each whole or not at all. The coverage is
given over the whole b/a axis and over its part b/a >= 1e-4, where the report's sampled plane
(thm1_parameter_plane) has points.

The measure: every cell of the sweep stands for its rectangle (docs/cluster.md): on a log b/a axis
and a `mid` q/a axis the rectangles have equal area in (q/a, log b/a), so an area is a count of cells.
`covering` is the sampled search at the cell's point, `region` the proved fraction of the cell's
rectangle (by its linear b-length: within one cell of the default grid, a ratio of 1.06 in b/a, it
differs from the log measure by less than 1.5 % of the cell). Coverage = the sum of `region` over the
cells whose point has a covering, over their number; a cell in error counts as not proved. It is
given over the whole b/a axis (in this log measure the uniform route's part below the bounds weighs
much), over b/a >= 1e-4 (where the report's sampled plane has points), and over the cells above
their column's uniform bound (what the parameter boxes prove).
"""
import datetime
import hashlib
import math
import os
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paper_items import fmt as tex_number  # noqa: E402  (a number for math mode, powers of ten typeset)


def refuse(msg):
    print(f"region_summary: {msg}", file=sys.stderr)
    sys.exit(2)


def read_sweep(path):
    """(header dict, column names, rows as lists of str); refuses a file whose seal does not match."""
    try:
        data = Path(path).read_bytes()
    except OSError as e:
        refuse(f"{path}: cannot read it ({e.strerror})")
    cut = data.rstrip(b"\n").rfind(b"\n") + 1
    last = data[cut:].decode("utf-8", "replace").strip()
    if not last.startswith("# end: "):
        refuse(f"{path}: no seal line '# end: N rows, sha256 HEX' (cut short or not a sweep output)")
    try:
        words = last.split()
        nrows, digest = int(words[2]), words[5]
    except (IndexError, ValueError):
        refuse(f"{path}: a malformed seal line: {last[:80]!r}")
    if hashlib.sha256(data[:cut]).hexdigest() != digest:
        refuse(f"{path}: its bytes do not match its seal (damaged)")
    lines = data[:cut].decode("utf-8").splitlines()
    columns = lines[0].split("\t")
    header = {}
    for line in lines[1:]:
        if line.startswith("# ") and " = " in line:
            k, v = line[2:].split(" = ", 1)
            header[k] = v
    rows = [line.split("\t") for line in lines[1:] if not line.startswith("#")]
    if len(rows) != nrows:
        refuse(f"{path}: {len(rows)} rows, its seal says {nrows}")
    for need in ("q_over_a", "b_over_a", "status", "covering", "region", "region_uniform", "region_boxes", "region_stop"):
        if need not in columns:
            refuse(f"{path}: no column '{need}' (run the sweep with --observables covering,region)")
    if "shard" in header:
        refuse(f"{path}: a shard ({header['shard']}); merge the shards first (dfchaos sweep-merge)")
    return header, columns, rows


def fmt_down(x, digits):
    """x >= 0 rounded down to `digits` decimals (a coverage printed never exceeds the computed one)."""
    s = math.floor(x * 10**digits) / 10**digits
    return f"{s:.{digits}f}"


def main():
    if len(sys.argv) != 5:
        refuse("usage: region_summary.py SWEEP.tsv SECONDS WORKERS OUTDIR")
    path, seconds, workers, outdir = sys.argv[1:]
    try:
        seconds = float(seconds)
    except ValueError:
        refuse(f"SECONDS must be a number (got {seconds!r})")
    if not (math.isfinite(seconds) and seconds >= 0):
        refuse(f"SECONDS must be finite and >= 0 (got {seconds})")
    if not Path(outdir).is_dir():
        refuse(f"OUTDIR {outdir} is not a directory")
    header, columns, rows = read_sweep(path)
    col = {c: i for i, c in enumerate(columns)}
    q_axis, b_axis = header.get("q_over_a", ""), header.get("b_over_a", "")
    if not (q_axis.endswith(":mid") and b_axis.endswith(":log")):
        refuse(f"the measure needs a mid q/a axis and a log b/a axis (got {q_axis}, {b_axis})")

    cells = len(rows)
    errors = sum(1 for r in rows if r[col["status"]] == "error")

    def proved(r):
        """The proved fraction of a cell's rectangle; a cell in error (region nan) counts as 0."""
        x = float(r[col["region"]])
        return x if r[col["status"]] == "ok" and x == x else 0.0

    def share(cs):
        return sum(proved(r) for r in cs) / len(cs) if cs else float("nan")

    covering = [r for r in rows if r[col["covering"]] == "1"]
    if not covering:
        refuse("no cell with a sampled covering: nothing to measure")
    # The same share where the report's sampled plane has points (b/a >= 1e-4, thm1_parameter_plane):
    # below it the uniform route proves everything, which lifts the share over the whole axis; and
    # above each column's uniform bound, where only parameter boxes prove anything.
    upper = [r for r in covering if float(r[col["b_over_a"]]) >= 1e-4]
    above = [r for r in covering if r[col["status"]] == "ok" and float(r[col["b_over_a"]]) >= float(r[col["region_uniform"]])]
    proved_all = sum(proved(r) for r in rows)
    proved_outside = sum(proved(r) for r in rows if r[col["covering"]] != "1")
    boxes = sum(int(float(r[col["region_boxes"]])) for r in rows if r[col["status"]] == "ok")

    # Per column of q/a: the uniform bound, the b/a up to which every cell from the bottom is proved,
    # the covering cells and their proved share.
    by_q = {}
    for r in rows:
        by_q.setdefault(float(r[col["q_over_a"]]), []).append(r)
    table = ["q_over_a\tuniform_bound\tproved_from_bottom_to\tcovering_cells\tproved_share_of_covering"]
    uniform = []
    for q in sorted(by_q):
        cs = sorted(by_q[q], key=lambda r: float(r[col["b_over_a"]]))
        u = max((float(r[col["region_uniform"]]) for r in cs if r[col["status"]] == "ok"), default=0.0)
        uniform.append(u)
        top = cs[0][col["b_over_a"]] if cs else "nan"
        for k, r in enumerate(cs):
            if r[col["status"]] != "ok" or float(r[col["region"]]) < 1:
                break
            top = cs[k + 1][col["b_over_a"]] if k + 1 < len(cs) else "end"
        cov = [r for r in cs if r[col["covering"]] == "1"]
        table.append(f"{q!r}\t{u!r}\t{top}\t{len(cov)}\t{share(cov)!r}")

    def number(x):
        return "%.0f" % x

    lo, hi, n, _ = b_axis.split(":")
    qlo, qhi, qn, _ = q_axis.split(":")
    macros = {
        "Coverage": fmt_down(100 * share(covering), 1),
        "CoverageAbovePlaneLo": fmt_down(100 * share(upper), 1) if upper else "nan",
        "CoverageAboveUniform": fmt_down(100 * share(above), 1) if above else "nan",
        "CoveringCellsAboveUniform": number(len(above)),
        "ProvedArea": fmt_down(100 * proved_all / cells, 1),
        "ProvedOutside": fmt_down(100 * proved_outside / cells, 1),
        "Cells": number(cells),
        "CoveringCells": number(len(covering)),
        "ErrorCells": number(errors),
        "Boxes": number(boxes),
        "Seconds": number(seconds),
        "Minutes": "%.0f" % (seconds / 60),
        "Workers": workers,
        "QLo": tex_number(float(qlo)), "QHi": tex_number(float(qhi)), "QN": qn, "BLo": tex_number(float(lo)), "BHi": tex_number(float(hi)),
        "BN": n,
        "UniformMin": "%.3g" % min(uniform), "UniformMax": "%.3g" % max(uniform),
        "Commit": "unknown",
        "When": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d"),
    }
    # The version line of the header holds the git hash: '# dfchaos 0.1.0 (HASH), compiler'.
    for line in Path(path).read_text().splitlines()[:4]:
        if line.startswith("# dfchaos ") and "(" in line:
            macros["Commit"] = line.split("(", 1)[1].split(")", 1)[0]
    tex = ["% SPDX-License-Identifier: GPL-3.0-or-later",
           "% written by scripts/region_summary.py from " + os.path.basename(path) + "; do not edit"]
    text_macros = ("Workers", "Commit", "When")  # free text: made safe for LaTeX; the others are numbers or math
    for k, v in macros.items():
        v = str(v)
        if k in text_macros:
            v = "".join(ch for ch in v if ch.isalnum() or ch in " .-+:/()")
        tex.append("\\def\\dfcCertRegion%s{%s}" % (k, v))
    for name, text in (("certify-region.tex", "\n".join(tex) + "\n"), ("certify-region-columns.tsv", "\n".join(table) + "\n")):
        fd, tmp = tempfile.mkstemp(dir=outdir, prefix="." + name)
        with os.fdopen(fd, "w") as f:
            f.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, os.path.join(outdir, name))
    print(f"region_summary: {macros['Coverage']}% of the {len(covering)} covering cells proved ({macros['CoverageAbovePlaneLo']}% "
          f"above b/a = 1e-4, {macros['CoverageAboveUniform']}% of the {len(above)} above the uniform bounds; {macros['ProvedArea']}% of "
          f"all {cells} cells); {errors} cells in error; {boxes} box proofs; {seconds:.0f} s on {workers}")


if __name__ == "__main__":
    main()
