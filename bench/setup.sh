#!/usr/bin/env bash
# Installs the baselines of the bench, idempotently (bench/run.ts calls it before every run):
#
#   bash bench/setup.sh [ls] [msls] [mcf] [skeletor]     (no argument: all of them)
#
#   ls, msls  pygel3d==0.8.2 from PyPI in the virtual environment .deps/bench-venv
#   skeletor  pc-skeletor==1.0.0 (the cloud bench's Laplacian-contraction baseline) in .deps/skeletor-venv,
#             every package pinned in bench/skeletor-requirements.txt, with Debian's gfortran for mistree
#   mcf       Debian's CGAL 5.5 (with Eigen, GMP, MPFR, Boost) and our driver bench/mcf/mcf.cpp, compiled
#             to .deps/bench/mcf when the source is newer than the binary
#
# Progress goes to stderr, so that callers can keep stdout clean.
set -euo pipefail
cd "$(dirname "$0")/.."

PYGEL_VERSION=0.8.2
VENV=.deps/bench-venv
MCF_BIN=.deps/bench/mcf
DEBIAN_PACKAGES=(g++ libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev libboost-dev)
SKELETOR_VENV=.deps/skeletor-venv

say() { echo "bench setup: $*" >&2; }

want() {
  local method
  for method in "${WANTED[@]}"; do [ "$method" = "$1" ] && return 0; done
  return 1
}
WANTED=("$@")
[ ${#WANTED[@]} -eq 0 ] && WANTED=(ls msls mcf skeletor)

setup_gel() {
  if [ ! -x "$VENV/bin/python" ]; then
    say "creating the virtual environment $VENV"
    python3 -m venv "$VENV" >&2
  fi
  local installed
  installed=$("$VENV/bin/python" -c 'from importlib.metadata import version; print(version("PyGEL3D"))' 2>/dev/null || true)
  if [ "$installed" != "$PYGEL_VERSION" ]; then
    say "installing pygel3d==$PYGEL_VERSION into $VENV"
    "$VENV/bin/pip" install --quiet --disable-pip-version-check "pygel3d==$PYGEL_VERSION" >&2
  fi
}

# Debian packages, installed when missing.
apt_install() {
  local missing=() package
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' || missing+=("$package")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    say "installing Debian packages: ${missing[*]}"
    # The package lists may be missing or stale on a fresh machine: refresh them only when needed.
    if ! DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}" >&2; then
      apt-get update >&2
      DEBIAN_FRONTEND=noninteractive apt-get install -y "${missing[@]}" >&2
    fi
  fi
}

setup_mcf() {
  apt_install "${DEBIAN_PACKAGES[@]}"
  if [ ! -x "$MCF_BIN" ] || [ bench/mcf/mcf.cpp -nt "$MCF_BIN" ]; then
    say "compiling bench/mcf/mcf.cpp against CGAL (about a minute)"
    mkdir -p "$(dirname "$MCF_BIN")"
    # CGAL_EIGEN3_ENABLED selects Eigen's sparse solver, which extract_mean_curvature_flow_skeleton needs.
    g++ -O2 -std=c++17 -DNDEBUG -DCGAL_EIGEN3_ENABLED -I/usr/include/eigen3 \
      bench/mcf/mcf.cpp -o "$MCF_BIN.tmp" -lgmp -lmpfr >&2
    mv "$MCF_BIN.tmp" "$MCF_BIN"
  fi
}

setup_skeletor() {
  local installed
  installed=$("$SKELETOR_VENV/bin/python" -c 'from importlib.metadata import version; print(version("pc-skeletor"))' 2>/dev/null || true)
  [ "$installed" = "1.0.0" ] && return
  apt_install gfortran
  [ -x "$SKELETOR_VENV/bin/python" ] || python3 -m venv "$SKELETOR_VENV" >&2
  say "installing pc-skeletor 1.0.0 and its pinned dependencies into $SKELETOR_VENV (open3d is about 400 MB; a few minutes)"
  "$SKELETOR_VENV/bin/pip" install --quiet --disable-pip-version-check 'setuptools<60' wheel >&2
  "$SKELETOR_VENV/bin/pip" install --quiet --disable-pip-version-check --no-deps -r bench/skeletor-requirements.txt >&2
  say "building mistree 1.2.0 (Fortran) against numpy 1.23.5"
  "$SKELETOR_VENV/bin/pip" install --quiet --disable-pip-version-check --no-deps --no-build-isolation mistree==1.2.0 >&2
  "$SKELETOR_VENV/bin/pip" install --quiet --disable-pip-version-check --no-deps pc-skeletor==1.0.0 >&2
}

if want ls || want msls; then setup_gel; fi
if want mcf; then setup_mcf; fi
if want skeletor; then setup_skeletor; fi
