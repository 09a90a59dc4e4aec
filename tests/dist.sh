#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `make dist` on a temporary clone of SOURCE_DIR's HEAD, with the Makefile and scripts/dist.sh of the
# working tree (so that a change to them is tested before it is committed), into a temporary BUILD:
#   - the archive is BUILD/dist/dfchaos-VERSION.tar.gz (VERSION: CMake's, passed by CTest), every
#     entry under dfchaos-VERSION/, exactly the tracked files (so CMakeLists.txt, LICENSE, CITATION.cff);
#   - without a report, no PDF and a line pointing to make reproduce; a report built from HEAD is
#     copied as dfchaos-VERSION-report.pdf, one built from another tree is not;
#   - a change to a tracked file, staged or not, is refused (non-zero, one line) and writes nothing;
#     an untracked file is not refused and not archived; no temporary file is left in dist/.
# Builds nothing. Skipped (exit 77) when SOURCE_DIR is not a git checkout or git is missing.
# usage: dist.sh SOURCE_DIR VERSION
set -euo pipefail
if (($# != 2)) || [[ ! -d "$1" ]]; then
  echo "usage: dist.sh SOURCE_DIR VERSION (SOURCE_DIR an existing directory)" >&2
  exit 2
fi
src=$1 version=$2
# (The top of a checkout, not a directory inside another one: an archive unpacked in a repository.)
if ! command -v git >/dev/null || ! git -C "$src" rev-parse --verify -q HEAD >/dev/null 2>&1 ||
   [[ "$(cd "$(git -C "$src" rev-parse --show-toplevel)" && pwd -P)" != "$(cd "$src" && pwd -P)" ]]; then
  echo "dist: SKIP: $src is not the top of a git checkout (or git is missing): make dist needs one"
  exit 77
fi
# The make of `make test` (jobserver, -s) is not this test's business.
unset MAKEFLAGS MFLAGS MAKELEVEL
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
bad() { echo "dist: FAIL: $*" >&2; fail=1; }

clone=$work/clone build=$work/build
git clone -q --no-checkout "$src" "$clone"
git -C "$clone" checkout -q --detach "$(git -C "$src" rev-parse HEAD)"
cp "$src/Makefile" "$clone/Makefile"
cp "$src/scripts/dist.sh" "$clone/scripts/dist.sh"
if ! git -C "$clone" diff --quiet; then
  git -C "$clone" -c user.name=dist-test -c user.email=dist-test@localhost -c commit.gpgsign=false commit -q -am "the working tree's make dist"
fi
name=dfchaos-$version
tar=$build/dist/$name.tar.gz pdf=$build/dist/$name-report.pdf

# 1. A clean tree, no report.
echo untracked > "$clone/untracked.txt"
if ! out=$(make -s -C "$clone" dist BUILD="$build" 2>&1); then
  bad "make dist failed on a clean tree: $out"
elif [[ ! -s "$tar" ]]; then
  bad "make dist wrote no $tar: $out"
else
  listed=$(tar -tzf "$tar" | grep -v '/$' | LC_ALL=C sort)
  expected=$(git -C "$clone" ls-files | sed "s|^|$name/|" | LC_ALL=C sort)
  [[ "$listed" == "$expected" ]] || bad "the archive does not hold exactly the tracked files under $name/: $(diff <(echo "$expected") <(echo "$listed") | head -5 | tr '\n' ' ')"
  for f in CMakeLists.txt LICENSE CITATION.cff; do
    grep -qx "$name/$f" <<< "$listed" || bad "the archive has no $name/$f"
  done
  grep -q "untracked.txt" <<< "$listed" && bad "an untracked file went into the archive"
  [[ -e "$pdf" ]] && bad "a report PDF was written though none was built"
  grep -q "make reproduce" <<< "$out" || bad "without a report, make dist did not point to make reproduce: $out"
fi

# 2. A report: copied when built from HEAD, left out when built from another tree.
mkdir -p "$build/paper" "$build/tables"
echo "%PDF-1.5 stand-in" > "$build/paper/report.pdf"
printf '\\dfcbuildrow{dfchaos}{%s}\n\\dfcbuildrow{git}{%s}\n' "$version" "$(git -C "$clone" describe --always --dirty --abbrev=12)" \
  > "$build/tables/build-info.tex"
make -s -C "$clone" dist BUILD="$build" > /dev/null 2>&1 || bad "make dist failed with a report"
cmp -s "$build/paper/report.pdf" "$pdf" || bad "the report built from HEAD was not copied to $pdf"
sed -i 's/^\\dfcbuildrow{git}{.*}$/\\dfcbuildrow{git}{0123456789ab-dirty}/' "$build/tables/build-info.tex"
out=$(make -s -C "$clone" dist BUILD="$build" 2>&1) || bad "make dist failed with a stale report: $out"
[[ -e "$pdf" ]] && bad "a report built from another tree was put in dist/: $out"

# 3. Uncommitted changes to a tracked file, unstaged then staged: refused, nothing written.
rm -rf "$build/dist"
echo "# changed" >> "$clone/README.md"
for how in unstaged staged; do
  [[ "$how" == staged ]] && git -C "$clone" add README.md
  if out=$(make -s -C "$clone" dist BUILD="$build" 2>&1); then
    bad "make dist accepted a tree with $how changes to README.md"
  else
    dist_lines=$(grep -c '^dist:' <<< "$out" || true)
    { [[ "$dist_lines" == 1 ]] && grep -q "uncommitted" <<< "$out"; } ||
      bad "the refusal ($how) is not one line naming the uncommitted changes: $out"
  fi
  [[ -z "$(ls -A "$build/dist" 2>/dev/null)" ]] || bad "a refused make dist ($how) wrote $(ls -A "$build/dist" | tr '\n' ' ')"
done

((fail == 0)) && echo "dist: $name.tar.gz holds the $(git -C "$clone" ls-files | wc -l) tracked files under $name/; the report only from HEAD; a dirty tree refused"
exit $fail
