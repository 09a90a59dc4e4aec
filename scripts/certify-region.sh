#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `make certify-region`: Theorem 1 (Lemma 4's covering) proved over area across the plane, through
# the sweep engine, into BUILD/region/region.tsv, then its summary (scripts/region_summary.py):
# BUILD/region/certify-region.tex (the report's macros) and certify-region-columns.tsv.
#
#   scripts/certify-region.sh BUILD [RANKS]      (default RANKS = 2)
#
# The sweep: `--observables covering,region` over q/a the 23 columns of [0.76, 0.99] (mid) and b/a
# 173 log-spaced points from 1e-6 to 0.02 (each cell's rectangle reaches the next point: 40 cells a
# decade); REGION_Q and REGION_B override the axes (lo:hi:n:mid and lo:hi:n:log). Every cell is
# proved for every parameter of its rectangle below the uniform bound of its column (Lemma 4 for
# every small b/a) and by parameter boxes above it (docs/cluster.md has the measured time). Runs
# dfchaos-sweep-mpi on RANKS ranks (one thread each) when it was built, else dfchaos sweep on all
# OpenMP threads. Resumable: interrupted, the same command continues from the chunks done.
set -euo pipefail
build=${1:?usage: certify-region.sh BUILD [RANKS]}
ranks=${2:-2}
[[ "$ranks" =~ ^[0-9]+$ && "$ranks" -ge 1 && "$ranks" -le 1024 ]] || { echo "certify-region: RANKS must be an integer in [1, 1024] (got '$ranks')" >&2; exit 2; }
qaxis=${REGION_Q:-0.76:0.99:23:mid}
baxis=${REGION_B:-1e-6:0.02:173:log}
cli=$build/bin/dfchaos
mpi=$build/bin/dfchaos-sweep-mpi
out=$build/region/region.tsv
mkdir -p "$build/region"
spec=(--q-range "$qaxis" --b-range "$baxis" --observables covering,region --resume "$out" --progress)
# The wall time of every invocation is added up in $out.seconds (a resumed run counts all of its parts);
# a fresh run (no output, no chunks) starts it again.
[[ -e "$out" || -d "$out.chunks" ]] || rm -f "$out.seconds"
start=$(date +%s)
rc=0
if [[ -x "$mpi" ]] && command -v mpiexec > /dev/null; then
  workers="$ranks MPI ranks"
  echo "certify-region: q/a $qaxis x b/a $baxis on $workers -> $out"
  OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    mpiexec --oversubscribe --bind-to none -np "$ranks" "$mpi" "${spec[@]}" || rc=$?
else
  workers="$(nproc) OpenMP threads"
  echo "certify-region: q/a $qaxis x b/a $baxis on $workers (no MPI driver built) -> $out"
  "$cli" sweep "${spec[@]}" || rc=$?
fi
echo $(( $(date +%s) - start )) >> "$out.seconds"
if [[ $rc -eq 2 ]]; then
  echo "certify-region: the sweep refused its request (above); a file of another build or spec is not resumed: remove $out and $out.chunks" >&2
  exit 2
elif [[ $rc -ne 0 ]]; then
  echo "certify-region: the sweep stopped (exit $rc); rerun to continue" >&2; exit "$rc"
fi
seconds=$(awk '{ s += $1 } END { print s }' "$out.seconds")
echo "certify-region: done in $seconds s (all invocations): $out"
/usr/bin/python3 "$(dirname "$0")/region_summary.py" "$out" "$seconds" "$workers" "$build/region"
