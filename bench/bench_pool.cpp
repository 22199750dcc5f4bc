// Pool model: breaks and random shots (docs/performance.md).
//
//   build/release/bench/bench_pool --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
//
// BM_Break/8 and /9: the examples/pool break scenes built in code (9 ft
// table, regulation rack, cue ball on the head spot, cue stick at 7.5 m/s
// straight at the apex), run to rest; the racks of seeds 1 to 256 cycled,
// as bench/compare.sh's break8 and break9, so that one rack's luck is not
// the figure.
// BM_RandomShot15: 15 object balls at random places, a cue ball and a
// random shot (speed 1-6 m/s, any direction, tip offsets up to 0.3 R),
// run to rest; a new layout and shot for each of 4096 cases, cycled
// (bench/random_shots.hpp; export_random_shots writes them as JSON).
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "random_shots.hpp"

using namespace breakshot;

namespace {

using bench::random_shots;

constexpr std::uint64_t kRacks = 256;

void BM_Break(benchmark::State& state) {
  std::vector<Scenario> racks;
  for (std::uint64_t seed = 1; seed <= kRacks; ++seed) {
    racks.push_back(
        make_break_scenario(state.range(0) == 8 ? "eight_ball" : "nine_ball", "9ft", seed, 7.5));
  }
  std::size_t k = 0;
  std::uint64_t events = 0;
  for (auto _ : state) {
    Simulation sim(racks[k]);
    sim.advance_to_rest();
    events += sim.event_count();
    benchmark::DoNotOptimize(sim.events().data());
    k = (k + 1) % racks.size();
  }
  state.counters["events/break"] =
      static_cast<double>(events) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_Break)->Arg(8)->Arg(9)->Unit(benchmark::kMicrosecond);

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
