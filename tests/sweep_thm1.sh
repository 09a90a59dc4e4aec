#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The sweep reproduces the classification of experiments/thm1_parameter_plane on the same cells:
#   sweep_thm1.sh DFCHAOS THM1-PARAMETER-PLANE
# The experiment's 2 x 100 grid (q/a: 2 cell centres of (sin vartheta0, 1); b/a: 100 log-spaced
# points of [1e-4, 0.1], one of them in a superstable window) is swept with
# --q-range S0:1:2:mid --b-range 1e-4:0.1:100:log, S0 printed by
# `dfchaos info` in %.17g (round-trip exact), and the columns q_over_a, b_over_a, covering,
# superstable, epsilon must agree as text; class -1 (a failed cell) must be status error.
set -u
cli=$1
thm1=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$thm1" --nq 2 --nb 100 --out "$tmp/exp" > "$tmp/exp.log" 2>&1 || { echo "FAIL: the experiment: $(tail -3 "$tmp/exp.log")"; exit 1; }
s0=$("$cli" info --a 1 --b 0.01 --q 0.85 | awk -F'\t' '$1 == "a*sin(vartheta0)" { print $2 }')
[[ -n "$s0" ]] || { echo "FAIL: no a*sin(vartheta0) from dfchaos info"; exit 1; }
"$cli" sweep --q-range "$s0:1:2:mid" --b-range 1e-4:0.1:100:log --observables covering,superstable > "$tmp/sweep.tsv" || exit 1
python3 - "$tmp/exp/data/thm1_parameter_plane.tsv" "$tmp/sweep.tsv" <<'PY'
import sys
def rows(path):
    lines = [l.rstrip("\n").split("\t") for l in open(path) if not l.startswith("#")]
    head = lines[0]
    return [dict(zip(head, r)) for r in lines[1:]]
exp, swp = rows(sys.argv[1]), rows(sys.argv[2])
bad = 0
if len(exp) != len(swp) or len(exp) != 200:
    print(f"FAIL: {len(exp)} experiment rows, {len(swp)} sweep rows (200 expected)"); sys.exit(1)
for e, s in zip(exp, swp):
    failed = e["class"] == "-1"
    if failed != (s["status"] == "error"):
        print(f"FAIL: cell {s['index']}: experiment class {e['class']}, sweep status {s['status']}"); bad += 1; continue
    for col in ["q_over_a", "b_over_a"] + ([] if failed else ["covering", "superstable", "epsilon"]):
        if e[col] != s[col]:
            print(f"FAIL: cell {s['index']}: {col} = {e[col]} (experiment) vs {s[col]} (sweep)"); bad += 1
covering = sum(s["covering"] == "1" for s in swp)
superstable = sum(s["superstable"] == "1" for s in swp)
if covering == 0 or covering == len(swp) or superstable == 0:
    print(f"FAIL: the grid must hold cells with and without the covering and a superstable one ({covering}, {superstable})"); bad += 1
print(f"{'ok' if bad == 0 else 'FAIL'}: 200 cells, {covering} with the covering, {superstable} superstable, {bad} disagreements")
sys.exit(1 if bad else 0)
PY
