#!/usr/bin/env bash
# Compare T between two builds of the library, judged against the 40-digit reference.
#
#   scripts/compare-builds.sh [--time] BASE [NEW]
#
# BASE and NEW are git revisions; NEW defaults to the working tree (uncommitted changes
# included). Each is built (the library target only, RelWithDebInfo, in
# build/compare/<name>/), the driver scripts/compare/t_table.cpp is linked against it, and the
# two tables of T (36 324 phases: 12 values of b/a from 0.3 to 1e-12, three q/a) are compared
# by scripts/compare/judge.py: per b/a, how many values changed, by how many ulp, and which
# build is closer to tests/precision_reference.py where they differ. For any change to the
# root search or the return map that is not bit-identical (docs/performance.md).
# With --time, also the time of one evaluation of T in each build at the b/a of `make bench`: the
# two drivers run alternately 3 times (`t_table --time`, itself the fastest of 5 rounds), the
# fastest kept; on an otherwise idle machine.
# Takes ~3 min per build on 2 cores, and seconds to judge a few thousand changed phases.
set -euo pipefail
usage="usage: compare-builds.sh [--time] BASE [NEW]   (git revisions; NEW defaults to the working tree)"
timing=0
if [[ "${1:-}" == "--time" ]]; then timing=1; shift; fi
[[ $# -ge 1 && $# -le 2 ]] || { echo "$usage" >&2; exit 2; }
root=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
base=$1
new=${2:-}
work=$root/build/compare
mkdir -p "$work"

# build NAME REV: the library of revision REV (or of the working tree when REV is empty) and the
# table of T from it, into $work/NAME/.
build() {
  local name=$1 rev=$2 src
  if [[ -n "$rev" ]]; then
    git -C "$root" rev-parse --verify --quiet "$rev^{commit}" > /dev/null \
      || { echo "compare-builds: $name revision '$rev' is not a commit" >&2; exit 2; }
    src=$work/$name/src
    rm -rf "$src" && mkdir -p "$src"
    git -C "$root" archive "$rev" | tar -x -C "$src"
  else
    src=$root
  fi
  local bld=$work/$name/build
  mkdir -p "$work/$name"
  # (The default options, which every revision configures with; only the library is built. A
  # cache left by an earlier run is dropped, its objects kept.)
  rm -f "$bld/CMakeCache.txt"
  cmake -S "$src" -B "$bld" -DCMAKE_BUILD_TYPE=RelWithDebInfo > "$work/$name/configure.log" 2>&1 \
    || { cat "$work/$name/configure.log"; exit 1; }
  cmake --build "$bld" -j "$(nproc)" --target dfchaos > "$work/$name/build.log" 2>&1 || { tail -30 "$work/$name/build.log"; exit 1; }
  local lib
  lib=$(find "$bld" -name libdfchaos.a | head -1)
  g++ -std=c++20 -O2 -I"$src/src" -I"$bld/src" "$root/scripts/compare/t_table.cpp" "$lib" -lgsl -lgslcblas -o "$work/$name/t_table"
  "$work/$name/t_table" > "$work/$name/T.txt"
  echo "compare-builds: $name (${rev:-working tree}): $(wc -l < "$work/$name/T.txt") phases -> $work/$name/T.txt" >&2
}

build base "$base"
build new "$new"
/usr/bin/python3 "$root/scripts/compare/judge.py" "$work/base/T.txt" "$work/new/T.txt"
if [[ $timing == 1 ]]; then
  for i in 1 2 3; do
    "$work/base/t_table" --time > "$work/base/time.$i"
    "$work/new/t_table" --time > "$work/new/time.$i"
  done
  echo
  echo -e "b/a\tbase [us]\tnew [us]\tnew/base"
  fastest() { cat "$work/$1"/time.[123] | awk -v b="$2" '$1 == b && (m == "" || $2 < m) { m = $2 } END { print m }'; }
  for ba in $(cut -d' ' -f1 "$work/base/time.1"); do
    tb=$(fastest base "$ba") tn=$(fastest new "$ba")
    awk -v ba="$ba" -v tb="$tb" -v tn="$tn" 'BEGIN { printf "%s\t%.3f\t%.3f\t%.3f\n", ba, tb, tn, tn / tb }'
  done
fi
