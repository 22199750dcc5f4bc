// A fixed amount of work for instruction counting (docs/performance.md):
// 200 breaks of the benchmark scene, so that
//
//   valgrind --tool=callgrind build/release/bench/break_instructions [nine_ball] [cycled] [airborne]
//
// reports instructions that, divided by 200, are the cost of one break,
// independent of machine load (plus a small fixed start-up cost).
// `cycled` racks with seeds 1 ... 200 instead of seed 1 every time;
// `airborne` turns physics.airborne on (nothing leaves the cloth on a
// level break: it measures the cost of the machinery alone).
#include <cstdint>
#include <cstdio>
#include <string>

#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"

int main(int argc, char** argv) {
  std::string game = "eight_ball";
  bool cycled = false;
  bool airborne = false;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "eight_ball" || arg == "nine_ball") {
      game = arg;
    } else if (arg == "cycled") {
      cycled = true;
    } else if (arg == "airborne") {
      airborne = true;
    } else {
      std::fprintf(stderr, "usage: break_instructions [eight_ball|nine_ball] [cycled] [airborne]\n");
      return 2;
    }
  }
  constexpr int kBreaks = 200;
  std::size_t events = 0;
  breakshot::Scenario one = breakshot::make_break_scenario(game, "9ft", 1, 7.5);
  one.physics.airborne = airborne;
  for (int k = 0; k < kBreaks; ++k) {
    // Cycled, each rack is built here (its cost is in the count, the same
    // for every build compared); else the one scene is reused.
    breakshot::Scenario s = one;
    if (cycled) {
      s = breakshot::make_break_scenario(game, "9ft", static_cast<std::uint64_t>(k + 1), 7.5);
      s.physics.airborne = airborne;
    }
    breakshot::Simulation sim(s);
    sim.advance_to_rest();
    events += sim.event_count();
  }
  std::printf("%d %s breaks, %zu events\n", kBreaks, game.c_str(), events);
  return 0;
}
