#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `dfchaos orbit-diagram` against the orbit diagrams of the report (experiment bifurcation_diagram,
# run small): at every parameter value of both of the experiment's sweeps (b/a at fixed q/a, q/a at
# fixed b/a), the tool with the experiment's settings gives the same kept phases, Lyapunov exponent,
# return time of t2 and superstable mark, to the last bit. Both call orbit_diagram_column, so this
# checks the tool's grid, start, settings and output against the report's. Then bad input is refused
# with one line naming the option, exit 2 and nothing on stdout.
#   orbit_diagram_vs_experiment.sh EXPERIMENT DFCHAOS
set -euo pipefail
exp=$1 cli=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$exp" --fast --out "$tmp/exp" > /dev/null 2>&1
keep=$(sed -n 's/^# keep = //p' "$tmp/exp/data/bifurcation_diagram-lyapunov.tsv")
transient=$(sed -n 's/^# transient = //p' "$tmp/exp/data/bifurcation_diagram-lyapunov.tsv")
[[ -n "$keep" && -n "$transient" ]] || { echo "FAIL: no keep or transient in the experiment's header"; exit 1; }
steps=$((4 * keep))  # the experiment averages 4 keep steps (bifurcation_diagram.cpp)
fails=0 values=0
# per value: b q lyapunov period_of_t2 t2_cycle_resolved (the experiment's columns)
while IFS=$'\t' read -r sweep b q lyap flat period resolved rest; do
  [[ "$sweep" == sweep || "$sweep" == \#* ]] && continue
  [[ "${rest##*$'\t'}" == 1 ]] && continue  # a value where the experiment's map was not defined
  values=$((values + 1))
  "$cli" orbit-diagram --q-range "$q" --b-range "$b" --transient "$transient" --steps "$steps" --keep "$keep" > "$tmp/tool.tsv"
  # the tool's rows: q b k theta lyapunov period superstable; the experiment's: sweep b q theta
  awk -F'\t' '!/^#/ && NR > 1 { print $4 }' "$tmp/tool.tsv" > "$tmp/tool.theta"
  awk -F'\t' -v s="$sweep" -v b="$b" -v q="$q" '!/^#/ && $1 == s && $2 == b && $3 == q { print $4 }' \
      "$tmp/exp/data/bifurcation_diagram-orbits.tsv" > "$tmp/exp.theta"
  marks=$(awk -F'\t' '!/^#/ && NR > 1 { print $5 "\t" $6 "\t" $7; exit }' "$tmp/tool.tsv")
  if ! cmp -s "$tmp/tool.theta" "$tmp/exp.theta" || [[ ! -s "$tmp/tool.theta" ]] || [[ "$marks" != "$lyap	$period	$resolved" ]]; then
    echo "FAIL: at b/a = $b, q/a = $q the tool gives $(wc -l < "$tmp/tool.theta") phases and marks '$marks', the experiment $(wc -l < "$tmp/exp.theta") and '$lyap	$period	$resolved'"
    fails=$((fails + 1))
  fi
done < "$tmp/exp/data/bifurcation_diagram-lyapunov.tsv"
((values >= 20)) || { echo "FAIL: only $values parameter values compared"; exit 1; }
echo "orbit-diagram equals the experiment at $values parameter values"
refuse() {  # refuse NAME-IN-MESSAGE ARGS...
  local pat=$1; shift
  if "$cli" orbit-diagram "$@" > "$tmp/out" 2> "$tmp/err"; then rc=0; else rc=$?; fi
  if [[ $rc -ne 2 || -s "$tmp/out" || $(wc -l < "$tmp/err") -ne 1 ]] || ! grep -q -- "$pat" "$tmp/err"; then
    echo "FAIL: orbit-diagram $* -> rc=$rc, stdout $(wc -c < "$tmp/out") bytes, stderr: $(head -c 300 "$tmp/err")"; fails=$((fails + 1))
  fi
}
refuse "b-range: T must be defined" --q-range 0.85 --b-range 0.01:0.6:5
refuse "q-range" --q-range 0.85:x:3 --b-range 0.01
refuse "keep: " --q-range 0.85 --b-range 0.01 --steps 10 --keep 11
refuse "theta0-fraction" --q-range 0.85 --b-range 0.01 --theta0-fraction 1
refuse "transient" --q-range 0.85 --b-range 0.01 --transient -1
refuse "steps: " --q-range 0.8:0.9:1000 --b-range 0.01:0.02:1000 --keep 1 --transient 2000
refuse "keep: " --q-range 0.8:0.9:1000 --b-range 0.01:0.02:1000 --keep 200 --steps 200 --transient 0
refuse "a: " --a 0 --q-range 0.85 --b-range 0.01
refuse "q-range: T must be defined" --q-range 0.01:0.85:3 --b-range 0.01
# a grid of 1e16 cells is refused from the sizes of its axes, before they are built (under 500 MB;
# not under AddressSanitizer, whose shadow memory needs far more address space than that)
if ldd "$cli" | grep -q asan; then
  echo "skip: the 500 MB address-space limit (AddressSanitizer)"
  refuse "keep: " --q-range 0.5:0.99:1e8 --b-range 0.001:0.2:1e8
else
  ulimit -v 500000
  refuse "keep: " --q-range 0.5:0.99:1e8 --b-range 0.001:0.2:1e8
fi
((fails == 0)) || exit 1
