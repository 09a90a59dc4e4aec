#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The `region` observable of `dfchaos sweep` (tests/CMakeLists.txt: sweep_region).

usage: sweep_region.py DFCHAOS SOURCE_DIR

Checks, each able to fail:
  1. the uniform route: region_uniform of every cell equals the bound b_over_a_max that
     `dfchaos certify lemma4-uniform -q LO:HI` proves for the cell's q/a range (its extent); a cell
     whose rectangle lies below it is proved whole with no box, a cell straddling it is proved at
     least up to it, a cell above it tries boxes;
  2. proved implies sampled: at points inside every rectangle proved by boxes, the sampled covering
     search (the covering observable at that point) finds two disjoint covering segments;
  3. region_max_boxes bounds the work: with 1 box a cell above the bound tries exactly one and says
     so (region_stop 2, the box budget);
  4. the header states the budget and the legend of region_stop; region is not in the default set;
  3b. only the ratios matter: with a = 3 the region columns equal those of a = 1;
  5. bad input (a b/a axis of one point, --region-max-boxes 0, a mid axis from 0) is refused with
     exit 2, one line naming the option, and no output file;
  6. scripts/region_summary.py: its coverage equals the one computed here from the same file, a
     covering cell in error counts as not proved, and it refuses a damaged file, a file cut short and
     a shard (exit 2, nothing written).
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

cli, src = sys.argv[1], Path(sys.argv[2])
sys.path.insert(0, str(Path(__file__).resolve().parent))
from sweep_checks import Checks, parse  # noqa: E402

tests = Checks(cli)
check, sweep = tests.check, tests.sweep


# A grid of 2 q/a columns (mid: [0.85, 0.86] and [0.86, 0.87]) and b/a points 1e-3 ... 3.2e-3 (log):
# the rectangles reach the next point, the last one step beyond 3.2e-3.
Q, B = "0.85:0.87:2:mid", "1e-3:3.2e-3:4:log"
text = sweep("--q-range", Q, "--b-range", B, "--observables", "covering,region", "--region-max-boxes", "300")
comments, columns, rows = parse(text)
check(columns[4:9] == ["covering", "region", "region_uniform", "region_boxes", "region_stop"], f"columns: {columns}")
b_points = sorted({float(r["b_over_a"]) for r in rows})
ratio = b_points[1] / b_points[0]


def extent(r):
    q = float(r["q_over_a"])
    i = 0 if q < 0.86 else 1
    q_lo, q_hi = (0.85, 0.86) if i == 0 else (0.86, 0.87)
    b = float(r["b_over_a"])
    k = b_points.index(b)
    b_hi = b_points[k + 1] if k + 1 < len(b_points) else b * ratio
    return q_lo, q_hi, b, b_hi


# ---- 1: the uniform route ------------------------------------------------------------------------------
bounds = {}
for lo, hi in ((0.85, 0.86), (0.86, 0.87)):
    c = subprocess.run([cli, "certify", "lemma4-uniform", "-q", f"{lo}:{hi}"], capture_output=True, text=True)
    j = json.loads(c.stdout)
    bounds[(lo, hi)] = j["b_over_a_max"] if j["proved"] else 0.0
kinds = {"below": 0, "straddling": 0, "above": 0}
for r in rows:
    q_lo, q_hi, b_lo, b_hi = extent(r)
    u = bounds[(q_lo, q_hi)]
    region, boxes = float(r["region"]), int(float(r["region_boxes"]))
    check(float(r["region_uniform"]) == u, f"cell {r['index']}: region_uniform {r['region_uniform']} = certify lemma4-uniform's {u!r}")
    if b_hi <= u:
        kinds["below"] += 1
        check(region == 1 and boxes == 0, f"cell {r['index']} below the bound: region {region}, boxes {boxes}")
    elif b_lo < u:
        kinds["straddling"] += 1
        check(region >= (u - b_lo) / (b_hi - b_lo) * (1 - 1e-12) and boxes > 0,
              f"cell {r['index']} straddling the bound: region {region} >= {(u - b_lo) / (b_hi - b_lo):.4f}, boxes {boxes}")
    else:
        kinds["above"] += 1
        check(boxes > 0, f"cell {r['index']} above the bound: {boxes} boxes tried")
check(all(v > 0 for v in kinds.values()), f"the grid holds cells below, straddling and above the bound: {kinds}")

# ---- 2: proved by boxes implies a sampled covering inside ---------------------------------------------
# Narrow rectangles above the bound (q/a in [0.9, 0.91], b/a from 5e-3 in steps of 0.2%), proved by boxes.
_, _, narrow = parse(sweep("--q-range", "0.9:0.91:1:mid", "--b-range", "5e-3:5.01e-3:2:log", "--observables", "region",
                           "--region-max-boxes", "300"))
looked = 0
for r in narrow:
    q_lo, q_hi = 0.9, 0.91
    b_lo = float(r["b_over_a"])
    b_hi = 5.01e-3 if r["index"] == "0" else 5.01e-3 * 5.01e-3 / 5e-3
    check(float(r["region"]) == 1 and int(float(r["region_boxes"])) > 0 and float(r["region_uniform"]) < b_lo,
          f"cell {r['index']} of the narrow grid: proved whole by {r['region_boxes']} boxes above the bound {r['region_uniform']}")
    if float(r["region"]) == 1 and int(float(r["region_boxes"])) > 0:
        for fq, fb in ((0.5, 0.5), (0.2, 0.9), (0.9, 0.1)):
            q, b = q_lo + fq * (q_hi - q_lo), b_lo + fb * (b_hi - b_lo)
            _, _, inner = parse(sweep("--q-range", repr(q), "--b-range", repr(b), "--observables", "covering"))
            check(inner[0]["covering"] == "1", f"cell {r['index']} proved: a covering is found at q/a {q:.6f}, b/a {b:.6g}")
            looked += 1
check(looked >= 3, f"points looked at inside rectangles proved by boxes: {looked}")

# ---- 3: the box budget -----------------------------------------------------------------------------------
_, _, one = parse(sweep("--q-range", "0.85:0.86:1:mid", "--b-range", "3e-3:3.1e-3:2:log", "--observables", "region",
                        "--region-max-boxes", "1"))
check(all(r["region_boxes"] == "1" and r["region_stop"] == "2" for r in one),
      f"--region-max-boxes 1: one box a cell, stop code 2: {[(r['region_boxes'], r['region_stop']) for r in one]}")

# ---- 3b: only the ratios matter: with a = 3 (products rounded) the region columns are those of a = 1 ----
# (q/a 0.785 and 0.795 times 3 round, so that a rectangle in q, b would fall outside the uniform proof's box.)
A3 = ["--q-range", "0.78:0.8:2:mid", "--b-range", "1e-6:1e-5:2:log", "--observables", "region", "--region-max-boxes", "1"]
_, _, one_a = parse(sweep(*A3))
_, _, three = parse(sweep("-a", "3", *A3))
same = all(x[k] == y[k] for x, y in zip(one_a, three) for k in ("region", "region_uniform", "region_boxes", "region_stop"))
check(same and len(three) == len(one_a) == 4 and all(x["region"] == "1" for x in one_a),
      f"a = 3: the region columns equal those of a = 1 (all proved by the uniform route): {[x['region'] for x in three]}")

# ---- 4: header and default set --------------------------------------------------------------------------
check(any(c.startswith("# region_max_boxes = 300") for c in comments), "the header states region_max_boxes")
check(any(c.startswith("# region_stop = 0 decided to the top | 1 gave up after") for c in comments), "the header has the region_stop legend")
_, dcolumns, _ = parse(sweep("--q-range", "0.8:0.9:2", "--b-range", "0.01:0.02:2", "--transient", "5", "--steps", "5"))
check("region" not in dcolumns, f"the default set has no region column: {dcolumns}")

# ---- 5: bad input ------------------------------------------------------------------------------------------
with tempfile.TemporaryDirectory() as tmp:
    out = Path(tmp) / "out.tsv"
    for args, option in ((["--q-range", "0.85", "--b-range", "0.002"], "b-range"),
                         (["--q-range", "0.85", "--b-range", "0.002:0.003:2", "--region-max-boxes", "0"], "region-max-boxes"),
                         (["--q-range", "0.85", "--b-range", "0:0.003:2:mid"], "b-range"),
                         (["--q-range", "0:0.9:1:mid", "--b-range", "0.002:0.003:2"], "q-range")):
        r = subprocess.run([cli, "sweep", "--observables", "region", "--out", str(out), *args], capture_output=True, text=True)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.count("\n") == 1 and option in r.stderr and not out.exists(),
              f"{' '.join(args)}: exit {r.returncode}, {r.stderr.strip()!r}, file {'written' if out.exists() else 'absent'}")

    # ---- 6: the summary script ----------------------------------------------------------------------------
    sweep_file = Path(tmp) / "region.tsv"
    sweep_file.write_text(text)
    summary = src / "scripts" / "region_summary.py"
    r = subprocess.run([sys.executable, str(summary), str(sweep_file), "12", "1 thread", tmp], capture_output=True, text=True)
    tex = (Path(tmp) / "certify-region.tex").read_text() if r.returncode == 0 else ""
    cov = [float(x["region"]) for x in rows if x["status"] == "ok" and x["covering"] == "1"]
    expected = int(1000 * sum(cov) / len(cov)) / 10 if cov else None
    check(r.returncode == 0 and "\\def\\dfcCertRegionCoverage{%.1f}" % expected in tex and "\\def\\dfcCertRegionSeconds{12}" in tex,
          f"region_summary: coverage {expected} of {len(cov)} covering cells (exit {r.returncode}, {r.stderr.strip()[:200]})")
    for name in ("certify-region.tex", "certify-region-columns.tsv"):
        (Path(tmp) / name).unlink(missing_ok=True)
    damaged = text.replace("\t1\t", "\t0\t", 1)
    sweep_file.write_text(damaged)
    r = subprocess.run([sys.executable, str(summary), str(sweep_file), "12", "1 thread", tmp], capture_output=True, text=True)
    check(r.returncode == 2 and "damaged" in r.stderr and not (Path(tmp) / "certify-region.tex").exists(),
          f"region_summary refuses a damaged file: exit {r.returncode}, {r.stderr.strip()!r}")
    # A cell in error counts as not proved: re-sealed with one covering cell made an error cell.
    body = text[: text.rindex("# end: ")]
    lines = body.split("\n")
    k = next(i for i, line in enumerate(lines) if line.split("\t")[4:6] == ["1", "1"])
    f = lines[k].split("\t")
    f[3], f[5:9], f[9] = "error", ["nan"] * 4, "region: a test"
    lines[k] = "\t".join(f)
    body = "\n".join(lines)
    import hashlib
    n = sum(1 for line in body.splitlines()[1:] if not line.startswith("#"))
    sweep_file.write_text(body + f"# end: {n} rows, sha256 {hashlib.sha256(body.encode()).hexdigest()} (of every byte above this line)\n")
    r = subprocess.run([sys.executable, str(summary), str(sweep_file), "12", "1 thread", tmp], capture_output=True, text=True)
    tex = (Path(tmp) / "certify-region.tex").read_text() if r.returncode == 0 else ""
    expected_err = int(1000 * (sum(cov) - 1) / len(cov)) / 10
    check(r.returncode == 0 and "\\def\\dfcCertRegionCoverage{%.1f}" % expected_err in tex and "\\def\\dfcCertRegionErrorCells{1}" in tex,
          f"region_summary: a covering cell in error counts as not proved: coverage {expected_err} ({r.stderr.strip()[:200]})")
    for name in ("certify-region.tex", "certify-region-columns.tsv"):
        (Path(tmp) / name).unlink(missing_ok=True)
    shard = Path(tmp) / "shard.tsv"
    subprocess.run([cli, "sweep", "--q-range", Q, "--b-range", B, "--observables", "covering,region", "--region-max-boxes", "1",
                    "--shard", "0/2", "--out", str(shard)], capture_output=True, text=True)
    r = subprocess.run([sys.executable, str(summary), str(shard), "12", "1 thread", tmp], capture_output=True, text=True)
    check(r.returncode == 2 and "shard" in r.stderr and not (Path(tmp) / "certify-region.tex").exists(),
          f"region_summary refuses a shard: exit {r.returncode}, {r.stderr.strip()!r}")
    sweep_file.write_text(text[: len(text) // 2])
    r = subprocess.run([sys.executable, str(summary), str(sweep_file), "12", "1 thread", tmp], capture_output=True, text=True)
    check(r.returncode == 2 and "seal" in r.stderr and not (Path(tmp) / "certify-region.tex").exists(),
          f"region_summary refuses a file cut short: exit {r.returncode}, {r.stderr.strip()!r}")

tests.finish()
