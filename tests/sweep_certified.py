#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The `certified` observable of `dfchaos sweep` (tests/CMakeLists.txt: sweep_certified).

usage: sweep_certified.py DFCHAOS SOURCE_DIR

Checks, each able to fail:
  1. cross-check: on a small grid, the certified column and its step code agree, cell by cell,
     with `dfchaos certify covering --a 1 --b B --q Q` run separately (its JSON "proved" and
     "failed_step"); the grid must hold both proved and not-proved cells;
  2. certified implies covering: wherever a proof succeeds (certified = 1), the sampled covering
     search (covering column) finds two disjoint covering segments too; cells with covering = 1
     and certified = 0 are only counted (the proof may fail where the covering exists);
  3. the step legend of the header names exactly the steps the certified layer can report
     (the "covering: ..." steps of src/dfchaos/certified/covering.cpp and the admissibility step
     of parameters.cpp), so a new or renamed step is noticed here;
  4. certified is not in the default set, and is computed only when asked for;
  5. bad input (an unknown or repeated name) is refused with exit 2, one line naming
     `observables`, and no output file.
"""
import json
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

cli, src = sys.argv[1], Path(sys.argv[2])
sys.path.insert(0, str(Path(__file__).resolve().parent))
from sweep_checks import Checks, parse  # noqa: E402

tests = Checks(cli)
check, sweep = tests.check, tests.sweep


def legend_of(comments):
    line = next((c for c in comments if c.startswith("# certified_step = ")), None)
    if line is None:
        return {}
    text = line[len("# certified_step = "):].split("  (")[0]
    legend = {}
    for item in text.split(" | "):
        code, name = item.split(" ", 1)
        legend[int(code)] = name
    return legend


# ---- 1 and 2: the cross-check and certified => covering ---------------------------------------------
grid = ["--q-range", "0.75:1.05:4", "--b-range", "1e-4:3e-2:4:log", "--observables", "covering,certified"]
comments, columns, rows = parse(sweep(*grid))
check(columns[-3:] == ["certified", "certified_step", "error"] and columns[4] == "covering",
      f"columns covering ... certified, certified_step, error: {columns}")
legend = legend_of(comments)
check(legend.get(0) == "proved" and len(legend) >= 2, f"the header's step legend: {legend}")
compared = {"proved": 0, "not proved": 0}
for r in rows:
    if r["status"] != "ok":
        check(r["status"] == "inadmissible" and r["certified"] == "nan",
              f"cell {r['index']}: status {r['status']}, certified {r['certified']} ({r['error']})")
        continue
    q, b = r["q_over_a"], r["b_over_a"]
    c = subprocess.run([cli, "certify", "covering", "--a", "1", "--b", b, "--q", q], capture_output=True, text=True)
    if c.returncode == 2 and "q - 2b < a" in c.stderr:
        # The tool refuses q - 2b >= a as bad input; the sweep, where T is defined (q > 2b), records the
        # same condition as the step the certified layer could not prove: admissibility (code 1).
        check(float(q) - 2 * float(b) >= 1 and (r["certified"], r["certified_step"]) == ("0", "1") and legend.get(1) == "admissibility",
              f"cell {r['index']} (q/a {q}, b/a {b}): certify refuses q - 2b >= a; sweep certified {r['certified']} "
              f"step {r['certified_step']}")
        compared["refused"] = compared.get("refused", 0) + 1
        continue
    try:
        j = json.loads(c.stdout)
    except ValueError:
        check(False, f"certify covering --b {b} --q {q}: exit {c.returncode}, no JSON: {c.stderr[:200]}")
        continue
    proved = bool(j["proved"])
    step = 0 if proved else next((k for k, v in legend.items() if v == j.get("failed_step")), None)
    ours = (int(float(r["certified"])), int(float(r["certified_step"])))
    check(ours == (int(proved), step) and c.returncode == (0 if proved else 1),
          f"cell {r['index']} (q/a {q}, b/a {b}): sweep certified {ours[0]} step {ours[1]}; certify covering proved "
          f"{proved} failed_step {j.get('failed_step', '-')!r} (exit {c.returncode})")
    compared["proved" if proved else "not proved"] += 1
check(compared["proved"] >= 2 and compared["not proved"] >= 2 and compared.get("refused", 0) >= 1,
      f"cells compared with certify covering: {compared}")

# On a finer grid of the chaotic region, certified = 1 implies covering = 1.
comments, columns, rows = parse(sweep("--q-range", "0.7:1:8:mid", "--b-range", "1e-4:0.1:8:log", "--observables", "covering,certified"))
ok = [r for r in rows if r["status"] == "ok"]
both = sum(1 for r in ok if r["certified"] == "1" and r["covering"] == "1")
proof_only = [r for r in ok if r["certified"] == "1" and r["covering"] != "1"]
sampled_only = sum(1 for r in ok if r["covering"] == "1" and r["certified"] == "0")
neither = sum(1 for r in ok if r["covering"] == "0" and r["certified"] == "0")
print(f"      {len(rows)} cells, {len(ok)} ok: certified and covering {both}, covering only {sampled_only}, neither {neither}, "
      f"certified only {len(proof_only)}")
check(not proof_only, "certified = 1 implies covering = 1" +
      "".join(f"; not at q/a {r['q_over_a']}, b/a {r['b_over_a']}" for r in proof_only))
check(both > 0, "the grid holds proved cells")

# ---- 3: the legend names exactly the steps the certified layer reports --------------------------------
steps = set(re.findall(r'"(covering: [^"]+)"', (src / "src/dfchaos/certified/covering.cpp").read_text()))
steps |= set(re.findall(r'Outcome::fail\("([^"]+)"', (src / "src/dfchaos/certified/parameters.cpp").read_text()))
named = {v for k, v in legend.items() if k != 0}
check(steps == named, f"legend = the steps of covering.cpp and parameters.cpp (missing {sorted(steps - named)}, "
      f"unknown {sorted(named - steps)})")

# ---- 4: not in the default set -----------------------------------------------------------------------
comments, columns, rows = parse(sweep("--q-range", "0.8:0.9:2", "--b-range", "0.01:0.02:2", "--transient", "5", "--steps", "5"))
check("certified" not in columns and "# observables = covering,superstable,lyapunov,rate,period" in comments
      and not any(c.startswith("# certified_step") for c in comments), f"the default set has no certified column: {columns}")

# ---- 5: bad input --------------------------------------------------------------------------------------
with tempfile.TemporaryDirectory() as tmp:
    for bad in ("covering,certifed", "certified,certified"):
        out = Path(tmp) / "out.tsv"
        r = subprocess.run([cli, "sweep", "--q-range", "0.8:0.9:2", "--b-range", "0.01:0.02:2", "--observables", bad, "--out", str(out)],
                           capture_output=True, text=True)
        check(r.returncode == 2 and r.stdout == "" and r.stderr.count("\n") == 1 and "observables" in r.stderr and not out.exists(),
              f"--observables {bad}: exit {r.returncode}, {r.stderr.strip()!r}, file {'written' if out.exists() else 'absent'}")

tests.finish()
