#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `pip install .` works offline from the clone (docs/python-install.md): a venv of
# Debian's interpreter gets the module from the build directory BUILD (no download, --no-index), it
# imports from outside the clone, its T equals the build tree's to the last bit, and it uninstalls.
#   tests/pip_install.sh SOURCE BUILD PYTHON
set -euo pipefail
src=$1 build=$2 python=$3
# the preload of a sanitizer build is for the import only; pip and cmake run without it
preload=${LD_PRELOAD:-}
unset LD_PRELOAD PIP_FIND_LINKS PIP_INDEX_URL PIP_EXTRA_INDEX_URL
venv="$build/test-pip/venv"
rm -rf "$build/test-pip"
mkdir -p "$build/test-pip"
"$python" -m venv --system-site-packages "$venv"
DFCHAOS_BUILD_DIR="$build" PIP_CONFIG_FILE=/dev/null \
  "$venv/bin/pip" install --no-build-isolation --no-index --disable-pip-version-check "$src" > "$build/test-pip/pip.log" 2>&1 \
  || { echo "FAIL: pip install failed:" >&2; tail -20 "$build/test-pip/pip.log" >&2; exit 1; }
probe='import sys, dfchaos; p = dfchaos.Parameters(1, 0.01, 0.85); print(dfchaos.__file__); print(repr(dfchaos.T(p, 4.0)), repr(dfchaos.T1(p, 3.3)), dfchaos.__version__)'
cd "$build/test-pip"   # outside the clone: nothing on the path but the venv
installed=$(LD_PRELOAD="$preload" PYTHONDONTWRITEBYTECODE=1 "$venv/bin/python" -c "$probe")
tree=$(LD_PRELOAD="$preload" PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$build/python" "$python" -c "$probe")
file=$(head -1 <<< "$installed")
[[ $file == "$venv/"* ]] || { echo "FAIL: imported $file, not the venv's module" >&2; exit 1; }
[[ $(tail -n +2 <<< "$installed") == $(tail -n +2 <<< "$tree") ]] \
  || { echo "FAIL: the installed module differs from the build tree's:" >&2; echo "$installed" >&2; echo "$tree" >&2; exit 1; }
"$venv/bin/pip" uninstall -y dfchaos > /dev/null
if LD_PRELOAD="$preload" "$venv/bin/python" -c "import dfchaos" 2> /dev/null; then
  echo "FAIL: dfchaos still imports after pip uninstall" >&2; exit 1
fi
# the clone stays clean: setuptools' scratch files went to the build directory
if git -C "$src" rev-parse --git-dir > /dev/null 2>&1; then
  dirty=$(git -C "$src" status --porcelain --ignored=no -- '*.egg-info' 'build/lib*' 'build/bdist*' || true)
  [[ -z $dirty ]] || { echo "FAIL: pip left files in the clone: $dirty" >&2; exit 1; }
fi
echo "pip_install: installed into a venv offline, imported as $file, equal to the build tree, uninstalled"
