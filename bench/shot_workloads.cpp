// The shot workloads of the speed comparisons (docs/performance.md), with
// their inputs cycled: 8-ball and 9-ball breaks (9 ft, cue stick 7.5 m/s,
// rack seeds 1 to 256) and random shots among 15 object balls (the 4096
// shots of bench/random_shots.hpp). Built only on the public API, so
// bench/compare.sh compiles this one file against an older commit's
// libraries and against the working tree's and runs the two side by side.
//
//   shot_workloads WORKLOAD time SECONDS   shots for about SECONDS; prints
//                                          "WORKLOAD ns/shot events/shot"
//   shot_workloads WORKLOAD count N        exactly N shots (for callgrind:
//                                          --toggle-collect=bs_run_shots)
//   shot_workloads WORKLOAD digest         one pass over the inputs; prints
//                                          a digest of every final table
//
// WORKLOAD: break8, break9, random15, gas, each as a new Simulation per shot;
// with "-rearm" (break8-rearm, ...) one Simulation re-armed for every shot
// (Simulation::reset), the way play_shots and the AI play them, where the
// library has it (BREAKSHOT_SIMULATION_RESET), else a new one per shot as
// before. "gas": scenes large enough for the cell grid (from 48 balls):
// ideal gases of 3000 disks for 30,000 events and gases of 1000 disks of the
// friction model to rest, four seeds each (compare.sh checks its digest).
// The digest (FNV-1a over the bits of
// every ball's final position, velocity, spin and motion state and the event count) is equal
// for two builds only if they give the same results.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "breakshot/physics.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "ideal_gas.hpp"
#include "random_shots.hpp"

namespace {

using breakshot::Scenario;

/// The workload without its "-rearm" suffix; `rearm` says whether it had one.
std::string base_name(const std::string& workload, bool* rearm) {
  const std::string suffix = "-rearm";
  *rearm = workload.size() > suffix.size() &&
           workload.compare(workload.size() - suffix.size(), suffix.size(), suffix) == 0;
  return *rearm ? workload.substr(0, workload.size() - suffix.size()) : workload;
}

std::vector<Scenario> inputs(const std::string& name) {
  const std::string workload = name;
  std::vector<Scenario> out;
  if (workload == "break8" || workload == "break9") {
    const char* game = workload == "break8" ? "eight_ball" : "nine_ball";
    for (std::uint64_t seed = 1; seed <= 256; ++seed) {
      out.push_back(breakshot::make_break_scenario(game, "9ft", seed, 7.5));
    }
  } else if (workload == "random15") {
    out = breakshot::bench::random_shots(4096);
  } else if (workload == "gas") {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      Scenario ideal = breakshot::bench::ideal_gas(3000, seed);
      ideal.max_events = 30000;  // never at rest: stopped by the event limit
      out.push_back(ideal);
      Scenario friction = breakshot::bench::ideal_gas(1000, seed + 100);
      friction.physics = breakshot::default_physics(breakshot::Model::friction);
      friction.physics.deceleration = 0.5;
      friction.until.rest = true;
      out.push_back(friction);
    }
  }
  return out;
}

struct Digest {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  void add(const void* data, std::size_t size) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash ^= b[i];
      hash *= 0x100000001b3ULL;
    }
  }
};

}  // namespace

/// Plays shots `first` .. `first + count - 1` of `shots` (cycled) to rest;
/// returns the events. Not inlined, so that callgrind can count it alone.
extern "C" __attribute__((noinline)) std::uint64_t bs_run_shots(const Scenario* shots,
                                                                std::size_t n, std::size_t first,
                                                                std::size_t count, bool rearm) {
  std::uint64_t events = 0;
#ifdef BREAKSHOT_SIMULATION_RESET
  if (rearm && count > 0) {
    breakshot::Simulation sim(shots[first % n]);
    for (std::size_t k = 0; k < count; ++k) {
      if (k > 0) sim.reset(shots[(first + k) % n]);
      sim.advance_to_rest();
      events += sim.event_count();
    }
    return events;
  }
#else
  (void)rearm;
#endif
  for (std::size_t k = 0; k < count; ++k) {
    breakshot::Simulation sim(shots[(first + k) % n]);
    sim.advance_to_rest();
    events += sim.event_count();
  }
  return events;
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: shot_workloads break8|break9|random15|gas time SECONDS|count N|digest\n");
    return 2;
  }
  const std::string workload = argv[1];
  const std::string mode = argv[2];
  bool rearm = false;
  const std::vector<Scenario> shots = inputs(base_name(workload, &rearm));
  if (shots.empty()) {
    std::fprintf(stderr,
                 "shot_workloads: unknown workload '%s' (break8, break9, random15, gas, each also "
                 "with -rearm)\n",
                 workload.c_str());
    return 2;
  }
  const std::size_t n = shots.size();
  if (mode == "digest") {
    Digest d;
    for (const Scenario& s : shots) {
      breakshot::Simulation sim(s);
      sim.advance_to_rest();
      const std::uint64_t events = sim.event_count();
      d.add(&events, sizeof events);
      for (const breakshot::BallState& b : sim.balls()) {
        d.add(&b.position, sizeof b.position);
        d.add(&b.velocity, sizeof b.velocity);
        d.add(&b.spin, sizeof b.spin);
        d.add(&b.state, sizeof b.state);
      }
    }
    std::printf("%s digest %016llx\n", workload.c_str(), static_cast<unsigned long long>(d.hash));
    return 0;
  }
  if (argc < 4) {
    std::fprintf(stderr, "shot_workloads: %s needs a number\n", mode.c_str());
    return 2;
  }
  const double arg = std::strtod(argv[3], nullptr);
  if (!(arg > 0.0)) {
    std::fprintf(stderr, "shot_workloads: '%s' is not a positive number\n", argv[3]);
    return 2;
  }
  if (mode == "count") {
    const auto count = static_cast<std::size_t>(arg);
    const std::uint64_t events = bs_run_shots(shots.data(), n, 0, count, rearm);
    std::printf("%s %zu shots %llu events\n", workload.c_str(), count,
                static_cast<unsigned long long>(events));
    return 0;
  }
  if (mode != "time") {
    std::fprintf(stderr, "shot_workloads: unknown mode '%s' (time, count, digest)\n", mode.c_str());
    return 2;
  }
  // Warm up with one pass, then time whole passes until the time is up.
  (void)bs_run_shots(shots.data(), n, 0, n, rearm);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  std::size_t done = 0;
  std::uint64_t events = 0;
  double seconds = 0.0;
  do {
    events += bs_run_shots(shots.data(), n, done, n, rearm);
    done += n;
    seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } while (seconds < arg);
  std::printf("%s %.1f ns/shot %.2f events/shot\n", workload.c_str(),
              seconds * 1e9 / static_cast<double>(done),
              static_cast<double>(events) / static_cast<double>(done));
  return 0;
}
