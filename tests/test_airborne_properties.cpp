// Invariants of balls that leave the cloth (physics.airborne) over
// 100,000 random shots on racked tables (stick speeds up to 15 m/s), a
// third of them with the cue raised up to 85 degrees: no two balls overlap in three dimensions,
// no ball goes below the slate, a ball leaves the table over a rail only
// with its bottom above the rail's nose, kinetic plus potential energy
// never rises, every run ends at rest. Fixed seed. Under the sanitizers
// (ten times slower) the first 10,000 shots.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "breakshot/lab.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "sanitizers.hpp"

namespace test_airborne_properties {

using namespace breakshot;

namespace {

constexpr double kR = kPoolBallRadius;

constexpr int kShots = kUnderSanitizers ? 10000 : 100000;

double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

double height(const Simulation::Trajectory& tr, double t) {
  if (tr.state != MotionState::airborne) return 0.0;
  const double dt = t - tr.t0;
  return tr.z0 + tr.vz0 * dt - 0.5 * tr.gravity * dt * dt;
}

// Kinetic plus potential energy (the potential from the resting height).
double energy(const Scenario& s, const std::vector<BallState>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    e += kinetic_energy(s.balls[i], b[i]) + s.balls[i].mass * s.physics.gravity * b[i].z;
  }
  return e;
}

bool out(MotionState s) { return s == MotionState::pocketed || s == MotionState::off_table; }

}  // namespace

TEST(AirborneProperties, RandomShotsWithJumps) {
  std::mt19937_64 g(22);
  std::uint64_t events = 0;
  int flights = 0;
  int off_table = 0;
  const double nose = 0.635 * 2 * kR;
  for (int k = 0; k < kShots; ++k) {
    Scenario s = make_break_scenario((k % 2) ? "nine_ball" : "eight_ball", "9ft", g(), 1.0);
    s.physics.airborne = true;
    s.max_events = 5000;
    s.start[0].position = {kR + 0.01 + (s.table.length / 4 - kR - 0.01) * unit(g),
                           kR + 0.01 + (s.table.width - 2 * kR - 0.02) * unit(g)};
    CueSpec c;
    c.ball = 0;
    c.strike.speed = 0.5 + 14.5 * unit(g);
    c.strike.phi = 360.0 * unit(g);
    c.strike.theta = (k % 3 == 0) ? 85.0 * unit(g) : 5.0 * unit(g);
    c.strike.a = unit(g) - 0.5;
    c.strike.b = unit(g) - 0.5;
    s.cue = c;

    Simulation sim(s);
    const std::size_t n = s.balls.size();
    double last = energy(s, sim.balls());
    std::vector<Simulation::Trajectory> before(n);
    std::size_t seen = sim.events().size();
    while (!sim.at_rest()) {
      const double t = sim.next_event_time();
      ASSERT_LT(t, 1e3) << "shot " << k;
      ASSERT_LT(sim.event_count(), s.max_events) << "shot " << k << " never comes to rest";
      for (std::size_t i = 0; i < n; ++i) before[i] = sim.trajectory(i);
      sim.advance_to(t);
      // A ball leaves over a rail only with its bottom above the nose.
      for (std::size_t q = seen; q < sim.events().size(); ++q) {
        const Event& ev = sim.events()[q];
        if (ev.type != EventType::ball_off_table) continue;
        ++off_table;
        const Simulation::Trajectory& tr = before[static_cast<std::size_t>(ev.ball)];
        ASSERT_EQ(tr.state, MotionState::airborne) << "shot " << k;
        if (ev.wall >= 0) {
          ASSERT_GE(height(tr, ev.time), nose - 1e-9) << "shot " << k << " ball " << ev.ball;
        }
      }
      seen = sim.events().size();
      const auto balls = sim.balls();
      const double e = energy(s, balls);
      const double bound = 0.5 * (0.17 / 2) * kPoolCollapseSpeed * kPoolCollapseSpeed;
      ASSERT_LE(e, last + bound + 1e-12) << "shot " << k << " energy grew at t=" << t;
      last = e;
      for (std::size_t i = 0; i < n; ++i) {
        if (out(balls[i].state)) continue;
        ASSERT_GE(balls[i].z, 0.0) << "shot " << k << ": " << s.balls[i].id << " below the slate";
        if (balls[i].state == MotionState::airborne) ++flights;
        for (std::size_t j = i + 1; j < n; ++j) {
          if (out(balls[j].state)) continue;
          const Vec2 d = balls[i].position - balls[j].position;
          const double dz = balls[i].z - balls[j].z;
          ASSERT_GE(norm2(d) + dz * dz, (2 * kR - 1e-9) * (2 * kR - 1e-9))
              << "shot " << k << ": " << s.balls[i].id << " and " << s.balls[j].id
              << " overlap at t=" << t;
        }
      }
    }
    events += sim.event_count();
  }
  EXPECT_GT(events, 10u * static_cast<std::uint64_t>(kShots));
  EXPECT_GT(flights, kShots / 10);      // balls do fly
  EXPECT_GT(off_table, kShots / 1000);  // and some leave the table
  RecordProperty("off_table", off_table);
}

}  // namespace test_airborne_properties
