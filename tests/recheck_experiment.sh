#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The certificates that certified_claims writes (as in make reproduce, here in --fast mode) are all
# accepted by dfchaos-recheck through scripts/recheck_certificates.py, which lists them with their
# SHA-256; a certificate changed after the fact makes the script fail and write no table.
# usage: recheck_experiment.sh CERTIFIED_CLAIMS DFCHAOS_RECHECK SCRIPT PYTHON
set -u
exe=$1 checker=$2 script=$3 py=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok:   $1"; else echo "FAIL: $1"; fails=$((fails + 1)); fi; }
# A certificate left by an earlier run whose proof this run does not make (a stale one) is removed;
# a file the experiment does not own is left alone.
mkdir -p "$tmp/certificates" && echo '{}' >"$tmp/certificates/cert.lemma4.Z.json" && echo '{}' >"$tmp/certificates/mine.json"
"$exe" --fast --out "$tmp" >/dev/null 2>"$tmp/log" || { cat "$tmp/log"; echo "FAIL: certified_claims --fast"; exit 1; }
check "a stale certificate of the experiment is removed" '[[ ! -e $tmp/certificates/cert.lemma4.Z.json ]]'
check "a file the experiment does not own is kept" '[[ -e $tmp/certificates/mine.json ]]' && rm -f "$tmp/certificates/mine.json"
n=$(ls "$tmp"/certificates/*.json 2>/dev/null | wc -l)
check "certified_claims wrote certificates ($n)" '((n >= 3))'
check "the checker accepts every one" '"$py" "$script" "$tmp" "$checker" >"$tmp/out" 2>&1'
cat "$tmp/out"
rows=$(grep -c '{accepted}$' "$tmp/tables/certificates.tex" 2>/dev/null || echo 0)
check "one accepted row per certificate ($rows of $n)" '((rows == n))'
for f in "$tmp"/certificates/*.json; do
  sha=$(sha256sum "$f" | cut -d' ' -f1)
  check "$(basename "$f")'s row carries its SHA-256" 'grep -q "{$sha}" "$tmp/tables/certificates.tex"'
done
# The paper's digits of vartheta0: a certificate claiming 0.81048 is rejected by the checker.
"$py" - "$tmp/certificates/cert.eq1.paper_digits.json" "$tmp/digits.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["witnesses"]["decimals"][0]["value"] = "0.81048"
json.dump(d, open(sys.argv[2], "w"), indent=1)
PY
check "a wrong printed digit of vartheta0 is rejected" '"$checker" "$tmp/digits.json" | grep -q "^FAIL .*correctly rounded to 5 decimals"'
rm -f "$tmp/digits.json"
# Tamper: the lemma1 certificate of point A claims another q, which its sub-boxes do not cover.
victim=$tmp/certificates/cert.lemma1.A.json
check "the lemma1 certificate of point A exists" '[[ -f $victim ]]'
before=$(sha256sum "$tmp/tables/certificates.tex")
"$py" - "$victim" <<'PY'
import json, sys
p = sys.argv[1]
d = json.load(open(p))
for end in ("lo", "hi"):   # q = 0.75 instead of 0.85: the sub-boxes no longer cover it
    d["parameters"]["q"][end]["hex"] = "0x1.8p-1"
json.dump(d, open(p, "w"), indent=1)
PY
check "a tampered certificate fails the script" '! "$py" "$script" "$tmp" "$checker" >"$tmp/out2" 2>&1'
check "and names the file" 'grep -q "cert.lemma1.A.json" "$tmp/out2"'
check "and leaves the table as it was" '[[ "$(sha256sum "$tmp/tables/certificates.tex")" == "$before" ]]'
# Swap: a valid certificate of another statement filed under point B's Lemma 1 claim. The checker
# accepts the file on its own; the script must see that it does not prove the claim.
rm -rf "$tmp/swap" && mkdir -p "$tmp/swap" && "$exe" --fast --out "$tmp/swap" >/dev/null 2>&1
cp "$tmp/swap/certificates/cert.eq1.vartheta0.json" "$tmp/swap/certificates/cert.lemma1.B.json"
check "the checker alone accepts the swapped file" '"$checker" "$tmp/swap/certificates/cert.lemma1.B.json" >/dev/null'
check "a certificate of another statement filed under a claim fails the script" \
      '! "$py" "$script" "$tmp/swap" "$checker" >"$tmp/out3" 2>&1 && grep -q "not a proof of claim cert.lemma1.B" "$tmp/out3"'
# Lemma 2: the record of cert.lemma2.C made to count one discontinuity more; the certificate, accepted
# by the checker, no longer proves the claim.
rm -rf "$tmp/count" && cp -r "$tmp/swap" "$tmp/count" && rm -f "$tmp/count/certificates/cert.lemma1.B.json"
cp "$tmp/certificates/cert.lemma1.B.json" "$tmp/count/certificates/" 2>/dev/null
"$py" - "$tmp/count/claims" <<'PY'
import glob, json, sys
for p in glob.glob(sys.argv[1] + "/*.json"):
    d = json.load(open(p))
    for c in d["claims"]:
        if c["id"] == "cert.lemma2.C":
            c["evidence"]["n"] += 1
    json.dump(d, open(p, "w"))
PY
check "a Lemma 2 certificate whose count is not the claim's fails the script" \
      '! "$py" "$script" "$tmp/count" "$checker" >"$tmp/out4" 2>&1 && grep -q "cert.lemma2.C: its number of discontinuities is not the claim" "$tmp/out4"'
# The entropy claim of point A with a valid Lemma 1 certificate (its claim text made the entropy
# claim's) in place of its own: the checker accepts the file, the script must not bind it.
rm -rf "$tmp/ent" && cp -r "$tmp/swap" "$tmp/ent" && rm -f "$tmp/ent/certificates/cert.lemma1.B.json"
cp "$tmp/certificates/cert.lemma1.B.json" "$tmp/ent/certificates/" 2>/dev/null
"$py" - "$tmp/ent/certificates/cert.lemma1.A.json" "$tmp/ent/certificates/cert.sec7.entropy_graph.A.json" <<'PY'
import json, sys
lemma1, target = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
lemma1["claim"] = target["claim"]
json.dump(lemma1, open(sys.argv[2], "w"), indent=1)
PY
check "the checker alone accepts the Lemma 1 file under the entropy claim" '"$checker" "$tmp/ent/certificates/cert.sec7.entropy_graph.A.json" >/dev/null'
check "a certificate of another statement under the entropy claim fails the script" \
      '! "$py" "$script" "$tmp/ent" "$checker" >"$tmp/out5" 2>&1 && grep -q "its statement is .lemma1., claim cert.sec7.entropy_graph.A needs .entropy." "$tmp/out5"'
echo "recheck_experiment: $fails failures"
exit $((fails > 0))
