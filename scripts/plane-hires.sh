#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `make plane-hires`: the (q/a, b/a) plane of thm1_parameter_plane at high resolution, every
# observable, into BUILD/plane/plane-NxN.tsv.
#
#   scripts/plane-hires.sh BUILD [N [RANKS]]      (defaults: N = 2000, RANKS = 2)
#
# Axes as the experiment's: q/a the N cell centres of (sin vartheta0, 1), b/a N points log-spaced in
# [1e-4, 0.1]. Runs dfchaos-sweep-mpi on RANKS ranks (one OpenMP thread each) when it was built,
# else dfchaos sweep on all OpenMP threads. The run is resumable: interrupted (Ctrl-C, a reboot),
# the same command continues from the chunks done (BUILD/plane/plane-NxN.tsv.chunks/).
# docs/cluster.md gives the measured time and the Slurm equivalents.
set -euo pipefail
build=${1:?usage: plane-hires.sh BUILD [N [RANKS]]}
n=${2:-2000}
ranks=${3:-2}
[[ "$n" =~ ^[0-9]+$ && "$n" -ge 1 && "$n" -le 10000 ]] || { echo "plane-hires: N must be an integer in [1, 10000] (got '$n')" >&2; exit 2; }
[[ "$ranks" =~ ^[0-9]+$ && "$ranks" -ge 1 && "$ranks" -le 1024 ]] || { echo "plane-hires: RANKS must be an integer in [1, 1024] (got '$ranks')" >&2; exit 2; }
cli=$build/bin/dfchaos
mpi=$build/bin/dfchaos-sweep-mpi
s0=$("$cli" info --a 1 --b 0.01 --q 0.85 | awk -F'\t' '$1 == "a*sin(vartheta0)" { print $2 }')
out=$build/plane/plane-${n}x${n}.tsv
mkdir -p "$build/plane"
spec=(--q-range "$s0:1:$n:mid" --b-range "1e-4:0.1:$n:log" --observables covering,superstable,lyapunov,rate,period
      --resume "$out" --progress)
start=$(date +%s)
if [[ -x "$mpi" ]] && command -v mpiexec > /dev/null; then
  echo "plane-hires: ${n} x ${n} cells on $ranks MPI ranks -> $out"
  # --oversubscribe: run RANKS ranks even where fewer slots are declared; --bind-to none: let the
  # ranks move to whichever core is idle (a shared machine); the two OMPI variables let
  # OpenMPI run as root (a container); harmless otherwise.
  OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    mpiexec --oversubscribe --bind-to none -np "$ranks" "$mpi" "${spec[@]}"
else
  echo "plane-hires: ${n} x ${n} cells on $(nproc) OpenMP threads (no MPI driver built) -> $out"
  "$cli" sweep "${spec[@]}"
fi
echo "plane-hires: done in $(( $(date +%s) - start )) s: $out"
