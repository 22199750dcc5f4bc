// The soak: many random shots across the models, tables and games, each
// checked at every event (docs/performance.md, "Soak"). A benchmark, not a
// test; scripts/test.sh runs a short one.
//
//   soak [--shots N] [--seed S] [--threads T] [--out FILE] [--from K]
//        [--inject nan|off-table|overlap|energy]
//
// Shot k (k = from .. from + N - 1, default 0 .. 10^7 - 1) is drawn from
// mix_seed(S, k) alone, in one of eight kinds (k % 8): random pool shots
// (three kinds: 1-15 object balls on a 7, 8 or 9 ft table, any strike,
// raised cues among them), 8-ball and 9-ball breaks, snooker (the break or
// a random layout), three-cushion (three balls at random), a gas of the
// ideal model and one of the friction model in a rectangle. At every event
// the soak checks that
//
//   - every ball's position, velocity, spin and height are finite;
//   - every ball on the cloth is on the table (inside the table's bounding
//     box of reachable centres) or pocketed or off the table;
//   - no two balls in play overlap by more than 1e-9 m (in three
//     dimensions when one is in the air);
//   - the energy (kinetic, rotational and, in flight, potential) has not
//     risen since the previous event beyond 1e-9 of itself and what the
//     model allows: a pressed pair is pushed apart at physics.collapse_speed
//     (docs/physics-core.md), m v^2 per ball at most.
//
// It prints the totals (shots and events by kind, a digest of every final
// table, equal for two builds only if they give the same results,
// violations by check,
// shots per second of wall clock and per second of CPU, which is per core)
// and, for the first
// violating shot (the lowest k), the violation and its scenario written
// as FILE (default soak-violation.json), which `breakshot simulate FILE`
// reproduces: the soak reads the file back and checks that it gives the
// same violation. --inject corrupts what the checks see at the first event
// of every shot (a NaN velocity, a ball off the table, two balls in one
// place, more energy), to show that each check fails when it should
// (scripts/test.sh runs each). Exit status: 0 no violation, 1 a violation, 2 bad
// arguments.
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "breakshot/carom.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"

namespace {

using namespace breakshot;

constexpr int kKinds = 8;
constexpr std::array<const char*, kKinds> kKindNames{
    "pool 1-5 balls", "pool 6-15 balls", "pool raised cue", "8/9-ball break",
    "snooker",        "three-cushion",   "ideal gas",       "friction gas"};
constexpr std::array<const char*, 4> kCheckNames{"not finite", "off the table", "overlap",
                                                 "energy rose"};
constexpr std::array<const char*, 4> kInjectNames{"nan", "off-table", "overlap", "energy"};

/// Draws from one shot's seed.
struct Draw {
  std::uint64_t seed;
  std::uint64_t k = 0;
  double unit() { return static_cast<double>(mix_seed(seed, k++) >> 11) * 0x1.0p-53; }
  double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
  int whole(int lo, int hi) {  // lo .. hi inclusive
    return std::min(hi, lo + static_cast<int>(unit() * (hi - lo + 1)));
  }
};

/// A shot and how to write its table as JSON.
struct Shot {
  int kind = 0;
  bool valid = true;
  Scenario scenario;
  std::string table_json;
};

std::string num(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string vec2(Vec2 v) { return "[" + num(v.x) + ", " + num(v.y) + "]"; }

/// The scenario as a file `breakshot simulate` reads (docs/contract.md):
/// every ball with its radius, mass and wall restitution, the physics
/// model with the clusters and airborne switches, the cue.
std::string scenario_json(const Shot& shot) {
  const Scenario& s = shot.scenario;
  std::string o = "{\n  \"physics\": {\"model\": \"";
  o += s.physics.model == Model::ideal      ? "ideal"
       : s.physics.model == Model::friction ? "friction"
                                            : "pool";
  o += "\"";
  if (s.physics.ball_clusters) o += ", \"ball_clusters\": true";
  if (s.physics.model == Model::pool)
    o += std::string(", \"airborne\": ") + (s.physics.airborne ? "true" : "false");
  if (s.physics.model == Model::friction) o += ", \"deceleration\": " + num(s.physics.deceleration);
  o += "},\n  \"table\": " + shot.table_json + ",\n  \"balls\": [\n";
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const BallSpec& b = s.balls[i];
    const BallState& st = s.start[i];
    o += "    {\"id\": \"" + b.id + "\", \"position\": " + vec2(st.position) +
         ", \"velocity\": " + vec2(st.velocity) + ", \"radius\": " + num(b.radius) +
         ", \"mass\": " + num(b.mass) + ", \"wall_restitution\": " + num(b.wall_restitution) + "}";
    o += i + 1 < s.balls.size() ? ",\n" : "\n";
  }
  o += "  ]";
  if (s.cue) {
    const CueStrike& c = s.cue->strike;
    o += ",\n  \"cue\": {\"ball\": \"" + s.balls[static_cast<std::size_t>(s.cue->ball)].id +
         "\", \"speed\": " + num(c.speed) + ", \"phi\": " + num(c.phi) +
         ", \"theta\": " + num(c.theta) + ", \"a\": " + num(c.a) + ", \"b\": " + num(c.b) + "}";
  }
  if (s.until.rest) {
    o += ",\n  \"until\": \"rest\"";
  } else {
    o += ",\n  \"until\": {\"time\": " + num(s.until.time) + "}";
  }
  o += ",\n  \"max_events\": " + std::to_string(s.max_events) + "\n}\n";
  return o;
}

void add_ball(Scenario& s, const std::string& id, double r, double m, Vec2 p, Vec2 v = {}) {
  BallSpec b{id, r, m, 1.0};
  s.balls.push_back(b);
  BallState st;
  st.position = p;
  st.velocity = v;
  st.state = (v.x != 0.0 || v.y != 0.0) ? MotionState::moving : MotionState::stationary;
  s.start.push_back(st);
}

/// Up to `count` balls of radius r at random places on the table, clear
/// of the cushions and of each other; ball 0 is "cue".
void scatter(Scenario& s, Draw& d, int count, double r, double m,
             const std::vector<std::string>& ids) {
  const Table& t = s.table;
  for (int tries = 0; tries < 60 * count && static_cast<int>(s.balls.size()) < count; ++tries) {
    const Vec2 p{d.range(t.min.x + r, t.max.x - r), d.range(t.min.y + r, t.max.y - r)};
    if (wall_clearance(t, p, r) <= 1e-4) continue;
    bool free = true;
    for (const Pocket& pk : t.pockets) free = free && norm(p - pk.centre) > pk.radius + r;
    for (const BallState& b : s.start) free = free && norm(b.position - p) > 2.0 * r + 1e-4;
    if (free) add_ball(s, ids[s.balls.size()], r, m, p);
  }
}

/// A random strike on ball `cue`; raised: an elevation of up to 30 degrees.
void strike(Scenario& s, Draw& d, std::int32_t cue, bool raised) {
  CueSpec c;
  c.ball = cue;
  c.strike.speed = d.range(0.3, 8.0);
  c.strike.phi = d.range(0.0, 360.0);
  c.strike.theta = raised ? d.range(0.0, 30.0) : 0.0;
  c.strike.a = d.range(-0.45, 0.45);
  c.strike.b = d.range(-0.45, 0.45);
  s.cue = c;
}

/// The wall restitution the reader gives a ball without one: the pool
/// model's cushion law's own, else 1.
void default_walls(Scenario& s) {
  const double e = s.physics.model == Model::pool ? s.table.cushion.restitution : 1.0;
  for (BallSpec& b : s.balls) b.wall_restitution = e;
}

Shot make_shot_from(std::uint64_t draw_seed, std::uint64_t k) {
  Draw d{draw_seed};
  Shot shot;
  shot.kind = static_cast<int>(k % kKinds);
  Scenario& s = shot.scenario;
  std::vector<std::string> ids{"cue"};
  for (int i = 1; i <= 64; ++i) ids.push_back("b" + std::to_string(i));
  switch (shot.kind) {
    case 0:
    case 1:
    case 2: {
      static constexpr std::array<const char*, 3> kSizes{"7ft", "8ft", "9ft"};
      const char* size = kSizes[static_cast<std::size_t>(d.whole(0, 2))];
      s.physics = default_physics(Model::pool);
      s.table = make_pool_table(size);
      shot.table_json = std::string("{\"shape\": \"pool\", \"size\": \"") + size + "\"}";
      const int balls = shot.kind == 0   ? d.whole(2, 6)
                        : shot.kind == 1 ? d.whole(7, 16)
                                         : d.whole(2, 16);
      scatter(s, d, balls, kPoolBallRadius, kPoolBallMass, ids);
      default_walls(s);
      strike(s, d, 0, shot.kind == 2);
      break;
    }
    case 3: {
      const bool eight = d.unit() < 0.5;
      s = make_break_scenario(eight ? "eight_ball" : "nine_ball", "9ft", mix_seed(d.seed, 99),
                              d.range(3.0, 11.0));
      s.cue->strike.a = d.range(-0.3, 0.3);
      s.cue->strike.b = d.range(-0.3, 0.3);
      shot.table_json = "{\"shape\": \"pool\", \"size\": \"9ft\"}";
      break;
    }
    case 4: {
      shot.table_json = "{\"shape\": \"snooker\"}";
      if (d.unit() < 0.3) {
        s = make_break_scenario("snooker", "12ft", mix_seed(d.seed, 98), d.range(4.0, 10.0));
        s.cue->strike.a = d.range(-0.3, 0.3);
        s.cue->strike.b = d.range(-0.3, 0.3);
      } else {
        s.physics = default_physics(Model::pool);
        s.table = make_snooker_table();
        scatter(s, d, d.whole(2, 22), kSnookerBallRadius, kSnookerBallMass, ids);
        default_walls(s);
        strike(s, d, 0, d.unit() < 0.2);
      }
      break;
    }
    case 5: {
      s.physics = default_physics(Model::pool);
      s.table = make_carom_table();
      shot.table_json = "{\"shape\": \"carom\"}";
      scatter(s, d, 3, kCaromBallRadius, kCaromBallMass, ids);
      default_walls(s);
      strike(s, d, 0, d.unit() < 0.2);
      break;
    }
    default: {
      const bool ideal = shot.kind == 6;
      s.physics = default_physics(ideal ? Model::ideal : Model::friction);
      const Vec2 lo{0.0, 0.0};
      const Vec2 hi{d.range(0.5, 2.0), d.range(0.5, 2.0)};
      s.table = make_rectangle(lo, hi);
      shot.table_json =
          "{\"shape\": \"rectangle\", \"min\": " + vec2(lo) + ", \"max\": " + vec2(hi) + "}";
      const int balls = d.whole(2, 16);
      for (int tries = 0; tries < 60 * balls && static_cast<int>(s.balls.size()) < balls; ++tries) {
        const double r = d.range(0.01, 0.04);
        const Vec2 p{d.range(lo.x + r + 1e-4, hi.x - r - 1e-4),
                     d.range(lo.y + r + 1e-4, hi.y - r - 1e-4)};
        bool free = true;
        for (std::size_t j = 0; j < s.start.size(); ++j) {
          free = free && norm(s.start[j].position - p) > r + s.balls[j].radius + 1e-4;
        }
        if (!free) continue;
        const Vec2 v = d.unit() < 0.7 ? Vec2{d.range(-2.0, 2.0), d.range(-2.0, 2.0)} : Vec2{};
        add_ball(s, ids[s.balls.size()], r, d.range(0.05, 0.3), p, v);
      }
      if (!ideal) s.physics.deceleration = d.range(0.3, 2.0);
      s.until.rest = !ideal;
      s.until.time = ideal ? 1.0 : 0.0;
      break;
    }
  }
  s.max_events = 200000;
  // Every layout is valid (scatter keeps balls off the walls and out of
  // the pockets); one that is not is counted and not played.
  // wall_clearance() leaves out the jaws' round tips: a ball validate()
  // finds on one is taken off (never the cue ball, which the strike needs).
  std::optional<ScenarioError> why = validate(s);
  while (why && why->path.rfind("balls[", 0) == 0) {
    const std::size_t i = std::strtoul(why->path.c_str() + 6, nullptr, 10);
    if (i == 0 || i >= s.balls.size() || (s.cue && s.cue->ball >= static_cast<std::int32_t>(i)))
      break;
    s.balls.erase(s.balls.begin() + static_cast<std::ptrdiff_t>(i));
    s.start.erase(s.start.begin() + static_cast<std::ptrdiff_t>(i));
    why = validate(s);
  }
  shot.valid = !why;
  return shot;
}

/// Shot k: its layout drawn again (at most 8 times) until it is valid.
Shot make_shot(std::uint64_t seed, std::uint64_t k) {
  Shot shot;
  for (std::uint64_t attempt = 0; attempt < 8; ++attempt) {
    shot = make_shot_from(mix_seed(mix_seed(seed, k), attempt), k);
    if (shot.valid) break;
  }
  return shot;
}

/// The energy of the balls in play: kinetic, rotational and, in the
/// pool model, potential above the cloth.
double energy(const Scenario& s, const std::vector<BallState>& balls) {
  const double g = s.physics.model == Model::pool ? s.physics.gravity : 0.0;
  double e = 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const BallState& b = balls[i];
    if (b.state == MotionState::pocketed || b.state == MotionState::off_table) continue;
    e += kinetic_energy(s.balls[i], b) + s.balls[i].mass * g * b.z;
  }
  return e;
}

bool finite(const BallState& b) {
  return std::isfinite(b.position.x) && std::isfinite(b.position.y) &&
         std::isfinite(b.velocity.x) && std::isfinite(b.velocity.y) && std::isfinite(b.spin.x) &&
         std::isfinite(b.spin.y) && std::isfinite(b.spin.z) && std::isfinite(b.z) &&
         std::isfinite(b.vz);
}

struct Violation {
  int check = -1;
  std::uint64_t event = 0;
  double time = 0.0;
  std::string what;
};

/// FNV-1a over the bits of every ball's final state.
std::uint64_t state_digest(const std::vector<BallState>& balls) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto add = [&h](const void* data, std::size_t size) {
    const auto* c = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ c[i]) * 0x100000001b3ULL;
  };
  for (const BallState& b : balls) {
    add(&b.position, sizeof b.position);
    add(&b.velocity, sizeof b.velocity);
    add(&b.spin, sizeof b.spin);
    add(&b.state, sizeof b.state);
    add(&b.z, sizeof b.z);
  }
  return h;
}

/// Runs the scenario event by event with the checks; the first violation.
/// inject (0-3, or -1 for none) corrupts what the checks see at the first
/// event, in the way check `inject` must catch: to show that each can fail.
std::optional<Violation> run_checked(const Scenario& s, std::uint64_t* events, int inject,
                                     std::uint64_t* digest = nullptr) {
  Simulation sim(s);
  const double allowance = [&] {
    double a = 0.0;
    for (const BallSpec& b : s.balls)
      a += b.mass * s.physics.collapse_speed * s.physics.collapse_speed;
    return a;
  }();
  const double end = s.until.rest ? std::numeric_limits<double>::infinity() : s.until.time;
  const std::size_t n = sim.ball_count();
  std::vector<BallState> b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = sim.ball(i);
  double e_prev = energy(s, b);
  const auto in_play = [](const BallState& x) {
    return x.state != MotionState::pocketed && x.state != MotionState::off_table;
  };
  for (;;) {
    const double t = sim.next_event_time();
    if (!(t < std::numeric_limits<double>::infinity()) || !(t <= end) ||
        sim.event_count() >= s.max_events) {
      break;
    }
    sim.advance_to(t);
    for (std::size_t i = 0; i < n; ++i) b[i] = sim.ball(i);
    if (inject >= 0 && sim.event_count() <= 2) {
      if (inject == 0) b[0].velocity.x = std::numeric_limits<double>::quiet_NaN();
      if (inject == 1)
        b[0] = BallState{s.table.max + Vec2{1.0, 1.0}, {}, {}, MotionState::stationary};
      if (inject == 2 && n > 1) b[1] = b[0];
      if (inject == 3) b[0].velocity = b[0].velocity * 2.0 + Vec2{1.0, 0.0};
    }
    Violation v;
    v.event = sim.event_count();
    v.time = t;
    for (std::size_t i = 0; i < n && v.check < 0; ++i) {
      if (!finite(b[i])) {
        v.check = 0;
        v.what = "ball " + s.balls[i].id + " is not finite";
      } else if (in_play(b[i]) && b[i].state != MotionState::airborne &&
                 (b[i].position.x < s.table.min.x - 1e-9 ||
                  b[i].position.x > s.table.max.x + 1e-9 ||
                  b[i].position.y < s.table.min.y - 1e-9 ||
                  b[i].position.y > s.table.max.y + 1e-9)) {
        v.check = 1;
        v.what = "ball " + s.balls[i].id + " at " + vec2(b[i].position) + " is off the table";
      }
    }
    for (std::size_t i = 0; i < n && v.check < 0; ++i) {
      if (!in_play(b[i])) continue;
      for (std::size_t j = i + 1; j < n && v.check < 0; ++j) {
        if (!in_play(b[j])) continue;
        const double ri = s.balls[i].radius;
        const double rj = s.balls[j].radius;
        const Vec2 dp = b[j].position - b[i].position;
        const double dz = (rj + b[j].z) - (ri + b[i].z);
        const double reach = ri + rj - 1e-9;
        const double d2 = norm2(dp) + dz * dz;
        if (d2 < reach * reach) {  // the square root only for the message
          v.check = 2;
          v.what = "balls " + s.balls[i].id + " and " + s.balls[j].id + " overlap by " +
                   num(ri + rj - std::sqrt(d2)) + " m";
        }
      }
    }
    if (v.check < 0) {
      const double e = energy(s, b);
      if (e > e_prev * (1.0 + 1e-9) + allowance) {
        v.check = 3;
        v.what = "the energy rose from " + num(e_prev) + " J to " + num(e) + " J";
      }
      e_prev = e;
    }
    if (v.check >= 0) {
      *events = sim.event_count();
      return v;
    }
    if (s.until.rest && sim.at_rest()) break;
  }
  *events = sim.event_count();
  if (digest) {
    for (std::size_t i = 0; i < n; ++i) b[i] = sim.ball(i);
    *digest = state_digest(b);
  }
  return std::nullopt;
}

struct Totals {
  std::array<std::uint64_t, kKinds> shots{};
  std::array<std::uint64_t, kKinds> events{};
  std::array<std::uint64_t, 4> violations{};
  std::uint64_t invalid = 0;  ///< layouts validate() refused (none expected)
  std::uint64_t digest = 0;   ///< of every final table (shots without a violation)
};

/// CPU time of the process (every thread), user and system.
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

bool parse_u64(const char* text, std::uint64_t& out) {
  const char* end = text + std::char_traits<char>::length(text);
  const auto r = std::from_chars(text, end, out);
  return r.ec == std::errc{} && r.ptr == end;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t shots = 10'000'000;
  std::uint64_t seed = 1;
  std::uint64_t from = 0;
  std::uint64_t threads = std::max(1u, std::thread::hardware_concurrency());
  std::string out = "soak-violation.json";
  int inject = -1;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const bool has = a + 1 < argc;
    bool ok = has;
    if (arg == "--shots" && has) {
      ok = parse_u64(argv[++a], shots) && shots > 0;
    } else if (arg == "--seed" && has) {
      ok = parse_u64(argv[++a], seed);
    } else if (arg == "--from" && has) {
      ok = parse_u64(argv[++a], from);
    } else if (arg == "--threads" && has) {
      ok = parse_u64(argv[++a], threads) && threads > 0 && threads <= 1024;
    } else if (arg == "--out" && has) {
      out = argv[++a];
    } else if (arg == "--inject" && has) {
      const std::string what = argv[++a];
      for (std::size_t c = 0; c < kInjectNames.size(); ++c) {
        if (what == kInjectNames[c]) inject = static_cast<int>(c);
      }
      ok = inject >= 0;
    } else {
      ok = false;
    }
    if (!ok) {
      std::fprintf(stderr,
                   "soak: bad argument '%s'\nusage: soak [--shots N>0] [--seed S] [--threads T>0] "
                   "[--out FILE] [--from K] [--inject nan|off-table|overlap|energy]\n",
                   arg.c_str());
      return 2;
    }
  }

  std::atomic<std::uint64_t> next{0};
  std::mutex mutex;
  std::vector<Totals> totals(threads);
  std::optional<std::uint64_t> first_bad;  // under mutex
  Violation first_violation;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  const auto work = [&](std::size_t w) {
    constexpr std::uint64_t kChunk = 64;
    for (std::uint64_t i = next.fetch_add(kChunk); i < shots; i = next.fetch_add(kChunk)) {
      for (std::uint64_t k = from + i; k < from + std::min(i + kChunk, shots); ++k) {
        const Shot shot = make_shot(seed, k);
        if (!shot.valid) {
          totals[w].invalid += 1;
          continue;
        }
        std::uint64_t events = 0;
        std::uint64_t digest = 0;
        const std::optional<Violation> v = run_checked(shot.scenario, &events, inject, &digest);
        Totals& t = totals[w];
        t.digest += mix_seed(digest, k);  // a sum: the same for any order of the shots
        t.shots[static_cast<std::size_t>(shot.kind)] += 1;
        t.events[static_cast<std::size_t>(shot.kind)] += events;
        if (!v) continue;
        t.violations[static_cast<std::size_t>(v->check)] += 1;
        const std::lock_guard<std::mutex> lock(mutex);
        if (!first_bad || k < *first_bad) {
          first_bad = k;
          first_violation = *v;
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < threads; ++w) pool.emplace_back(work, w);
  work(0);
  for (std::thread& t : pool) t.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpu_seconds() - cpu_start;

  Totals sum;
  for (const Totals& t : totals) {
    for (int k = 0; k < kKinds; ++k) {
      sum.shots[static_cast<std::size_t>(k)] += t.shots[static_cast<std::size_t>(k)];
      sum.events[static_cast<std::size_t>(k)] += t.events[static_cast<std::size_t>(k)];
    }
    for (std::size_t c = 0; c < 4; ++c) sum.violations[c] += t.violations[c];
    sum.invalid += t.invalid;
    sum.digest += t.digest;
  }
  std::uint64_t all_events = 0;
  std::uint64_t all_violations = 0;
  std::printf("soak: shots %llu .. %llu of seed %llu, %llu threads\n",
              static_cast<unsigned long long>(from),
              static_cast<unsigned long long>(from + shots - 1),
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(threads));
  std::printf("%-16s %10s %12s\n", "kind", "shots", "events");
  for (int k = 0; k < kKinds; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    std::printf("%-16s %10llu %12llu\n", kKindNames[uk],
                static_cast<unsigned long long>(sum.shots[uk]),
                static_cast<unsigned long long>(sum.events[uk]));
    all_events += sum.events[uk];
  }
  std::printf("digest of the final tables: %016llx\n", static_cast<unsigned long long>(sum.digest));
  std::printf("violations:");
  for (std::size_t c = 0; c < 4; ++c) {
    std::printf(" %s %llu%s", kCheckNames[c], static_cast<unsigned long long>(sum.violations[c]),
                c + 1 < 4 ? "," : "\n");
    all_violations += sum.violations[c];
  }
  std::printf(
      "%llu shots, %llu events in %.1f s (%.1f s of CPU): %.0f shots/s, %.0f shots per "
      "CPU second\n",
      static_cast<unsigned long long>(shots), static_cast<unsigned long long>(all_events), seconds,
      cpu, static_cast<double>(shots) / seconds, static_cast<double>(shots) / cpu);
  if (sum.invalid > 0) {
    std::printf("invalid layouts (not played): %llu\n",
                static_cast<unsigned long long>(sum.invalid));
  }
  if (!first_bad) return sum.invalid > 0 ? 1 : 0;

  const Shot shot = make_shot(seed, *first_bad);
  const std::string text = scenario_json(shot);
  std::printf(
      "first violation: shot %llu (%s), event %llu at t = %s s: %s (%s)\n",
      static_cast<unsigned long long>(*first_bad), kKindNames[static_cast<std::size_t>(shot.kind)],
      static_cast<unsigned long long>(first_violation.event), num(first_violation.time).c_str(),
      first_violation.what.c_str(), kCheckNames[static_cast<std::size_t>(first_violation.check)]);
  std::ofstream(out, std::ios::binary) << text;
  // The file must give the same run: read it back and check again.
  const auto read = read_scenario(text);
  if (const auto* err = std::get_if<ScenarioError>(&read)) {
    std::printf("%s: written, but it does not read back: %s: %s\n", out.c_str(), err->path.c_str(),
                err->reason.c_str());
    return 1;
  }
  std::uint64_t events = 0;
  const std::optional<Violation> again = run_checked(std::get<Scenario>(read), &events, inject);
  const bool same = again && again->check == first_violation.check &&
                    again->event == first_violation.event && again->what == first_violation.what;
  std::printf("%s: written; `breakshot simulate %s` %s\n", out.c_str(), out.c_str(),
              same ? "reproduces it (checked here)" : "does NOT reproduce it");
  return 1;
}
