#!/usr/bin/env bash
# Installs what the build needs, idempotently: Debian's emscripten and chromium, and the pinned
# potpourri3d sdist that carries geometry-central and Eigen (unpacked into .deps/, never tracked).
set -euo pipefail
cd "$(dirname "$0")/.."

POTPOURRI_VERSION=1.4.0
POTPOURRI_SHA256=83c31ac4ee69b90cc0f3af1139f91ec952077defcc9166056cc4434712679292
DEPS=.deps
SRC="$DEPS/potpourri3d-$POTPOURRI_VERSION"

need_apt=()
command -v emcc >/dev/null 2>&1 || need_apt+=(emscripten)
[ -x /usr/bin/chromium ] || need_apt+=(chromium)
if [ ${#need_apt[@]} -gt 0 ]; then
  if [ "$(id -u)" != 0 ]; then
    echo "toolchain: missing ${need_apt[*]}; install them with apt-get (needs root)" >&2
    exit 1
  fi
  echo "toolchain: installing ${need_apt[*]} from Debian" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need_apt[@]}" >/dev/null
fi

if [ ! -f "$SRC/.unpacked" ]; then
  mkdir -p "$DEPS/download"
  tarball="$DEPS/download/potpourri3d-$POTPOURRI_VERSION.tar.gz"
  if [ ! -f "$tarball" ]; then
    echo "toolchain: fetching potpourri3d==$POTPOURRI_VERSION sdist (geometry-central + Eigen)" >&2
    python3 -m pip download --quiet --no-deps --no-binary :all: \
      "potpourri3d==$POTPOURRI_VERSION" -d "$DEPS/download"
  fi
  echo "$POTPOURRI_SHA256  $tarball" | sha256sum --check --quiet || {
    echo "toolchain: sha256 mismatch for $tarball" >&2
    rm -f "$tarball"
    exit 1
  }
  rm -rf "$SRC"
  tar xzf "$tarball" -C "$DEPS" \
    "potpourri3d-$POTPOURRI_VERSION/deps/geometry-central" "potpourri3d-$POTPOURRI_VERSION/deps/eigen"
  touch "$SRC/.unpacked"
fi
