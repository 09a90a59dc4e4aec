#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The version is written once, in CMakeLists.txt's project(VERSION), and everything reads it from
# there: each tool's `--version` prints "VERSION (git hash)", the package's dfchaosConfigVersion.cmake
# sets PACKAGE_VERSION to it, and the Python module's __version__ equals it.
# usage: version.sh VERSION CONFIG_VERSION_FILE PYTHON|- PYTHONPATH|- TOOL...
#   PYTHON is - when the Python module is not built.
set -uo pipefail
if (($# < 5)); then
  echo "usage: version.sh VERSION CONFIG_VERSION_FILE PYTHON|- PYTHONPATH|- TOOL..." >&2
  exit 2
fi
version=$1 config=$2 python=$3 pythonpath=$4
shift 4
fail=0
for tool in "$@"; do
  out=$("$tool" --version 2>&1) || { echo "version: $tool --version failed: $out" >&2; fail=1; continue; }
  if [[ ! "$out" =~ ^$(printf '%s' "$version" | sed 's/\./\\./g')\ \(.+\)$ ]]; then
    echo "version: $(basename "$tool") --version prints '$out', expected '$version (<git hash>)'" >&2
    fail=1
  fi
done
got=$(sed -n 's/^set(PACKAGE_VERSION "\(.*\)")$/\1/p' "$config" 2>/dev/null)
if [[ "$got" != "$version" ]]; then
  echo "version: $config sets PACKAGE_VERSION '$got', expected '$version'" >&2
  fail=1
fi
if [[ "$python" != "-" ]]; then
  got=$(PYTHONPATH=$pythonpath PYTHONDONTWRITEBYTECODE=1 "$python" -c 'import dfchaos; print(dfchaos.__version__)' 2>&1)
  if [[ "$got" != "$version" ]]; then
    echo "version: the Python module's __version__ is '$got', expected '$version'" >&2
    fail=1
  fi
fi
what="$# tool(s) and the package config"
[[ "$python" != "-" ]] && what+=" and the Python module"
((fail == 0)) && echo "version: $what all give $version"
exit $fail
