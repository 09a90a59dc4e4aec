#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `dfchaos certify`: exit 0 when proved, 1 when not proved (with JSON naming the failed
# step), 2 for bad input (one line on stderr naming the parameter, nothing on stdout).
set -u
cli=$1
fails=0
checks=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

expect() {  # expect RC PATTERN ARGS...: exit status RC and stdout matching PATTERN (rc 2: stderr)
  local rc_want=$1 pat=$2; shift 2
  checks=$((checks + 1))
  "$cli" certify "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  local ok=1
  if [[ $rc -ne $rc_want ]]; then ok=0; fi
  if [[ $rc_want -eq 2 ]]; then
    [[ -s "$tmp/out" || $(wc -l <"$tmp/err") -ne 1 ]] && ok=0
    grep -q -- "$pat" "$tmp/err" || ok=0
  else
    grep -q -- "$pat" "$tmp/out" || ok=0
  fi
  if ((ok)); then
    echo "ok:   dfchaos certify $* -> $rc"
  else
    echo "FAIL: dfchaos certify $* -> rc=$rc (want $rc_want), stdout $(head -c 200 "$tmp/out"), stderr $(head -c 200 "$tmp/err")"
    fails=$((fails + 1))
  fi
}

expect 0 '"proved": true'  vartheta0
expect 0 '0.8104702831753706"' vartheta0
expect 0 '"J0"'            covering --a 1 --b 0.001 --q 0.85
expect 0 '"proved": true'  covering --b 0.003:0.00300001 --q 0.85
expect 1 '"failed_step"'   covering --b 0.02 --q 0.85
expect 1 '"proved": false' covering --b 0.02 --q 0.85
expect 0 '"itinerary": "0001"' periodic --b 0.003 --q 0.85 --period 4
expect 0 '"n": 15'         discontinuities --b 0.01
expect 0 '"proved": true'  lemma1 --b 0.001 --q 0.85
expect 1 '"refuted": true' lemma1 --b 0.001 --q 0.70
expect 0 '"b0_lower_bound"' b0 --q 0.85
expect 0 '"condition"'     superstable --b 0.0641 --q 0.85
expect 1 '"failed_step"'   superstable --b 0.05 --q 0.85
# T = t2 near t2 is proved, but assumptions (2) fail: the record must not call it Theorem 2
expect 0 '"theorem2": false' superstable --b 0.49 --q 1.9
expect 0 '"theorem2": true'  superstable --b 0.0641 --q 0.85
expect 0 '"right_edge"'    superstable --b 0.0641 --q 0.85 --window 0.0640755627691:0.064187276763
# Section 7's covering graph (a statement added through the registry): h_top >= ln rho > ln 2 at C
expect 0 '"h_lower"'       entropy --b 0.01 --q 0.95
expect 2 'b:'              entropy --b 0.01:0.011 --q 0.95
expect 2 '--q is required' entropy --b 0.01
expect 0 '"b_over_a_max": 0.047' arc-l1 --q 0.72:1
expect 0 '"proved": true'  arc-l1 -a 2 -q 1.5
expect 1 '"failed_step": "arc L1: progression' arc-l1 --q 0.3:1
expect 2 'q:'   arc-l1 --q 0.5:1.2
expect 2 'q:'   arc-l1 --q 0
expect 2 '--q is required' arc-l1
expect 2 'b'    arc-l1 --q 0.8 --b 0.001
expect 0 '"proved": true' lemma4-uniform --q 0.73:0.999
expect 0 'wider than L2' lemma4-uniform --q 0.85:0.999
expect 1 '"failed_step": "Lemma 4 for small b/a: (I9) Lemma 1' lemma4-uniform --q 0.62:0.999
expect 1 '"failed_step": "Lemma 4 for small b/a: (I9) Lemma 1' lemma4-uniform --q 0.85:1
expect 2 'q:'   lemma4-uniform --q 0.7:2
expect 2 'b:'   covering --b x --q 0.85
expect 2 'b:'   covering --b "" --q 0.85
expect 2 'b:'   covering --b nan --q 0.85
expect 2 'b:'   covering --b 0.6 --q 0.85
expect 2 'b:'   covering --b 0.002:0.001 --q 0.85
expect 2 '--q is required'   covering --b 0.001
expect 2 'q:'   covering --b 0.001 --q 0.001
expect 2 'a:'   covering --a -1 --b 0.001 --q 0.85
expect 2 'period: ' periodic --b 0.003 --q 0.85
expect 2 'period:' periodic --b 0.003 --q 0.85 --period 0
expect 2 'b:'   periodic --b 0.003:0.004 --q 0.85 --period 2
expect 2 'segment:' discontinuities --b 0.01 --segment L7
expect 2 'window:' superstable --b 0.06 --q 0.85 --window 0.07:0.06
expect 2 'what'  covered --b 0.001 --q 0.85
expect 2 'what'
# The statement comes first: a word or an option before it is refused, never dropped.
expect 2 "certify: 'foo' before the statement covering" foo covering --b 0.001 --q 0.85
expect 2 "certify: '--period' before the statement covering" --period 3 covering --b 0.001 --q 0.85
expect 2 "certify: '-b' before the statement covering" -b 0.3 covering --b 0.001 --q 0.85
# One subcommand per statement: an option of another statement is refused.
expect 2 'not expected' discontinuities --b 0.01 --q 0.85
expect 2 'not expected' vartheta0 --b 0.01
expect 2 '--J0 requires --J1' covering --b 0.001 --q 0.85 --J0 3.3:3.4
# The usage line names the statement (the hidden positional that catches a wrong word is not shown as
# "[]"), and a statement's own usage is its own.
checks=$((checks + 1))
usage=$("$cli" certify --help | grep '^Usage:')
if [[ "$usage" == *"certify STATEMENT [OPTIONS]" && "$usage" != *"[]"* ]] &&
   "$cli" certify covering --help | grep -q '^Usage: .*certify covering \[OPTIONS\]$'; then
  echo "ok:   certify --help: $usage"
else
  echo "FAIL: certify --help usage: $usage"; fails=$((fails + 1))
fi
# The statements of the help (the registry, certify/statements.hpp) are those of docs/certified.md's
# command-line block, in the same order.
checks=$((checks + 1))
helped=$("$cli" certify --help | awk '/^Subcommands:/{on=1; next} on && /^  [a-z]/{print $1}' | tr '\n' ' ')
documented=$(sed -n 's/^dfchaos certify \([a-z0-9-]*\).*/\1/p' "$(dirname "$0")/../docs/certified.md" | tr '\n' ' ')
if [[ -n "$helped" && "$helped" == "$documented" ]]; then
  echo "ok:   the statements of certify --help are docs/certified.md's: $helped"
else
  echo "FAIL: certify --help lists '$helped', docs/certified.md '$documented'"; fails=$((fails + 1))
fi
echo "cli_certify: $checks checks, $fails failures"
exit $((fails > 0))
