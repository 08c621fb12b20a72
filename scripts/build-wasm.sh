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
if ! cmake --build "$BUILD" --target cscd -j "$(nproc)" >"$BUILD/last-build.log" 2>&1; then
  grep -E 'error|Error' "$BUILD/last-build.log" | head -20 >&2
  echo "build-wasm: the WASM core did not build; full log in $BUILD/last-build.log" >&2
  exit 1
fi
cp wasm/src/bindings/cscd.d.ts "$BUILD/cscd.d.ts"
