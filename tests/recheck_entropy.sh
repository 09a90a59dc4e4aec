#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The entropy bound from a covering graph (claims cert.sec7.entropy_graph.* of certified_claims):
# the certificate at point A is accepted; each of these mutations is rejected by dfchaos-recheck:
# a raised rho_lower, an edge to a segment T(I_j) does not cover, a gap in a segment's cover, two
# segments overlapping, a weight that is not positive.
# usage: recheck_entropy.sh CERTIFIED_CLAIMS DFCHAOS_RECHECK PYTHON
set -u
exe=$1 checker=$2 py=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
check() { if eval "$2"; then echo "ok:   $1"; else echo "FAIL: $1"; fails=$((fails + 1)); fi; }
"$exe" --out "$tmp" >/dev/null 2>"$tmp/log" || { tail -5 "$tmp/log"; echo "FAIL: certified_claims"; exit 1; }
f=$tmp/certificates/cert.sec7.entropy_graph.A.json
check "the certificate is accepted" '"$checker" "$f" >"$tmp/out" && grep -q "^OK .*entropy.*rho(A) >= " "$tmp/out"'
cat "$tmp/out"
"$py" - "$f" "$tmp" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
out = sys.argv[2]
segs = c["witnesses"]["segments"]
def save(name, d):
    json.dump(d, open(f"{out}/{name}.json", "w"))
def copy():
    return json.loads(json.dumps(c))
d = copy()  # rho_lower doubled
d["witnesses"]["rho_lower"] = float.hex(2 * float.fromhex(d["witnesses"]["rho_lower"]))
save("rho", d)
# an edge from a segment to one its image does not cover: a segment whose successors miss some k
d = copy()
for j, s in enumerate(d["witnesses"]["segments"]):
    missing = [k for k in range(len(segs)) if k not in s["successors"]]
    if missing:
        s["successors"].append(missing[0])
        break
else:
    raise SystemExit("no segment with a missing edge")
save("edge", d)
d = copy()  # a segment whose cover has a gap: its first ball dropped (if it has one more), else the segment widened
s = d["witnesses"]["segments"][0]
s["I"][1] = float.hex(float.fromhex(s["I"][1]) + 1e-6) if len(s["cover"]) == 1 else s["I"][1]
if len(s["cover"]) > 1:
    del s["cover"][0]
save("gap", d)
d = copy()  # two segments overlapping: the second's lower end moved below the first's upper end
d["witnesses"]["segments"][1]["I"][0] = d["witnesses"]["segments"][0]["I"][1]
save("overlap", d)
d = copy()
d["witnesses"]["segments"][0]["weight"] = float.hex(-1.0)
save("weight", d)
PY
for m in rho edge gap overlap weight; do
  "$checker" "$tmp/$m.json" >"$tmp/out" 2>&1; rc=$?
  check "mutation '$m': rejected (exit $rc)" '((rc == 1))'
  cat "$tmp/out" | cut -c1-300
done
((fails == 0))
