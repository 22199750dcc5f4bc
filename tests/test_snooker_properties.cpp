// Invariants of the pool model on the snooker table over random shots from
// racked tables (the reds, the colours on their spots, the cue ball
// anywhere in baulk): no overlap, no ball off the table or inside a round
// jaw, energy never increasing (but for the pressed-contact rule's
// documented bound), every run ending at rest; and the pockets take balls.
// Fixed seed. Under the sanitizers a tenth of the shots.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "breakshot/lab.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"
#include "sanitizers.hpp"

namespace test_snooker_properties {

using namespace breakshot;

namespace {

constexpr int kShots = kUnderSanitizers ? 1000 : 10000;

constexpr double kR = kSnookerBallRadius;

double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

double energy(const Scenario& s, const std::vector<BallState>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) e += kinetic_energy(s.balls[i], b[i]);
  return e;
}

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

TEST(SnookerProperties, RandomShotsOnARackedTable) {
  std::mt19937_64 g(23);
  std::uint64_t events = 0;
  int pocketed = 0;
  int corner = 0;
  int middle = 0;
  const SnookerMarks m = snooker_marks();
  for (int k = 0; k < kShots; ++k) {
    Scenario s = make_break_scenario("snooker", "12ft", g(), 1.0);
    s.physics.airborne = false;
    s.max_events = 5000;
    // The cue ball anywhere in baulk, clear of the brown, yellow and green.
    for (;;) {
      const Vec2 p{kR + 0.001 + (m.baulk_x - kR - 0.001) * unit(g),
                   kR + 0.001 + (s.table.width - 2 * kR - 0.002) * unit(g)};
      if (norm(p - m.brown) > 2 * kR && norm(p - m.yellow) > 2 * kR && norm(p - m.green) > 2 * kR &&
          wall_clearance(s.table, p, kR) > 0.0) {
        s.start[0].position = p;
        break;
      }
    }
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
      // docs/physics-core.md: a pressed pair leaves at collapse_speed, at
      // most m v_c^2 / 2 per event (reduced mass m/2).
      const double bound = 0.5 * (kSnookerBallMass / 2) * kPoolCollapseSpeed * kPoolCollapseSpeed;
      ASSERT_LE(e, last + bound + 1e-12) << "shot " << k << " energy grew at t=" << t;
      last = e;
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(on_table(s.table, balls[i]))
            << "shot " << k << ": ball " << s.balls[i].id << " off the table at t=" << t << " ("
            << balls[i].position.x << ", " << balls[i].position.y << ")";
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
    for (const Event& e : sim.events()) {
      if (e.type != EventType::ball_pocket) continue;
      ++pocketed;
      (s.table.pockets[static_cast<std::size_t>(e.pocket)].name.rfind("side", 0) == 0 ? middle
                                                                                      : corner) +=
          1;
    }
  }
  EXPECT_GT(events, 20u * static_cast<std::uint64_t>(kShots));
  // The pockets take balls, the middle ones too (measured at 10,000
  // shots: about 7 balls in 100 shots, one in four into a middle pocket).
  EXPECT_GT(pocketed, kShots / 20);
  EXPECT_GT(middle, kShots / 100);
  EXPECT_GT(corner, kShots / 100);
  std::printf("%d shots: %d balls pocketed, %d in corner pockets, %d in middle pockets\n",
              kShots, pocketed, corner, middle);
}

}  // namespace test_snooker_properties
