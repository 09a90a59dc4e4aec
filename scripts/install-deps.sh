#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Install the Debian 12 packages dfchaos needs, and only those that are missing.
#
#   scripts/install-deps.sh build    compiler, CMake, Eigen, GSL, GoogleTest, CLI11, nlohmann-json, OpenSSL, Arb, MPFI, OpenMPI (for `make test`;
#                                    OpenMPI builds dfchaos-sweep-mpi and its test; python3-yaml reads CITATION.cff in the test citation;
#                                    git lists the sources for the tests spdx and dist, and for make dist; python3-pandas
#                                    reads every output in the test python_load_outputs; pip, venv, setuptools and wheel
#                                    install the module offline in the test python_pip_install)
#   scripts/install-deps.sh report   build + gnuplot, LaTeX, Doxygen (for `make reproduce`)
#   scripts/install-deps.sh check    build + clang, its OpenMP runtime and its sanitizer runtime (for `make test-clang`
#                                    and `make test-sanitize SANITIZE_CXX=clang++`), clang-format (for
#                                    `make format-check`) and clang-tidy (for `make test-tidy`)
#
# Idempotent: a second run finds nothing missing and does nothing. Runs apt-get as
# root, or through sudo; where neither is possible it prints the exact command and fails.
set -euo pipefail

profile=${1:-build}
build_pkgs=(g++ cmake make pkg-config git python3 python3-mpmath libeigen3-dev libgsl-dev libgtest-dev libgmock-dev
            libcli11-dev nlohmann-json3-dev libbenchmark-dev libssl-dev libflint-arb-dev libflint-dev libmpfr-dev libgmp-dev libmpfi-dev
            pybind11-dev python3-dev python3-numpy python3-pandas python3-pytest python3-matplotlib python3-yaml python3-pip python3-venv python3-setuptools python3-wheel libopenmpi-dev openmpi-bin)
report_pkgs=(gnuplot-nox latexmk texlive-latex-base texlive-latex-recommended
             texlive-latex-extra texlive-fonts-recommended texlive-pictures doxygen poppler-utils)

check_pkgs=(clang libomp-dev libclang-rt-14-dev clang-format clang-tidy)

case "$profile" in
  build)  wanted=("${build_pkgs[@]}") ;;
  check)  wanted=("${build_pkgs[@]}" "${check_pkgs[@]}") ;;
  report) wanted=("${build_pkgs[@]}" "${report_pkgs[@]}") ;;
  *) echo "install-deps.sh: profile must be 'build', 'report' or 'check', got '$profile'" >&2; exit 2 ;;
esac

missing=()
for p in "${wanted[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#wanted[@]} packages of profile '$profile' present"
  exit 0
fi

echo "install-deps: missing: ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
  sudo=(sudo -n)
else
  echo "install-deps: not root and no password-less sudo; run as root:" >&2
  echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: installed ${#missing[@]} package(s)"
