#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The Lyapunov plane of the report (experiment plane_lyapunov) equals `dfchaos sweep --observables
# lyapunov` on the same grid, cell by cell and to the last bit: the experiment is the sweep tool's
# computation, not a second implementation that could drift from it.
#   plane_lyapunov_vs_sweep.sh EXPERIMENT DFCHAOS
set -euo pipefail
exp=$1 cli=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
n=8
"$exp" --fast --out "$tmp/exp" > /dev/null
s0=$("$cli" info --a 1 --b 0.01 --q 0.85 | awk -F'\t' '$1 == "a*sin(vartheta0)" { print $2 }')
"$cli" sweep --q-range "$s0:1:$n:mid" --b-range "1e-4:0.1:$n:log" --observables lyapunov --out "$tmp/sweep.tsv"
# q_over_a b_over_a status lyapunov from both (comment and header lines dropped)
awk -F'\t' '!/^#/ && $1 != "q_over_a" { print $1 "\t" $2 "\t" $3 "\t" $4 }' "$tmp/exp/data/plane_lyapunov.tsv" > "$tmp/a"
awk -F'\t' '!/^#/ && $1 != "index"    { print $2 "\t" $3 "\t" $4 "\t" $5 }' "$tmp/sweep.tsv" > "$tmp/b"
rows=$(wc -l < "$tmp/a")
[[ $rows -eq $((n * n)) ]] || { echo "FAIL: the experiment wrote $rows cells, expected $((n * n))"; exit 1; }
if ! diff "$tmp/a" "$tmp/b" > "$tmp/diff"; then echo "FAIL: experiment and sweep differ:"; head -20 "$tmp/diff"; exit 1; fi
# both regimes are present on this small grid too, so the comparison covers -inf and positive values
grep -q -- "-inf$" "$tmp/a" || { echo "FAIL: no cell with lambda = -inf on the $n x $n grid"; exit 1; }
awk -F'\t' '$4 + 0 > 0 { found = 1 } END { exit !found }' "$tmp/a" || { echo "FAIL: no cell with lambda > 0"; exit 1; }
echo "ok: $rows cells identical"
