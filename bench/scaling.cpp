// How the cost grows with the work (docs/performance.md, "Scaling"):
// prints CSV that bench/plot_scaling.py draws as SVG.
//
//   scaling gas N              the lab's ideal gas of N disks: one CSV line
//                              "balls,events,seconds,events_per_second,
//                              bytes_per_ball,bytes_per_ball_without_events,
//                              peak_rss_mib" (set-up excluded from the
//                              time; bytes counted by this program's
//                              operator new)
//   scaling gas N --still K    the same with K of the balls, spread
//                              through the box, hardly moving (1 um/s)
//   scaling breaks             a triangle rack of 3 .. 28 balls on a 9 ft
//                              table, struck at 7.5 m/s (pool model, ball
//                              clusters), then the 9-ball, 8-ball and
//                              snooker breaks of the games (their racks
//                              and tables, 7.5 m/s): microseconds and
//                              events per break, racks cycled (64 seeds)
//   scaling threads [MAX]      random 15-ball shots per second through
//                              play_shots, and 9-ball baseline games per
//                              minute through play_match --jobs, on 1 ..
//                              MAX (default: the cores) threads
//
// The gas: disks of radius 1 cm at area fraction 0.3 in a square box,
// random directions at 1 m/s (bench_events' BM_IdealGas); each size runs
// max(200000, 4 N) events.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "breakshot/batch.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/players.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "ideal_gas.hpp"
#include "random_shots.hpp"

// Every allocation of the program is counted (a header before each block
// keeps its size), so that memory per ball is the engine's own, to the
// byte, whatever the allocator keeps resident.
namespace {
std::size_t g_live = 0;
std::size_t g_peak = 0;
constexpr std::size_t kHeader = 16;
}  // namespace

void* operator new(std::size_t size) {
  auto* p = static_cast<unsigned char*>(std::malloc(size + kHeader));
  if (!p) throw std::bad_alloc();
  *reinterpret_cast<std::size_t*>(p) = size;
  g_live += size;
  g_peak = std::max(g_peak, g_live);
  return p + kHeader;
}
void operator delete(void* q) noexcept {
  if (!q) return;
  auto* p = static_cast<unsigned char*>(q) - kHeader;
  g_live -= *reinterpret_cast<std::size_t*>(p);
  std::free(p);
}
void operator delete(void* q, std::size_t) noexcept { operator delete(q); }

namespace {

using namespace breakshot;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

/// The peak resident memory of the process so far, in bytes.
double peak_resident_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return 1024.0 * static_cast<double>(u.ru_maxrss);
}

/// One size of the gas, in a process of its own: memory is the peak of
/// the bytes allocated (scenario, simulation, events) less what was
/// allocated before, per ball; the process's peak resident set is printed
/// too.
int gas(long n, long still) {
  if (n < 2) {
    std::fprintf(stderr, "scaling gas: at least 2 balls\n");
    return 2;
  }
  if (still < 0 || still > n) {
    std::fprintf(stderr, "scaling gas: --still must be between 0 and the number of balls\n");
    return 2;
  }
  // Events are kept (Simulation::events): they are part of the memory a
  // run needs, and grow with the events asked for, not the balls.
  const std::size_t before = g_live;
  g_peak = g_live;
  Scenario s = bench::ideal_gas(n, 7);
  // Balls spread through the box that hardly move (1 um/s): their next
  // events lie ages away, a test of how the event queue copes.
  for (long k = 0; k < still; ++k) {
    s.start[static_cast<std::size_t>(k * (n / still))].velocity = {1e-6, 0.0};
  }
  Simulation sim(std::move(s));
  const std::uint64_t want = std::max<std::uint64_t>(200000, 4 * static_cast<std::uint64_t>(n));
  const std::uint64_t start_events = sim.event_count();
  const auto t0 = Clock::now();
  // Advance in slices of time until enough events have been taken.
  double t = 0.0;
  while (sim.event_count() - start_events < want) {
    t += 1e-3;
    sim.advance_to(t);
  }
  const double secs = seconds_since(t0);
  const double events = static_cast<double>(sim.event_count() - start_events);
  const double per_ball = static_cast<double>(g_peak - before) / static_cast<double>(n);
  const double events_bytes =
      static_cast<double>(sim.events().capacity() * sizeof(Event)) / static_cast<double>(n);
  std::printf("%ld,%.0f,%.3f,%.0f,%.0f,%.0f,%.0f\n", n, events, secs, events / secs, per_ball,
              per_ball - events_bytes, peak_resident_bytes() / 1048576.0);
  return 0;
}

/// A triangle of `rows` rows (rows (rows + 1) / 2 balls) with its apex on
/// the foot spot of a 9 ft table, gaps of up to 0.1 mm drawn from `seed`,
/// and the cue ball on the head spot struck straight at the apex.
Scenario triangle_break(int rows, std::uint64_t seed) {
  Scenario s;
  s.physics = default_physics(Model::pool);
  s.physics.ball_clusters = true;
  s.table = make_pool_table("9ft");
  const double R = kPoolBallRadius;
  const double e = s.table.cushion.restitution;
  std::mt19937_64 g(seed);
  auto add = [&](const std::string& id, Vec2 p) {
    s.balls.push_back(BallSpec{id, R, kPoolBallMass, e});
    BallState st;
    st.position = p;
    s.start.push_back(st);
  };
  add("cue", s.table.head_spot);
  const double d = 2 * R + 5e-5;
  int id = 1;
  for (int row = 0; row < rows; ++row) {
    for (int k = 0; k <= row; ++k) {
      const Vec2 jitter{2.5e-5 * unit(g), 2.5e-5 * (2 * unit(g) - 1)};
      add(std::to_string(id++),
          s.table.foot_spot + Vec2{row * d * std::sqrt(3.0) / 2, (k - row / 2.0) * d} + jitter);
    }
  }
  CueSpec cue;
  cue.ball = 0;
  cue.strike.speed = 7.5;
  cue.strike.phi = 0.0;
  s.cue = cue;
  return s;
}

// Microseconds and events per break over 64 racks, cycled: a warm-up
// pass, then whole passes for at least a second.
void time_breaks(const char* rack, int balls, const std::vector<Scenario>& racks) {
  std::uint64_t events = 0;
  for (const Scenario& r : racks) {
    Simulation sim(r);
    sim.advance_to_rest();
  }
  std::size_t done = 0;
  const auto t0 = Clock::now();
  double secs = 0.0;
  do {
    for (const Scenario& r : racks) {
      Simulation sim(r);
      sim.advance_to_rest();
      events += sim.event_count();
    }
    done += racks.size();
    secs = seconds_since(t0);
  } while (secs < 1.0);
  std::printf("%s,%d,%.1f,%.1f\n", rack, balls, secs * 1e6 / static_cast<double>(done),
              static_cast<double>(events) / static_cast<double>(done));
  std::fflush(stdout);
}

int breaks() {
  std::printf("rack,balls,us_per_break,events_per_break\n");
  for (int rows = 2; rows <= 7; ++rows) {
    std::vector<Scenario> racks;
    for (std::uint64_t seed = 1; seed <= 64; ++seed) racks.push_back(triangle_break(rows, seed));
    time_breaks("triangle", rows * (rows + 1) / 2, racks);
  }
  // The games' own breaks (make_break_scenario: their racks and tables,
  // the cue ball at 7.5 m/s as above; snooker's break-off takes the end
  // of the back row of reds, on the 12 ft table).
  struct Game {
    const char* name;
    const char* size;
    int balls;
  };
  for (const Game& game : {Game{"nine_ball", "9ft", 9}, Game{"eight_ball", "9ft", 15},
                           Game{"snooker", "12ft", 21}}) {
    std::vector<Scenario> racks;
    for (std::uint64_t seed = 1; seed <= 64; ++seed) {
      racks.push_back(make_break_scenario(game.name, game.size, seed, 7.5));
    }
    time_breaks(game.name, game.balls, racks);
  }
  return 0;
}

int threads(int max_threads) {
  // The layouts without their strikes; play_shots gives each its strike.
  std::vector<Scenario> shots = bench::random_shots(4096);
  std::vector<const Scenario*> ptrs;
  std::vector<CueStrike> strikes;
  for (Scenario& s : shots) {
    strikes.push_back(s.cue->strike);
    s.cue.reset();
    ptrs.push_back(&s);
  }
  std::printf("threads,shots_per_second,games_per_minute\n");
  for (int t = 1; t <= max_threads; ++t) {
    ShotBatchOptions o;
    o.threads = static_cast<unsigned>(t);
    (void)play_shots(ptrs, strikes, o);  // warm up
    std::size_t done = 0;
    const auto t0 = Clock::now();
    double secs = 0.0;
    do {
      (void)play_shots(ptrs, strikes, o);
      done += shots.size();
      secs = seconds_since(t0);
    } while (secs < 2.0);
    const double shots_per_second = static_cast<double>(done) / secs;

    MatchOptions m;
    m.game = GameType::nine_ball;
    m.players = {"baseline", "baseline"};
    m.games = 400;
    m.seed = 5;
    m.noise = parse_noise("tournament");
    m.jobs = t;
    const auto g0 = Clock::now();
    (void)play_match(m);
    const double games_per_minute = 60.0 * m.games / seconds_since(g0);
    std::printf("%d,%.0f,%.0f\n", t, shots_per_second, games_per_minute);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string what = argc > 1 ? argv[1] : "";
  if (what == "gas" && argc > 2) {
    const bool still = argc > 4 && std::string(argv[3]) == "--still";
    if (argc > 3 && !still) {
      std::fprintf(stderr, "scaling gas: unknown option %s (--still K)\n", argv[3]);
      return 2;
    }
    char* end = nullptr;
    const long k = still ? std::strtol(argv[4], &end, 10) : 0;
    if (still && (end == argv[4] || *end != '\0')) {
      std::fprintf(stderr, "scaling gas: --still needs a whole number, not '%s'\n", argv[4]);
      return 2;
    }
    return gas(std::atol(argv[2]), k);
  }
  if (what == "breaks") return breaks();
  if (what == "threads") {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return threads(argc > 2 ? std::max(1, std::atoi(argv[2])) : cores);
  }
  std::fprintf(stderr, "usage: scaling gas BALLS [--still K] | breaks | threads [MAX_THREADS]\n");
  return 2;
}
