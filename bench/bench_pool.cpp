// Pool model: breaks and random shots (docs/performance.md).
//
//   build/release/bench/bench_pool --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// BM_Break/8 and /9: the examples/pool break scenes built in code (9 ft
// table, regulation rack with seed 1, cue ball on the head spot, cue
// stick at 7.5 m/s straight at the apex), run to rest.
// BM_RandomShot15: 15 object balls at random places, a cue ball and a
// random shot (speed 1-6 m/s, any direction, tip offsets up to 0.3 R),
// run to rest; a new layout and shot for each of 4096 cases, cycled.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"

using namespace breakshot;

namespace {

constexpr double kR = kPoolBallRadius;

double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

Scenario pool_scene() {
  Scenario s;
  s.physics = default_physics(Model::pool);
  s.table = make_pool_table("9ft");
  s.until.rest = true;
  return s;
}

void add(Scenario& s, const std::string& id, Vec2 p) {
  s.balls.push_back({id, kR, kPoolBallMass, CushionParams{}.restitution});
  BallState st;
  st.position = p;
  s.start.push_back(st);
}

void BM_Break(benchmark::State& state) {
  const Scenario s =
      make_break_scenario(state.range(0) == 8 ? "eight_ball" : "nine_ball", "9ft", 1, 7.5);
  std::uint64_t events = 0;
  for (auto _ : state) {
    Simulation sim(s);
    sim.advance_to_rest();
    events += sim.event_count();
    benchmark::DoNotOptimize(sim.events().data());
  }
  state.counters["events/break"] =
      static_cast<double>(events) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_Break)->Arg(8)->Arg(9)->Unit(benchmark::kMicrosecond);

std::vector<Scenario> random_shots(std::size_t count) {
  std::mt19937_64 g(2026);
  std::vector<Scenario> out;
  while (out.size() < count) {
    Scenario s = pool_scene();
    const double L = s.table.length, W = s.table.width;
    for (int k = 0; k < 16 * 50 && s.balls.size() < 16; ++k) {
      const Vec2 p{kR + (L - 2 * kR) * unit(g), kR + (W - 2 * kR) * unit(g)};
      bool free = wall_clearance(s.table, p, kR) > 1e-4;
      for (const BallState& b : s.start) free = free && norm(b.position - p) > 2 * kR + 1e-4;
      if (free) add(s, s.balls.empty() ? "cue" : std::to_string(s.balls.size()), p);
    }
    CueSpec cue;
    cue.ball = 0;
    cue.strike.speed = 1.0 + 5.0 * unit(g);
    cue.strike.phi = 360.0 * unit(g);
    cue.strike.a = 0.6 * unit(g) - 0.3;
    cue.strike.b = 0.6 * unit(g) - 0.3;
    s.cue = cue;
    out.push_back(std::move(s));
  }
  return out;
}

void BM_RandomShot15(benchmark::State& state) {
  const std::vector<Scenario> shots = random_shots(4096);
  std::size_t k = 0;
  std::uint64_t events = 0;
  for (auto _ : state) {
    Simulation sim(shots[k]);
    sim.advance_to_rest();
    events += sim.event_count();
    benchmark::DoNotOptimize(sim.events().data());
    k = (k + 1) % shots.size();
  }
  state.counters["shots/s"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                 benchmark::Counter::kIsRate);
  state.counters["events/shot"] =
      static_cast<double>(events) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RandomShot15)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
