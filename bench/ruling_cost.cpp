// Not a benchmark of the engine: what the rules' own ruling of a shot
// costs beside the shot itself (docs/experiments.md, 2026-11-27), the
// figure behind the AI's judge being the ruleset's ruling path
// (Rules::apply_events) rather than a copy of the rules.
//
//   build/release/bench/ruling_cost [--games N] [--reps R]
//
// For 8-ball, 9-ball and snooker: the shots of N baseline-against-baseline
// games (seed 3, tournament noise), each timed R times as a whole
// (Rules::apply with a re-armed workspace: the simulation and its ruling)
// and as its ruling alone (Rules::apply_events on the events the
// simulation gave, words included). Prints microseconds per shot.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"

using namespace breakshot;

int main(int argc, char** argv) {
  int games = 20;
  int reps = 5;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--games") {
      games = std::atoi(argv[i + 1]);
    } else if (a == "--reps") {
      reps = std::atoi(argv[i + 1]);
    } else {
      std::fprintf(stderr, "ruling_cost: usage: ruling_cost [--games N] [--reps R]\n");
      return 2;
    }
  }
  if (games < 1 || reps < 1 || argc % 2 == 0) {
    std::fprintf(stderr, "ruling_cost: usage: ruling_cost [--games N >= 1] [--reps R >= 1]\n");
    return 2;
  }
  std::printf("game        shots   apply (us)   ruling alone (us)   share\n");
  for (const GameType g : {GameType::eight_ball, GameType::nine_ball, GameType::snooker}) {
    MatchOptions opt;
    opt.game = g;
    opt.players = {"baseline", "baseline"};
    opt.games = games;
    opt.seed = 3;
    opt.noise = parse_noise("tournament");
    if (g == GameType::snooker) opt.table_size = "12ft";
    std::vector<GameRecord> records;
    (void)play_match(opt, [&](int, const GameRecord& r) { records.push_back(r); });
    struct Shot {
      GameState before;
      Shoot shot;
      Outcome outcome;
    };
    std::vector<Shot> shots;
    const Rules rules(records.front().config);
    for (const GameRecord& r : records) {
      GameState s = r.start;
      for (const RecordedAction& ra : r.actions) {
        if (const auto* sh = std::get_if<Shoot>(&ra.action)) {
          shots.push_back({s, *sh, rules.apply(s, ra.action)});
        }
        s = ra.after;
      }
    }
    ShotWorkspace work;
    long sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < reps; ++k) {
      for (const Shot& x : shots) sink += rules.apply(x.before, Action{x.shot}, work).state.shots;
    }
    const auto t1 = std::chrono::steady_clock::now();
    for (int k = 0; k < reps; ++k) {
      for (const Shot& x : shots) {
        sink += rules
                    .apply_events(x.before, x.shot, x.outcome.events, x.outcome.state.position,
                                  x.outcome.facts.miscue)
                    .state.shots;
      }
    }
    const auto t2 = std::chrono::steady_clock::now();
    const double n = static_cast<double>(reps) * static_cast<double>(shots.size());
    const double whole = std::chrono::duration<double>(t1 - t0).count() / n * 1e6;
    const double ruling = std::chrono::duration<double>(t2 - t1).count() / n * 1e6;
    std::printf("%-10s %6zu   %10.2f   %17.2f   %4.1f %%\n", std::string(to_string(g)).c_str(),
                shots.size(), whole, ruling, 100.0 * ruling / whole);
    if (sink == 0) std::printf(" ");
  }
  return 0;
}
