#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Compare T between two builds of the library, judged against the 40-digit reference.
#
#   scripts/compare-builds.sh [--time] BASE [NEW]
#
# BASE and NEW are git revisions; NEW defaults to the working tree (uncommitted changes
# included). Each is built (the library target only, RelWithDebInfo, default options, in
# build/compare/<base|new>/), the driver scripts/compare/t_table.cpp of the working tree is linked
# against each, and the two tables of T (36 324 phases: 12 values of b/a from 0.3 to 1e-12, three
# q/a; the 1 009 with q = 2b fail in every build) are compared by scripts/compare/judge.py: per
# b/a, how many values changed, by how many ulp, and which build is closer to
# tests/precision_reference.py where they differ. For any change to the root search or the return
# map that is not bit-identical (docs/performance.md). A revision is built from a fresh copy of its
# sources each time, the working tree incrementally; the whole comparison takes ~30 s on 2 cores.
# With --time, also the time of one evaluation of T in each build at the b/a and phases of
# `make bench`: the two drivers run 3 times each, in alternating order (`t_table --time`, itself
# the fastest of 5 rounds), the fastest kept; run it on an otherwise idle machine.
# The phases are computed from each build's own t2 and t3: a change that moves them cannot be
# compared this way (the judge names the first line where the phases differ).
set -euo pipefail
usage="usage: compare-builds.sh [--time] BASE [NEW]   (git revisions; NEW defaults to the working tree)"
timing=0
revs=()
for arg in "$@"; do
  case "$arg" in
    --time) timing=1 ;;
    -h|--help) echo "$usage"; exit 0 ;;
    -*) echo "compare-builds: unknown option '$arg'; $usage" >&2; exit 2 ;;
    *) revs+=("$arg") ;;
  esac
done
[[ ${#revs[@]} -ge 1 && ${#revs[@]} -le 2 ]] || { echo "compare-builds: expected one or two revisions, BASE [NEW]; $usage" >&2; exit 2; }
root=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
base=${revs[0]}
new=${revs[1]:-}
for r in "$base" $new; do
  git -C "$root" rev-parse --verify --quiet "$r^{commit}" > /dev/null \
    || { echo "compare-builds: revision '$r' is not a commit of $root" >&2; exit 2; }
done
work=$root/build/compare

# build NAME REV: the library of revision REV (or of the working tree when REV is empty) and the
# table of T from it, into $work/NAME/.
build() {
  local name=$1 rev=$2 src
  local dir=$work/$name
  mkdir -p "$dir"
  if [[ -n "$rev" ]]; then
    src=$dir/src
    rm -rf "$src" && mkdir -p "$src"
    git -C "$root" archive "$rev" | tar -x -C "$src"
  else
    src=$root
  fi
  local bld=$dir/build
  # (The default options, which every revision configures with; only the library is built. A
  # cache left by an earlier run is dropped, its objects kept.)
  rm -f "$bld/CMakeCache.txt"
  cmake -S "$src" -B "$bld" -DCMAKE_BUILD_TYPE=RelWithDebInfo > "$dir/configure.log" 2>&1 \
    || { echo "compare-builds: configuring $name (${rev:-working tree}) failed; see $dir/configure.log" >&2; exit 1; }
  cmake --build "$bld" -j "$(nproc)" --target dfchaos > "$dir/build.log" 2>&1 \
    || { echo "compare-builds: building $name (${rev:-working tree}) failed; see $dir/build.log" >&2; exit 1; }
  local lib=$bld/src/libdfchaos.a
  [[ -f "$lib" ]] || { echo "compare-builds: $name: no library at $lib" >&2; exit 1; }
  "${CXX:-g++}" -std=c++20 -O2 -I"$src/src" -I"$bld/src" "$root/scripts/compare/t_table.cpp" "$lib" -lgsl -lgslcblas \
    -o "$dir/t_table" > "$dir/driver.log" 2>&1 \
    || { echo "compare-builds: the driver does not build against $name (${rev:-working tree}); see $dir/driver.log" >&2; exit 1; }
  "$dir/t_table" > "$dir/T.txt" || { echo "compare-builds: the driver failed on $name (${rev:-working tree})" >&2; exit 1; }
  echo "compare-builds: $name (${rev:-working tree}): $(wc -l < "$dir/T.txt") phases -> $dir/T.txt" >&2
}

build base "$base"
build new "$new"
/usr/bin/python3 "$root/scripts/compare/judge.py" "$work/base/T.txt" "$work/new/T.txt"
if [[ $timing == 1 ]]; then
  for i in 1 2 3; do
    if (( i % 2 )); then order=(base new); else order=(new base); fi
    for name in "${order[@]}"; do
      "$work/$name/t_table" --time > "$work/$name/time.$i" \
        || { echo "compare-builds: timing $name failed" >&2; exit 1; }
    done
  done
  echo
  echo -e "b/a\tbase [us]\tnew [us]\tnew/base"
  fastest() { cat "$work/$1"/time.[123] | awk -v b="$2" '$1 == b && (m == "" || $2 < m) { m = $2 } END { print m }'; }
  for ba in $(cut -d' ' -f1 "$work/base/time.1"); do
    tb=$(fastest base "$ba") tn=$(fastest new "$ba")
    awk -v ba="$ba" -v tb="$tb" -v tn="$tn" 'BEGIN { printf "%s\t%.3f\t%.3f\t%.3f\n", ba, tb, tn, tn / tb }'
  done
fi
