#!/usr/bin/env bash
# Installs what building and testing breakshot needs, from Debian's
# packages. Idempotent and non-interactive: it asks dpkg what is already
# there and runs apt-get (update, then install) only for what is missing.
#
#   scripts/setup.sh            install what is missing
#   scripts/setup.sh --check    only report; exit 1 if something is missing
set -euo pipefail

# Required: the toolchain, the test and benchmark frameworks, and the
# libraries the engine and its command use (Boost: Asio and Beast,
# header-only, for `breakshot serve`). libclang-rt-14-dev carries
# libFuzzer and clang's sanitizer runtimes (the asan preset is clang's).
# emscripten builds the browser version (scripts/web.sh), whose strtod
# reads decimals with fast_float (libfast-float-dev); chromium and a
# font are what its browser tests drive (web/tests/browser.mjs, with
# playwright-core from npm, which never downloads a browser);
# node-typescript checks the npm package's declarations (npm/tests). The Python
# package (scripts/python.sh) is built with pybind11 against Debian's
# python3 and uses its numpy, matplotlib and pytest; breakshot.distributed
# runs on Dask (python3-distributed), with tqdm for its progress bars.
required=(
  build-essential cmake ninja-build g++ clang libclang-rt-14-dev
  libgtest-dev googletest libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libboost-dev
  emscripten libfast-float-dev chromium fonts-dejavu-core curl node-typescript
  python3 python3-dev python3-venv python3-pip python3-setuptools python3-wheel
  python3-build pybind11-dev python3-numpy python3-matplotlib python3-pytest
  python3-dask python3-distributed python3-tqdm
)
# Optional: rsvg-convert, to turn the SVG plots into PNG previews.
optional=(librsvg2-bin)

check_only=0
for arg in "$@"; do
  case "$arg" in
    --check) check_only=1 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "setup.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

installed() {
  dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'install ok installed'
}

missing_from() {
  local p
  for p in "$@"; do installed "$p" || printf '%s\n' "$p"; done
}

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "setup.sh: this script needs a Debian-like system (dpkg-query, apt-get)." >&2
  echo "Install by hand: ${required[*]} (optional: ${optional[*]})" >&2
  exit 1
fi

mapfile -t missing < <(missing_from "${required[@]}")
mapfile -t missing_opt < <(missing_from "${optional[@]}")

if [ ${#missing[@]} -eq 0 ] && [ ${#missing_opt[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi

if [ "$check_only" -eq 1 ]; then
  [ ${#missing[@]} -eq 0 ] || echo "setup: missing: ${missing[*]}"
  [ ${#missing_opt[@]} -eq 0 ] || echo "setup: missing (optional): ${missing_opt[*]}"
  [ ${#missing[@]} -eq 0 ]
  exit $?
fi

# Root runs apt-get as is; anyone else goes through sudo if there is one.
if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
  echo "setup: not root; using sudo for apt-get"
elif [ ${#missing[@]} -eq 0 ]; then
  echo "setup: optional ${missing_opt[*]} missing (only plot previews need it);" \
    "install it as root to get rsvg-convert"
  exit 0
else
  all="${missing[*]}${missing_opt[*]:+ ${missing_opt[*]}}"
  echo "setup.sh: these packages are missing and installing them needs root:" >&2
  echo "  $all" >&2
  echo "Run this script as root or with sudo installed, or run as root:" >&2
  echo "  apt-get update && apt-get install -y $all" >&2
  exit 1
fi

export DEBIAN_FRONTEND=noninteractive
apt=("${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get
     -o DPkg::Lock::Timeout=300 -y -q)

echo "setup: installing ${missing[*]}${missing_opt[*]:+ ${missing_opt[*]}}"
if ! "${apt[@]}" update; then
  echo "setup: warning: apt-get update reported errors; trying to install anyway" >&2
fi
if [ ${#missing[@]} -gt 0 ]; then
  "${apt[@]}" install --no-install-recommends "${missing[@]}"
fi
if [ ${#missing_opt[@]} -gt 0 ]; then
  "${apt[@]}" install --no-install-recommends "${missing_opt[@]}" ||
    echo "setup: warning: could not install optional ${missing_opt[*]} (only plot previews need it)" >&2
fi

mapfile -t still < <(missing_from "${required[@]}")
if [ ${#still[@]} -gt 0 ]; then
  echo "setup.sh: still missing after apt-get: ${still[*]}" >&2
  exit 1
fi
echo "setup: done"
