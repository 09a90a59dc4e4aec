#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# thm2_windows: every superstable window it finds (here --fast, b/a in [0.03, 0.1])
# is proved, with a window certificate that dfchaos-recheck accepts and scripts/recheck_certificates.py
# binds to its record in the claim cert.thm2.all_windows (edges, window number); edges bracketed to
# 1e-12 relative, each edge's border collision named. Certificates filed under another window, or
# whose edge brackets are not the record's, are refused; a bracket moved off the edge is rejected by
# the checker itself.
# usage: recheck_thm2_windows.sh THM2_WINDOWS DFCHAOS_RECHECK SCRIPT PYTHON
set -u
exe=$1 checker=$2 script=$3 py=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok:   $1"; else echo "FAIL: $1"; fails=$((fails + 1)); fi; }
"$exe" --fast --out "$tmp/run" >/dev/null 2>"$tmp/log" || { cat "$tmp/log"; echo "FAIL: thm2_windows --fast"; exit 1; }
claims=$tmp/run/claims/thm2_windows.json
verdict() { "$py" -c "import json,sys; print({c['id']: c['verdict'] for c in json.load(open(sys.argv[1]))['claims']}[sys.argv[2]])" "$claims" "$1"; }
check "cert.thm2.all_windows holds" '[[ $(verdict cert.thm2.all_windows) == holds ]]'
check "thm2.windows_grid holds" '[[ $(verdict thm2.windows_grid) == holds ]]'
check "thm2.window_edges holds" '[[ $(verdict thm2.window_edges) == holds ]]'
n=$(ls "$tmp"/run/certificates/cert.thm2.all_windows--w*.json 2>/dev/null | wc -l)
rows=$(grep -v '^#' "$tmp/run/data/thm2_windows.tsv" | tail -n +2 | wc -l)
check "one certificate per window ($n certificates, $rows windows, at least 3)" '((n == rows && n >= 3))'
check "every edge bracket at most 1e-12 relative, every edge named" \
      '"$py" - "$tmp/run/data/thm2_windows.tsv" <<'"'"'PY'"'"'
import sys, pandas
t = pandas.read_csv(sys.argv[1], sep="\t", comment="#")
assert (t.proved == 1).all() and (t.left_rel <= 1e-12).all() and (t.right_rel <= 1e-12).all(), t
assert t.left_kind.isin(["plateau_t2", "plateau_t3", "grazing_at_t3", "grazing"]).all() and t.right_kind.isin(["plateau_t2", "plateau_t3", "grazing_at_t3", "grazing"]).all()
# the brackets are ordered and each floating window lies within its certified outer points
assert ((t.left_out < t.left_in) & (t.left_in < t.right_in) & (t.right_in < t.right_out)).all()
PY'
check "the checker and the binding accept every certificate" '"$py" "$script" "$tmp/run" "$checker" >"$tmp/out" 2>&1'
check "one accepted row per certificate" '(( $(grep -c "{accepted}$" "$tmp/run/tables/certificates.tex") == n ))'
# Window 1's certificate filed as window 2's: accepted by the checker alone, refused by the binding.
rm -rf "$tmp/swap" && cp -r "$tmp/run" "$tmp/swap"
cp "$tmp/swap/certificates/cert.thm2.all_windows--w001.json" "$tmp/swap/certificates/cert.thm2.all_windows--w002.json"
check "the checker alone accepts the swapped file" '"$checker" "$tmp/swap/certificates/cert.thm2.all_windows--w002.json" >/dev/null'
check "a window's certificate under another window fails the binding" \
      '! "$py" "$script" "$tmp/swap" "$checker" >"$tmp/out2" 2>&1 && grep -q "cert.thm2.all_windows--w002.json" "$tmp/out2" && grep -q "edge brackets are not the claim" "$tmp/out2"'
# A part that is no window of the claim.
rm -rf "$tmp/extra" && cp -r "$tmp/run" "$tmp/extra"
cp "$tmp/extra/certificates/cert.thm2.all_windows--w001.json" "$tmp/extra/certificates/cert.thm2.all_windows--w999.json"
check "a certificate of a window the claim does not have fails the binding" \
      '! "$py" "$script" "$tmp/extra" "$checker" >"$tmp/out3" 2>&1 && grep -q "none of the claim.s windows" "$tmp/out3"'
# A left bracket claimed tighter than proved (left_in moved down to the double above left_out): the
# b-boxes no longer start at left_in, and the checker rejects the file.
"$py" - "$tmp/run/certificates/cert.thm2.all_windows--w001.json" "$tmp/tight.json" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
w = d["witnesses"]
w["left_in"] = float.hex(math.nextafter(float.fromhex(w["left_out"]), 1.0))
json.dump(d, open(sys.argv[2], "w"), indent=1)
PY
check "a bracket tighter than the proof is rejected by the checker" '! "$checker" "$tmp/tight.json" >"$tmp/out4" 2>&1 && grep -q "^FAIL" "$tmp/out4"'
echo "recheck_thm2_windows: $fails failures"
exit $((fails > 0))
