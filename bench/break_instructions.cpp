// A fixed amount of work for instruction counting (docs/performance.md):
// 200 breaks of the benchmark scene, so that
//
//   valgrind --tool=callgrind build/release/bench/break_instructions [nine_ball]
//
// reports instructions that, divided by 200, are the cost of one break,
// independent of machine load (plus a small fixed start-up cost).
#include <cstdio>
#include <string>

#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"

int main(int argc, char** argv) {
  const std::string game = argc > 1 ? argv[1] : "eight_ball";
  if (game != "eight_ball" && game != "nine_ball") {
    std::fprintf(stderr, "usage: break_instructions [eight_ball|nine_ball]\n");
    return 2;
  }
  const breakshot::Scenario s = breakshot::make_break_scenario(game, "9ft", 1, 7.5);
  constexpr int kBreaks = 200;
  std::size_t events = 0;
  for (int k = 0; k < kBreaks; ++k) {
    breakshot::Simulation sim(s);
    sim.advance_to_rest();
    events += sim.event_count();
  }
  std::printf("%d %s breaks, %zu events\n", kBreaks, game.c_str(), events);
  return 0;
}
