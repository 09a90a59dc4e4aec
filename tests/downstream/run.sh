#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# package_downstream: build tests/downstream against the dfchaos installed under PREFIX, with the
# worked example of docs/adding-an-experiment.md copied under a new name as its only experiment;
# run both. Usage: run.sh PREFIX EXAMPLE.cpp WORKDIR CXX [FLAGS]
# FLAGS: compile and link flags the installed library needs (the sanitizers of make test-sanitize).
set -euo pipefail
prefix=$1 example=$2 work=$3 cxx=$4 flags=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work/experiments"
cp "$example" "$work/experiments/my_copied_experiment.cpp"
cmake -S "$here" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
      -DEXPERIMENTS_DIR="$work/experiments" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" > "$work/configure.log"
cmake --build "$work/build" -j 2 > "$work/build.log"
# The library call gives the same T as the dfchaos tool installed with it.
lib=$("$work/build/downstream")
cli=$("$prefix/bin/dfchaos" map --a 1 --b 0.01 --q 0.85 --theta 4 | awk '!/^#/ && ++n == 2 {print $3}')
[[ "$lib" == "$cli" ]] || { echo "downstream T = $lib, dfchaos map T = $cli" >&2; exit 1; }
# The copied experiment runs under its new name and writes its claims.
"$work/build/experiments/my_copied_experiment" --fast --out "$work/out" 2> "$work/run.log"
test -s "$work/out/claims/my_copied_experiment.json"
grep -q '"experiment": "my_copied_experiment"' "$work/out/claims/my_copied_experiment.json"
"$work/build/experiments/my_copied_experiment" --describe | grep -q '"name": "my_copied_experiment"'
echo "package_downstream: T = $lib from the installed library; the copied experiment ran as my_copied_experiment"
