#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `make dist`: what an archive (Zenodo, a journal's supplement) takes for a version of dfchaos:
#   BUILD/dist/dfchaos-<version>.tar.gz          git archive of HEAD, every path under dfchaos-<version>/
#   BUILD/dist/dfchaos-<version>-report.pdf      BUILD/paper/report.pdf, only if it was built from HEAD
# <version> is read from CMakeLists.txt's project(dfchaos VERSION ...), the one place it is written.
# The archive is of the last commit, so a tree with uncommitted changes to tracked files is refused
# (exit 2): the archive would not be the tree the user sees. The report is not rebuilt here (make
# reproduce takes long); a missing or stale one is left out, with one line saying so. Each output is
# written under a temporary name and renamed, so an interrupted run leaves no partial file.
# usage: dist.sh [BUILD]   (run from the top of the checkout, as the Makefile does)
set -euo pipefail
build=${1:-build}
if ! top=$(git rev-parse --show-toplevel 2>/dev/null) || [[ "$(cd "$top" && pwd -P)" != "$(pwd -P)" ]]; then
  echo "dist: $(pwd) is not the top of a git checkout: git archive needs one (an unpacked archive cannot make another)" >&2
  exit 2
fi
version=$(sed -n 's/^project(dfchaos VERSION \([0-9][0-9.]*\).*/\1/p' CMakeLists.txt)
if [[ -z "$version" ]]; then
  echo "dist: CMakeLists.txt has no line 'project(dfchaos VERSION X.Y.Z ...' to read the version from" >&2
  exit 1
fi
git update-index -q --refresh || true
if ! git diff-index --quiet HEAD --; then
  echo "dist: refused: tracked files have uncommitted changes (git status); the archive is of HEAD, commit or stash them first" >&2
  exit 2
fi

name=dfchaos-$version
out=$build/dist
mkdir -p "$out"
tmp_tar="" tmp_pdf=""
trap 'rm -f "$tmp_tar" "$tmp_pdf"' EXIT
tmp_tar=$(mktemp "$out/.$name.tar.gz.XXXXXX")
git archive --format=tar.gz --prefix="$name/" -o "$tmp_tar" HEAD
chmod 0644 "$tmp_tar"
mv -f "$tmp_tar" "$out/$name.tar.gz"
commit=$(git rev-parse --short=12 HEAD)
echo "dist: $out/$name.tar.gz ($(git ls-files | wc -l) files of commit $commit)"
if ! git describe --exact-match --tags HEAD >/dev/null 2>&1; then
  echo "dist: note: HEAD is not tagged (tag it v$version when this is the release)"
fi

# The report, only when its title page names this very tree: build-info.tex (written with it by
# `dfchaos provenance`) holds the `git describe --always --dirty --abbrev=12` of the build.
pdf=$build/paper/report.pdf
info=$build/tables/build-info.tex
here=$(git describe --always --dirty --abbrev=12)
built=$(sed -n 's/^\\dfcbuildrow{git}{\(.*\)}$/\1/p' "$info" 2>/dev/null || true)
if [[ ! -s "$pdf" ]]; then
  rm -f "$out/$name-report.pdf"
  echo "dist: no report in $pdf, none in dist/: run make reproduce first to include it"
elif [[ "$built" != "$here" ]]; then
  rm -f "$out/$name-report.pdf"
  echo "dist: $pdf was built from ${built:-an unknown tree}, not from $here: left out; run make reproduce first to include it"
else
  tmp_pdf=$(mktemp "$out/.$name-report.pdf.XXXXXX")
  cp "$pdf" "$tmp_pdf"
  chmod 0644 "$tmp_pdf"
  mv -f "$tmp_pdf" "$out/$name-report.pdf"
  echo "dist: $out/$name-report.pdf (the report of $here)"
fi
