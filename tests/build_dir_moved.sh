#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A build directory configured for another clone: `make configure` says what to do (remove it, or
# choose another BUILD) in one line and exits 2, instead of CMake's CMakeCache error.
# A directory configured for these sources passes the same check in every other make run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd -P)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/moved"
printf 'CMAKE_HOME_DIRECTORY:INTERNAL=/nonexistent/other-clone\n' > "$tmp/moved/CMakeCache.txt"
if make -C "$root" --no-print-directory configure BUILD="$tmp/moved" > "$tmp/out" 2> "$tmp/err"; then
  echo "FAIL: make configure accepted a build directory of other sources" >&2; exit 1
else
  status=$?
fi
# make reports the recipe's failure as its own exit status 2
[[ $status -eq 2 ]] || { echo "FAIL: exit status $status, expected 2" >&2; cat "$tmp/err" >&2; exit 1; }
grep -q "configured for the sources in /nonexistent/other-clone" "$tmp/err" || { echo "FAIL: no clear message:" >&2; cat "$tmp/err" >&2; exit 1; }
grep -q "rm -rf $tmp/moved" "$tmp/err" || { echo "FAIL: the message does not say what to do:" >&2; cat "$tmp/err" >&2; exit 1; }
[[ $(grep -c . "$tmp/err") -le 2 ]] || { echo "FAIL: more than the message:" >&2; cat "$tmp/err" >&2; exit 1; }
echo "build_dir_moved: refused with one line naming the remedy"
