// The event loop against closed-form physics.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "expect_states.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"

namespace test_simulation {

using namespace breakshot;

namespace {

BallSpec spec(const char* id, double r, double m, double e = 1.0) { return {id, r, m, e}; }

BallState at(double x, double y, double vx = 0.0, double vy = 0.0) {
  BallState s;
  s.position = {x, y};
  s.velocity = {vx, vy};
  s.state = (vx != 0.0 || vy != 0.0) ? MotionState::moving : MotionState::stationary;
  return s;
}

Scenario box(double x0, double y0, double x1, double y1, Model model = Model::ideal) {
  Scenario s;
  s.physics.model = model;
  s.table = make_rectangle({x0, y0}, {x1, y1});
  s.until.rest = model != Model::ideal;
  s.until.time = 1.0;
  return s;
}

void add(Scenario& s, BallSpec b, BallState st) {
  s.balls.push_back(std::move(b));
  s.start.push_back(st);
}

Vec2 total_momentum(const Scenario& s, const std::vector<BallState>& b) {
  Vec2 p;
  for (std::size_t i = 0; i < b.size(); ++i) p += momentum(s.balls[i], b[i]);
  return p;
}

double total_energy(const Scenario& s, const std::vector<BallState>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) e += kinetic_energy(s.balls[i], b[i]);
  return e;
}

}  // namespace

// A head-on hit between unequal masses: v1' = (m1 - e m2) v / (m1 + m2),
// v2' = (1 + e) m1 v / (m1 + m2).
TEST(Collision, HeadOnUnequalMassesMatchesClosedForm) {
  for (double e : {1.0, 0.8, 0.5, 0.0}) {
    for (double m2 : {0.05, 0.17, 0.6}) {
      Scenario s = box(0, 0, 2, 1);
      const double m1 = 0.17;
      const double v = 1.3;
      add(s, spec("a", 0.03, m1), at(0.3, 0.5, v, 0));
      add(s, spec("b", 0.02, m2), at(1.0, 0.5));
      s.physics.ball_ball_restitution = e;
      Simulation sim(s);
      const double t_hit = (1.0 - 0.05 - 0.3) / v;
      EXPECT_NEAR(sim.next_event_time(), t_hit, 1e-15);
      sim.advance_to(t_hit + 1e-6);
      ASSERT_EQ(sim.events().size(), 1u);
      EXPECT_EQ(sim.events()[0].type, EventType::ball_ball);
      EXPECT_NEAR(sim.ball(0).velocity.x, (m1 - e * m2) * v / (m1 + m2), 1e-14);
      EXPECT_NEAR(sim.ball(1).velocity.x, (1 + e) * m1 * v / (m1 + m2), 1e-14);
      EXPECT_NEAR(sim.ball(0).velocity.y, 0.0, 1e-15);
    }
  }
}

// Oblique impacts at any angle, mass and restitution: only the component
// along the line of centres changes, by the closed-form impulse.
TEST(Collision, ObliqueImpactsMatchClosedForm) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const double r1 = 0.01 + 0.03 * u(rng);
    const double r2 = 0.01 + 0.03 * u(rng);
    const double m1 = 0.05 + u(rng);
    const double m2 = 0.05 + u(rng);
    const double e = u(rng);
    const double angle = (u(rng) - 0.5) * 3.0;  // contact normal angle, radians
    // Ball 2 sits at the origin; ball 1 arrives from the direction of
    // -n with a velocity that has some tangential part.
    const Vec2 n{std::cos(angle), std::sin(angle)};
    const double gap = 0.1;
    const Vec2 contact1 = n * -(r1 + r2);
    const double vn = 0.5 + u(rng);
    const double vt = (u(rng) - 0.5) * 2.0;
    const Vec2 v1 = n * vn + perp(n) * vt;
    const Vec2 start1 = contact1 - v1 * (gap / vn);
    Scenario s = box(-1, -1, 1, 1);
    add(s, spec("a", r1, m1), at(start1.x, start1.y, v1.x, v1.y));
    add(s, spec("b", r2, m2), at(0, 0));
    s.physics.ball_ball_restitution = e;
    Simulation sim(s);
    const double t = sim.next_event_time();
    EXPECT_NEAR(t, gap / vn, 1e-12);
    sim.advance_to(t);
    ASSERT_GE(sim.events().size(), 1u);
    const double j = (1 + e) * vn * m1 * m2 / (m1 + m2);
    const Vec2 want1 = v1 - n * (j / m1);
    const Vec2 want2 = n * (j / m2);
    EXPECT_NEAR(sim.ball(0).velocity.x, want1.x, 1e-12);
    EXPECT_NEAR(sim.ball(0).velocity.y, want1.y, 1e-12);
    EXPECT_NEAR(sim.ball(1).velocity.x, want2.x, 1e-12);
    EXPECT_NEAR(sim.ball(1).velocity.y, want2.y, 1e-12);
  }
}

TEST(Collision, WallReflectsNormalComponentWithRestitution) {
  Scenario s = box(0, 0, 1, 1);
  add(s, spec("a", 0.05, 0.1, 0.6), at(0.5, 0.5, 0.2, -0.3));
  Simulation sim(s);
  const double t = sim.next_event_time();
  EXPECT_NEAR(t, (0.5 - 0.05) / 0.3, 1e-14);  // bottom wall first
  sim.advance_to(t);
  EXPECT_EQ(s.table.walls[static_cast<std::size_t>(sim.events()[0].wall)].name, "bottom");
  EXPECT_NEAR(sim.ball(0).velocity.x, 0.2, 1e-15);
  EXPECT_NEAR(sim.ball(0).velocity.y, 0.18, 1e-15);
}

// e = 0: the pair leaves with equal normal velocities and produces no
// further events between them.
TEST(Collision, PerfectlyInelasticPairStaysTogether) {
  Scenario s = box(0, 0, 4, 4);
  add(s, spec("a", 0.03, 0.2), at(1.0, 2.0, 0.6, 0.1));
  add(s, spec("b", 0.03, 0.1), at(1.5, 2.02, -0.2, 0.0));
  s.physics.ball_ball_restitution = 0.0;
  s.until.time = 1.5;
  const RunResult r = simulate(s);
  int pair_events = 0;
  for (const Event& e : r.events) pair_events += e.type == EventType::ball_ball;
  EXPECT_EQ(pair_events, 1);
  Simulation sim(s);
  sim.advance_to(sim.next_event_time());
  const Vec2 n = (sim.ball(1).position - sim.ball(0).position) / norm(sim.ball(1).position - sim.ball(0).position);
  EXPECT_NEAR(dot(sim.ball(0).velocity, n), dot(sim.ball(1).velocity, n), 1e-15);
}

// Newton's cradle: a striker hits a row of touching equal balls; the
// impulse passes down the row (sequential collisions at the same instant)
// and only the last ball leaves, at the striker's speed.
TEST(Collision, NewtonsCradleTransfersToLastBall) {
  Scenario s = box(0, 0, 3, 0.2);
  const double r = 0.02;
  add(s, spec("s", r, 0.1), at(0.2, 0.1, 0.5, 0));
  for (int k = 0; k < 4; ++k) add(s, spec("c", r, 0.1), at(1.0 + 2 * r * k, 0.1));
  for (std::size_t k = 1; k < s.balls.size(); ++k) s.balls[k].id = "c" + std::to_string(k);
  Simulation sim(s);
  sim.advance_to(1.8);  // after the row's collisions, before any wall
  const auto& ev = sim.events();
  ASSERT_EQ(ev.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(ev[k].ball, static_cast<int>(k));
    EXPECT_EQ(ev[k].other, static_cast<int>(k + 1));
    EXPECT_EQ(ev[k].time, ev[0].time);
  }
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(sim.ball(k).velocity.x, 0.0, 1e-15);
  EXPECT_NEAR(sim.ball(4).velocity.x, 0.5, 1e-15);
}

// A ball much faster than its clearance never tunnels: in a box a
// micrometre wider than the ball, at 1000 m/s, every wall is hit in turn.
TEST(NoTunnelling, ThousandMetresPerSecondInATightBox) {
  const double r = 0.028575;
  const double gap = 1e-6;
  Scenario s = box(-r - gap / 2, -r - gap / 2, r + gap / 2, r + gap / 2);
  add(s, spec("bullet", r, 0.17), at(0, 0, 1000.0, 700.0));
  s.until.time = 1e-5;
  const RunResult res = simulate(s);
  int nx = 0, ny = 0;
  int last_x = -1, last_y = -1;
  for (const Event& e : res.events) {
    ASSERT_EQ(e.type, EventType::ball_cushion);
    const std::string& name = s.table.walls[static_cast<std::size_t>(e.wall)].name;
    if (name == "left" || name == "right") {
      const int side = name == "right";
      EXPECT_NE(side, last_x);  // alternates right, left, right ...
      last_x = side;
      ++nx;
    } else {
      const int side = name == "top";
      EXPECT_NE(side, last_y);
      last_y = side;
      ++ny;
    }
  }
  // The centre travels v t in each axis; the first hit is after gap/2,
  // then one every gap.
  EXPECT_EQ(nx, static_cast<int>(std::floor((1000.0 * 1e-5 - gap / 2) / gap)) + 1);
  EXPECT_EQ(ny, static_cast<int>(std::floor((700.0 * 1e-5 - gap / 2) / gap)) + 1);
  const BallState& b = res.final_balls[0];
  EXPECT_LE(std::abs(b.position.x), gap / 2 + 1e-12);
  EXPECT_LE(std::abs(b.position.y), gap / 2 + 1e-12);
  EXPECT_NEAR(norm(b.velocity), std::hypot(1000.0, 700.0), 1e-9);
}

// A lone ball under constant deceleration stops after v^2 / 2a.
TEST(Friction, LoneBallStopsAtClosedFormDistance) {
  for (double v : {0.01, 0.5, 2.0}) {
    for (double a : {0.05, 0.3, 1.5}) {
      Scenario s = box(-50, -50, 50, 50, Model::friction);
      s.physics.deceleration = a;
      const Vec2 dir{0.6, -0.8};
      add(s, spec("a", 0.0285, 0.17), at(0.1, 0.2, v * dir.x, v * dir.y));
      const RunResult res = simulate(s);
      ASSERT_TRUE(res.complete);
      ASSERT_EQ(res.events.size(), 1u);
      EXPECT_EQ(res.events[0].type, EventType::state_change);
      EXPECT_NEAR(res.events[0].time, v / a, 1e-14 * (v / a));
      const double d = norm(res.final_balls[0].position - Vec2{0.1, 0.2});
      EXPECT_NEAR(d, v * v / (2 * a), 1e-14);
      EXPECT_EQ(res.final_balls[0].state, MotionState::stationary);
    }
  }
}

// Two balls decelerating toward each other: the contact time is the root
// of a quartic; check it against the motion computed by hand.
TEST(Friction, DeceleratingBallsMeetWhereTheyShould) {
  Scenario s = box(0, 0, 4, 1, Model::friction);
  s.physics.deceleration = 0.4;
  add(s, spec("a", 0.03, 0.1), at(1.0, 0.5, 1.0, 0.0));
  add(s, spec("b", 0.03, 0.1), at(2.0, 0.5, -0.5, 0.0));
  Simulation sim(s);
  const double t = sim.next_event_time();
  // The gap d(t) = 1 - 1.5 t + 0.4 t^2 (relative acceleration 0.8 while
  // both move; b stops at 1.25 s) reaches 2r = 0.06 at the smaller root.
  const double want = (1.5 - std::sqrt(1.5 * 1.5 - 4 * 0.4 * 0.94)) / (2 * 0.4);
  EXPECT_NEAR(t, want, 1e-14);
  sim.advance_to(t);
  EXPECT_NEAR(sim.ball(0).velocity.x, -0.5 + 0.4 * want, 1e-13);  // equal masses swap
}

TEST(Simulation, FrameStepsGiveExactlyTheSameEvents) {
  Scenario s = box(0, 0, 1.5, 1.0, Model::friction);
  s.physics.deceleration = 0.2;
  s.physics.ball_ball_restitution = 0.93;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 10; ++k) {
    add(s, spec("b", 0.03, 0.17, 0.8), at(0.1 + 0.13 * k, 0.2 + 0.6 * u(rng), 2 * u(rng) - 1, 2 * u(rng) - 1));
  }
  Simulation straight(s);
  straight.advance_to_rest();
  Simulation framed(s);
  while (!framed.at_rest()) framed.advance_to(framed.time() + 1.0 / 60.0);
  ASSERT_GT(straight.events().size(), 10u);
  ASSERT_EQ(straight.events().size(), framed.events().size());
  for (std::size_t k = 0; k < straight.events().size(); ++k) {
    EXPECT_EQ(straight.events()[k], framed.events()[k]) << "event " << k;
  }
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    EXPECT_EQ(straight.ball(i).position, framed.ball(i).position);
  }
}

TEST(Simulation, CopyRestoresState) {
  Scenario s = box(0, 0, 1, 1);
  add(s, spec("a", 0.05, 0.1), at(0.2, 0.3, 0.7, 0.4));
  add(s, spec("b", 0.05, 0.2), at(0.6, 0.6, -0.3, 0.2));
  s.until.time = 10.0;
  Simulation sim(s);
  sim.advance_to(2.5);
  const Simulation saved = sim;
  sim.advance_to(7.0);
  const auto events_after = sim.events();
  const auto balls_after = sim.balls();
  sim = saved;
  EXPECT_EQ(sim.time(), 2.5);
  sim.advance_to(7.0);
  EXPECT_EQ(sim.events(), events_after);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(sim.ball(i).position, balls_after[i].position);
}

// simulate() with samples until rest learns the end as it goes, in one
// run. It gives exactly what two runs give: one to rest to learn the end,
// then the sampled one (the way simulate() used to work).
namespace {

RunResult simulate_in_two_runs(const Scenario& scenario) {
  RunResult result;
  Simulation sim(scenario);
  Simulation probe = sim;
  probe.advance_to_rest();
  const double end = probe.time();
  bool complete = true;
  for (std::uint64_t k = 0;; ++k) {
    double t = static_cast<double>(k) * *scenario.sample_dt;
    const bool last = t >= end;
    if (last) t = end;
    if (sim.advance_to(t) == StopReason::event_limit) {
      complete = false;
      break;
    }
    result.samples.push_back({t, sim.balls()});
    if (last) break;
  }
  if (complete) complete = sim.advance_to_rest() == StopReason::reached;
  result.complete = complete;
  result.events = sim.events();
  result.final_time = sim.time();
  result.final_balls = sim.balls();
  return result;
}

}  // namespace

TEST(Simulate, SamplesUntilRestAreThoseOfTwoRuns) {
  std::vector<Scenario> scenarios;
  Scenario friction = box(0, 0, 1.5, 1.0, Model::friction);
  friction.physics.deceleration = 0.2;
  friction.physics.ball_ball_restitution = 0.9;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 10; ++k) {
    add(friction, spec("b", 0.03, 0.17, 0.8),
        at(0.1 + 0.13 * k, 0.2 + 0.6 * u(rng), 2 * u(rng) - 1, 2 * u(rng) - 1));
  }
  scenarios.push_back(friction);
  Scenario still = box(0, 0, 1, 1, Model::friction);
  add(still, spec("a", 0.03, 0.17), at(0.5, 0.5));
  scenarios.push_back(still);
  scenarios.push_back(make_break_scenario("eight_ball", "9ft", 2, 8.0));
  Scenario no_spin_decay = make_break_scenario("nine_ball", "9ft", 4, 6.0);
  no_spin_decay.physics.spinning_friction = 0.0;  // balls may spin forever
  scenarios.push_back(no_spin_decay);
  for (Scenario s : scenarios) {
    s.until.rest = true;
    for (double dt : {0.01, 0.3, 2.0, 100.0}) {
      for (std::uint64_t max_events : {std::uint64_t{3}, std::uint64_t{40}, std::uint64_t{1000000}}) {
        s.sample_dt = dt;
        s.max_events = max_events;
        SCOPED_TRACE(testing::Message() << s.balls.size() << " balls, dt " << dt << ", max_events "
                                        << max_events);
        const RunResult want = simulate_in_two_runs(s);
        const RunResult got = simulate(s);
        EXPECT_EQ(got.complete, want.complete);
        EXPECT_EQ(got.events, want.events);
        EXPECT_EQ(got.final_time, want.final_time);
        expect_same_states(got.final_balls, want.final_balls);
        ASSERT_EQ(got.samples.size(), want.samples.size());
        for (std::size_t k = 0; k < got.samples.size(); ++k) {
          EXPECT_EQ(got.samples[k].time, want.samples[k].time) << "sample " << k;
          expect_same_states(got.samples[k].balls, want.samples[k].balls);
        }
      }
    }
  }
}

// Inelastic collapse: a fast ball into a row of touching balls with very
// low restitution would make infinitely many collisions in finite time
// without the collapse rule.
TEST(Collapse, RowOfTouchingBallsFinishes) {
  for (double e : {0.0, 0.05, 0.3}) {
    Scenario s = box(0, 0, 3, 0.2);
    const double r = 0.02;
    add(s, spec("s", r, 0.1), at(0.2, 0.1, 1.0, 0));
    for (int k = 0; k < 6; ++k) add(s, spec("c", r, 0.1), at(1.0 + 2 * r * k, 0.1));
    for (std::size_t k = 0; k < s.balls.size(); ++k) s.balls[k].id = "b" + std::to_string(k);
    s.physics.ball_ball_restitution = e;
    s.until.time = 1.5;  // before anything reaches the far wall
    s.max_events = 100000;
    const RunResult res = simulate(s);
    EXPECT_TRUE(res.complete) << "e=" << e;
    EXPECT_LT(res.events.size(), 10000u) << "e=" << e;
    const Vec2 p = total_momentum(s, res.final_balls);
    EXPECT_NEAR(p.x, 0.1, 1e-12);
    EXPECT_LE(total_energy(s, res.final_balls), 0.05 + 1e-15);
  }
}

// Balls with low restitution driven into a corner under friction settle
// there and the run ends at rest.
TEST(Collapse, BallsSettleIntoACorner) {
  for (double e : {0.0, 0.2}) {
    Scenario s = box(0, 0, 1, 1, Model::friction);
    s.physics.deceleration = 0.3;
    s.physics.ball_ball_restitution = e;
    const double r = 0.03;
    add(s, spec("a", r, 0.1, e), at(0.05, 0.05));
    add(s, spec("b", r, 0.1, e), at(0.2, 0.2, -0.9, -0.9));
    add(s, spec("c", r, 0.1, e), at(0.4, 0.35, -1.0, -0.95));
    add(s, spec("d", r, 0.1, e), at(0.05, 0.6, 0.0, -1.0));
    add(s, spec("f", r, 0.1, e), at(0.7, 0.06, -1.1, 0.0));
    s.max_events = 1000000;
    const RunResult res = simulate(s);
    EXPECT_TRUE(res.complete) << "e=" << e;
    EXPECT_LT(res.events.size(), 100000u) << "e=" << e;
    for (const BallState& b : res.final_balls) EXPECT_EQ(b.state, MotionState::stationary);
  }
}

// Simulation::reset: a re-armed simulation runs exactly as a new one, from
// any scenario it held before, larger or smaller, on any model and table.
namespace {

/// A gas of `n` balls in a 4 m box (the cell grid from 48 balls on).
Scenario gas(std::size_t n, std::uint64_t seed, Model model) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.1, 3.9);
  std::uniform_real_distribution<double> v(-1.0, 1.0);
  Scenario s = box(0, 0, 4, 4, model);
  s.until.time = 3.0;
  s.until.rest = false;
  while (s.balls.size() < n) {
    const BallState b = at(u(g), u(g), v(g), v(g));
    bool free = true;
    for (const BallState& o : s.start) free = free && norm(o.position - b.position) > 0.11;
    if (free) add(s, spec(("b" + std::to_string(s.balls.size())).c_str(), 0.05, 0.1), b);
  }
  return s;
}

void expect_same_run(Simulation& reused, const Scenario& s, const std::string& what) {
  reused.reset(s);
  Simulation fresh(s);
  const bool rest = s.until.rest;
  if (rest) {
    EXPECT_EQ(reused.advance_to_rest(), fresh.advance_to_rest()) << what;
  } else {
    EXPECT_EQ(reused.advance_to(s.until.time), fresh.advance_to(s.until.time)) << what;
  }
  EXPECT_GT(fresh.event_count(), 0u) << what;
  EXPECT_EQ(reused.event_count(), fresh.event_count()) << what;
  EXPECT_TRUE(reused.events() == fresh.events()) << what;
  EXPECT_EQ(reused.time(), fresh.time()) << what;
  EXPECT_EQ(reused.cue_result().has_value(), fresh.cue_result().has_value()) << what;
  ASSERT_EQ(reused.ball_count(), fresh.ball_count()) << what;
  for (std::size_t i = 0; i < fresh.ball_count(); ++i) {
    const BallState a = reused.ball(i);
    const BallState b = fresh.ball(i);
    EXPECT_EQ(a.position, b.position) << what << " ball " << i;
    EXPECT_EQ(a.velocity, b.velocity) << what << " ball " << i;
    EXPECT_EQ(a.spin, b.spin) << what << " ball " << i;
    EXPECT_EQ(a.state, b.state) << what << " ball " << i;
  }
}

}  // namespace

TEST(Simulation, ResetRunsExactlyAsANewSimulation) {
  std::vector<std::pair<std::string, Scenario>> cases;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    cases.emplace_back("8-ball break " + std::to_string(seed),
                       make_break_scenario("eight_ball", "9ft", seed, 7.5));
    cases.emplace_back("9-ball break " + std::to_string(seed),
                       make_break_scenario("nine_ball", "7ft", seed, 6.0));
  }
  cases.emplace_back("gas of 60 (cells)", gas(60, 1, Model::ideal));
  cases.emplace_back("gas of 5 (no cells)", gas(5, 2, Model::ideal));
  cases.emplace_back("friction gas of 70", gas(70, 3, Model::friction));
  cases.emplace_back("snooker break", make_break_scenario("snooker", "12ft", 1, 8.0));
  cases.emplace_back("8-ball break again", make_break_scenario("eight_ball", "9ft", 9, 9.0));
  // Shots in a row on one table (reset keeps the walls' boxes then):
  // two more breaks, and an L-shaped room (corner walls) before and after
  // a rectangle of the same size, and back.
  cases.emplace_back("8-ball break 5", make_break_scenario("eight_ball", "9ft", 5, 7.0));
  cases.emplace_back("8-ball break 6", make_break_scenario("eight_ball", "9ft", 6, 8.0));
  for (int k = 0; k < 3; ++k) {
    Scenario room = box(0, 0, 2, 2);
    if (k != 2) room.table = make_polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
    add(room, spec("a", 0.05, 0.1), at(0.3, 0.5, 1.1 + 0.2 * k, 0.9));
    add(room, spec("b", 0.05, 0.1), at(1.5, 0.4, -0.4, 0.3 * k));
    room.until.time = 6.0;
    cases.emplace_back("room " + std::to_string(k), room);
  }
  Scenario two = box(0, 0, 1, 1);
  add(two, spec("a", 0.05, 0.1), at(0.2, 0.3, 0.7, 0.4));
  add(two, spec("b", 0.05, 0.2), at(0.6, 0.6, -0.3, 0.2));
  two.until.time = 5.0;
  cases.emplace_back("two balls", two);
  Simulation reused(cases.back().second);
  reused.advance_to(2.0);  // reset in the middle of a run, too
  for (const auto& [what, s] : cases) expect_same_run(reused, s, what);
  // And back through them in the other order.
  for (auto it = cases.rbegin(); it != cases.rend(); ++it) expect_same_run(reused, it->second, it->first);
}

}  // namespace test_simulation
