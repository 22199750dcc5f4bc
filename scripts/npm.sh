#!/usr/bin/env bash
# Builds the npm package `breakshot` (docs/js.md), which is never
# published: the wasm engine (scripts/web.sh, then the target
# breakshot_wasm_npm of build/web: build/web/npm/breakshot-wasm.js and
# .wasm; nothing rebuilt when nothing changed), then the package
# assembled in build/npm/package from npm/ (src/*.js, index.d.ts,
# README.md, package.json with the version of
# include/breakshot/version.hpp) and the page's engine.js and worker.js,
# then `npm pack`: build/npm/breakshot-VERSION.tgz. Prints the sizes.
#
#   scripts/npm.sh           build the package
#   scripts/npm.sh --test    and its tests (npm/tests/run.mjs: installed
#                            from the tarball into an empty folder, node
#                            and Chromium examples)
set -euo pipefail
cd "$(dirname "$0")/.."

run_test=0
for arg in "$@"; do
  case "$arg" in
    --test) run_test=1 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "npm.sh: unknown argument '$arg' (try --help)" >&2; exit 2 ;;
  esac
done

version=$(sed -nE 's/.*kVersion = "([0-9]+\.[0-9]+\.[0-9]+)".*/\1/p' include/breakshot/version.hpp)
if [ -z "$version" ]; then
  echo "npm.sh: no version in include/breakshot/version.hpp" >&2
  exit 1
fi

# The page's build (nothing to do when it is current), then the package's
# engine: the same objects linked with the wasm in a file of its own.
scripts/web.sh
NODE_PATH=${NODE_PATH:-/usr/share/nodejs} cmake --build build/web -j 2 --target breakshot_wasm_npm
wasm=build/web/npm

out=build/npm
pkg=$out/package
rm -rf "$pkg"
mkdir -p "$pkg"
cp npm/src/index.js npm/src/player.js npm/src/breakshot.js npm/index.d.ts npm/README.md "$pkg"/
cp web/page/engine.js web/page/worker.js "$pkg"/
cp "$wasm"/breakshot-wasm.js "$wasm"/breakshot-wasm.wasm "$pkg"/
# package.json with the library's version (npm/package.json holds a
# placeholder: version.hpp is the one source of the version).
node -e '
  const fs = require("fs");
  const [src, dst, version] = process.argv.slice(1);
  const p = JSON.parse(fs.readFileSync(src, "utf8"));
  p.version = version;
  fs.writeFileSync(dst, JSON.stringify(p, null, 2) + "\n");
' npm/package.json "$pkg/package.json" "$version"

rm -f "$out"/breakshot-*.tgz
(cd "$pkg" && npm pack --pack-destination .. --loglevel=error >/dev/null)
tgz=$out/breakshot-$version.tgz
[ -f "$tgz" ]

size() { stat -c %s "$1"; }
gz() { gzip -9 -c "$1" | wc -c; }
js=("$pkg"/index.js "$pkg"/player.js "$pkg"/breakshot.js "$pkg"/engine.js "$pkg"/worker.js)
w=$pkg/breakshot-wasm.wasm
l=$pkg/breakshot-wasm.js
echo "npm.sh: $tgz ($(size "$tgz") bytes)"
echo "npm.sh: breakshot-wasm.wasm $(size "$w") bytes ($(gz "$w") gzipped, gzip -9)," \
  "its loader breakshot-wasm.js $(size "$l") ($(gz "$l")), the package's JS $(cat "${js[@]}" | wc -c)" \
  "($(cat "${js[@]}" | gzip -9 -c | wc -c)); in all $(( $(size "$w") + $(size "$l") + $(cat "${js[@]}" | wc -c) )) bytes," \
  "$(( $(gz "$w") + $(gz "$l") + $(cat "${js[@]}" | gzip -9 -c | wc -c) )) gzipped file by file"

if [ "$run_test" -eq 1 ]; then
  node npm/tests/run.mjs --tarball "$tgz"
fi
