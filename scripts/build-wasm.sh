#!/usr/bin/env bash
# Builds the C++ core into build/wasm/cscd.js + cscd.wasm (an ES module factory, loadable in Node and in a
# module Web Worker), and the generic pipeline's test module cscd_toy.js + .wasm. Incremental; geometry-central's 5-7 minute build happens once per machine (cached
# outside the clone, see below).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/toolchain.sh

# Emscripten's JS optimizer needs Debian's node modules (acorn).
export NODE_PATH=/usr/share/nodejs
BUILD=build/wasm
DEPS="$PWD/.deps/potpourri3d-1.4.0/deps"

# Configured on every build, not only the first: the cache key below is read from the flags CMake
# writes, which must be those of wasm/CMakeLists.txt as it is now (a changed flag, such as the exception
# model, would otherwise pick the archive built with the old one and fail to link).
emcmake cmake -S wasm -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCSCD_DEPS_DIR="$DEPS" >/dev/null

# geometry-central's archive is kept outside the clone, one per key: the sdist's sha256, the compiler and
# the flags and include paths CMake gives the library (the clone's own path taken out), so a fresh clone
# on this machine links it instead of compiling it. A changed key builds anew; an archive whose sha256
# no longer matches the one recorded beside it is removed and rebuilt, never used.
GC_ARCHIVE="$BUILD/geometry-central/src/libgeometry-central.a"
CACHE_ROOT="${XDG_CACHE_HOME:-$HOME/.cache}/cscd-studio/geometry-central"
gc_key() {
  local flags="$BUILD/geometry-central/src/CMakeFiles/geometry-central.dir"
  {
    sed -n 's/^POTPOURRI_SHA256=//p' scripts/toolchain.sh
    em++ --version | head -1
    cat "$flags/flags.make" "$flags/includes_CXX.rsp" | grep -v '^#' | sed "s|$PWD|<clone>|g"
  } | sha256sum | cut -c1-16
}
CACHED="$CACHE_ROOT/$(gc_key)"
use=""
if [ -f "$CACHED/libgeometry-central.a" ]; then
  if (cd "$CACHED" && sha256sum --check --quiet libgeometry-central.a.sha256 >/dev/null 2>&1); then
    use="$CACHED/libgeometry-central.a"
  else
    echo "build-wasm: the cached geometry-central in $CACHED is damaged; removing it and building anew" >&2
    rm -rf "$CACHED"
  fi
fi
if [ "$(sed -n 's/^CSCD_GC_LIBRARY:FILEPATH=//p' "$BUILD/CMakeCache.txt")" != "$use" ]; then
  emcmake cmake -S wasm -B "$BUILD" -DCSCD_GC_LIBRARY="$use" >/dev/null
fi
if [ -n "$use" ]; then
  echo "build-wasm: geometry-central from the cache ($CACHED)" >&2
elif [ ! -f "$GC_ARCHIVE" ]; then
  echo "build-wasm: compiling geometry-central once (about 6 minutes on 2 cores; kept in $CACHE_ROOT)" >&2
fi
# The full output goes to the log; each step of make's "[ 42%] Building CXX object .../x.cpp.o" becomes
# one progress line on stderr, so a first build shows how far it is.
progress() {
  local line
  : >"$BUILD/last-build.log"
  while IFS= read -r line; do
    printf '%s\n' "$line" >>"$BUILD/last-build.log"
    if [[ $line =~ ^\[\ *([0-9]+)%\]\ Building\ CXX\ object\ .*/([^/]+)\.o$ ]]; then
      printf 'build-wasm: %3s%% %s\n' "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}" >&2
    fi
  done
}
# cscd_toy: the generic pipeline's test module (wasm/tests/), a few seconds more.
if ! cmake --build "$BUILD" --target cscd cscd_toy -j "$(nproc)" 2>&1 | progress; then
  grep -E 'error|Error' "$BUILD/last-build.log" | head -20 >&2
  echo "build-wasm: the WASM core did not build; full log in $BUILD/last-build.log" >&2
  exit 1
fi
cp wasm/src/bindings/cscd.d.ts "$BUILD/cscd.d.ts"
cp wasm/tests/cscd_toy.d.ts "$BUILD/cscd_toy.d.ts"

# Keep a newly compiled geometry-central for the next clone (written aside, then moved into place).
if [ -z "$use" ] && [ -f "$GC_ARCHIVE" ] && [ ! -f "$CACHED/libgeometry-central.a" ] && mkdir -p "$CACHE_ROOT" 2>/dev/null; then
  staging="$(mktemp -d "$CACHE_ROOT/.staging.XXXXXX")"
  cp "$GC_ARCHIVE" "$staging/libgeometry-central.a"
  (cd "$staging" && sha256sum libgeometry-central.a >libgeometry-central.a.sha256)
  rm -rf "$CACHED"
  mv "$staging" "$CACHED" 2>/dev/null || rm -rf "$staging"
fi
