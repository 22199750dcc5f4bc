// Throw in the engine (reader + Simulation) against the throw measured on
// real balls: Alciatore, TP B-3 "Throw calibration and contour plots"
// (2008), Colin Colenso's measurements, and Alciatore's refit of
// mu(v) = a + b exp(-c v) to them (kThrowFitTPB3).
//
// TP B-3's table (stun shots; throw in inches per yard of object ball
// travel), as transcribed with the document's page and revision in
// nicolas-found42/pool-game (tools/benchmark/gen_curves.py); TP B-3 itself
// was not at hand here:
//
//   cue ball speed            30 deg cut   45 deg cut
//   4 km/h  (1.111 m/s)       4.8          5.6
//   8 km/h  (2.222 m/s)       3.5          3.0
//   12 km/h (3.333 m/s)       3.0          2.3
//
// An angle is atan(inches / 36). Fit: a = 0.016, b = 0.219, c = 0.691.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include "breakshot/physics.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"

namespace test_throw {

using namespace breakshot;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.028575;

double deg(double rad) { return rad * 180.0 / kPi; }

// The object ball's angle off the line of centres (degrees) when a stun
// cue ball at `speed` cuts it at `cut` degrees, with `friction` the JSON
// of physics.ball_ball_friction ("" for the default).
double simulated_throw(double speed, double cut, const std::string& friction) {
  const double c = cut * kPi / 180.0;
  // The cue ball starts a micrometre short of contact, moving at the cut
  // angle to the line of centres (+x).
  const double gap = 1e-6;
  const std::string text =
      R"({"physics": {"model": "pool", "ball_ball_restitution": 1.0)" +
      (friction.empty() ? std::string() : ", \"ball_ball_friction\": " + friction) +
      R"(}, "table": {"shape": "rectangle", "min": [-20, -20], "max": [20, 20]},
        "balls": [
          {"id": "cue", "position": [)" + std::to_string(-(2 * kR + gap)) + R"(, 0],
           "velocity": [)" + std::to_string(speed * std::cos(c)) + ", " +
      std::to_string(speed * std::sin(c)) + R"(]},
          {"id": "obj", "position": [0, 0]}],
        "until": {"time": 0.01}})";
  auto parsed = read_scenario(text);
  if (const auto* e = std::get_if<ScenarioError>(&parsed)) {
    ADD_FAILURE() << e->path << ": " << e->reason;
    return 0.0;
  }
  Simulation sim(std::get<Scenario>(parsed));
  for (int k = 0; k < 10; ++k) {
    const std::size_t before = sim.events().size();
    sim.advance_to(sim.next_event_time());
    for (std::size_t i = before; i < sim.events().size(); ++i) {
      if (sim.events()[i].type == EventType::ball_ball) {
        const Vec2 n = sim.ball(1).position - sim.ball(0).position;  // at contact
        const Vec2 v = sim.ball(1).velocity;
        return deg(std::atan2(n.x * v.y - n.y * v.x, n.x * v.x + n.y * v.y));
      }
    }
  }
  ADD_FAILURE() << "no impact";
  return 0.0;
}

std::string curve_json(const FrictionCurve& k) {
  return R"({"a": )" + std::to_string(k.a) + R"(, "b": )" + std::to_string(k.b) + R"(, "c": )" +
         std::to_string(k.c) + "}";
}

struct Measured {
  double kmh, cut, inches_per_yard;
};
constexpr Measured kTpB3[] = {
    {4.0, 30.0, 4.8}, {4.0, 45.0, 5.6}, {8.0, 30.0, 3.5},
    {8.0, 45.0, 3.0}, {12.0, 30.0, 3.0}, {12.0, 45.0, 2.3},
};

double measured_deg(const Measured& m) { return deg(std::atan(m.inches_per_yard / 36.0)); }

}  // namespace

TEST(Throw, TheTpB3FitReproducesColensosMeasurements) {
  // With Alciatore's refit set explicitly, the simulated throw is within
  // 0.9 deg of every measured point that a stun shot can reach, which is
  // the fit's own residual in TP A-14's closed form (0.84 deg at most; the
  // engine gives that closed form to 1e-9, BallBallImpact tests). A stun
  // shot cannot throw more than atan(tan(cut) / 7), where the friction has
  // stopped the slip (4.715 deg at 30 deg, whatever the friction): the
  // slowest 30-degree point (7.6 deg measured) lies above that limit, and
  // there the simulation must sit at the limit. (The cue ball starts a
  // micrometre short of contact, so the cut at contact differs from the
  // nominal one by about 5e-4 deg: the limit is checked to 1e-3 deg.)
  ASSERT_EQ(kThrowFitTPB3, (FrictionCurve{0.016, 0.219, 0.691}));
  const std::string fit = curve_json(kThrowFitTPB3);
  for (const Measured& m : kTpB3) {
    const double v = m.kmh / 3.6;
    const double sim = simulated_throw(v, m.cut, fit);
    const double want = measured_deg(m);
    const double limit = deg(std::atan(std::tan(m.cut * kPi / 180.0) / 7.0));
    EXPECT_LE(sim, limit + 1e-3) << m.kmh << " km/h, " << m.cut << " deg";
    if (want > limit + 0.9) {
      EXPECT_NEAR(sim, limit, 1e-3) << m.kmh << " km/h, " << m.cut << " deg";
    } else {
      EXPECT_NEAR(sim, want, 0.9) << m.kmh << " km/h, " << m.cut << " deg";
    }
  }
}

TEST(Throw, CleanBallCurveIsTwoToThreeAndAHalfTimesBelowTheMeasurements) {
  // The clean-ball curve set explicitly (TP A-28, kThrowFitTPA28; breakshot
  // 0.1's default) at the same shots: 3.9, 3.2, 2.4, 1.7, 1.6, 1.0 deg
  // against the measured 7.6, 8.8, 5.6, 4.8, 4.8, 3.7 (ratios 1.9 to 3.5).
  const double expected[] = {3.945, 3.199, 2.416, 1.689, 1.579, 1.046};
  int k = 0;
  for (const Measured& m : kTpB3) {
    const double sim = simulated_throw(m.kmh / 3.6, m.cut, curve_json(kThrowFitTPA28));
    EXPECT_NEAR(sim, expected[k++], 0.005) << m.kmh << " km/h, " << m.cut << " deg";
    const double ratio = measured_deg(m) / sim;
    EXPECT_GT(ratio, 1.9) << m.kmh << " km/h, " << m.cut << " deg";
    EXPECT_LT(ratio, 3.6) << m.kmh << " km/h, " << m.cut << " deg";
    // The default is the measured table's curve (TP B-3), bit for bit.
    EXPECT_EQ(simulated_throw(m.kmh / 3.6, m.cut, ""),
              simulated_throw(m.kmh / 3.6, m.cut, curve_json(kThrowFitTPB3)));
  }
}

TEST(Throw, ConstantFrictionGivesTpA14sFrictionLimitedThrow) {
  // A constant mu: stun throw at a cut beyond the no-slip limit is
  // tan(throw) = mu (TP A-14 with e = 1).
  const double t = simulated_throw(2.0, 60.0, "0.05");
  EXPECT_NEAR(std::tan(t * kPi / 180.0), 0.05, 1e-6);
  // Frictionless: no throw.
  EXPECT_NEAR(simulated_throw(2.0, 45.0, "0"), 0.0, 1e-9);
}

}  // namespace test_throw
