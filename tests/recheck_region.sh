#!/usr/bin/env bash
# The certified region's certificates (one `coverings` file per column with a proved box) are accepted
# by dfchaos-recheck and bound to the region's claim and data file by scripts/recheck_certificates.py;
# a column certificate with one box deleted is still a valid proof of less, and the script refuses it
# (its boxes are no longer the column's proved boxes).
# usage: recheck_region.sh CERTIFIED_REGION DFCHAOS_RECHECK SCRIPT PYTHON
set -u
region=$1 checker=$2 script=$3 py=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok:   $1"; else echo "FAIL: $1"; fails=$((fails + 1)); fi; }
"$region" --fast --out "$tmp" >/dev/null 2>"$tmp/log" || { cat "$tmp/log"; echo "FAIL: certified_region --fast"; exit 1; }
n=$(ls "$tmp"/certificates/cert.thm1.region--column*.json 2>/dev/null | wc -l)
check "certified_region wrote column certificates ($n)" '((n >= 1))'
check "the checker accepts them and the script binds them to the claim" '"$py" "$script" "$tmp" "$checker" >"$tmp/out" 2>&1'
cat "$tmp/out"
f=$(ls "$tmp"/certificates/cert.thm1.region--column*.json | head -1)
"$py" - "$f" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
del c["witnesses"]["boxes"][0]
json.dump(c, open(sys.argv[1], "w"), indent=1)
PY
check "the checker accepts the column with a box deleted (a proof of less)" '"$checker" "$f" >"$tmp/one" 2>&1'
check "the script refuses it: not the column's proved boxes" '! "$py" "$script" "$tmp" "$checker" >"$tmp/out2" 2>&1 && grep -q "proved boxes" "$tmp/out2"'
cat "$tmp/out2"
((fails == 0))
