#!/usr/bin/env bash
# Compares the engine's speed at an older commit with the working tree's,
# side by side in one run (docs/performance.md, "Comparing two commits").
#
#   bench/compare.sh [--reps R] [--seconds S] [--no-callgrind] [--workloads "W ..."] OLD
#
# OLD is any commit (a hash, a tag, HEAD~3). The script
#   1. builds the engine's libraries (physics and game) of OLD from `git
#      archive` in $BREAKSHOT_COMPARE_DIR/<hash> (default /tmp/breakshot-compare;
#      kept, so a second comparison with the same commit builds nothing),
#      and of the working tree in build/release (the release preset);
#   2. compiles bench/shot_workloads.cpp of the working tree twice, with the
#      same flags, against each build's headers and libraries;
#   3. checks that both give the same results (a digest of every final
#      table of every workload and of large gases, which the cell grid
#      serves, and the events and final tables of 20,000 shots of
#      bench/soak across the models and games): a speed-up that changes
#      results is not one;
#   4. times the workloads (8-ball and 9-ball breaks with racks cycled,
#      random 15-ball shots cycled; "-rearm": one simulation re-armed for
#      every shot where the commit has Simulation::reset, else a new one
#      per shot, as its users had to), old and new interleaved (old first in
#      odd rounds, new first in even ones), R rounds of S seconds each, and
#      prints the medians and their ratio;
#   5. counts instructions per shot with callgrind (valgrind; these do not
#      move with the machine's load) and prints their ratio.
#
# Exit status: 0 compared; 1 a build failed; 3 the results differ (the
# table is still printed).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

reps=5
seconds=2
callgrind=1
workloads="break8 break9 random15 break8-rearm random15-rearm"
old=""
while [ $# -gt 0 ]; do
  case "$1" in
    --reps) reps="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --no-callgrind) callgrind=0; shift ;;
    --workloads) workloads="$2"; shift 2 ;;
    -h|--help) sed -n '2,29p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "compare.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) [ -z "$old" ] || { echo "compare.sh: one commit only" >&2; exit 2; }; old="$1"; shift ;;
  esac
done
[ -n "$old" ] || { echo "compare.sh: which commit? (see --help)" >&2; exit 2; }
case "$reps" in ''|*[!0-9]*|0) echo "compare.sh: --reps must be a whole number >= 1" >&2; exit 2 ;; esac
sha=$(git rev-parse --verify --quiet "$old^{commit}") ||
  { echo "compare.sh: '$old' is not a commit" >&2; exit 2; }
short=${sha:0:7}

work=${BREAKSHOT_COMPARE_DIR:-/tmp/breakshot-compare}
old_src="$work/$sha/src"
old_build="$work/$sha/build"
mkdir -p "$work"

libs=(breakshot_io breakshot_game breakshot_physics)
build_libs() {  # SOURCE BUILD
  cmake -S "$1" -B "$2" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBREAKSHOT_BUILD_TESTS=OFF \
    -DBREAKSHOT_BUILD_APPS=OFF -DBREAKSHOT_BUILD_BENCH=OFF >/dev/null
  cmake --build "$2" -j2 --target "${libs[@]}" >/dev/null
}

echo "compare: building $short (old) in $old_build" >&2
if [ ! -f "$old_src/CMakeLists.txt" ]; then
  rm -rf "$old_src"
  mkdir -p "$old_src"
  git archive "$sha" | tar -x -C "$old_src"
fi
build_libs "$old_src" "$old_build" || { echo "compare: the build of $short failed" >&2; exit 1; }
echo "compare: building the working tree in build/release" >&2
[ -f build/release/build.ninja ] || cmake --preset release >/dev/null
cmake --build build/release -j2 --target "${libs[@]}" >/dev/null ||
  { echo "compare: the build of the working tree failed" >&2; exit 1; }

# The same program, the same flags, each build's headers and libraries.
flags=(-std=c++20 -O3 -DNDEBUG -ffp-contract=off)
compile() {  # SOURCE_TREE BUILD PROGRAM OUT
  local lib_args=()
  for l in "${libs[@]}"; do lib_args+=("$2/lib$l.a"); done
  g++ "${flags[@]}" -I"$1/include" -I"$root/bench" "$root/bench/$3.cpp" "${lib_args[@]}" -o "$4"
}
bin_old="$work/$sha/shot_workloads"
bin_new="$work/shot_workloads-working-tree"
soak_old="$work/$sha/soak"
soak_new="$work/soak-working-tree"
compile "$old_src" "$old_build" shot_workloads "$bin_old" || { echo "compare: shot_workloads does not build against $short" >&2; exit 1; }
compile "$root" "$root/build/release" shot_workloads "$bin_new"
compile "$old_src" "$old_build" soak "$soak_old" || { echo "compare: soak does not build against $short" >&2; exit 1; }
compile "$root" "$root/build/release" soak "$soak_new"

status=0
echo "## results"
for w in $workloads; do
  a=$("$bin_old" "$w" digest | awk '{print $3}')
  b=$("$bin_new" "$w" digest | awk '{print $3}')
  if [ "$a" = "$b" ]; then
    echo "$w: identical ($a)"
  else
    echo "$w: DIFFER ($short $a, working tree $b)"
    status=3
  fi
done
# Scenes of 48 balls and more, which the cell grid serves (the workloads
# above are smaller): ideal and friction gases.
a=$("$bin_old" gas digest | awk '{print $3}')
b=$("$bin_new" gas digest | awk '{print $3}')
if [ "$a" = "$b" ]; then
  echo "gas (cell grid): identical ($a)"
else
  echo "gas (cell grid): DIFFER ($short $a, working tree $b)"
  status=3
fi
# The soak's 20,000 shots of every kind (pool layouts, raised cues,
# breaks, snooker, three-cushion, gases): their events and final tables.
a=$("$soak_old" --shots 20000 --threads 2 --out "$work/soak-violation-old.json" | grep -E '^(digest|[a-z0-9/ -]+ +[0-9]+ +[0-9]+$)' | md5sum | cut -c1-16) || true
b=$("$soak_new" --shots 20000 --threads 2 --out "$work/soak-violation-new.json" | grep -E '^(digest|[a-z0-9/ -]+ +[0-9]+ +[0-9]+$)' | md5sum | cut -c1-16) || true
if [ "$a" = "$b" ]; then
  echo "soak (20,000 shots of every kind): identical ($a)"
else
  echo "soak (20,000 shots of every kind): DIFFER ($short $a, working tree $b)"
  status=3
fi

median() { sort -g | awk '{v[NR]=$1} END {if (NR%2) print v[(NR+1)/2]; else print (v[NR/2]+v[NR/2+1])/2}'; }

echo
echo "## time per shot (ns), medians of $reps interleaved rounds of ${seconds} s"
echo
echo "| workload | $short | working tree | ratio |"
echo "| --- | ---: | ---: | ---: |"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for r in $(seq 1 "$reps"); do
  for w in $workloads; do
    if [ $((r % 2)) -eq 1 ]; then order="old new"; else order="new old"; fi
    for side in $order; do
      if [ "$side" = old ]; then bin=$bin_old; else bin=$bin_new; fi
      "$bin" "$w" time "$seconds" | awk '{print $2}' >>"$tmp/$w.$side"
    done
  done
done
for w in $workloads; do
  a=$(median <"$tmp/$w.old")
  b=$(median <"$tmp/$w.new")
  awk -v w="$w" -v a="$a" -v b="$b" 'BEGIN {printf "| %s | %.0f | %.0f | %.3f |\n", w, a, b, b / a}'
done

if [ "$callgrind" = 1 ]; then
  if ! command -v valgrind >/dev/null 2>&1; then
    echo
    echo "(no valgrind: instruction counts skipped)"
  else
    echo
    echo "## instructions per shot (callgrind, bs_run_shots only)"
    echo
    echo "| workload | shots | $short | working tree | ratio |"
    echo "| --- | ---: | ---: | ---: | ---: |"
    for w in $workloads; do
      case "$w" in random15*) n=2048 ;; *) n=256 ;; esac
      count() {
        valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" --collect-atstart=no \
          --toggle-collect=bs_run_shots "$1" "$w" count "$n" >/dev/null 2>"$tmp/cg.err"
        awk '/^summary:/ {print $2}' "$tmp/cg"
      }
      a=$(count "$bin_old")
      b=$(count "$bin_new")
      awk -v w="$w" -v n="$n" -v a="$a" -v b="$b" \
        'BEGIN {printf "| %s | %d | %.0f | %.0f | %.3f |\n", w, n, a / n, b / n, b / a}'
    done
  fi
fi
exit "$status"
