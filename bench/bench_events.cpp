// Events per second of the event loop (docs/performance.md records the
// figures and how to reproduce them).
//
//   build/release/bench/bench_events --benchmark_min_time=2
//
// BM_IdealGas/N: N equal disks in a square box at area fraction 0.3, with
// random velocities: a mix of ball-ball and wall events, and cell
// crossings once N is large enough for the cell grid.
// BM_FrictionBreak: a 15-ball triangle hit by a cue ball at 8 m/s on a
// 9 ft playing surface, friction model, run to rest.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "ideal_gas.hpp"

using namespace breakshot;

namespace {

Scenario friction_break() {
  Scenario s;
  s.physics = default_physics(Model::friction);
  s.physics.deceleration = 0.2;  // a faster-stopping cloth than the default
  s.physics.ball_ball_restitution = kPoolBallBallRestitution;
  const double L = 2.54, W = 1.27, R = kPoolBallRadius;
  s.table = make_rectangle({0, 0}, {L, W});
  auto add = [&](const std::string& id, Vec2 p, Vec2 v) {
    BallSpec b{id, R, kPoolBallMass, 0.75};
    BallState st;
    st.position = p;
    st.velocity = v;
    st.state = v == Vec2{} ? MotionState::stationary : MotionState::moving;
    s.balls.push_back(b);
    s.start.push_back(st);
  };
  add("cue", {L / 4, W / 2 + 0.01}, {8.0, 0.0});
  // Frozen rack with 0.1 mm gaps, apex on the foot spot.
  const double d = 2 * R + 1e-4;
  int id = 1;
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      add(std::to_string(id++), {3 * L / 4 + row * d * std::sqrt(3.0) / 2, W / 2 + (k - row / 2.0) * d}, {});
    }
  }
  s.until.rest = true;
  return s;
}

void BM_IdealGas(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Scenario s = bench::ideal_gas(n, 42);
  // Enough events per iteration that set-up is negligible and the gas is
  // well mixed.
  const std::uint64_t events = n <= 16 ? 200000 : 500000;
  s.max_events = events;
  std::uint64_t total = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Simulation sim(s);
    state.ResumeTiming();
    sim.advance_to(1e300);
    total += sim.event_count();
    benchmark::DoNotOptimize(sim.events().data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(total));
  state.counters["events/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_IdealGas)->Arg(2)->Arg(16)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_FrictionBreak(benchmark::State& state) {
  const Scenario s = friction_break();
  std::uint64_t total = 0;
  for (auto _ : state) {
    Simulation sim(s);
    sim.advance_to_rest();
    total += sim.event_count();
    benchmark::DoNotOptimize(sim.events().data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(total));
  state.counters["events/break"] =
      static_cast<double>(total) / static_cast<double>(state.iterations());
  state.counters["events/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FrictionBreak)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
