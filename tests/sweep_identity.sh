#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Byte identity of the sweep's outputs (tests/CMakeLists.txt: sweep_identity, sweep_mpi):
#
#   sweep_identity.sh serial DFCHAOS
#       the serial sweep with 1 and 2 threads; the same spec spelt differently; 3 shards merged in
#       any order (stdout and --out); a run stopped by --max-chunks and resumed with another chunk
#       size; a run killed (SIGKILL) while writing chunks and resumed; a finished run resumed again.
#   sweep_identity.sh mpi DFCHAOS DFCHAOS-SWEEP-MPI MPIEXEC [MPIEXEC-FLAGS...]
#       dfchaos-sweep-mpi on 2 ranks (1 thread each): unsharded, a shard, and resumed after a stop.
#
# The grid, 6 x 5 cells with every default observable, holds ok, inadmissible (q/a <= 2 b/a) and error
# cells (eternal stick-slip at b/a = 0.45). A second grid C, 5 x 5 cells with covering and
# certified (a proof in ball arithmetic per cell), holds proved and not-proved cells, and R (region:
# proofs over each cell's rectangle) cells proved whole and in part: their outputs too must not depend
# on threads, shards, resumption or ranks; so must E (entropy: both bounds proved per cell). Each
# check prints ok/FAIL; exit 1 if
# any failed.
set -u
mode=$1
cli=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
checks=0
S=(--q-range 0.6:0.98:6 --b-range 2e-3:0.45:5:log --transient 200 --steps 200)
C=(--q-range 0.7:1.1:5 --b-range 1e-3:0.45:5:log --observables covering,certified)
# R: 2 x 4 cells with region (Lemma 4 over each cell's rectangle): below, across and above the
# uniform bound of each q/a column, 40 boxes a cell at most.
R=(--q-range 0.85:0.87:2:mid --b-range 1e-3:3.2e-3:4:log --observables covering,region --region-max-boxes 40)
# E: 2 x 3 cells with entropy (the laps of T and both bounds proved per cell, each on all its threads).
E=(--q-range 0.85:0.95:2 --b-range 8e-3:2e-2:3:log --observables entropy)

same() {  # same DESCRIPTION FILE-A FILE-B
  checks=$((checks + 1))
  if [[ -s "$2" ]] && cmp -s "$2" "$3"; then
    echo "ok:   $1"
  else
    echo "FAIL: $1 ($2 and $3 differ or are missing)"; cmp "$2" "$3" | head -2
    fails=$((fails + 1))
  fi
}
status() {  # status DESCRIPTION EXPECTED ACTUAL
  checks=$((checks + 1))
  if [[ "$2" == "$3" ]]; then echo "ok:   $1 (exit $3)"; else echo "FAIL: $1: exit $3, expected $2"; fails=$((fails + 1)); fi
}

OMP_NUM_THREADS=1 "$cli" sweep "${S[@]}" > "$tmp/serial.tsv" || { echo "FAIL: the serial sweep"; exit 1; }
checks=$((checks + 1))
for kind in ok inadmissible error; do  # the grid exercises every status
  if ! awk -F'\t' -v k="$kind" '!/^#/ && $4 == k { found = 1 } END { exit !found }' "$tmp/serial.tsv"; then
    echo "FAIL: no '$kind' cell in the test grid"; fails=$((fails + 1))
  fi
done
[[ $(grep -vc '^#' "$tmp/serial.tsv") -eq 31 ]] || { echo "FAIL: 30 rows and a column line expected"; fails=$((fails + 1)); }
OMP_NUM_THREADS=1 "$cli" sweep "${C[@]}" > "$tmp/cserial.tsv" || { echo "FAIL: the serial sweep of C"; exit 1; }
checks=$((checks + 1))
# certified is column 6, certified_step 7: C holds proved cells, not-proved ones (two steps at least)
# and inadmissible ones.
if awk -F'\t' '!/^#/ && $4 == "ok" && $6 == 1 && $7 == 0 { p = 1 } !/^#/ && $4 == "ok" && $6 == 0 { n[$7] = 1 }
                !/^#/ && $4 == "inadmissible" { i = 1 } END { k = 0; for (s in n) k++; exit !(p && k >= 2 && i) }' "$tmp/cserial.tsv"; then
  echo "ok:   the certified grid holds proved, not-proved (2 steps or more) and inadmissible cells"
else
  echo "FAIL: the certified grid lacks proved, not-proved or inadmissible cells"; fails=$((fails + 1))
fi

OMP_NUM_THREADS=1 "$cli" sweep "${R[@]}" > "$tmp/rserial.tsv" || { echo "FAIL: the serial sweep of R"; exit 1; }
checks=$((checks + 1))
# region is column 6: R holds cells proved whole and cells proved in part.
if awk -F'\t' '!/^#/ && NR > 1 && $6 == 1 { w = 1 } !/^#/ && NR > 1 && $6 > 0 && $6 < 1 { p = 1 } END { exit !(w && p) }' "$tmp/rserial.tsv"; then
  echo "ok:   the region grid holds cells proved whole and in part"
else
  echo "FAIL: the region grid lacks cells proved whole or in part"; fails=$((fails + 1))
fi

OMP_NUM_THREADS=1 "$cli" sweep "${E[@]}" > "$tmp/eserial.tsv" || { echo "FAIL: the serial sweep of E"; exit 1; }
checks=$((checks + 1))
# entropy_lower is column 5, entropy_upper 6, entropy_laps 7: every cell proved, ln 2 < lower <= upper.
if awk -F'\t' '!/^#/ && NR > 1 { n++; if ($4 == "ok" && $7 > 0 && $5 > 0.6931 && $5 <= $6) p++ } END { exit !(n == 6 && p == 6) }' "$tmp/eserial.tsv"; then
  echo "ok:   the entropy grid: 6 cells, each with ln 2 < entropy_lower <= entropy_upper"
else
  echo "FAIL: the entropy grid: a cell not proved or bounds out of order"; fails=$((fails + 1))
fi

# grid_identity LABEL SERIAL-FILE PREFIX SWEEP-ARGS...: the grid's rows on 2 threads, in 3 shards
# merged, and stopped by --max-chunks then resumed with another chunk size, against its serial run.
grid_identity() {
  local label=$1 serial=$2 p=$3
  shift 3
  OMP_NUM_THREADS=2 "$cli" sweep "$@" --chunk 3 > "$tmp/$p-threads.tsv"
  same "$label: 2 threads, chunks of 3 = 1 thread" "$serial" "$tmp/$p-threads.tsv"
  for i in 0 1 2; do "$cli" sweep "$@" --shard "$i/3" --out "$tmp/$p-shard$i.tsv"; done
  "$cli" sweep-merge "$tmp/$p-shard1.tsv" "$tmp/$p-shard0.tsv" "$tmp/$p-shard2.tsv" > "$tmp/$p-merged.tsv"
  same "$label: 3 shards merged" "$serial" "$tmp/$p-merged.tsv"
  "$cli" sweep "$@" --resume "$tmp/$p-resumed.tsv" --chunk 2 --max-chunks 2 2> /dev/null
  status "$label: stopped by --max-chunks 2" 3 $?
  OMP_NUM_THREADS=2 "$cli" sweep "$@" --resume "$tmp/$p-resumed.tsv" --chunk 3 2> /dev/null
  same "$label: stopped and resumed = one run" "$serial" "$tmp/$p-resumed.tsv"
}

case "$mode" in
serial)
  OMP_NUM_THREADS=2 "$cli" sweep "${S[@]}" --chunk 7 > "$tmp/threads.tsv"
  same "2 threads, chunks of 7 = 1 thread" "$tmp/serial.tsv" "$tmp/threads.tsv"
  "$cli" sweep --q-range 0.60:0.980:6:lin --b-range 0.002:0.45:5:log --transient 2e2 --steps 200 \
    --observables period,rate,lyapunov,superstable,covering --a 1.0 > "$tmp/spelt.tsv"
  same "another spelling of the same spec" "$tmp/serial.tsv" "$tmp/spelt.tsv"
  for i in 0 1 2; do "$cli" sweep "${S[@]}" --shard "$i/3" --out "$tmp/shard$i.tsv"; done
  "$cli" sweep-merge "$tmp/shard2.tsv" "$tmp/shard0.tsv" "$tmp/shard1.tsv" > "$tmp/merged.tsv"
  same "3 shards merged (given as 2, 0, 1)" "$tmp/serial.tsv" "$tmp/merged.tsv"
  "$cli" sweep-merge "$tmp/shard1.tsv" "$tmp/shard2.tsv" "$tmp/shard0.tsv" --out "$tmp/merged-out.tsv"
  same "3 shards merged with --out" "$tmp/serial.tsv" "$tmp/merged-out.tsv"
  "$cli" sweep "${S[@]}" --shard 0/1 > "$tmp/one.tsv"
  "$cli" sweep-merge "$tmp/one.tsv" > "$tmp/merged-one.tsv"
  same "a single shard 0/1 merged" "$tmp/serial.tsv" "$tmp/merged-one.tsv"
  for i in 0 1 2; do OMP_NUM_THREADS=2 "$cli" sweep "${S[@]}" --shard "$i/3" --resume "$tmp/rshard$i.tsv" --chunk 2 2> /dev/null; done
  "$cli" sweep-merge "$tmp/rshard0.tsv" "$tmp/rshard1.tsv" "$tmp/rshard2.tsv" > "$tmp/merged-resumable.tsv"
  same "3 resumable shards merged" "$tmp/serial.tsv" "$tmp/merged-resumable.tsv"

  grid_identity certified "$tmp/cserial.tsv" c "${C[@]}"
  grid_identity region "$tmp/rserial.tsv" r "${R[@]}"
  grid_identity entropy "$tmp/eserial.tsv" e "${E[@]}"

  "$cli" sweep "${S[@]}" --resume "$tmp/resumed.tsv" --chunk 4 --max-chunks 3 2> /dev/null
  status "stopped by --max-chunks 3" 3 $?
  checks=$((checks + 1))
  if [[ ! -e "$tmp/resumed.tsv" && $(ls "$tmp/resumed.tsv.chunks" | grep -c '^chunk-') -eq 3 ]]; then
    echo "ok:   3 chunks kept, no output file yet"
  else
    echo "FAIL: after --max-chunks 3: $(ls "$tmp"/resumed.tsv* 2>&1 | tr '\n' ' ')"; fails=$((fails + 1))
  fi
  "$cli" sweep "${S[@]}" --steps 201 --resume "$tmp/resumed.tsv" 2> /dev/null
  status "resume with another spec refused" 2 $?
  "$cli" sweep "${S[@]}" --resume "$tmp/resumed.tsv" --chunk 5 2> /dev/null
  status "resumed (chunks of 5 after chunks of 4)" 0 $?
  same "stopped and resumed = one run" "$tmp/serial.tsv" "$tmp/resumed.tsv"
  checks=$((checks + 1))
  if [[ -e "$tmp/resumed.tsv.chunks" ]]; then echo "FAIL: the chunk directory is left behind"; fails=$((fails + 1)); else echo "ok:   the chunk directory removed"; fi
  "$cli" sweep "${S[@]}" --resume "$tmp/resumed.tsv" 2> /dev/null
  status "a finished run resumed again" 0 $?
  same "a finished run resumed again is unchanged" "$tmp/serial.tsv" "$tmp/resumed.tsv"

  # Killed without warning while it writes chunks of one cell (SIGKILL after 0.1 to 0.5 s, again
  # and again until a run finishes by itself), resumed each time: the final file is the same.
  # A larger sweep than S, with longer orbits, so that a run lasts well over 0.5 s (the covering
  # search alone is now too fast for S to be interrupted).
  K=(--q-range 0.6:0.98:12 --b-range 2e-3:0.45:10:log --transient 2000 --steps 2000)
  "$cli" sweep "${K[@]}" > "$tmp/kserial.tsv" 2> /dev/null
  status "the larger sweep, serial" 0 $?
  killed=0
  for attempt in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
    ( timeout -s KILL "0.$((1 + attempt % 5))" "$cli" sweep "${K[@]}" --resume "$tmp/killed.tsv" --chunk 1 ) 2> /dev/null
    rc=$?
    [[ $rc -eq 137 ]] && killed=$((killed + 1))
    [[ $rc -eq 0 ]] && break
  done
  "$cli" sweep "${K[@]}" --resume "$tmp/killed.tsv" 2> /dev/null
  status "resumed after $killed SIGKILL(s)" 0 $?
  checks=$((checks + 1))
  if [[ $killed -ge 1 ]]; then echo "ok:   killed at least once"; else echo "FAIL: never killed (the run is faster than 0.1 s?)"; fails=$((fails + 1)); fi
  same "killed $killed time(s) and resumed = one run" "$tmp/kserial.tsv" "$tmp/killed.tsv"
  ;;
mpi)
  mpi=$3
  shift 3
  launch=("$@")
  export OMP_NUM_THREADS=1
  "${launch[@]}" "$mpi" "${S[@]}" > "$tmp/mpi.tsv"
  status "dfchaos-sweep-mpi on 2 ranks" 0 $?
  same "2 MPI ranks = serial" "$tmp/serial.tsv" "$tmp/mpi.tsv"
  "${launch[@]}" "$mpi" "${R[@]}" --chunk 1 > "$tmp/mpi-region.tsv"
  same "region: 2 MPI ranks, chunks of 1 = serial" "$tmp/rserial.tsv" "$tmp/mpi-region.tsv"
  "${launch[@]}" "$mpi" "${E[@]}" --chunk 1 > "$tmp/mpi-entropy.tsv"
  same "entropy: 2 MPI ranks, chunks of 1 = serial" "$tmp/eserial.tsv" "$tmp/mpi-entropy.tsv"
  "${launch[@]}" "$mpi" "${S[@]}" --chunk 3 --out "$tmp/mpi-out.tsv"
  same "2 MPI ranks, chunks of 3, --out = serial" "$tmp/serial.tsv" "$tmp/mpi-out.tsv"
  "$cli" sweep "${S[@]}" --shard 1/4 > "$tmp/shard.tsv"
  "${launch[@]}" "$mpi" "${S[@]}" --shard 1/4 > "$tmp/mpi-shard.tsv"
  same "shard 1/4 on 2 MPI ranks = serial shard 1/4" "$tmp/shard.tsv" "$tmp/mpi-shard.tsv"
  "${launch[@]}" "$mpi" "${S[@]}" --resume "$tmp/mpi-resumed.tsv" --chunk 4 --max-chunks 2 > /dev/null 2>&1
  status "MPI run stopped by --max-chunks" 3 $?
  "${launch[@]}" "$mpi" "${S[@]}" --resume "$tmp/mpi-resumed.tsv" --chunk 3 > /dev/null 2>&1
  same "MPI run stopped and resumed = serial" "$tmp/serial.tsv" "$tmp/mpi-resumed.tsv"
  "${launch[@]}" "$mpi" "${C[@]}" > "$tmp/cmpi.tsv"
  same "certified: 2 MPI ranks = serial" "$tmp/cserial.tsv" "$tmp/cmpi.tsv"
  "$cli" sweep "${C[@]}" --shard 2/3 > "$tmp/cshard.tsv"
  "${launch[@]}" "$mpi" "${C[@]}" --shard 2/3 --chunk 2 > "$tmp/cmpi-shard.tsv"
  same "certified: shard 2/3 on 2 MPI ranks, chunks of 2 = serial shard 2/3" "$tmp/cshard.tsv" "$tmp/cmpi-shard.tsv"
  "$mpi" --q-range 1:0:3 --b-range 0.1:0.2:2 > "$tmp/bad.out" 2> "$tmp/bad.err"
  rc=$?
  checks=$((checks + 1))
  if [[ $rc -eq 2 && ! -s "$tmp/bad.out" && $(wc -l < "$tmp/bad.err") -eq 1 ]] && grep -q "q-range" "$tmp/bad.err"; then
    echo "ok:   bad input to dfchaos-sweep-mpi: $(cat "$tmp/bad.err")"
  else
    echo "FAIL: bad input to dfchaos-sweep-mpi: exit $rc, $(head -c 300 "$tmp/bad.err")"; fails=$((fails + 1))
  fi
  ;;
*) echo "usage: sweep_identity.sh serial|mpi ..." >&2; exit 2 ;;
esac
echo "$((checks - fails)) passed, $fails failed"
exit $((fails > 0))
