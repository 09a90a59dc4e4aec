#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Every box that certified_region proves can be re-proved alone from its row of the data file:
# `dfchaos certify covering --b LO:HI --q LO:HI --J0 TOP:T2 --J1 TOP:T2` with the segments the row
# records, no candidate search. Also: the J's must come together, J0 left of J1, inside [t2, 3pi/2].
# usage: region_reprove.sh DFCHAOS CERTIFIED_REGION
set -u
cli=$1
region=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$region" --fast --out "$tmp" >/dev/null 2>&1 || { echo "FAIL: certified_region --fast did not run"; exit 1; }
data=$tmp/data/certified_region.tsv
fails=0
proved=0
# columns: q_lo q_hi b_lo b_hi proved sub_boxes failed_step J0_top J0_t2 J1_top J1_t2
# (read through '|': with IFS=tab, bash would merge the empty failed_step column into its neighbours)
while IFS='|' read -r qlo qhi blo bhi ok sub step j0t j0e j1t j1e; do
  [[ $ok == 1 ]] || continue
  proved=$((proved + 1))
  if "$cli" certify covering --b "$blo:$bhi" --q "$qlo:$qhi" --J0 "$j0t:$j0e" --J1 "$j1t:$j1e" >"$tmp/out" 2>"$tmp/err" &&
     grep -q '"proved": true' "$tmp/out"; then
    echo "ok:   box b in [$blo, $bhi], q in [$qlo, $qhi] re-proved with its J0, J1"
  else
    echo "FAIL: box b in [$blo, $bhi], q in [$qlo, $qhi] not re-proved: $(head -c 300 "$tmp/err") $(grep -m1 failed_step "$tmp/out")"
    fails=$((fails + 1))
  fi
  last=("$blo" "$bhi" "$qlo" "$qhi" "$j0t" "$j0e" "$j1t" "$j1e")
done < <(grep -v '^#' "$data" | tail -n +2 | tr '\t' '|')
((proved > 0)) || { echo "FAIL: certified_region --fast proved no box"; exit 1; }

# Bad requests: one line on stderr naming the option, exit 2.
bad() {  # bad PATTERN ARGS...: PATTERN must appear in the one line on stderr
  local pat=$1; shift
  "$cli" certify covering "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  if [[ $rc -eq 2 && ! -s $tmp/out && $(wc -l <"$tmp/err") -eq 1 ]] && grep -q -- "$pat" "$tmp/err"; then echo "ok:   refused: $(cat "$tmp/err")"
  else echo "FAIL: certify covering $* -> rc=$rc, $(head -c 200 "$tmp/err")"; fails=$((fails + 1)); fi
}
b=(--b "${last[0]}:${last[1]}" --q "${last[2]}:${last[3]}")
bad "J0 requires --J1" "${b[@]}" --J0 "${last[4]}:${last[5]}"                                    # J1 missing
bad "J1: .*J1 to the right of J0" "${b[@]}" --J0 "${last[6]}:${last[7]}" --J1 "${last[4]}:${last[5]}"       # J0 right of J1
bad "J0: .*both ends in \[t2(b_hi), 3pi/2\]" "${b[@]}" --J0 "1:${last[5]}" --J1 "${last[6]}:${last[7]}"                # an end below t2
bad "J0: two phases TOP:T2" "${b[@]}" --J0 "${last[4]}" --J1 "${last[6]}:${last[7]}"                  # not TOP:T2
# A given segment that fails is named: J0's ends swapped (T = t2 claimed at the top end) with J1 as
# recorded: not proved (exit 1), and the failed step starts with "J0: ".
"$cli" certify covering "${b[@]}" --J0 "${last[5]}:${last[4]}" --J1 "${last[6]}:${last[7]}" >"$tmp/out" 2>"$tmp/err"
rc=$?
if [[ $rc -eq 1 ]] && grep -q '"failed_step": "J0: ' "$tmp/out"; then echo "ok:   a failed J0 is named: $(grep -o '"failed_step": "[^"]*"' "$tmp/out")"
else echo "FAIL: a failed J0 is not named (rc=$rc): $(grep -o '"failed_step": "[^"]*"' "$tmp/out")"; fails=$((fails + 1)); fi
echo "region_reprove: $proved proved boxes, $fails failures"
exit $((fails > 0))
