#!/usr/bin/env bash
# Builds the C++ core into build/wasm/cscd.js + cscd.wasm (an ES module factory, loadable in Node and in a
# module Web Worker). Incremental: geometry-central's 5-7 minute build happens once per build folder.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/toolchain.sh

# Emscripten's JS optimizer needs Debian's node modules (acorn).
export NODE_PATH=/usr/share/nodejs
BUILD=build/wasm
DEPS="$PWD/.deps/potpourri3d-1.4.0/deps"

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  emcmake cmake -S wasm -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCSCD_DEPS_DIR="$DEPS" >/dev/null
fi
if [ ! -f "$BUILD/geometry-central/src/libgeometry-central.a" ]; then
  echo "build-wasm: compiling geometry-central once (about 6 minutes on 2 cores)" >&2
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
if ! cmake --build "$BUILD" --target cscd -j "$(nproc)" 2>&1 | progress; then
  grep -E 'error|Error' "$BUILD/last-build.log" | head -20 >&2
  echo "build-wasm: the WASM core did not build; full log in $BUILD/last-build.log" >&2
  exit 1
fi
cp wasm/src/bindings/cscd.d.ts "$BUILD/cscd.d.ts"
