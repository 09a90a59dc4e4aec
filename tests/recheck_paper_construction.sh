#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The paper's construction in the proof of Lemma 4 (claim cert.lemma4.paper_construction of
# certified_claims): its certificate is accepted; with the covering replaced by the tool's own covering
# at the same point (a valid covering whose J0 is not inside a branch of L2) it is rejected, and so it
# is with one discontinuity deleted.
# usage: recheck_paper_construction.sh CERTIFIED_CLAIMS DFCHAOS DFCHAOS_RECHECK PYTHON
set -u
exe=$1 cli=$2 checker=$3 py=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok:   $1"; else echo "FAIL: $1"; fails=$((fails + 1)); fi; }
"$exe" --out "$tmp" >/dev/null 2>"$tmp/log" || { tail -5 "$tmp/log"; echo "FAIL: certified_claims"; exit 1; }
f=$tmp/certificates/cert.lemma4.paper_construction.json
check "the certificate is accepted" '"$checker" "$f" >"$tmp/out" && grep -q "^OK .*paper_construction" "$tmp/out"'
cat "$tmp/out"
"$cli" certify covering --b 5e-5 --q 0.85 --certificate "$tmp/cov.json" >/dev/null || { echo "FAIL: dfchaos certify covering"; exit 1; }
"$py" - "$f" "$tmp/cov.json" "$tmp/swapped.json" "$tmp/fewer.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
s = json.loads(json.dumps(c))
s["witnesses"]["covering"] = json.load(open(sys.argv[2]))
json.dump(s, open(sys.argv[3], "w"), indent=1)
del c["witnesses"]["discontinuities"]["witnesses"]["tangencies"][2]
json.dump(c, open(sys.argv[4], "w"), indent=1)
PY
"$checker" "$tmp/swapped.json" >"$tmp/out" 2>&1; rc=$?
check "another valid covering at the point, J0 not in a branch of L2: rejected (exit $rc)" '((rc == 1)) && grep -q "J0 lies strictly between" "$tmp/out"'
cat "$tmp/out"
"$checker" "$tmp/fewer.json" >"$tmp/out" 2>&1; rc=$?
check "one discontinuity deleted: rejected (exit $rc)" '((rc == 1))'
cat "$tmp/out"
# The embedded certificates must be of this format and version, as files of their own.
"$py" - "$f" "$tmp" <<'PY'
import json, os, sys
c = json.load(open(sys.argv[1]))
for name, part, change in [("cov-format-missing", "covering", lambda e: e.pop("format")),
                           ("dis-format-garbled", "discontinuities", lambda e: e.update(format="dfchaos-certificate-2")),
                           ("dis-version-missing", "discontinuities", lambda e: e.pop("version")),
                           ("cov-version-garbled", "covering", lambda e: e.update(version=1.5))]:
    m = json.loads(json.dumps(c))
    change(m["witnesses"][part])
    json.dump(m, open(os.path.join(sys.argv[2], name + ".json"), "w"), indent=1)
PY
for m in cov-format-missing dis-format-garbled dis-version-missing cov-version-garbled; do
  "$checker" "$tmp/$m.json" >"$tmp/out" 2>&1; rc=$?
  check "embedded certificate $m: refused as malformed (exit $rc)" '((rc == 2)) && grep -q "witnesses\.\(covering\|discontinuities\)\.\(format\|version\)" "$tmp/out"'
  cat "$tmp/out"
done
((fails == 0))
