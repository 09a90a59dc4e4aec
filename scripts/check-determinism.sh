#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Determinism: every experiment must write the same bytes whatever the number of OpenMP threads.
# When the manifest of the last `make reproduce` exists and this machine has at least 2 cores
# (reproduce ran each experiment on all of them, OMP_NUM_THREADS unset), every experiment is run
# once with one thread (one experiment per core at a time) and its SHA-256 manifest of data/ and tables/ compared with that one.
# Otherwise every experiment runs twice, with one thread and with two, and the two are compared.
# Any difference is printed and fails the check.
set -euo pipefail
build=${1:-build}
abs=$(cd "$build" && pwd)
manifest() { (cd "$1" && find data tables $(test -d certificates && echo certificates) -type f ! -name '*.tmp*' ! -name 'build-info.tex' | LC_ALL=C sort | xargs sha256sum); }
rm -rf "$abs/determinism"  # no manifest of an earlier check is compared
threads=(1 2)
if [[ -f "$abs/MANIFEST.sha256" && $(nproc) -ge 2 && -z "${OMP_NUM_THREADS:-}" ]]; then threads=(1); fi
for t in "${threads[@]}"; do
  out="$abs/determinism/threads-$t"
  rm -rf "$out"
  mkdir -p "$out"
  # as many experiments at once as there are cores (each on $t threads; they write distinct files,
  # as under make -j in make reproduce)
  echo "check-determinism: all experiments with OMP_NUM_THREADS=$t, $(nproc) at a time"
  export t out
  if ! printf '%s\0' "$abs"/bin/experiments/* | xargs -0 -n 1 -P "$(nproc)" bash -c \
      'OMP_NUM_THREADS=$t "$0" --out "$out" 2> "$out/$(basename "$0").log" || { echo "check-determinism: $0 failed:"; cat "$out/$(basename "$0").log"; exit 1; }' >&2; then
    echo "check-determinism: an experiment failed (above)" >&2
    exit 1
  fi
  manifest "$out" > "$out/MANIFEST.sha256"
done
status=0
if [[ -f "$abs/determinism/threads-2/MANIFEST.sha256" ]] && ! diff "$abs/determinism/threads-1/MANIFEST.sha256" "$abs/determinism/threads-2/MANIFEST.sha256"; then
  echo "check-determinism: outputs differ between 1 and 2 threads" >&2
  status=1
fi
if [[ -f "$abs/MANIFEST.sha256" ]]; then
  # The reproduce manifest also covers what the report step generates from the claims (claims map,
  # verdict tables, appendices): compare the files the experiments write, and all of them.
  if ! diff <(awk 'NR == FNR { mine[$2] = 1; next } ($2 in mine)' "$abs/determinism/threads-1/MANIFEST.sha256" "$abs/MANIFEST.sha256") \
            "$abs/determinism/threads-1/MANIFEST.sha256"; then
    echo "check-determinism: outputs differ from the last make reproduce ($abs/MANIFEST.sha256)" >&2
    status=1
  fi
fi
((status == 0)) && echo "check-determinism: identical manifests ($(wc -l < "$abs/determinism/threads-1/MANIFEST.sha256") files)"
exit $status
