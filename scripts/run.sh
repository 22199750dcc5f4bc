#!/usr/bin/env bash
# The main job: install what is missing, build the release preset, then
# simulate the lab's two-ball scenario and draw its plots.
#
#   scripts/run.sh [SCENARIO]     default: examples/lab/two_balls.json
#
# Writes out/NAME.json (the result) and out/NAME-trajectories.svg,
# out/NAME-energy.svg, out/NAME-momentum.svg (the plots).
set -euo pipefail
cd "$(dirname "$0")/.."

scenario=${1:-examples/lab/two_balls.json}
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
if command -v rsvg-convert >/dev/null 2>&1; then
  echo "(preview as PNG: rsvg-convert $prefix-trajectories.svg -o $prefix-trajectories.png)"
fi
