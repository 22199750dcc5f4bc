// Tests of the stronge_compliant cushion law (src/physics/cushion.cpp,
// part 5): Stronge's compliant contact (W. J. Stronge, "Impact
// Mechanics", Cambridge UP 2000/2018, ch. 5; Stronge, James and Ravani,
// Phil. Trans. R. Soc. A 359 (2001)) at the nose, the ball held on the
// cloth. With the nose at the centre's height (t = 0) and a slip along
// the rail (w_x = w_y = 0), the held ball's contact has inverse masses 1
// (normal) and 7/2 (along the rail), as a free sphere on a half-space,
// and the book's closed forms apply; those are checked here, together
// with energy, the rigid limit (eta^2 -> 0: mathavan_2010's nose without
// cloth friction) and the scenario format.
//
// Frame: the rail at +x (normal n = (-1, 0) into the table), so the
// local frame is x towards the rail, y along it.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "breakshot/pool.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/vec.hpp"

namespace test_cushion_stronge {

namespace {

namespace bs = breakshot;
using bs::cushion_impact;
using bs::CushionImpact;
using bs::CushionModel;
using bs::CushionParams;
using bs::Vec2;
using bs::Vec3;
using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMass = 0.17;
constexpr double kR = 0.028575;
const Vec2 kN{-1.0, 0.0};

CushionParams stronge(double e, double mu, double eta2, double nose = 0.635) {
  CushionParams p;
  p.model = CushionModel::stronge_compliant;
  p.restitution = e;
  p.friction = mu;
  p.compliance_ratio = eta2;
  p.nose_height = nose;
  return p;
}

double energy(Vec2 v, Vec3 w) {  // per unit mass
  return 0.5 * dot(v, v) + 0.2 * kR * kR * (w.x * w.x + w.y * w.y + w.z * w.z);
}

// At t = 0 without friction the normal spring alone acts: the ball
// leaves with -e v_x (the unloading line gives back e^2 of the stored
// energy), its tangential velocity and spin untouched.
TEST(CushionStronge, FrictionlessAtCentreHeightIsReflectionScaledByE) {
  for (const double e : {1.0, 0.85, 0.3}) {
    const CushionParams p = stronge(e, 0.0, 1.08, 0.5);
    const Vec2 v{1.3, -0.4};
    const Vec3 w{3.0, -20.0, 50.0};
    const CushionImpact r = cushion_impact(v, w, kN, kMass, kR, p);
    EXPECT_NEAR(r.velocity.x, -e * 1.3, 1e-12) << e;
    EXPECT_NEAR(r.velocity.y, -0.4, 1e-12);
    EXPECT_NEAR(r.spin.x, 3.0, 1e-10);
    EXPECT_NEAR(r.spin.y, -20.0, 1e-10);
    EXPECT_NEAR(r.spin.z, 50.0, 1e-10);
  }
  // e = 0: the impact ends at the largest compression, nothing comes back.
  const CushionImpact r0 =
      cushion_impact({1.0, 0.0}, {}, kN, kMass, kR, stronge(0.0, 0.0, 1.08, 0.5));
  EXPECT_NEAR(r0.velocity.x, 0.0, 1e-12);
}

// A restitution so small that 1/e^2 overflows: the impact still ends at
// the largest compression with finite numbers (as e = 0), on the impact
// and in a run that a scenario sets up with it.
TEST(CushionStronge, TinyRestitutionStaysFinite) {
  for (const double e : {1e-90, 1e-100, 1e-160, 1e-200, 5e-324}) {
    const CushionImpact r = cushion_impact({1.0, 0.3}, {-10.0, 35.0, 40.0}, kN, kMass, kR,
                                           stronge(e, 0.14, 1.08));
    EXPECT_TRUE(std::isfinite(r.velocity.x) && std::isfinite(r.velocity.y)) << e;
    EXPECT_TRUE(std::isfinite(r.spin.x) && std::isfinite(r.spin.y) && std::isfinite(r.spin.z))
        << e;
    EXPECT_LE(r.velocity.x, 1e-12) << e;  // never into the rail
  }
  auto parsed = bs::read_scenario(R"({"physics": {"model": "pool"},
    "table": {"shape": "pool", "size": "9ft", "cushion_model": "stronge_compliant",
              "cushion_restitution": 1e-200},
    "balls": [{"id": "cue", "position": [0.9, 0.35]}],
    "cue": {"ball": "cue", "speed": 3.0, "phi": 30.0, "theta": 0.0, "a": 0.3, "b": 0.1}})");
  ASSERT_TRUE(std::holds_alternative<bs::Scenario>(parsed));
  const bs::RunResult run = bs::simulate(std::get<bs::Scenario>(parsed));
  EXPECT_TRUE(run.complete);
  for (const bs::BallState& b : run.final_balls) {
    EXPECT_TRUE(std::isfinite(b.position.x) && std::isfinite(b.position.y));
  }
}

// Gross slip (Stronge's condition u0/a0 > mu ((1 + e) beta - eta^2 / e),
// beta = 7/2 along the rail): friction mu F throughout, so the slip drops
// by beta mu (1 + e) a0 and v_y by mu (1 + e) v_x, w_z by (5/2R) times
// that: the rigid law's Coulomb slide. At 1 m/s, mu = 0.14, e = 0.85,
// eta^2 = 1.08 the threshold is 0.14 (1.85 * 3.5 - 1.271) = 0.729; the
// slip here is 2.0. Along t2 (vertical at t = 0) the held ball answers
// with 5/2 (the slate takes the linear part), and the same form holds.
TEST(CushionStronge, GrossSlipIsCoulombSlide) {
  const double e = 0.85;
  const double mu = 0.14;
  const CushionParams p = stronge(e, mu, 1.08, 0.5);
  const CushionImpact r = cushion_impact({1.0, 0.5}, {0.0, 0.0, 1.5 / kR}, kN, kMass, kR, p);
  const double dp = mu * (1.0 + e) * 1.0;  // friction impulse per unit mass
  EXPECT_NEAR(r.velocity.x, -e, 1e-9);
  EXPECT_NEAR(r.velocity.y, 0.5 - dp, 1e-5);
  EXPECT_NEAR(r.spin.z * kR, 1.5 - 2.5 * dp, 1e-5);
  // Slip along t2: u2 = -R w_y = -2.0 (w_y = 2/R, topspin-like sense).
  const CushionImpact r2 = cushion_impact({1.0, 0.0}, {0.0, 2.0 / kR, 0.0}, kN, kMass, kR, p);
  EXPECT_NEAR(r2.velocity.x, -e, 1e-9);
  EXPECT_NEAR(r2.spin.y * kR, 2.0 - 2.5 * dp, 1e-5);
}

// A perfectly rough contact (mu large: the particle sticks all through)
// turns the slip like the tangential oscillator: u_f = u0 cos(wt T),
// wt = sqrt(beta / eta^2) in units of the normal frequency, T = (1 + e)
// pi / 2 the impact's duration. With e = 1 and eta^2 = beta = 7/2 the two
// periods are equal and the slip reverses exactly (u_f = -u0, no energy
// lost: the rough elastic sphere); at eta^2 = 7/8 (wt = 2) it comes back
// unchanged; at pooltool's eta^2 = 3.5 / 1.8^2 and e = 0.85,
// cos(1.8 * 1.85 pi / 2) = -0.4258... The slip is along the rail
// (v_y + R w_z), 0.05 of the approach speed.
TEST(CushionStronge, StickingSlipOscillatesAndReverses) {
  struct Case {
    double e, eta2;
  };
  for (const Case k : {Case{1.0, 3.5}, Case{1.0, 0.875}, Case{0.85, bs::kStrongeComplianceRatio},
                       Case{0.6, 1.5}}) {
    const CushionParams p = stronge(k.e, 1e4, k.eta2, 0.5);
    const double u0 = 0.05;
    const CushionImpact r = cushion_impact({1.0, u0}, {}, kN, kMass, kR, p);
    const double uf = r.velocity.y + kR * r.spin.z;
    const double expected = u0 * std::cos(std::sqrt(3.5 / k.eta2) * (1.0 + k.e) * kPi / 2.0);
    // The scheme's error is first order here: the spring still holds
    // f_end = kt (u0 / wt) sin(wt T) when the cap closes, which the last
    // step applies for up to h = pi / 512 (in 1/sqrt(k)), moving u by about
    // 7/2 h f_end / 2 < 3e-4 at u0 = 0.05; the cosines compared differ by
    // 0.4 u0 and more between the cases.
    EXPECT_NEAR(uf, expected, 1e-2 * u0) << k.e << " " << k.eta2;
    EXPECT_NEAR(r.velocity.x, -k.e, 1e-9);
  }
  const CushionImpact rr =
      cushion_impact({1.0, 0.05}, {}, kN, kMass, kR, stronge(1.0, 1e4, 3.5, 0.5));
  EXPECT_NEAR(rr.velocity.y + kR * rr.spin.z, -0.05, 1e-4);
  EXPECT_NEAR(energy(rr.velocity, rr.spin), energy({1.0, 0.05}, {}), 1e-6);
}

// Stick, then slip (Stronge's regime u0/a0 < mu eta^2, pooltool's
// "stick-slip case"): with the normal force F(t) = sin t while
// compressing (k = 1, a0 = 1) and cos((t - pi/2) / e) after, the
// particle sticks while |kt (u0/wt) sin(wt t)| <= mu F(t); from the first
// time ts that fails the slider slips to the end with the friction
// -sign(sin(wt ts)) mu F, so u_f = u0 cos(wt ts) - sign(sin(wt ts)) beta
// mu e (1 - sin((ts - pi/2)/e)). ts is found here by bisection; the law
// integrates in time and must agree.
TEST(CushionStronge, StickThenSlipMatchesClosedForm) {
  const double e = 0.85;
  const double mu = 0.2;
  const double eta2 = bs::kStrongeComplianceRatio;
  const double kt = 1.0 / eta2;
  const double wt = std::sqrt(3.5 * kt);
  const double T = (1.0 + e) * kPi / 2.0;
  auto force = [&](double t) {
    return t <= kPi / 2.0 ? std::sin(t) : std::cos((t - kPi / 2.0) / e);
  };
  for (const double u0 : {0.02, 0.1, 0.2}) {
    ASSERT_LT(u0, mu * eta2);  // sticks at first
    auto sticks = [&](double t) {
      return kt * u0 / wt * std::abs(std::sin(wt * t)) <= mu * force(t);
    };
    double lo = 1e-6;
    double hi = lo;
    for (int i = 1; i <= 100000; ++i) {
      hi = T * i / 100000.0;
      if (!sticks(hi)) break;
      lo = hi;
    }
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (sticks(mid) ? lo : hi) = mid;
    }
    const double ts = lo;
    ASSERT_GT(ts, kPi / 2.0);  // slip begins in the restitution (pooltool's case)
    const double sgn = std::sin(wt * ts) > 0.0 ? 1.0 : -1.0;
    const double expected =
        u0 * std::cos(wt * ts) - sgn * 3.5 * mu * e * (1.0 - std::sin((ts - kPi / 2.0) / e));
    const CushionImpact r = cushion_impact({1.0, u0}, {}, kN, kMass, kR, stronge(e, mu, eta2, 0.5));
    EXPECT_NEAR(r.velocity.y + kR * r.spin.z, expected, 1e-3) << u0;
  }
}

// Energy never increases, over incidences, spins, speeds, restitutions,
// frictions, compliance ratios and nose heights.
TEST(CushionStronge, EnergyNeverIncreases) {
  int n = 0;
  for (const double nose : {0.5, 0.635, 0.8})
    for (const double e : {1.0, 0.85, 0.4})
      for (const double mu : {0.14, 0.6})
        for (const double eta2 : {0.05, 1.08, 3.5})
          for (int deg = 0; deg <= 85; deg += 17)
            for (const double speed : {0.3, 2.0})
              for (const Vec3 spin : {Vec3{0, 1, 0}, Vec3{0, 0, 0}, Vec3{0, -1, 0},
                                      Vec3{0.3, 1, 1.5}, Vec3{0, 2, -2}}) {
                const double a = deg * kPi / 180.0;
                const Vec2 v{speed * std::cos(a), speed * std::sin(a)};
                // spin in units of speed / R: (0, 1, 0) rolls straight in
                const Vec3 w{(spin.x - spin.y * std::sin(a)) * speed / kR,
                             spin.y * std::cos(a) * speed / kR, spin.z * speed / kR};
                const CushionImpact r =
                    cushion_impact(v, w, kN, kMass, kR, stronge(e, mu, eta2, nose));
                const double e0 = energy(v, w);
                EXPECT_LE(energy(r.velocity, r.spin), e0 * (1.0 + 1e-8))
                    << nose << " " << e << " " << mu << " " << eta2 << " " << deg;
                EXPECT_LE(r.velocity.x, 1e-12 * speed);
                ++n;
              }
  EXPECT_EQ(n, 3 * 3 * 2 * 3 * 6 * 2 * 5);
}

// The law is homogeneous in the speed (k drops out, every step is linear
// in the state): doubling velocity and spin doubles the result exactly,
// bit for bit, since doubling is exact in binary. Mirroring the shot
// along the rail mirrors the result exactly.
TEST(CushionStronge, HomogeneousAndMirrorSymmetric) {
  const CushionParams p = stronge(0.85, 0.14, 1.08);
  const Vec2 v{0.8, 0.45};
  const Vec3 w{-10.0, 25.0, 30.0};
  const CushionImpact r = cushion_impact(v, w, kN, kMass, kR, p);
  const CushionImpact r2 = cushion_impact(v * 2.0, {2 * w.x, 2 * w.y, 2 * w.z}, kN, kMass, kR, p);
  EXPECT_EQ(r2.velocity.x, 2.0 * r.velocity.x);
  EXPECT_EQ(r2.velocity.y, 2.0 * r.velocity.y);
  EXPECT_EQ(r2.spin.x, 2.0 * r.spin.x);
  EXPECT_EQ(r2.spin.y, 2.0 * r.spin.y);
  EXPECT_EQ(r2.spin.z, 2.0 * r.spin.z);
  // Mirror y -> -y: v_y, w_x and w_z change sign.
  const CushionImpact m = cushion_impact({v.x, -v.y}, {-w.x, w.y, -w.z}, kN, kMass, kR, p);
  EXPECT_EQ(m.velocity.x, r.velocity.x);
  EXPECT_EQ(m.velocity.y, -r.velocity.y);
  EXPECT_EQ(m.spin.x, -r.spin.x);
  EXPECT_EQ(m.spin.y, r.spin.y);
  EXPECT_EQ(m.spin.z, -r.spin.z);
}

// Rigid limit: as eta^2 -> 0 the tangential spring stores nothing and
// the law is the rigid one with Coulomb friction at the nose and
// energetic restitution, i.e. mathavan_2010 with no cloth friction
// (src/physics/cushion.cpp, part 3). At eta^2 = 0.01 they agree within
// 0.01 m/s over incidences and spins at 1 m/s, with the nose tilted.
TEST(CushionStronge, SmallComplianceRatioIsTheRigidLaw) {
  CushionParams rigid;
  rigid.model = CushionModel::mathavan_2010;
  rigid.restitution = 0.85;
  rigid.friction = 0.2;
  rigid.cloth_friction = 0.0;
  rigid.nose_height = 0.635;
  const CushionParams p = stronge(0.85, 0.2, 0.01);
  double worst = 0.0;
  for (int deg = 0; deg <= 80; deg += 10) {
    for (const double roll : {1.0, 0.0, -0.5}) {
      for (const double side : {0.0, 1.0, -1.0}) {
        const double a = deg * kPi / 180.0;
        const Vec2 v{std::cos(a), std::sin(a)};
        const Vec3 w{-roll * v.y / kR, roll * v.x / kR, side / kR};
        const CushionImpact r = cushion_impact(v, w, kN, kMass, kR, p);
        const CushionImpact q = cushion_impact(v, w, kN, kMass, kR, rigid);
        worst = std::max(
            {worst, std::abs(r.velocity.x - q.velocity.x), std::abs(r.velocity.y - q.velocity.y)});
        EXPECT_NEAR(r.velocity.x, q.velocity.x, 0.01) << deg << " " << roll << " " << side;
        EXPECT_NEAR(r.velocity.y, q.velocity.y, 0.01) << deg << " " << roll << " " << side;
        EXPECT_NEAR(r.spin.z * kR, q.spin.z * kR, 0.02) << deg << " " << roll << " " << side;
      }
    }
  }
  // ... and the compliance matters away from that limit: a small slip
  // along the rail (0.1 of the approach speed, no spin) sticks in the
  // rigid law (the slip stops) but swings back at eta^2 = 7/2 (nearly
  // u0 cos(1.85 pi / 2) = -0.97 u0), so v_y differs by about 2/7 of 0.1.
  const CushionImpact d = cushion_impact({1.0, 0.1}, {}, kN, kMass, kR, stronge(0.85, 0.2, 3.5));
  const CushionImpact q = cushion_impact({1.0, 0.1}, {}, kN, kMass, kR, rigid);
  EXPECT_GT(std::abs(d.velocity.y - q.velocity.y), 0.02);
  RecordProperty("worst", std::to_string(worst));
}

Vec2 rebound(double deg, const CushionParams& p, double& speed) {
  const double a = deg * kPi / 180.0;
  const Vec2 v{std::cos(a), std::sin(a)};
  const CushionImpact r = cushion_impact(v, {-v.y / kR, v.x / kR, 0.0}, kN, kMass, kR, p);
  speed = std::hypot(r.velocity.x, r.velocity.y);
  return r.velocity;
}

// The figures of docs/physics.md, "Cushions": a rolling ball at 1 m/s,
// the law at its scenario defaults (e = 0.85, mu = 0.14, eta^2 = 1.080,
// nose 0.635): rebound angle from the normal at 30/40/50 degrees and the
// straight-in speed ratio.
TEST(CushionStronge, DefaultRebounds) {
  CushionParams p;
  p.model = CushionModel::stronge_compliant;
  p.restitution = bs::default_cushion_restitution(CushionModel::stronge_compliant);
  EXPECT_EQ(p.restitution, 0.85);
  EXPECT_EQ(p.compliance_ratio, 3.5 / 3.24);
  double speed = 0.0;
  rebound(0.0, p, speed);
  EXPECT_NEAR(speed, 0.850, 0.0005);
  const double want[] = {27.0, 37.7, 49.1};
  const double deg[] = {30.0, 40.0, 50.0};
  for (int i = 0; i < 3; ++i) {
    const Vec2 v = rebound(deg[i], p, speed);
    EXPECT_NEAR(std::atan2(v.y, -v.x) * 180.0 / kPi, want[i], 0.05) << deg[i];
  }
}

// --- the scenario format ---------------------------------------------------

json rail_shot() {
  return json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "pool", "size": "9ft", "cushion_model": "stronge_compliant"},
    "balls": [{"id": "cue", "position": [0.635, 0.635], "velocity": [1.5, 0.9]}]
  })");
}

TEST(CushionStronge, ScenarioParsesAndRunsToRest) {
  auto r = bs::read_scenario(rail_shot().dump());
  ASSERT_TRUE(std::holds_alternative<bs::Scenario>(r)) << std::get<bs::ScenarioError>(r).reason;
  const bs::Scenario s = std::get<bs::Scenario>(r);
  EXPECT_EQ(s.table.cushion.model, CushionModel::stronge_compliant);
  EXPECT_EQ(s.table.cushion.restitution, 0.85);
  EXPECT_EQ(s.balls[0].wall_restitution, 0.85);
  EXPECT_EQ(s.table.cushion.compliance_ratio, bs::kStrongeComplianceRatio);
  const bs::RunResult run = bs::simulate(s);
  ASSERT_TRUE(run.complete);
  int cushions = 0;
  for (const bs::Event& ev : run.events) cushions += ev.type == bs::EventType::ball_cushion ? 1 : 0;
  EXPECT_GE(cushions, 2);
  EXPECT_EQ(run.final_balls[0].state, bs::MotionState::stationary);
  // The same run again: the same events, bit for bit.
  EXPECT_EQ(bs::simulate(s).events, run.events);

  json doc = rail_shot();
  doc["table"]["cushion_compliance_ratio"] = 1.5;
  auto r2 = bs::read_scenario(doc.dump());
  ASSERT_TRUE(std::holds_alternative<bs::Scenario>(r2));
  EXPECT_EQ(std::get<bs::Scenario>(r2).table.cushion.compliance_ratio, 1.5);
  const bs::RunResult run2 = bs::simulate(std::get<bs::Scenario>(r2));
  EXPECT_NE(run2.events, run.events);  // the ratio matters
}

void expect_error(const json& doc, const std::string& path, const std::string& part) {
  auto r = bs::read_scenario(doc.dump());
  ASSERT_TRUE(std::holds_alternative<bs::ScenarioError>(r)) << doc.dump();
  const bs::ScenarioError& e = std::get<bs::ScenarioError>(r);
  EXPECT_EQ(e.path, path) << e.reason;
  EXPECT_FALSE(e.unsupported);
  EXPECT_NE(e.reason.find(part), std::string::npos) << e.reason;
}

TEST(CushionStronge, BadComplianceRatioNamesThePath) {
  const std::string path = "table.cushion_compliance_ratio";
  for (const double bad : {0.0, -1.0, 0.005, 101.0}) {
    json doc = rail_shot();
    doc["table"]["cushion_compliance_ratio"] = bad;
    expect_error(doc, path, "between 0.01 and 100");
  }
  json doc = rail_shot();
  doc["table"]["cushion_compliance_ratio"] = "soft";
  expect_error(doc, path, "expected a number");
  // Another law: refused, naming the law in use.
  doc = rail_shot();
  doc["table"]["cushion_model"] = "han_2005";
  doc["table"]["cushion_compliance_ratio"] = 1.2;
  expect_error(doc, path, "only the \"stronge_compliant\" cushion law");
  doc["table"].erase("cushion_model");
  expect_error(doc, path, "(table.cushion_model is \"han_2005\")");
  // A table without the pool model's cushions.
  doc = json::parse(R"({
    "physics": {"model": "friction"},
    "table": {"shape": "rectangle", "min": [0, 0], "max": [2, 1],
              "cushion_compliance_ratio": 1.2},
    "balls": [{"id": "a", "position": [1, 0.5]}]
  })");
  expect_error(doc, path, "only the pool model's cushions");
}

}  // namespace

}  // namespace test_cushion_stronge
