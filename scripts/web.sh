#!/usr/bin/env bash
# Builds the browser version (docs/web.md): the engine, the rules, the AI
# and the facade compiled to WebAssembly with Debian's emscripten into
# build/web/dist/breakshot.js, next to a copy of every file of web/page/.
# Installs emscripten and fast_float with apt-get if they are missing.
# Idempotent: when nothing changed it only asks ninja, which says so in
# well under a second.
#
#   scripts/web.sh          build build/web/dist
#   scripts/web.sh --test   build, then the identity test: the native probe
#                           (web_api_probe, built in $BREAKSHOT_NATIVE_BUILD,
#                           default build/release, configured with the
#                           release preset if missing) and the wasm build
#                           give the same replies byte for byte
#                           (web/tests/identity.mjs)
set -euo pipefail
cd "$(dirname "$0")/.."

run_test=0
for arg in "$@"; do
  case "$arg" in
    --test) run_test=1 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "web.sh: unknown argument '$arg' (try --help)" >&2; exit 2 ;;
  esac
done

# emscripten (and node, which it runs) and fast_float (header-only: the
# wasm build's strtod, web/compat/fast_strtod.cpp), from Debian's packages.
if ! command -v emcmake >/dev/null 2>&1 || ! command -v em++ >/dev/null 2>&1 ||
   ! command -v node >/dev/null 2>&1 || [ ! -f /usr/include/fast_float/fast_float.h ]; then
  echo "web.sh: installing emscripten and fast_float (apt-get)"
  if [ "$(id -u)" -eq 0 ]; then
    as_root=()
  elif command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    echo "web.sh: emscripten or fast_float is missing and installing them needs root:" >&2
    echo "  apt-get update && apt-get install -y emscripten nodejs libfast-float-dev" >&2
    exit 1
  fi
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
    emscripten nodejs libfast-float-dev
fi
# Debian's emscripten runs its JavaScript optimizer with node and finds
# its modules (acorn, ...) there.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}

build=build/web
if [ ! -f "$build/build.ninja" ]; then
  emcmake cmake -S web -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
start=$SECONDS
cmake --build "$build" -j 2
if [ $((SECONDS - start)) -gt 2 ]; then
  echo "web.sh: built $build/dist/breakshot.js ($(stat -c %s "$build/dist/breakshot.js") bytes) in $((SECONDS - start)) s"
fi

if [ "$run_test" -eq 1 ]; then
  native=${BREAKSHOT_NATIVE_BUILD:-build/release}
  if [ ! -f "$native/build.ninja" ]; then
    if [ "$native" = build/release ]; then
      cmake --preset release
    else
      cmake -S . -B "$native" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBREAKSHOT_WERROR=ON
    fi
  fi
  cmake --build "$native" -j 2 --target web_api_probe
  node web/tests/identity.mjs --probe "$native/web_api_probe" --engine "$build/dist/breakshot.js"
fi
