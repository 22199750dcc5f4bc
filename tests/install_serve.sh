#!/usr/bin/env bash
# ctest install_serve: `cmake --install` into a temporary prefix, then the
# installed `breakshot serve` finds the page beside itself
# (PREFIX/share/breakshot/web) with no --root, and says clearly when there
# is none.
#
#   tests/install_serve.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
prefix=$(mktemp -d "${TMPDIR:-/tmp}/breakshot_install_serve.XXXXXX")
prefix=$(cd "$prefix" && pwd -P)
server=""
cleanup() {
  if [ -n "$server" ]; then kill "$server" 2>/dev/null || true; wait "$server" 2>/dev/null || true; fi
  rm -rf "$prefix"
}
trap cleanup EXIT
fail() { echo "install_serve: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >"$prefix/install.log"
cli=$prefix/bin/breakshot
page=$prefix/share/breakshot/web
[ -x "$cli" ] || fail "no command installed at $cli"

# The page is installed when scripts/web.sh has built it; else this test
# puts one there, as an install of a built page would.
if [ -f "$source/build/web/dist/index.html" ]; then
  cmp "$source/build/web/dist/index.html" "$page/index.html" ||
    fail "cmake --install did not install build/web/dist into $page"
else
  [ ! -e "$page" ] || fail "$page installed without a built page"
  mkdir -p "$page"
  echo '<!doctype html><title>installed</title>' >"$page/index.html"
fi

# Served without --root: the installed page, found from the command's place.
"$cli" serve --port 0 --quiet >"$prefix/serve.out" 2>"$prefix/serve.err" &
server=$!
for _ in $(seq 100); do
  grep -q "^breakshot: open http" "$prefix/serve.out" 2>/dev/null && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.1
done
grep -qx "breakshot: serving $page" "$prefix/serve.out" ||
  fail "the installed command does not serve $page: $(cat "$prefix/serve.out" "$prefix/serve.err")"
kill "$server"
wait "$server" || true
server=""

# No page installed: a clear message naming where it looked, exit 1.
rm -rf "$page"
status=0
"$cli" serve --port 0 --quiet >"$prefix/none.out" 2>"$prefix/none.err" || status=$?
[ "$status" -eq 1 ] || fail "serve without a page exited $status, not 1"
grep -q "breakshot: no page found: no index.html in $page" "$prefix/none.err" ||
  fail "serve without a page did not say so: $(cat "$prefix/none.err")"
grep -q -- "--root DIR" "$prefix/none.err" || fail "the message does not name --root"
# The build tree's page is not the installed command's.
! grep -q "$source/build/web/dist" "$prefix/none.err" ||
  fail "the installed command looked in the build tree"
echo "install_serve: the installed command serves $page"
