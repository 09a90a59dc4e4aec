#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Failure tier for the dfchaos CLI: every bad input gives exit status 2, exactly one line on
# stderr naming the parameter, and nothing on stdout. Also a few well-formed calls.
set -u
cli=$1
fails=0
checks=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

expect_error() {  # expect_error NAME-IN-MESSAGE ARGS...
  local name=$1; shift
  checks=$((checks + 1))
  "$cli" "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$?
  local lines; lines=$(wc -l <"$tmp/err")
  if [[ $rc -ne 2 || -s "$tmp/out" || $lines -ne 1 ]] || ! grep -q -- "$name" "$tmp/err"; then
    echo "FAIL: dfchaos $* -> rc=$rc, stdout $(wc -c <"$tmp/out") bytes, stderr $lines lines: $(head -c 300 "$tmp/err")"
    fails=$((fails + 1))
  else
    echo "ok:   dfchaos $* -> $(cat "$tmp/err")"
  fi
}
expect_ok() {  # expect_ok HEADER-REGEX ARGS...
  local pat=$1; shift
  checks=$((checks + 1))
  if ! "$cli" "$@" >"$tmp/out" 2>"$tmp/err" || ! head -n 3 "$tmp/out" | grep -qE "$pat"; then
    echo "FAIL: dfchaos $* should succeed with /$pat/: $(head -c 300 "$tmp/err")"
    fails=$((fails + 1))
  else
    echo "ok:   dfchaos $*"
  fi
}

P=(--a 1 --b 0.01 --q 0.85)
expect_error "a:"     map --a x --b 0.01 --q 0.85 --theta 4
expect_error "--a"    map --a "" --b 0.01 --q 0.85 --theta 4
expect_error "--steps" orbit --a 1 --b 0.01 --q 0.85 --theta0 4 --steps ""
expect_error "a:"     map --a nan --b 0.01 --q 0.85 --theta 4
expect_error "a:"     map --a 0 --b 0.01 --q 0.85 --theta 4
expect_error "a:"     map --a -1 --b 0.01 --q 0.85 --theta 4
expect_error "a:"     map --a inf --b 0.01 --q 0.85 --theta 4
expect_error "b:"     map --a 1 --b 0 --q 0.85 --theta 4
expect_error "b:"     map --a 1 --b 0.5 --q 0.85 --theta 4
expect_error "b:"     orbit --a 1 --b 0.7 --q 0.85 --theta0 4 --steps 3
expect_error "q:"     map --a 1 --b 0.3 --q 0.5 --theta 4
expect_error "q:"     map --a 1 --b 0.01 --q -2 --theta 4
expect_error "theta:" map "${P[@]}" --theta 1.0
expect_error "theta:" map "${P[@]}" --theta 4.0 7.0
expect_error "theta:" map "${P[@]}" --theta nan
expect_error "theta0:" orbit "${P[@]}" --theta0 6.5 --steps 3
expect_error "theta"  map "${P[@]}"
expect_error "--theta" map "${P[@]}" --theta
expect_error "grid n: .*1 <= n <= 1e7" map "${P[@]}" --grid 3.5:4:0
expect_error "grid n: .*1 <= n <= 1e7" map "${P[@]}" --grid 3.5:4:100000001
expect_error "grid n:" map "${P[@]}" --grid 3.5:4:2.5
expect_error "grid: .*lo < hi" map "${P[@]}" --grid 4:3.5:10
expect_error "grid: .*t2 <= grid < t3" map "${P[@]}" --grid 1:3.5:10
expect_error "grid: .*t2 <= grid < t3" map "${P[@]}" --grid 3.5:7:10
# The old spelling 'LO HI N' (HI left out) is refused with the new one named.
expect_error "grid: write the grid as one word LO:HI:N" map "${P[@]}" --grid 3.5 4 10
expect_error "grid: write the grid as one word LO:HI:N" map "${P[@]}" --grid 3.5 4
expect_error "steps"  orbit "${P[@]}" --theta0 4 --steps 0
expect_error "steps:" orbit "${P[@]}" --theta0 4 --steps many
expect_error "x0:"    simulate "${P[@]}" --x0 1 --y0 0 --v0 0 --t0 0 --t-end 10
expect_error "t-end:" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 10 --t-end 0
expect_error "v0:"    simulate "${P[@]}" --x0 0 --y0 0 --v0 nan --t0 0 --t-end 10
expect_error "sample:" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 0 --t-end 10 --sample -1
expect_error "--t-end" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 0
expect_error "steps:" orbit "${P[@]}" --theta0 4 --steps 1.5e8
expect_error "steps:" orbit "${P[@]}" --theta0 4 --steps 2.5
expect_error "arc:"   map "${P[@]}" --arc 0
expect_error "arc:"   map "${P[@]}" --arc 1e8
expect_error "arc:"   map "${P[@]}" --arc x
expect_error "--arc"  map "${P[@]}" --arc 3 --theta 4
expect_error "max-events:" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 0 --t-end 10 --max-events 0
# The accuracy contract (docs/accuracy.md).
expect_error "a:"     info --a 1e-320 --b 0.01 --q 0.85
expect_error "b:"     info --a 1 --b 1e-300 --q 0.85
expect_error "q:"     info --a 1 --b 0.01 --q 1e101
expect_error "b:"     map --a 1 --b 1e-17 --q 0.85 --theta 4
expect_error "b:"     map --a 1 --b 1e-13 --q 0.85 --theta 4
expect_error "b:"     orbit --a 1 --b 1e-16 --q 0.85 --theta0 4 --steps 3
expect_error "t-end:" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 1e20
expect_error "t-end:" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 6e19
expect_error "t-end:" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 1e308
expect_error "t0:"    simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 1e20 --t-end 1.00000000001e20
expect_error "frobnicate" frobnicate "${P[@]}"
expect_error "--bogus" map "${P[@]}" --theta 4 --bogus 1
expect_error "subcommand" 

# ---- sweep and sweep-merge ----------------------------------------------------------------------
G=(--q-range 0.7:0.9:2 --b-range 0.01:0.1:2)   # 4 cells
W=("${G[@]}" --observables period --transient 5)  # cheap ones
expect_error "--q-range" sweep --b-range 0.01:0.1:2
expect_error "q-range:"  sweep --q-range 1:0.5:3 --b-range 0.01:0.1:2
expect_error "q-range:"  sweep --q-range 0.5:0.5:3 --b-range 0.01:0.1:2
expect_error "q-range:"  sweep --q-range 0.5:1 --b-range 0.01:0.1:2
expect_error "within \[1e-100, 1e100\] for every cell"  sweep --q-range 1e308 --b-range 0.01   # no cell computable: refused, not a file of error rows
expect_error "q-range:"  sweep --q-range 0.5:1:3:cubic --b-range 0.01:0.1:2
expect_error "q-range n:" sweep --q-range 0.5:1:0 --b-range 0.01:0.1:2
expect_error "q-range n:" sweep --q-range 0.5:1:2.5 --b-range 0.01:0.1:2
expect_error "q-range n:" sweep --q-range 0.5:1:1e9 --b-range 0.01:0.1:2
expect_error "q-range lo:" sweep --q-range x:1:3 --b-range 0.01:0.1:2
expect_error "q-range hi:" sweep --q-range 0.5:inf:3 --b-range 0.01:0.1:2
expect_error "q-range:"  sweep --q-range -0.5:1:3 --b-range 0.01:0.1:2
expect_error "q-range:"  sweep --q-range 0.5:1:1e5 --b-range 0.01:0.1:1e4
expect_error "b-range:"  sweep --q-range 0.5:1:3 --b-range 0.1:0.5:3
expect_error "b-range:"  sweep --q-range 0.5:1:3 --b-range 0:0.1:3:log
expect_error "a:"        sweep --a 0 "${W[@]}"
expect_error "a:"        sweep --a 1e308 "${W[@]}"
expect_error "observables:" sweep "${G[@]}" --observables covering,chaos
expect_error "observables:" sweep "${G[@]}" --observables ,
expect_error "observables:" sweep "${G[@]}" --observables rate,rate
expect_error "observables:" sweep "${G[@]}" --observables covering,certified,certified
expect_error "observables:" sweep "${G[@]}" --observables certified_step
expect_error "max-branches:" sweep "${G[@]}" --observables certified --max-branches 0
expect_error "shard:"    sweep "${W[@]}" --shard 2/2
expect_error "shard:"    sweep "${W[@]}" --shard 1/0
expect_error "shard:"    sweep "${W[@]}" --shard 1
expect_error "shard i:"  sweep "${W[@]}" --shard a/2
expect_error "shard:"    sweep "${W[@]}" --shard 0/5
expect_error "transient:" sweep "${G[@]}" --transient -1
expect_error "steps:"    sweep "${W[@]}" --steps 0
expect_error "theta0-fraction:" sweep "${W[@]}" --theta0-fraction 1
# One meaning per name: --theta0 is a phase (orbit); a sweep's start is a fraction, named so.
expect_error "theta0: .*use --theta0-fraction" sweep "${W[@]}" --theta0 0.5
# One value for an axis, the same as x:x:1.
checks=$((checks + 1))
if ! cmp -s <("$cli" sweep --q-range 0.85 --b-range 0.01:0.02:2 --observables covering) \
            <("$cli" sweep --q-range 0.85:0.85:1 --b-range 0.01:0.02:2 --observables covering); then
  echo "FAIL: --q-range 0.85 is not the same sweep as 0.85:0.85:1"; fails=$((fails + 1))
fi
# The same cap on orbit steps in sweep and orbit.
expect_error "steps:" sweep "${W[@]}" --steps 100000001
expect_error "steps:" orbit "${P[@]}" --theta0 3.5 --steps 100000001
expect_error "period-max:" sweep "${W[@]}" --period-max 0
expect_error "period-tol:" sweep "${W[@]}" --period-tol 0
expect_error "superstable-scan:" sweep "${W[@]}" --superstable-scan 1
expect_error "chunk:"    sweep "${W[@]}" --chunk 0
expect_error "max-chunks:" sweep "${W[@]}" --max-chunks 2
expect_error "--resume"  sweep "${W[@]}" --out "$tmp/o.tsv" --resume "$tmp/r.tsv"
expect_error "out:"      sweep "${W[@]}" --out "$tmp/no/such/dir/o.tsv"
expect_error "resume:"   sweep "${W[@]}" --resume "$tmp/no/such/dir/r.tsv"
"$cli" sweep "${W[@]}" --steps 5 --resume "$tmp/res.tsv" --chunk 1 --max-chunks 1 2>/dev/null
expect_error "resume:"   sweep "${W[@]}" --steps 6 --resume "$tmp/res.tsv"
expect_error "resume:"   sweep "${W[@]}" --steps 5 --shard 0/2 --resume "$tmp/res.tsv"
for i in 0 1; do "$cli" sweep "${W[@]}" --shard $i/2 --out "$tmp/sh$i.tsv"; done
for i in 0 1 2; do "$cli" sweep "${W[@]}" --shard $i/3 --out "$tmp/th$i.tsv"; done
"$cli" sweep "${W[@]}" --steps 6 --shard 1/2 --out "$tmp/other1.tsv"
"$cli" sweep "${W[@]}" > "$tmp/whole.tsv"
head -c -1 "$tmp/sh1.tsv" > "$tmp/cut1.tsv"
head -n -1 "$tmp/sh1.tsv" > "$tmp/short1.tsv"
expect_error "files"       sweep-merge
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv" "$tmp/sh0.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv" "$tmp/other1.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv" "$tmp/th1.tsv" "$tmp/th2.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv" "$tmp/cut1.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv" "$tmp/short1.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/whole.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv" "$tmp/no-such-file.tsv"
expect_error "sweep-merge:" sweep-merge "$tmp/sh0.tsv" "$cli"
expect_ok "^# dfchaos sweep: " sweep "${W[@]}"
expect_ok "^# dfchaos sweep: " sweep-merge "$tmp/sh1.tsv" "$tmp/sh0.tsv"

expect_ok "^theta	T1	T	scenario	elapsed	penetration$" map "${P[@]}" --theta 3.5 4.5
expect_ok "^n	theta	scenario	elapsed	penetration	time	y$" orbit "${P[@]}" --theta0 3.5 --steps 5
expect_ok "^t	phase	before	after	kind" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 100 --sample 1 --samples-out "$tmp/smp.tsv"
checks=$((checks + 1))
if [[ $(head -n 1 "$tmp/smp.tsv") != $'t\tx\ty\tv\tregime' || $(grep -vc '^#' "$tmp/smp.tsv") -ne 98 ]]; then
  echo "FAIL: the samples file: column line and 97 rows expected"; fails=$((fails + 1))
fi
# The samples are a table of their own: --sample needs --samples-out, and the other way round.
expect_error "sample: .*--samples-out" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 100 --sample 1
# The file the shell opened for stdout or stderr is not replaced by the samples (nor by a sweep's --out).
checks=$((checks + 1))
echo keep > "$tmp/elog.txt"
"$cli" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 10 --sample 1 --samples-out /dev/stderr 2>>"$tmp/elog.txt" >/dev/null
rc=$?
if [[ $rc -ne 2 || $(head -n 1 "$tmp/elog.txt") != keep ]] || ! grep -q "samples-out: .*standard error" "$tmp/elog.txt"; then
  echo "FAIL: --samples-out /dev/stderr replaced the file of stderr (rc=$rc)"; fails=$((fails + 1))
fi
checks=$((checks + 1))
"$cli" sweep --q-range 0.85 --b-range 0.01 --observables covering --out "$tmp/same.tsv" > "$tmp/same.tsv" 2>"$tmp/err"
rc=$?
if [[ $rc -ne 2 ]] || ! grep -q "out: .*standard output" "$tmp/err"; then echo "FAIL: sweep --out onto its own stdout (rc=$rc)"; fails=$((fails + 1)); fi
# A closed stdout: the rows cannot be written (exit 1); they never land in the samples file.
checks=$((checks + 1))
"$cli" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 100 --sample 1 --samples-out "$tmp/closed.tsv" >&- 2>"$tmp/err"
rc=$?
if [[ $rc -ne 1 || -e "$tmp/closed.tsv" ]]; then echo "FAIL: simulate with stdout closed: rc=$rc, samples file $(ls "$tmp"/closed.tsv* 2>&1)"; fails=$((fails + 1)); fi
# A reader that stops early (SIGPIPE) leaves no temporary of the samples file.
checks=$((checks + 1))
mkdir -p "$tmp/pipe"
"$cli" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 1e5 --sample 1 --samples-out "$tmp/pipe/s.tsv" 2>/dev/null | head -n 2 > /dev/null
if [[ -n $(ls -A "$tmp/pipe") ]]; then echo "FAIL: SIGPIPE left $(ls -A "$tmp/pipe")"; fails=$((fails + 1)); fi
expect_error "samples-out:" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 100 --samples-out "$tmp/smp2.tsv"
expect_error "samples-out" simulate "${P[@]}" --x0 0 --y0 0 --v0 0 --t0 4 --t-end 100 --sample 1 --samples-out "$tmp"
checks=$((checks + 1))
[[ -e "$tmp/smp2.tsv" ]] && { echo "FAIL: a refused simulate left a samples file"; fails=$((fails + 1)); }
expect_ok "^quantity	value" info "${P[@]}"
# The short forms -a -b -q are the same options as --a --b --q.
checks=$((checks + 1))
if ! cmp -s <("$cli" map -a 1 -b 0.01 -q 0.85 --theta 4) <("$cli" map --a 1 --b 0.01 --q 0.85 --theta 4); then
  echo "FAIL: map -a -b -q differs from --a --b --q"; fails=$((fails + 1))
fi
expect_ok "^index	q_over_a" sweep -a 2 --q-range 0.85 --b-range 0.01 --observables covering
expect_ok "^theta	T1	T" map --a 1 --b 1e-12 --q 0.85 --theta 3.5 4 5
# The double just below t3 is not a fixed point (the t3 edge): scenario C, T = t2.
checks=$((checks + 1))
row=$("$cli" map "${P[@]}" --theta 6.2631839736061945 | tail -n 1)
if [[ $(cut -f3,4 <<<"$row") != $'3.1615939871631835\tC' ]]; then
  echo "FAIL: map just below t3 should give T = t2, scenario C: $row"; fails=$((fails + 1))
else
  echo "ok:   dfchaos map ${P[*]} --theta 6.2631839736061945 -> T = t2, C"
fi

expect_ok "^n	theta" orbit "${P[@]}" --theta0 3.5 --steps 1e1
checks=$((checks + 1))
[[ $(grep -vc '^#' < <("$cli" map "${P[@]}" --arc 5)) -eq 6 ]] || { echo "FAIL: --arc N gives N rows"; fails=$((fails + 1)); }
checks=$((checks + 1))
[[ $(grep -vc '^#' < <("$cli" map "${P[@]}" --grid 3.5:4.5:7)) -eq 8 ]] || { echo "FAIL: --grid N gives N rows"; fails=$((fails + 1)); }
checks=$((checks + 1))
[[ $("$cli" map "${P[@]}" --grid 3.5:4.5:7 | tail -n 1 | cut -f 1) == 4.5 ]] || { echo "FAIL: --grid includes HI, as sweep's axes"; fails=$((fails + 1)); }
checks=$((checks + 1))
[[ $("$cli" map "${P[@]}" --grid 3.5:4.5:2:mid | tail -n 1 | cut -f 1) == 4.25 ]] || { echo "FAIL: --grid LO:HI:N:mid gives the cell centres"; fails=$((fails + 1)); }
# orbit streams its rows (memory flat in the step count): --steps 1e8 under a 300 MB
# address-space limit delivers its first rows at once (the reader closes the pipe after 3 lines).
checks=$((checks + 1))
# (Under AddressSanitizer, which reserves terabytes of address space, only the streaming is checked.)
limit=300000; [[ -n "${ASAN_OPTIONS:-}" ]] && limit=unlimited
first=$( (ulimit -v $limit; timeout 30 "$cli" orbit "${P[@]}" --theta0 3.5 --steps 1e8 2>/dev/null) | head -n 3 | wc -l)
if [[ $first -ne 3 ]]; then
  echo "FAIL: orbit --steps 1e8 under ulimit -v 300000 should stream its first rows (got $first lines)"; fails=$((fails + 1))
else
  echo "ok:   dfchaos orbit --steps 1e8 streams (3 lines read under a 300 MB limit)"
fi
echo "$((checks - fails)) passed, $fails failed"
exit $((fails > 0))
