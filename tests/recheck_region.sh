#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The certified region's certificates (one `coverings` file per column with a proved box) are accepted
# by dfchaos-recheck and bound to the region's claim and data file by scripts/recheck_certificates.py;
# a column certificate with one box deleted is still a valid proof of less, and the script refuses it
# (its boxes are no longer the column's proved boxes).
# Also refused: a column certificate filed twice under an alias of its name (column2 for column02),
# and a box replaced by a valid covering certificate of the same b range and segments over part of
# the column's q range only.
# usage: recheck_region.sh CERTIFIED_REGION DFCHAOS_RECHECK SCRIPT PYTHON DFCHAOS
set -u
region=$1 checker=$2 script=$3 py=$4 cli=$5
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
cp "$f" "$tmp/column.json"
# an alias: the same column again as column2 (int("2") == int("02"))
alias=$(echo "$f" | sed -E 's/--column0*([0-9]+)\.json$/--column\1.json/')
if [[ $alias != "$f" ]]; then
  cp "$f" "$alias"
  check "the script refuses a column filed under an alias of its name" '! "$py" "$script" "$tmp" "$checker" >"$tmp/out3" 2>&1 && grep -q "none of the claim'"'"'s columns" "$tmp/out3"'
  rm -f "$alias"
fi
# a box narrowed in q: a valid covering of the same b range and J0, J1 over the lower half of the column's q
"$py" - "$f" "$tmp/narrow-args" <<'PY'
import json, sys
b = json.load(open(sys.argv[1]))["witnesses"]["boxes"][0]
p, s = b["parameters"], b["witnesses"]["segments"]
lo, hi = float.fromhex(p["q"]["lo"]["hex"]), float.fromhex(p["q"]["hi"]["hex"])
r = lambda x: repr(float.fromhex(x))
open(sys.argv[2], "w").write(" ".join(["--b", r(p["b"]["lo"]["hex"]) + ":" + r(p["b"]["hi"]["hex"]), "--q", repr(lo) + ":" + repr((lo + hi) / 2),
                                        "--J0", r(s[0]["theta_top"]) + ":" + r(s[0]["theta_t2"]), "--J1", r(s[1]["theta_top"]) + ":" + r(s[1]["theta_t2"])]))
PY
check "the box narrowed in q is proved with its segments (a subset of a proved box)" \
  '"$cli" certify covering $(cat "$tmp/narrow-args") --certificate "$tmp/narrow.json" >/dev/null 2>&1'
if [[ -s $tmp/narrow.json ]]; then
  "$py" - "$f" "$tmp/narrow.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
c["witnesses"]["boxes"][0] = json.load(open(sys.argv[2]))
json.dump(c, open(sys.argv[1], "w"))
PY
  check "the script refuses a box over part of the column's q range" '! "$py" "$script" "$tmp" "$checker" >"$tmp/out4" 2>&1 && grep -q "whole q range" "$tmp/out4"'
  cp "$tmp/column.json" "$f"
fi
"$py" - "$f" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
del c["witnesses"]["boxes"][0]
json.dump(c, open(sys.argv[1], "w"), indent=1)
PY
"$py" -c 'import json, sys; c = json.load(open(sys.argv[1])); c["witnesses"]["boxes"] = []; json.dump(c, open(sys.argv[2], "w"))' "$f" "$tmp/empty.json"
"$checker" "$tmp/empty.json" >/dev/null 2>&1; rc=$?
check "a column certificate with no box is malformed (exit $rc)" '((rc == 2))'
check "the checker accepts the column with a box deleted (a proof of less)" '"$checker" "$f" >"$tmp/one" 2>&1'
check "the script refuses it: not the column's proved boxes" '! "$py" "$script" "$tmp" "$checker" >"$tmp/out2" 2>&1 && grep -q "proved boxes" "$tmp/out2"'
cat "$tmp/out2"
((fails == 0))
