// Not a benchmark of Google Benchmark's kind: the cost of the C API
// (include/breakshot.h, libbreakshot.so) over the C++ call, side by side
// (docs/c-api.md, "Cost"; docs/performance.md):
//
//   random15  bs_simulate on random shots among 15 object balls (the
//             shots of bench/random_shots.hpp) against simulate()
//   break8    8-ball breaks, racks 1 to 64 cycled, against simulate()
//   frame     bs_simulation_states_at for the 16 balls of a break at
//             random times of it: one 60 fps frame's query
//
// Each round times every shot through the C++ calls and through the C API
// (the scenarios are built beforehand in both: a C++ Scenario and a
// BsScenario of the same shot): simulate(), the run with its record
// (src/physics/run_record.hpp: what the first states query of a
// simulation runs, so that the states at any time can be read back), and
// bs_simulate with bs_simulation_free.
// The figures are medians over the rounds. bs_simulate keeps no record;
// the first bs_simulation_states_at on a simulation makes it, by running
// the shot again recorded: each round also times bs_simulate with that
// first query (a shot drawn), against simulate() run right after it.
// Before timing, every shot's result through the C API is checked to be
// write_result(simulate())'s bytes.
//
// capi_overhead calls the shared library (libbreakshot.so), whose copy of
// the engine is not the one this program's C++ calls run;
// capi_overhead_static links the static library (libbreakshot_c.a) alone,
// so that the C API and the C++ calls run the same machine code, and also
// times simulate() on the Scenario objects the C API itself read from its
// calls (capi/capi.hpp's scenario_of), so that only the call differs.
//
//   capi_overhead [ROUNDS]          (default 11)
//   capi_overhead_static [ROUNDS]

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "breakshot.h"
#include "breakshot/rack.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "physics/run_record.hpp"
#include "random_shots.hpp"
#if defined(BREAKSHOT_CAPI_OVERHEAD_STATIC)
#include "capi.hpp"
#endif

namespace bs = breakshot;

namespace {

// The thread's CPU time: the machine is shared, and time spent
// descheduled is not the call's.
struct Clock {
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<Clock, duration>;
  static time_point now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return time_point(duration(std::int64_t{ts.tv_sec} * 1'000'000'000 + ts.tv_nsec));
  }
};

void must(BsStatus st, const void* handle, const char* what) {
  if (st != BS_OK) {
    std::fprintf(stderr, "capi_overhead: %s: %s: %s\n", what, bs_status_name(st),
                 bs_error_message(handle));
    std::exit(1);
  }
}

/// The same shot through the C API's calls: pool physics (ball clusters
/// as the scenario has them), the 9 ft table, each ball with its own
/// radius, mass and restitution, the cue strike.
BsScenario* to_c(const bs::Scenario& s) {
  BsScenario* c = nullptr;
  must(bs_scenario_new(&c), nullptr, "bs_scenario_new");
  BsPhysics p;
  must(bs_physics_default(BS_MODEL_POOL, &p), nullptr, "bs_physics_default");
  p.ball_clusters = s.physics.ball_clusters ? 1 : 0;
  must(bs_scenario_set_physics(c, &p), c, "bs_scenario_set_physics");
  BsTable t;
  must(bs_table_default(BS_TABLE_POOL, &t), nullptr, "bs_table_default");
  t.size = "9ft";
  must(bs_scenario_set_table(c, &t), c, "bs_scenario_set_table");
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    BsBall b;
    must(bs_ball_default(&b), nullptr, "bs_ball_default");
    b.id = s.balls[i].id.c_str();
    b.position[0] = s.start[i].position.x;
    b.position[1] = s.start[i].position.y;
    b.radius = s.balls[i].radius;
    b.mass = s.balls[i].mass;
    b.wall_restitution = s.balls[i].wall_restitution;
    must(bs_scenario_add_ball(c, &b, nullptr), c, "bs_scenario_add_ball");
  }
  const bs::CueStrike& k = s.cue->strike;
  const BsStrike strike{k.speed, k.phi, k.theta, k.a, k.b};
  must(bs_scenario_strike(c, s.balls[static_cast<std::size_t>(s.cue->ball)].id.c_str(), &strike), c,
       "bs_scenario_strike");
  must(bs_scenario_validate(c), c, "bs_scenario_validate");
  return c;
}

void check_identical(const std::vector<bs::Scenario>& cpp, const std::vector<BsScenario*>& c) {
  for (std::size_t k = 0; k < cpp.size(); ++k) {
    BsSimulation* sim = nullptr;
    must(bs_simulate(c[k], &sim), c[k], "bs_simulate");
    char* text = nullptr;
    must(bs_simulation_result_json(sim, &text), sim, "bs_simulation_result_json");
    if (bs::write_result(cpp[k], bs::simulate(cpp[k])) != text) {
      std::fprintf(stderr, "capi_overhead: shot %zu differs between the C API and C++\n", k);
      std::exit(1);
    }
    bs_string_free(text);
    bs_simulation_free(sim);
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

volatile std::size_t g_sink = 0;

void compare(const char* name, const std::vector<bs::Scenario>& cpp, int rounds) {
  std::vector<BsScenario*> c;
  for (const bs::Scenario& s : cpp) c.push_back(to_c(s));
  check_identical(cpp, c);
  // Each round runs the three in the order A B C C B A, so that a drift
  // of the machine's speed within a round falls on all three alike; the
  // ratios are taken within each round, then their median.
  std::vector<double> t_cpp, t_rec, t_c, r_cpp, r_rec;
  const double n = 2.0 * static_cast<double>(cpp.size());
  const auto run_cpp = [&] {
    const auto t0 = Clock::now();
    for (const bs::Scenario& s : cpp) g_sink = g_sink + bs::simulate(s).events.size();
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  };
#if defined(BREAKSHOT_CAPI_OVERHEAD_STATIC)
  // simulate() on the very Scenario objects that bs_simulate runs (the
  // ones the C API read from its calls): only the call differs.
  const auto run_same = [&] {
    const auto t0 = Clock::now();
    for (BsScenario* s : c) g_sink = g_sink + bs::simulate(capi::scenario_of(*s)).events.size();
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  };
#endif
  const auto run_rec = [&] {
    const auto t0 = Clock::now();
    for (const bs::Scenario& s : cpp) {
      bs::detail::RunRecord record;
      g_sink = g_sink + bs::detail::simulate_recorded(s, record).events.size();
    }
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  };
  const auto run_c = [&] {
    const auto t0 = Clock::now();
    for (BsScenario* s : c) {
      BsSimulation* sim = nullptr;
      must(bs_simulate(s, &sim), s, "bs_simulate");
      BsSimulationInfo info;
      must(bs_simulation_info(sim, &info), sim, "bs_simulation_info");
      g_sink = g_sink + info.events;
      bs_simulation_free(sim);
    }
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  };
  // A shot drawn: bs_simulate, then the first states query, which
  // records the run (src/physics/run_record.hpp) by running it again.
  const auto run_drawn = [&] {
    std::vector<BsBallState> states;
    const auto t0 = Clock::now();
    for (BsScenario* s : c) {
      BsSimulation* sim = nullptr;
      must(bs_simulate(s, &sim), s, "bs_simulate");
      BsSimulationInfo info;
      must(bs_simulation_info(sim, &info), sim, "bs_simulation_info");
      states.resize(info.balls);
      must(bs_simulation_states_at(sim, 0.0, states.data(), states.size()), sim,
           "bs_simulation_states_at");
      g_sink = g_sink + static_cast<std::size_t>(states[0].motion);
      bs_simulation_free(sim);
    }
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  };
  std::vector<double> t_drawn, r_drawn, t_same, r_same;
  for (int r = 0; r < rounds; ++r) {
    double a = run_cpp(), b = run_rec(), x = run_c();
#if defined(BREAKSHOT_CAPI_OVERHEAD_STATIC)
    const double y = run_same() + run_same();
#endif
    x += run_c();
#if defined(BREAKSHOT_CAPI_OVERHEAD_STATIC)
    t_same.push_back(y / n);
    r_same.push_back(x / y);
#endif
    b += run_rec();
    a += run_cpp();
    t_cpp.push_back(a / n);
    t_rec.push_back(b / n);
    t_c.push_back(x / n);
    r_cpp.push_back(x / a);
    r_rec.push_back(x / b);
    const double d = run_drawn(), a2 = run_cpp();
    t_drawn.push_back(d / (0.5 * n));
    r_drawn.push_back(d / a2);
  }
  std::printf(
      "%-9s %4zu shots x %d rounds (median us/shot): C++ simulate() %7.1f, C++ recorded "
      "%7.1f, C API bs_simulate %7.1f; median ratio C API / simulate() %.3f, "
      "C API / recorded %.3f\n",
      name, cpp.size(), rounds, median(t_cpp), median(t_rec), median(t_c), median(r_cpp),
      median(r_rec));
#if defined(BREAKSHOT_CAPI_OVERHEAD_STATIC)
  std::printf(
      "%-9s C++ simulate() of the C API's own scenarios (median us/shot) %7.1f; median ratio "
      "C API / that %.3f\n",
      name, median(t_same), median(r_same));
#endif
  std::printf(
      "%-9s first states query too (bs_simulate + bs_simulation_states_at, median us/shot): "
      "%7.1f; median ratio to simulate() %.3f\n",
      name, median(t_drawn), median(r_drawn));
  for (BsScenario* s : c) bs_scenario_free(s);
}

void frame_cost(int rounds) {
  BsScenario* s = to_c(bs::make_break_scenario("eight_ball", "9ft", 1, 7.5));
  BsSimulation* sim = nullptr;
  must(bs_simulate(s, &sim), s, "bs_simulate");
  BsSimulationInfo info;
  must(bs_simulation_info(sim, &info), sim, "bs_simulation_info");
  std::mt19937_64 g(7);
  std::vector<double> times(100000);
  for (double& t : times) t = info.end_time * static_cast<double>(g() >> 11) * 0x1.0p-53;
  BsBallState states[16];
  std::vector<double> per;
  for (int r = 0; r < rounds; ++r) {
    auto t0 = Clock::now();
    for (const double t : times) {
      must(bs_simulation_states_at(sim, t, states, 16), sim, "bs_simulation_states_at");
      g_sink = g_sink + static_cast<std::size_t>(states[5].motion);
    }
    auto t1 = Clock::now();
    per.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count() /
                  static_cast<double>(times.size()));
  }
  std::printf(
      "frame     16 balls of an 8-ball break (%zu events), %zu random times x %d rounds: "
      "%.3f us per bs_simulation_states_at\n",
      info.events, times.size(), rounds, median(per));
  bs_simulation_free(sim);
  bs_scenario_free(s);
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 11;
#if defined(BREAKSHOT_CAPI_OVERHEAD_STATIC)
  std::printf("the C API from libbreakshot_c.a: both sides run the same copy of the engine\n");
#else
  std::printf("the C API from libbreakshot.so: the C++ side runs this program's copy of the engine\n");
#endif
  std::vector<bs::Scenario> breaks;
  for (std::uint64_t seed = 1; seed <= 64; ++seed) {
    breaks.push_back(bs::make_break_scenario("eight_ball", "9ft", seed, 7.5));
  }
  compare("random15", bs::bench::random_shots(256), rounds);
  compare("break8", breaks, rounds);
  frame_cost(rounds);
  return 0;
}
