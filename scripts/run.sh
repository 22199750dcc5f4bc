#!/usr/bin/env bash
# The main job: install what is missing, build the engine and its browser
# version, simulate the lab's two-ball scenario and draw its plots, then
# serve the game and the lab on 127.0.0.1 and print the address.
#
#   scripts/run.sh [--port P] [--check] [SCENARIO]
#
#   SCENARIO   lab scenario to simulate and plot (default examples/lab/two_balls.json):
#              writes out/NAME.json (the result) and out/NAME-trajectories.svg,
#              out/NAME-energy.svg, out/NAME-momentum.svg (the plots)
#   --port P   port of the page (default 8000; 0 picks a free one)
#   --check    do everything, but instead of serving until Ctrl-C, start the
#              server, fetch the page and the engine from it, and stop
#              (scripts/test.sh runs this)
set -euo pipefail
cd "$(dirname "$0")/.."

port=8000
check=0
scenario=examples/lab/two_balls.json
while [ $# -gt 0 ]; do
  case "$1" in
    --port)
      [ $# -ge 2 ] || { echo "run.sh: --port needs a number" >&2; exit 2; }
      port=$2
      shift 2
      ;;
    --check) check=1; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    -*) echo "run.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
    *) scenario=$1; shift ;;
  esac
done
case "$port" in
  ''|*[!0-9]*) echo "run.sh: --port must be a number from 0 to 65535, not '$port'" >&2; exit 2 ;;
esac

name=$(basename "$scenario" .json)
result=out/$name.json
prefix=out/$name

if [ ! -f "$scenario" ]; then
  echo "run.sh: no scenario file '$scenario'" >&2
  exit 1
fi

scripts/setup.sh
cmake --preset release
cmake --build --preset release --target breakshot_cli
scripts/web.sh
scripts/python.sh

mkdir -p out
status=0
build/release/breakshot simulate "$scenario" -o "$result" --plot "$prefix" || status=$?
if [ "$status" -ne 0 ]; then
  case "$status" in
    2) why="invalid scenario" ;;
    3) why="the max_events guard stopped the run; partial result in $result" ;;
    *) why="error" ;;
  esac
  echo "run.sh: breakshot simulate failed (exit $status: $why)" >&2
  exit "$status"
fi

echo
echo "Scenario: $scenario"
echo "Result:   $result"
echo "Plots:"
for kind in trajectories energy momentum; do
  svg=$prefix-$kind.svg
  if [ -f "$svg" ]; then
    echo "  $svg"
  else
    echo "run.sh: expected plot $svg was not written" >&2
    exit 1
  fi
done
echo

if [ "$check" -eq 0 ]; then
  echo "The game and the lab (Ctrl-C stops the server):"
  exec build/release/breakshot serve --port "$port" --quiet
fi

# --check: serve on a free port, fetch the page and the engine, stop.
log=$(mktemp)
build/release/breakshot serve --port 0 --quiet >"$log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true; rm -f "$log"' EXIT
url=""
for _ in $(seq 1 100); do
  url=$(grep -o 'http://127\.0\.0\.1:[0-9]*/' "$log" || true)
  [ -n "$url" ] && break
  sleep 0.1
done
if [ -z "$url" ]; then
  echo "run.sh: breakshot serve did not start:" >&2
  cat "$log" >&2
  exit 1
fi
for file in "" breakshot.js engine.js; do
  if ! curl -fsS -o /dev/null "$url$file"; then
    echo "run.sh: the server at $url does not give /$file" >&2
    exit 1
  fi
done
echo "run.sh: the page is served at $url (index.html, breakshot.js and engine.js fetched); stopped"
