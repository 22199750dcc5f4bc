// Balls that leave the cloth (physics.airborne), against closed forms:
// the flight of a launched ball, bounces decaying by the slate's
// restitution, a rail cleared or not by a flying ball, the jump shot's
// launch from the cue and the slate, a ball flying over another and one
// landing on it, and the 3-D impulses' conservation laws.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <variant>

#include "breakshot/lab.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "physics/airborne.hpp"

namespace test_airborne {

using namespace breakshot;

namespace {

constexpr double kR = kPoolBallRadius;
constexpr double kG = 9.81;
constexpr double kL = 2.54;               // 9 ft playing surface
constexpr double kNose = 0.635 * 2 * kR;  // default nose height above the slate

Scenario scenario(const std::string& json) {
  auto r = read_scenario(json);
  if (auto* e = std::get_if<ScenarioError>(&r)) {
    ADD_FAILURE() << e->path << ": " << e->reason;
    return {};
  }
  return std::get<Scenario>(std::move(r));
}

// One ball on a 9 ft table with the given velocity (3 components) and
// the given extra physics fields.
std::string one_ball(double x, double vx, double vz, const std::string& physics = "") {
  return R"({"physics": {"model": "pool", "airborne": true)" + physics +
         R"(}, "table": {"shape": "pool", "size": "9ft"},
             "balls": [{"id": "a", "position": [)" +
         std::to_string(x) + R"(, 0.635], "velocity": [)" + std::to_string(vx) + ", 0.0, " +
         std::to_string(vz) + "]}]}";
}

const Event* first_of(const std::vector<Event>& events, EventType type) {
  for (const Event& e : events) {
    if (e.type == type) return &e;
  }
  return nullptr;
}

double dot3(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Kinetic energy of a ball of mass m and radius r.
double energy(const Motion3& m, double mass, double r) {
  return 0.5 * mass * dot3(m.velocity, m.velocity) + 0.2 * mass * r * r * dot3(m.spin, m.spin);
}

}  // namespace

// Launched with (vx, vz): it lands after 2 vz / g, vx times that further,
// having risen vz^2 / 2g; nothing slows it in the air.
TEST(Airborne, FlightTimeDistanceAndHeight) {
  const double vx = 1.0;
  const double vz = 2.0;
  Simulation sim(scenario(one_ball(0.5, vx, vz)));
  const double T = 2.0 * vz / kG;
  sim.advance_to(0.5 * T);
  EXPECT_EQ(sim.ball(0).state, MotionState::airborne);
  EXPECT_NEAR(sim.ball(0).z, vz * vz / (2.0 * kG), 1e-12);
  EXPECT_NEAR(sim.ball(0).vz, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(sim.ball(0).velocity.x, vx);
  sim.advance_to_rest();
  const Event* land = first_of(sim.events(), EventType::ball_slate);
  ASSERT_NE(land, nullptr);
  EXPECT_NEAR(land->time, T, 1e-12);
  EXPECT_EQ(land->from, MotionState::airborne);
}

// Straight up: each bounce leaves at e times the landing speed, so the
// flights last 2 v e^k / g and rise (v e^k)^2 / 2g, until a rebound would
// stay below min_bounce_height (here 1 mm: v e^k < sqrt(2 g 0.001)).
TEST(Airborne, BouncesDecayByTheSlateRestitution) {
  const double v = 2.0;
  const double e = 0.5;
  Simulation sim(scenario(one_ball(1.0, 0.0, v)));
  sim.advance_to_rest();
  std::vector<const Event*> landings;
  for (const Event& ev : sim.events()) {
    if (ev.type == EventType::ball_slate) landings.push_back(&ev);
  }
  // Speeds 2, 1, 0.5, 0.25 fly; 0.125 < 0.140 does not.
  ASSERT_EQ(landings.size(), 4u);
  double t = 0.0;
  double speed = v;
  for (std::size_t k = 0; k < landings.size(); ++k) {
    t += 2.0 * speed / kG;
    EXPECT_NEAR(landings[k]->time, t, 1e-12) << "landing " << k;
    EXPECT_EQ(landings[k]->to,
              k + 1 < landings.size() ? MotionState::airborne : MotionState::stationary);
    speed *= e;
  }
  // The apex of the third flight.
  Simulation again(scenario(one_ball(1.0, 0.0, v)));
  const double t3 = 2.0 * v / kG * (1.0 + e);
  again.advance_to(t3 + v * e * e / kG);
  EXPECT_NEAR(again.ball(0).z, (v * e * e) * (v * e * e) / (2.0 * kG), 1e-12);
}

// A ball flying at the foot rail (x = L): high enough, it crosses the
// nose's line with its bottom above the nose and leaves the table there;
// low enough, it meets the rail's face when its centre is R from the line;
// in between, it meets the nose's edge where d^2 + (R + z - h)^2 = R^2.
TEST(Airborne, ARailClearedOrNot) {
  const double x0 = 2.0;
  const double vx = 2.0;
  const auto height = [](double vz, double t) { return vz * t - 0.5 * kG * t * t; };
  {  // cleared
    const double vz = 2.0;
    const double tc = (kL - x0) / vx;
    ASSERT_GT(height(vz, (kL - kR - x0) / vx), kNose);  // above the nose all the way in
    Simulation sim(scenario(one_ball(x0, vx, vz)));
    sim.advance_to_rest();
    const Event* off = first_of(sim.events(), EventType::ball_off_table);
    ASSERT_NE(off, nullptr);
    EXPECT_NEAR(off->time, tc, 1e-12);
    EXPECT_EQ(sim.scenario().table.walls[static_cast<std::size_t>(off->wall)].name, "rail_right");
    EXPECT_EQ(sim.ball(0).state, MotionState::off_table);
    EXPECT_EQ(first_of(sim.events(), EventType::ball_cushion), nullptr);
  }
  {  // the face
    const double vz = 1.28;
    const double tf = (kL - kR - x0) / vx;
    ASSERT_LE(kR + height(vz, tf), kNose);  // the centre below the nose at contact
    ASSERT_GT(height(vz, tf), 0.0);         // still in flight
    Simulation sim(scenario(one_ball(x0, vx, vz)));
    sim.advance_to_rest();
    const Event* hit = first_of(sim.events(), EventType::ball_cushion);
    ASSERT_NE(hit, nullptr);
    EXPECT_NEAR(hit->time, tf, 1e-12);
    EXPECT_EQ(first_of(sim.events(), EventType::ball_off_table), nullptr);
    EXPECT_NE(sim.ball(0).state, MotionState::off_table);
  }
  {  // the nose's edge: it hops back up
    const double vz = 1.36;
    Simulation sim(scenario(one_ball(x0, vx, vz)));
    double t = 0.0;
    while (first_of(sim.events(), EventType::ball_cushion) == nullptr) {
      t = sim.next_event_time();
      ASSERT_LT(t, 10.0);
      sim.advance_to(t);
    }
    const Event* hit = first_of(sim.events(), EventType::ball_cushion);
    const double d = kL - (x0 + vx * hit->time);
    const double e = kR + height(vz, hit->time) - kNose;
    ASSERT_GT(e, 0.0);  // above the nose: the edge
    EXPECT_NEAR(d * d + e * e, kR * kR, 1e-12);
    const BallState b = sim.ball(0);
    EXPECT_LT(b.velocity.x, 0.0);  // back into the table
    // The edge's normal points up: the ball leaves rising faster than it
    // came (it was falling or rising slower).
    EXPECT_GT(b.vz, vz - kG * hit->time);
    EXPECT_EQ(first_of(sim.events(), EventType::ball_off_table), nullptr);
  }
}

// The jump shot's launch: the cue's impulse along the raised cue gives
// the ball (J/m) (cos t along the aim, -sin t down); the slate returns
// e_s (J/m) sin t up, and its friction (at most mu_s (1 + e_s) (J/m) sin t,
// at most the 2/7 of the slip that makes it roll) acts on the slip
// (J/m) cos t. At 45 degrees with the defaults the cap wins: the ball
// leaves rolling at 5/7 of (J/m) cos t.
TEST(Airborne, JumpShotLaunch) {
  const double theta = 45.0;
  Scenario s = scenario(R"({"physics": {"model": "pool", "airborne": true},
    "table": {"shape": "pool", "size": "9ft"},
    "balls": [{"id": "cue", "position": [0.6, 0.635]}],
    "cue": {"ball": "cue", "speed": 4.0, "phi": 0.0, "theta": 45.0, "a": 0.0, "b": 0.0}})");
  const StrikeResult k = strike(s.cue->strike, s.balls[0].mass, kR, s.cue->params);
  const double along = std::hypot(k.velocity.x, k.vertical);
  const double st = std::sin(theta * M_PI / 180.0);
  const double ct = std::cos(theta * M_PI / 180.0);
  EXPECT_NEAR(k.vertical, -along * st, 1e-12);
  ASSERT_GT(0.2 * 1.5 * st, 2.0 / 7.0 * ct);  // the friction cap is the slip's
  Simulation sim(s);
  const BallState b = sim.ball(0);
  EXPECT_EQ(b.state, MotionState::airborne);
  EXPECT_NEAR(b.vz, 0.5 * along * st, 1e-12);
  EXPECT_NEAR(b.velocity.x, 5.0 / 7.0 * along * ct, 1e-12);
  EXPECT_NEAR(b.spin.y * kR, b.velocity.x, 1e-12);  // rolling: no slip
  // A level cue does not jump; neither does a raised one without
  // physics.airborne.
  s.cue->strike.theta = 0.0;
  EXPECT_NE(Simulation(s).ball(0).state, MotionState::airborne);
  s.cue->strike.theta = 45.0;
  s.physics.airborne = false;
  EXPECT_NE(Simulation(s).ball(0).state, MotionState::airborne);
}

// A ball flying high over another does not touch it; one coming down on
// it does, at a 3-D distance of 2R.
TEST(Airborne, OverABallOrOntoIt) {
  const auto two = [](double bx) {
    return scenario(R"({"physics": {"model": "pool", "airborne": true},
      "table": {"shape": "pool", "size": "9ft"},
      "balls": [{"id": "a", "position": [1.0, 0.635], "velocity": [2.0, 0.0, 2.5]},
                {"id": "b", "position": [)" +
                    std::to_string(bx) + R"(, 0.635]}]})");
  };
  const double T = 2.0 * 2.5 / kG;  // the first landing, at x = 1 + 2 T = 2.019
  {
    // Over b at x = 1.3: while the two are within 2R along the cloth
    // (|x - 1.3| < 2R), a's bottom is far above b's top.
    const double t_in = (1.3 - 2 * kR - 1.0) / 2.0;
    ASSERT_GT(2.5 * t_in - 0.5 * kG * t_in * t_in, 2 * kR);
    Simulation sim(two(1.3));
    sim.advance_to(T);
    EXPECT_EQ(first_of(sim.events(), EventType::ball_ball), nullptr);
    ASSERT_NE(first_of(sim.events(), EventType::ball_slate), nullptr);
  }
  {
    Simulation sim(two(1.98));
    while (first_of(sim.events(), EventType::ball_ball) == nullptr) {
      const double t = sim.next_event_time();
      ASSERT_LT(t, T) << "a lands before it meets b";
      sim.advance_to(t);
      if (first_of(sim.events(), EventType::ball_ball) != nullptr) {
        // The contact, just before the impact changed a's course: the
        // trajectory now starts at the event.
        const Simulation::Trajectory& a = sim.trajectory(0);
        const Simulation::Trajectory& b = sim.trajectory(1);
        const double dz = (kR + a.z0) - (kR + (b.state == MotionState::airborne ? b.z0 : 0.0));
        const double dx = a.p0.x - b.p0.x;
        const double dy = a.p0.y - b.p0.y;
        EXPECT_NEAR(dx * dx + dy * dy + dz * dz, 4 * kR * kR, 1e-12);
        EXPECT_GT(a.z0, 0.0);
      }
    }
  }
}

// With physics.airborne off (on by default in the pool model) nothing
// leaves the cloth: a vertical velocity is an error; with it on, a level
// shot leaves no "z" in the result.
TEST(Airborne, ScenarioChecksAndResultFields) {
  const auto error = [](const std::string& json) {
    auto r = read_scenario(json);
    const auto* e = std::get_if<ScenarioError>(&r);
    return e == nullptr ? std::string("no error") : e->path + ": " + e->reason;
  };
  const std::string table = R"("table": {"shape": "pool", "size": "9ft"})";
  EXPECT_EQ(error(R"({"physics": {"model": "pool", "airborne": false}, )" + table +
                  R"(, "balls": [{"id": "a", "position": [1, 0.6], "velocity": [1, 0, 1]}]})"),
            "balls[0].velocity: a vertical component (1.0) needs physics.airborne true");
  EXPECT_EQ(
      error(
          R"({"physics": {"model": "ideal"}, "table": {"shape": "rectangle", "min": [0, 0], "max": [1, 1]},
                     "balls": [{"id": "a", "position": [0.5, 0.5], "velocity": [1, 0, 0]}], "until": {"time": 1}})"),
      "balls[0].velocity: a vertical component needs the pool model");
  EXPECT_EQ(error(R"({"physics": {"model": "friction", "airborne": true}, )" + table +
                  R"(, "balls": [{"id": "a", "position": [1, 0.6]}]})"),
            "physics.airborne: true needs the pool model");
  EXPECT_EQ(error(R"({"physics": {"model": "pool", "airborne": true, "slate_restitution": 1}, )" +
                  table + R"(, "balls": [{"id": "a", "position": [1, 0.6]}]})"),
            "physics.slate_restitution: must be in [0, 1) (at 1 a ball would bounce forever), "
            "not 1.0");
  EXPECT_EQ(
      error(R"({"physics": {"model": "pool", "airborne": false, "min_bounce_height": 0.01}, )" +
            table + R"(, "balls": [{"id": "a", "position": [1, 0.6]}]})"),
      "physics.min_bounce_height: needs physics.airborne true");

  EXPECT_EQ(error(R"({"physics": {"model": "pool"}, )" + table +
                  R"(, "balls": [{"id": "a", "position": [1, 0.6], "velocity": [1, 0, 2, 3]}]})"),
            "balls[0].velocity: expected an array of 2 numbers, or 3 with a vertical "
            "component, not an array of 4");
  // Without gravity nothing would land: the default is then the cloth.
  EXPECT_TRUE(scenario(R"({"physics": {"model": "pool"}, )" + table +
                       R"(, "balls": [{"id": "a", "position": [1, 0.6]}]})")
                  .physics.airborne);
  EXPECT_FALSE(scenario(R"({"physics": {"model": "pool", "gravity": 0}, )" + table +
                        R"(, "balls": [{"id": "a", "position": [1, 0.6]}], "until": {"time": 1}})")
                   .physics.airborne);

  Scenario level =
      scenario(R"({"physics": {"model": "pool", "airborne": true}, )" + table +
               R"(, "balls": [{"id": "a", "position": [1, 0.6], "velocity": [1, 0]}]})");
  EXPECT_EQ(write_result(level, simulate(level)).find("\"z\""), std::string::npos);
  Scenario jump = scenario(one_ball(1.0, 0.5, 1.0));
  const std::string out = write_result(jump, simulate(jump));
  EXPECT_NE(out.find("\"z\": "), std::string::npos);
  EXPECT_NE(out.find("\"type\": \"ball_slate\", \"balls\": [\"a\"], \"from\": \"airborne\""),
            std::string::npos);
}

// The 3-D impulses: a fixed contact reverses the normal speed times e and
// never adds energy; sticking leaves the contact point at rest; two balls
// keep their momentum, never gain energy, and with a level line of
// centres and no friction reduce to the 1-D law.
TEST(Airborne, ImpulsesKeepTheirLaws) {
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    Vec3 n{u(g), u(g), u(g)};
    const double len = std::sqrt(dot3(n, n));
    if (len < 0.1) continue;
    n = n * (1.0 / len);
    const Motion3 in{{3 * u(g), 3 * u(g), 3 * u(g)}, {100 * u(g), 100 * u(g), 100 * u(g)}};
    const double e = 0.5 * (u(g) + 1.0);
    const double mu = 0.5 * (u(g) + 1.0);
    const Motion3 out = fixed_contact_impact(in, n, kR, e, mu);
    const double vn = dot3(in.velocity, n);
    if (vn < 0.0) {
      EXPECT_NEAR(dot3(out.velocity, n), -e * vn, 1e-12);
    } else {
      EXPECT_EQ(out.velocity, in.velocity);
    }
    EXPECT_LE(energy(out, 0.17, kR), energy(in, 0.17, kR) * (1 + 1e-12) + 1e-15);

    const Motion3 m2{{3 * u(g), 3 * u(g), 3 * u(g)}, {100 * u(g), 100 * u(g), 100 * u(g)}};
    const Vec3 c1{0, 0, 0};
    const Vec3 c2 = n * (2 * kR);
    const Impact3 r =
        ball_ball_impact_3d(c1, in, 0.17, kR, c2, m2, 0.16, kR, e, BallFriction{mu, 0.0, 0.0});
    const Vec3 p0 = in.velocity * 0.17 + m2.velocity * 0.16;
    const Vec3 p1 = r.a.velocity * 0.17 + r.b.velocity * 0.16;
    EXPECT_NEAR(p0.x, p1.x, 1e-12);
    EXPECT_NEAR(p0.y, p1.y, 1e-12);
    EXPECT_NEAR(p0.z, p1.z, 1e-12);
    EXPECT_LE(energy(r.a, 0.17, kR) + energy(r.b, 0.16, kR),
              (energy(in, 0.17, kR) + energy(m2, 0.16, kR)) * (1 + 1e-12) + 1e-15);
  }
  // Sticking on the slate: a sliding ball with little speed into it.
  const Motion3 slide{{1.0, 0.0, -3.0}, {0.0, 0.0, 0.0}};
  const Motion3 stuck = fixed_contact_impact(slide, {0, 0, 1}, kR, 0.5, 0.5);
  EXPECT_NEAR(stuck.velocity.x - kR * stuck.spin.y, 0.0, 1e-12);
  EXPECT_NEAR(stuck.velocity.x, 5.0 / 7.0, 1e-12);
  // Level, frictionless, equal masses, e = 1: the balls swap velocities.
  const Impact3 swap =
      ball_ball_impact_3d({0, 0, kR}, {{2.0, 0.0, 0.0}, {}}, 0.17, kR, {2 * kR, 0, kR},
                          {{0.0, 0.0, 0.0}, {}}, 0.17, kR, 1.0, BallFriction{0.0, 0.0, 0.0});
  EXPECT_NEAR(swap.a.velocity.x, 0.0, 1e-15);
  EXPECT_NEAR(swap.b.velocity.x, 2.0, 1e-15);
}

// A ball in flight that comes down on a ball on the cloth and rests on it
// (a raised, drawn stroke into a loose cluster, found by random play): the
// pair is pressed together by gravity, so it leaves each contact at
// collapse_speed and the top ball slides off in a few dozen contacts,
// instead of meeting the other again at the same instant forever.
TEST(Airborne, ABallRestingOnAnotherSlidesOff) {
  std::ifstream in(std::string(BREAKSHOT_SOURCE_DIR) + "/tests/data/airborne_rest_on_ball.json");
  ASSERT_TRUE(in.good());
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Scenario s = scenario(text);
  Simulation sim(s);
  ASSERT_EQ(sim.advance_to_rest(), StopReason::reached);
  int contacts = 0;
  double last = -1.0;
  int same_instant = 0;
  for (const Event& e : sim.events()) {
    if (e.type != EventType::ball_ball || e.ball != 0 || e.other != 6) continue;
    ++contacts;
    if (e.time == last) ++same_instant;
    last = e.time;
  }
  EXPECT_GT(contacts, 5);      // it did land on the 6 and stay on it a while
  EXPECT_LT(contacts, 200);    // and slid off
  EXPECT_EQ(same_instant, 0);  // never twice at one instant
  EXPECT_LT(sim.event_count(), 1000u);
}

}  // namespace test_airborne
