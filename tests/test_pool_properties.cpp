// Invariants of the pool model over 100,000 random shots on a racked
// table: no overlap, no ball off the table, energy never increasing,
// every run ending at rest. Fixed seed.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "breakshot/lab.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "sanitizers.hpp"

namespace test_pool_properties {

using namespace breakshot;

namespace {

constexpr double kR = 0.028575;

double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

double energy(const Scenario& s, const std::vector<BallState>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) e += kinetic_energy(s.balls[i], b[i]);
  return e;
}

// The ball is on the table: clear of every wall (segments and jaw tips)
// or already in a pocket.
bool on_table(const Table& t, const BallState& b) {
  if (b.state == MotionState::pocketed) return true;
  if (wall_clearance(t, b.position, kR) < -1e-9) return false;
  for (const Wall& w : t.walls) {
    if (w.kind == WallKind::arc && norm(b.position - w.a) < kR + w.radius - 1e-9) return false;
  }
  return b.position.x > t.min.x && b.position.x < t.max.x && b.position.y > t.min.y &&
         b.position.y < t.max.y;
}

}  // namespace

// A hundred thousand shots; under the sanitizers (memory and undefined
// behaviour, not the statistics, are what they add) a tenth of them, the
// first ten thousand of the same sequence.
constexpr int kRandomShots = kUnderSanitizers ? 10000 : 100000;

TEST(PoolProperties, HundredThousandRandomShotsOnARackedTable) {
  std::mt19937_64 g(7);
  const int shots = kRandomShots;
  std::uint64_t events = 0;
  int pocketed = 0;
  for (int k = 0; k < shots; ++k) {
    // A rack (new seed each time) and the cue ball anywhere behind the
    // head string, shot in any direction with any spin.
    Scenario s = make_break_scenario((k % 2) ? "nine_ball" : "eight_ball", "9ft", g(), 1.0);
    // Balls on the cloth (raised cues only curve): the invariants of
    // balls that leave it are in test_airborne_properties.cpp.
    s.physics.airborne = false;
    s.max_events = 5000;
    s.start[0].position = {kR + 0.01 + (s.table.length / 4 - kR - 0.01) * unit(g),
                           kR + 0.01 + (s.table.width - 2 * kR - 0.02) * unit(g)};
    CueSpec c;
    c.ball = 0;
    c.strike.speed = 0.5 + 8.0 * unit(g);
    c.strike.phi = 360.0 * unit(g);
    c.strike.theta = (k % 10 == 0) ? 40.0 * unit(g) : 0.0;
    c.strike.a = unit(g) - 0.5;
    c.strike.b = unit(g) - 0.5;
    s.cue = c;

    Simulation sim(s);
    double last = energy(s, sim.balls());
    const std::size_t n = s.balls.size();
    while (!sim.at_rest()) {
      const double t = sim.next_event_time();
      ASSERT_LT(t, 1e3) << "shot " << k;
      ASSERT_LT(sim.event_count(), s.max_events) << "shot " << k << " never comes to rest";
      sim.advance_to(t);
      const auto balls = sim.balls();
      const double e = energy(s, balls);
      // Never increasing, but for the pressed-contact rule's documented
      // bound (docs/physics-core.md): a pressed pair leaves at
      // collapse_speed, at most m_red v_c^2 / 2 per event.
      const double bound = 0.5 * (0.17 / 2) * kPoolCollapseSpeed * kPoolCollapseSpeed;
      ASSERT_LE(e, last + bound + 1e-12) << "shot " << k << " energy grew at t=" << t;
      last = e;
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(on_table(s.table, balls[i])) << "shot " << k << ": ball " << s.balls[i].id
                                                 << " off the table at t=" << t << " ("
                                                 << balls[i].position.x << ", "
                                                 << balls[i].position.y << ")";
        if (balls[i].state == MotionState::pocketed) continue;
        for (std::size_t j = i + 1; j < n; ++j) {
          if (balls[j].state == MotionState::pocketed) continue;
          ASSERT_GE(norm(balls[i].position - balls[j].position), 2 * kR - 1e-9)
              << "shot " << k << ": " << s.balls[i].id << " and " << s.balls[j].id
              << " overlap at t=" << t;
        }
      }
    }
    events += sim.event_count();
    for (const BallState& b : sim.balls()) pocketed += b.state == MotionState::pocketed;
  }
  EXPECT_GT(events, 100u * static_cast<std::uint64_t>(shots) / 10u);
  EXPECT_GT(pocketed, shots / 10);  // the pockets take balls
}

// A frozen rack: every ball touching its neighbours exactly (to rounding),
// broken hard and soft. No overlap, no repeated collision stalls the run.
TEST(PoolProperties, FrozenRackBreaks) {
  for (double speed : {0.5, 3.0, 9.0}) {
    // The regulation break, with the rack pushed together until every
    // ball touches its neighbours.
    Scenario s = make_break_scenario("eight_ball", "9ft", 0, speed);
    s.max_events = 100000;
    const double d = 2 * kR;  // touching
    std::size_t ball = 1;
    for (int row = 0; row < 5; ++row) {
      for (int k = 0; k <= row; ++k) {
        s.start[ball++].position = {s.table.foot_spot.x + row * d * std::sqrt(3.0) / 2,
                                    s.table.foot_spot.y + (k - row / 2.0) * d};
      }
    }
    Simulation sim(s);
    int ball_ball = 0;
    while (!sim.at_rest()) {
      const double t = sim.next_event_time();
      ASSERT_LT(sim.event_count(), s.max_events) << "speed " << speed;
      sim.advance_to(t);
      const auto balls = sim.balls();
      for (std::size_t i = 0; i < balls.size(); ++i) {
        ASSERT_TRUE(on_table(s.table, balls[i])) << "speed " << speed;
        for (std::size_t j = i + 1; j < balls.size(); ++j) {
          if (balls[i].state == MotionState::pocketed || balls[j].state == MotionState::pocketed) continue;
          ASSERT_GE(norm(balls[i].position - balls[j].position), 2 * kR - 1e-9) << "speed " << speed;
        }
      }
    }
    for (const Event& e : sim.events()) ball_ball += e.type == EventType::ball_ball;
    EXPECT_GT(ball_ball, 15) << "speed " << speed;  // the hit went through the rack
  }
}

}  // namespace test_pool_properties
