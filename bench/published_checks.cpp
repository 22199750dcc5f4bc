// Not a benchmark: the engine's figures beside the published ones that
// its defaults are checked against (docs/physics.md, "Published checks of
// the defaults"). Each line prints the published figure, where it comes
// from, and what the engine gives with its defaults (and with the
// alternatives the section compares).
//
//   build/release/bench/published_checks
//
// Deterministic: the same lines on every run.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "breakshot/physics.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"

using namespace breakshot;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.028575;
constexpr double kM = 0.170;

double deg(double rad) { return rad * 180.0 / kPi; }

/// Physics of the pool model with the defaults, then `change` applied.
template <class F>
PhysicsParams pool_physics(F change) {
  PhysicsParams p = default_physics(Model::pool);
  change(p);
  return p;
}

Scenario open_field(const PhysicsParams& physics) {
  Scenario s;
  s.physics = physics;
  s.table = make_rectangle({-40, -40}, {40, 40});
  s.until.rest = true;
  return s;
}

void add(Scenario& s, const char* id, Vec2 p, Vec2 v, Vec3 w) {
  s.balls.push_back({id, kR, kM, 0.8});
  BallState st;
  st.position = p;
  st.velocity = v;
  st.spin = w;
  s.start.push_back(st);
}

/// The cue ball's deflection (degrees off its first direction) when it
/// rolls at `speed` into an object ball at a cut of `cut` degrees: its
/// direction once it rolls again after the impact.
double rolling_deflection(const PhysicsParams& physics, double speed, double cut) {
  const double c = cut * kPi / 180.0;
  Scenario s = open_field(physics);
  add(s, "cue", {0, 0}, {speed, 0}, {0, speed / kR, 0});
  // A micrometre short of contact along the line of the cut.
  add(s, "obj", {2 * kR * std::cos(c) + 1e-6, 2 * kR * std::sin(c)}, {0, 0}, {0, 0, 0});
  Simulation sim(s);
  sim.advance_to_rest();
  double hit = -1.0;
  double rolls = -1.0;
  for (const Event& e : sim.events()) {
    if (e.type == EventType::ball_ball && hit < 0.0) hit = e.time;
    if (hit >= 0.0 && e.type == EventType::state_change && e.ball == 0 &&
        e.to == MotionState::rolling) {
      rolls = e.time;
      break;
    }
  }
  if (rolls < 0.0) return std::nan("");
  Simulation again(s);
  again.advance_to(rolls);
  const Vec2 v = again.ball(0).velocity;
  return deg(std::atan2(-v.y, v.x));
}

/// The object ball's angle off the line of centres (degrees) when a stun
/// cue ball at `speed` cuts it at `cut` degrees (the throw).
double stun_throw(const PhysicsParams& physics, double speed, double cut) {
  const double c = cut * kPi / 180.0;
  Scenario s = open_field(physics);
  s.until.rest = false;
  s.until.time = 0.01;
  add(s, "cue", {-(2 * kR + 1e-6), 0}, {speed * std::cos(c), speed * std::sin(c)}, {0, 0, 0});
  add(s, "obj", {0, 0}, {0, 0}, {0, 0, 0});
  Simulation sim(s);
  sim.advance_to(0.01);
  const Vec2 v = sim.ball(1).velocity;
  return deg(std::atan2(v.y, v.x));
}

double mu_of(const FrictionCurve& k, double v) { return k.a + k.b * std::exp(-k.c * v); }

}  // namespace

int main() {
  const PhysicsParams def = default_physics(Model::pool);

  std::printf("# Spin about the vertical: Alciatore's property constants, 5-15 rad/s^2\n");
  std::printf("ball      R (mm)   default (rad/s^2)   legacy 0.044 (rad/s^2)\n");
  for (const auto& [name, r] : {std::pair{"pool", 0.028575}, std::pair{"snooker", 0.02625},
                                std::pair{"carom", 0.03075}}) {
    std::printf("%-8s %7.3f   %17.2f   %22.2f\n", name, r * 1e3,
                2.5 * def.spinning_friction * def.gravity / r,
                2.5 * kLegacySpinningFriction * def.gravity / r);
  }

  std::printf("\n# Ball-ball friction mu at a slip speed: Alciatore's property constants, "
              "0.03-0.08\n");
  std::printf("slip (m/s)   TP B-3 curve (default)   TP A-28 curve\n");
  for (const double v : {0.1, 0.5, 1.0, 2.0, 4.0}) {
    std::printf("%10.1f   %22.3f   %13.3f\n", v, mu_of(kThrowFitTPB3, v), mu_of(kThrowFitTPA28, v));
  }

  std::printf("\n# Stun throw (degrees, e = 1): TP B-3's table as transcribed, atan(in/yd / 36)\n");
  std::printf("speed (km/h)  cut   TP B-3     default    TP A-28    stun limit\n");
  const double table[3][2] = {{4.8, 5.6}, {3.5, 3.0}, {3.0, 2.3}};
  const PhysicsParams stun_b3 = pool_physics([](PhysicsParams& p) {
    p.ball_ball_restitution = 1.0;
  });
  const PhysicsParams stun_a28 = pool_physics([](PhysicsParams& p) {
    p.ball_ball_restitution = 1.0;
    p.ball_ball_friction_curve = kThrowFitTPA28;
  });
  for (int i = 0; i < 3; ++i) {
    const double kmh = 4.0 * (i + 1);
    for (int j = 0; j < 2; ++j) {
      const double cut = j == 0 ? 30.0 : 45.0;
      std::printf("%12.0f  %4.0f  %7.2f  %9.2f  %9.2f  %12.2f\n", kmh, cut,
                  deg(std::atan(table[i][j] / 36.0)), stun_throw(stun_b3, kmh / 3.6, cut),
                  stun_throw(stun_a28, kmh / 3.6, cut),
                  deg(std::atan(std::tan(cut * kPi / 180.0) / 7.0)));
    }
  }

  std::printf("\n# Rolling cue ball's deflection (degrees): TP A-4's frictionless, elastic "
              "theory,\n# 33.7 at a half-ball hit (30 deg cut), 27.3 and 27.6 at 1/4- and "
              "3/4-ball hits\n");
  const PhysicsParams ideal = pool_physics([](PhysicsParams& p) {
    p.ball_ball_restitution = 1.0;
    p.ball_ball_friction_fit = false;
    p.ball_ball_friction = 0.0;
  });
  const PhysicsParams tpa28 = pool_physics([](PhysicsParams& p) {
    p.ball_ball_friction_curve = kThrowFitTPA28;
  });
  const PhysicsParams constant = pool_physics([](PhysicsParams& p) {
    p.ball_ball_friction_fit = false;
    p.ball_ball_friction = 0.06;
  });
  std::printf("cut    theory  speed   frictionless  default (TP B-3)  TP A-28   mu = 0.06\n");
  for (const double cut : {14.4775, 30.0, 48.5904}) {
    const double p = cut * kPi / 180.0;
    const double theory =
        deg(std::atan(std::sin(p) * std::cos(p) / (std::sin(p) * std::sin(p) + 0.4)));
    for (const double v : {0.5, 1.0, 1.5, 2.0, 3.0}) {
      std::printf("%5.1f  %6.2f  %5.1f  %12.2f  %16.2f  %8.2f  %10.2f\n", cut, theory, v,
                  rolling_deflection(ideal, v, cut), rolling_deflection(def, v, cut),
                  rolling_deflection(tpa28, v, cut), rolling_deflection(constant, v, cut));
    }
  }
  return 0;
}
