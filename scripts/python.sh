#!/usr/bin/env bash
# The Python package (docs/python.md): makes the virtual environment .venv at
# the repository root from Debian's /usr/bin/python3 with
# --system-site-packages (numpy, matplotlib, pytest and dask come from
# Debian's python3-* packages; PyPI is not needed) and installs breakshot
# into it with `pip install --no-build-isolation .`. The extension is built
# in the release build tree (build/release, configured with the release
# preset if it is missing; setup.py's BREAKSHOT_CMAKE_BUILD_DIR), beside
# the command and the tests, so the engine is compiled once for all of
# them. Run again after a change: that build is incremental.
#
#   scripts/python.sh            make .venv if missing, install breakshot
#   scripts/python.sh --wheel    also build a wheel into dist/ (for cluster nodes)
set -euo pipefail
cd "$(dirname "$0")/.."

wheel=0
for arg in "$@"; do
  case "$arg" in
    --wheel) wheel=1 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "python.sh: unknown argument '$arg' (try --help)" >&2; exit 2 ;;
  esac
done

py=/usr/bin/python3
if [ ! -x .venv/bin/python ] || ! .venv/bin/python -c 'import numpy' 2>/dev/null; then
  rm -rf .venv
  "$py" -m venv --system-site-packages .venv
fi
if [ ! -f build/release/CMakeCache.txt ]; then
  cmake --preset release >/dev/null
fi
export BREAKSHOT_CMAKE_BUILD_DIR=$PWD/build/release
.venv/bin/python -m pip install --no-build-isolation --no-deps --no-index \
  --disable-pip-version-check --quiet .
.venv/bin/python -c 'import breakshot; print("python: breakshot", breakshot.__version__, "in .venv")'
if [ "$wheel" -eq 1 ]; then
  .venv/bin/python -m build --no-isolation --wheel --outdir dist .
fi
