#!/usr/bin/env bash
# Fingerprints of what breakshot produces, to show that a change which
# must not change behaviour (a refactoring) leaves every output byte for
# byte as it was. Prints one "sha256  what" line per output:
#
#   - `simulate` of every scenario in examples/lab, examples/pool,
#     examples/snooker and examples/carom, and the three plots of
#     two_balls.json (--plot);
#   - match summaries and every game record of short matches (8-ball,
#     9-ball and snooker; the baseline and the AI levels), and `replay` of
#     each record;
#   - the replies of web_api_probe to web/tests/probe_script.json (the
#     native side of the wasm identity test).
#
#   scripts/fingerprint.sh [BUILD_DIR] [OUT_DIR]
#
# BUILD_DIR defaults to build/release (it must hold `breakshot` and
# `web_api_probe`); the outputs themselves are left in OUT_DIR (default: a
# temporary folder, removed) so that two runs can be compared with diff -r.
# Compare two commits with: scripts/fingerprint.sh A > a.txt; ... ; diff a.txt b.txt
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
cli=$build/breakshot
probe=$build/web_api_probe
for exe in "$cli" "$probe"; do
  [ -x "$exe" ] || { echo "fingerprint.sh: $exe is missing (build first)" >&2; exit 2; }
done
if [ -n "${2:-}" ]; then
  out=$2
  rm -rf "$out"
  mkdir -p "$out"
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi

sum() { sha256sum "$1" | awk -v what="$2" '{print $1 "  " what}'; }

mkdir -p "$out/simulate"
for f in examples/lab/*.json examples/pool/*.json examples/snooker/*.json examples/carom/*.json; do
  name=$(basename "$(dirname "$f")")-$(basename "$f")
  status=0
  "$cli" simulate "$f" -o "$out/simulate/$name" || status=$?
  echo "exit $status" >>"$out/simulate/$name"
  sum "$out/simulate/$name" "simulate $f"
done
"$cli" simulate examples/lab/two_balls.json -o "$out/simulate/plot.json" --plot "$out/simulate/plot" >/dev/null
for kind in trajectories energy momentum; do
  sum "$out/simulate/plot-$kind.svg" "simulate --plot two_balls ($kind)"
done

# game players games seed noise
matches=(
  "eight_ball baseline,baseline 12 7 tournament"
  "nine_ball baseline,baseline 12 11 2x"
  "eight_ball beginner,amateur 3 5 tournament"
  "nine_ball club,champion 2 3 tournament"
  "snooker baseline,baseline 2 5 tournament"
  "snooker baseline,beginner 1 9 tournament"
)
i=0
for m in "${matches[@]}"; do
  read -r game players games seed noise <<<"$m"
  dir=$out/match-$i
  mkdir -p "$dir"
  "$cli" match --game "$game" --players "$players" --games "$games" --seed "$seed" \
    --noise "$noise" --records "$dir/records" >"$dir/summary.json"
  sum "$dir/summary.json" "match $m: summary"
  cat "$dir"/records/*.json >"$dir/records.all"
  sum "$dir/records.all" "match $m: records"
  : >"$dir/replay.txt"
  for r in "$dir"/records/*.json; do
    status=0
    "$cli" replay "$r" >>"$dir/replay.txt" 2>&1 || status=$?
    echo "exit $status" >>"$dir/replay.txt"
  done
  sum "$dir/replay.txt" "match $m: replay of every record"
  i=$((i + 1))
done

"$probe" --script web/tests/probe_script.json >"$out/web_api_probe.txt"
sum "$out/web_api_probe.txt" "web_api_probe web/tests/probe_script.json"
