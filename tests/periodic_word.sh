#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A periodic orbit of any itinerary, three ways: `dfchaos periodic --word W`
# (floating point: the fixed point of the composed inverse branches), `dfchaos certify periodic
# --word W` (Krawczyk enclosure in Arb, with a certificate) and `dfchaos-recheck` (the MPFI checker
# re-verifies the certificate). The floating orbit must lie within its precision floor of the
# certified balls, both multipliers agree, the certificate is accepted, and the checker refuses
# certificates whose word was forged (another word of the same letters, a power of a shorter word).
# Bad words are refused by both commands, one line naming --word, exit 2.
#   periodic_word.sh DFCHAOS DFCHAOS_RECHECK
set -uo pipefail
cli=$1 recheck=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0
P=(--b 0.003 --q 0.85)
for w in 0011 01101 1 0111010; do
  "$cli" periodic "${P[@]}" --word "$w" > "$tmp/float.tsv" || { echo "FAIL: periodic --word $w"; fails=$((fails + 1)); continue; }
  "$cli" certify periodic "${P[@]}" --word "$w" --certificate "$tmp/cert-$w.json" > "$tmp/cert.json" \
    || { echo "FAIL: certify periodic --word $w"; fails=$((fails + 1)); continue; }
  if ! /usr/bin/python3 - "$tmp/float.tsv" "$tmp/cert.json" "$w" <<'PY'
import json, math, sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1]) if not l.startswith("#")]
head = {l[2:].split(" = ")[0]: l[2:].split(" = ")[1] for l in open(sys.argv[1]) if l.startswith("# ") and " = " in l}
cert, word = json.load(open(sys.argv[2])), sys.argv[3]
assert rows[0] == ["j", "letter", "x", "T"] and len(rows) == len(word) + 1, rows[:2]
assert "".join(r[1] for r in rows[1:]) == word and cert["itinerary"] == word and cert["period"] == len(word)
floor = float(head["precision_floor"])
for r, ball in zip(rows[1:], cert["orbit"]):
    d = abs(float(r[2]) - float(ball["mid"]))
    assert d <= max(floor, 1e-15) + float(ball["rad"]), (word, r, ball, floor)
# ln|(T^m)'|: central differences against the enclosure (relative 1e-4)
lm, lc = float(head["log_multiplier"].split()[0]), float(cert["log_multiplier"]["mid"])
assert abs(lm - lc) <= 1e-4 * abs(lc), (lm, lc)
print(f"ok:   word {word}: the floating orbit lies in the certified balls (floor {floor:.1e}); ln|(T^m)'| {lm:.6f} vs {lc:.6f}")
PY
  then fails=$((fails + 1)); fi
  "$recheck" "$tmp/cert-$w.json" > "$tmp/recheck.out" || { echo "FAIL: recheck of --word $w: $(cat "$tmp/recheck.out")"; fails=$((fails + 1)); }
done
# forged words: the boxes stay, the word changes
forge() {  # forge WORD-IN-FILE NEW-WORD
  sed "s/\"word\": \"$1\"/\"word\": \"$2\"/" "$tmp/cert-$1.json" > "$tmp/forged.json"
  if "$recheck" "$tmp/forged.json" > "$tmp/recheck.out" 2>&1; then
    echo "FAIL: the checker accepted word $2 for the boxes of $1"; fails=$((fails + 1))
  else echo "ok:   the checker refuses word $2 for the boxes of $1: $(head -c 160 "$tmp/recheck.out")"; fi
}
forge 0011 0101
forge 0011 1100
forge 0011 0012
refuse() {  # refuse ARGS...: exit 2, one line naming --word, nothing on stdout
  if "$cli" "$@" > "$tmp/out" 2> "$tmp/err"; then rc=0; else rc=$?; fi
  if [[ $rc -ne 2 || -s "$tmp/out" || $(wc -l < "$tmp/err") -ne 1 ]] || ! grep -q "word" "$tmp/err"; then
    echo "FAIL: $* -> rc=$rc: $(head -c 200 "$tmp/err")"; fails=$((fails + 1))
  else echo "ok:   $* refused: $(cat "$tmp/err")"; fi
}
for bad in 0101 012 "" 000; do
  refuse periodic "${P[@]}" --word "$bad"
  refuse certify periodic "${P[@]}" --word "$bad"
done
refuse certify periodic "${P[@]}" --word "$(printf '0%.0s' {1..64})1"
refuse certify covering "${P[@]}" --word 01
((fails == 0))
