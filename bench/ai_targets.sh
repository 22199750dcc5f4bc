#!/usr/bin/env bash
# The AI's target matches (docs/ai.md, "Targets of the rules-driven AI"),
# played in chunks of `breakshot match --first-game` so that a long match
# can be spread over sittings: a chunk whose summary is already in OUT is
# not played again, and `breakshot match-sum` adds the chunks when all of
# a match's are there.
#
#   bench/ai_targets.sh OUT TARGET...     play (or finish) the targets' chunks
#   bench/ai_targets.sh OUT --list        the targets and their commands
#
# Targets (seed 21 throughout, a seed no other figure of docs/ai.md uses;
# tournament noise, each level at its own unless the player names one):
#   nine         9-ball champion vs baseline, 200 games
#   eight        8-ball champion vs baseline, 200 games
#   ten          10-ball champion vs baseline, 200 games
#   ten-ladder   10-ball amateur:beginner, club:amateur, expert:club,
#                champion:expert, 200 games each
#   snooker      snooker champion vs baseline, 200 frames
#   snooker-half snooker champion@0.5x vs baseline, 100 frames
#   carom        three-cushion champion vs champion, 50 games
#   timing       decision times: champion vs beginner, 20 games of each
#                pool game and snooker, --timing --jobs 1 (not chunked)
#
# BREAKSHOT (default build/release/breakshot) names the command; JOBS
# (default 0: one game per core) is passed to --jobs. The matches are the
# same for any JOBS.
set -Eeuo pipefail
cd "$(dirname "$0")/.."
bin=${BREAKSHOT:-build/release/breakshot}
jobs=${JOBS:-0}
seed=21

if [ $# -lt 2 ]; then
  sed -n '2,29p' "$0"
  exit 2
fi
out=$1
shift
mkdir -p "$out"

# name game players games chunk
matches_of() {
  case "$1" in
    nine) echo "nine nine_ball champion,baseline 200 20" ;;
    eight) echo "eight eight_ball champion,baseline 200 20" ;;
    ten) echo "ten ten_ball champion,baseline 200 20" ;;
    ten-ladder)
      echo "ten-amateur-beginner ten_ball amateur,beginner 200 50"
      echo "ten-club-amateur ten_ball club,amateur 200 50"
      echo "ten-expert-club ten_ball expert,club 200 50"
      echo "ten-champion-expert ten_ball champion,expert 200 20" ;;
    snooker) echo "snooker snooker champion,baseline 200 10" ;;
    snooker-half) echo "snooker-half snooker champion@0.5x,baseline 100 10" ;;
    carom) echo "carom three_cushion champion,champion 50 10" ;;
    *) echo "ai_targets.sh: unknown target '$1' (try --list)" >&2; return 2 ;;
  esac
}

command_of() {  # game players games first
  echo "$bin match --game $1 --players $2 --games $3 --first-game $4 --seed $seed --noise tournament --jobs $jobs"
}

if [ "$1" = "--list" ]; then
  for t in nine eight ten ten-ladder snooker snooker-half carom; do
    matches_of "$t" | while read -r name game players games chunk; do
      echo "$name: $(command_of "$game" "$players" "$chunk" F) > $name-F.json   # F = 0, $chunk, ... < $games"
    done
  done
  echo "timing: $bin match --game G --players champion,beginner --games 20 --seed $seed --noise tournament --timing --jobs 1"
  exit 0
fi

play_match() {  # name game players games chunk
  local name=$1 game=$2 players=$3 games=$4 chunk=$5 f files=()
  for ((f = 0; f < games; f += chunk)); do
    local file=$out/$name-$f.json
    files+=("$file")
    if [ -s "$file" ]; then continue; fi
    echo "[$(date -u +%H:%M:%S)] $name: games $f..$((f + chunk - 1))" >&2
    "$bin" match --game "$game" --players "$players" --games "$chunk" --first-game "$f" \
      --seed $seed --noise tournament --jobs "$jobs" > "$file.part"
    mv "$file.part" "$file"
  done
  "$bin" match-sum "${files[@]}" > "$out/$name.json"
  echo "[$(date -u +%H:%M:%S)] $name: $out/$name.json" >&2
}

for target in "$@"; do
  if [ "$target" = timing ]; then
    for game in eight_ball nine_ball ten_ball snooker; do
      file=$out/timing-$game.json
      [ -s "$file" ] && continue
      "$bin" match --game "$game" --players champion,beginner --games 20 --seed $seed \
        --noise tournament --timing --jobs 1 > "$file.part"
      mv "$file.part" "$file"
    done
    continue
  fi
  matches=$(matches_of "$target")
  while read -r name game players games chunk; do
    play_match "$name" "$game" "$players" "$games" "$chunk"
  done <<< "$matches"
done
