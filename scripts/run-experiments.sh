#!/usr/bin/env bash
# Runs every experiment executable in BUILD/bin/experiments (one per paper result), in name order.
# Each writes its own data, tables and claims under BUILD/; a failing experiment stops the run.
set -euo pipefail
build=${1:-build}
dir="$build/bin/experiments"
shopt -s nullglob
exes=("$dir"/*)
if ((${#exes[@]} == 0)); then
  echo "run-experiments: no experiments built yet in $dir"
  exit 0
fi
i=0
for exe in "${exes[@]}"; do
  i=$((i + 1))
  echo "-- [$i/${#exes[@]}] $(basename "$exe")"
  "$exe" --out "$build"
done
