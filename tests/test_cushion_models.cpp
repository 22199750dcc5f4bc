// Tests of the selectable cushion laws (table.cushion_model, issue 22):
// han_2005_v0 (breakshot 0.1's law, the legacy one), han_2005 (the same
// impulse law with the slate's reaction, the default), mathavan_2010 (Mathavan,
// Jackson and Parkin, "A theoretical analysis of billiard ball dynamics
// under cushion impacts", Proc. IMechE C 224 (2010) 1863-1873; "Mathavan
// 2010" below), impulse_frictional (one frictional impulse with the
// slate's reaction) and stronge_compliant (its own tests:
// tests/test_cushion_stronge.cpp). Equations: src/physics/cushion.cpp.
//
// About Mathavan 2010's figures: their curves (Figs 8-11) exist only as
// images, which could not be retrieved here, so no digitized point is
// compared. No public text found quotes numbers read off them either
// (pooltool's mathavan_2010/_plots.py redraws the figures from its own
// model with the paper's constants, and quotes no value of the paper's). What is compared is what
// the paper states in its text about them and its constants (e = 0.98, mu_w = 0.14 fitted to the
// authors' measurements, mu_s = 0.212, h = 7R/5, R = 26.25 mm, M = 0.1406 kg), and the closed forms
// each law has in special cases.
//
// Frame: for a cushion with inward normal n, ex = -n (towards the rail),
// ey = perp(ex) (along it), z up; angles from the normal, positive
// towards +ey.
#include "breakshot/pool.hpp"
#include "breakshot/vec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace test_cushion_models {

namespace {

using breakshot::cushion_impact;
using breakshot::CushionImpact;
using breakshot::CushionModel;
using breakshot::CushionParams;
using breakshot::Vec2;
using breakshot::Vec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kMass = 0.17;     // kg, a pool ball
constexpr double kR = 0.028575;    // m, 2.25 in diameter
constexpr double kPaperR = 0.02625;  // Mathavan 2010's snooker ball (its radius)

constexpr CushionModel kModels[] = {CushionModel::han_2005_v0, CushionModel::han_2005,
                                    CushionModel::mathavan_2010, CushionModel::impulse_frictional,
                                    CushionModel::stronge_compliant};

/// Mathavan 2010's constants: e = 0.98, mu_w = 0.14, mu_s = 0.212,
/// h = 7R/5.
CushionParams paper(CushionModel m) {
  CushionParams p;
  p.model = m;
  p.restitution = 0.98;
  p.friction = 0.14;
  p.cloth_friction = 0.212;
  p.nose_height = 0.7;
  return p;
}

/// Each law at the defaults a scenario gives it (docs/scenario.md).
CushionParams defaults(CushionModel m) {
  CushionParams p;
  p.model = m;
  p.cloth_friction = 0.2;  // physics.sliding_friction
  p.restitution = breakshot::default_cushion_restitution(m);
  if (m == CushionModel::mathavan_2010) p.nose_height = breakshot::kMathavanNoseHeight;
  return p;
}

struct Rebound {
  double speed;
  double angle;  // degrees from the normal
  double vn;     // away from the rail
  double vt;     // along +ey
  Vec3 spin;
};

Vec2 unit(double a) { return {std::cos(a), std::sin(a)}; }

/// A ball at speed V, incidence inc (degrees from the normal, coming
/// along +ey), with topspin k V / R about the axis of a rolling ball
/// (k = 1: rolling) and side spin w_z = side V / R.
Rebound hit(const CushionParams& p, double V, double inc, double k, double side = 0.0,
            double radius = kR, double normal_angle = 0.4) {
  const Vec2 n = unit(normal_angle);
  const Vec2 ex = -n;
  const Vec2 ey = breakshot::perp(ex);
  const Vec2 v = ex * (V * std::cos(inc * kDeg)) + ey * (V * std::sin(inc * kDeg));
  const Vec2 wh = breakshot::perp(v) * (k / radius);
  const CushionImpact r = cushion_impact(v, {wh.x, wh.y, side * V / radius}, n, kMass, radius, p);
  const double vn = breakshot::dot(r.velocity, n);
  const double vt = breakshot::dot(r.velocity, ey);
  return {breakshot::norm(r.velocity), std::atan2(vt, vn) / kDeg, vn, vt, r.spin};
}

double energy(double m, double R, Vec2 v, Vec3 w) {
  return 0.5 * m * breakshot::norm2(v) + 0.2 * m * R * R * (w.x * w.x + w.y * w.y + w.z * w.z);
}

// The check: a ball driven straight into a cushion with
// restitution 1 and no friction comes back at its full speed. The legacy
// law gives 2 cos^2 t - 1 = 0.854 at the 63.5 % nose (the issue's
// figure), the corrected laws 1.
TEST(CushionModels, StraightInElasticFrictionless) {
  for (CushionModel m : kModels) {
    CushionParams p;
    p.model = m;
    p.restitution = 1.0;
    p.friction = 0.0;
    p.cloth_friction = 0.0;
    for (double k : {0.0, 1.0}) {  // stun and rolling: no friction, no spin effect
      const Rebound r = hit(p, 1.7, 0.0, k);
      const double ratio = r.vn / 1.7;
      if (m == CushionModel::han_2005_v0) {
        const double s = 2.0 * 0.635 - 1.0;
        EXPECT_NEAR(ratio, 2.0 * (1.0 - s * s) - 1.0, 1e-14);
        EXPECT_NEAR(ratio, 0.854, 0.0005);
      } else {
        EXPECT_NEAR(ratio, 1.0, 1e-12) << breakshot::cushion_model_name(m);
      }
    }
  }
}

// Frictionless, any restitution, nose and incidence: the corrected laws
// reverse the normal velocity times e and keep the rest (no friction, so
// no torque: the rail's normal passes through the centre, the slate's
// reaction too).
TEST(CushionModels, FrictionlessIsPlainRestitution) {
  for (CushionModel m :
       {CushionModel::han_2005, CushionModel::mathavan_2010, CushionModel::impulse_frictional}) {
    for (double e : {0.0, 0.5, 0.98}) {
      for (double nose : {0.55, 0.635, 0.7, 0.9}) {
        CushionParams p;
        p.model = m;
        p.restitution = e;
        p.friction = 0.0;
        p.cloth_friction = 0.0;
        p.nose_height = nose;
        const double V = 1.3;
        const double inc = 35.0;
        const Rebound r = hit(p, V, inc, 0.6, 0.8);
        EXPECT_NEAR(r.vn, e * V * std::cos(inc * kDeg), 1e-12 * V) << e << " " << nose;
        EXPECT_NEAR(r.vt, V * std::sin(inc * kDeg), 1e-12 * V);
      }
    }
  }
}

// han_2005, rolling straight in: it slides on the nose throughout (with
// the defaults), so by hand (src/physics/cushion.cpp, part 2)
//   v' / V = e + mu (1 + e) s / c
// = 0.912 at the defaults (e = 0.84, mu = 0.14, nose 63.5 %; 0.819 at
// e = 0.75); the legacy law gives (1 + e) c (c + mu s) - 1 = 0.686 at its
// 0.75.
TEST(CushionModels, Han2005RollingStraightInClosedForm) {
  const double s = 2.0 * 0.635 - 1.0;
  const double c = std::sqrt(1.0 - s * s);
  const double e = 0.84;
  ASSERT_EQ(breakshot::default_cushion_restitution(CushionModel::han_2005), e);
  for (double V : {0.5, 1.0, 2.0}) {
    const Rebound r = hit(defaults(CushionModel::han_2005), V, 0.0, 1.0);
    EXPECT_NEAR(r.vn / V, e + 0.14 * (1.0 + e) * s / c, 1e-13);
    const Rebound o = hit(defaults(CushionModel::han_2005_v0), V, 0.0, 1.0);
    EXPECT_NEAR(o.vn / V, 1.75 * c * (c + 0.14 * s) - 1.0, 1e-13);
  }
  EXPECT_NEAR(0.75 + 0.14 * 1.75 * s / c, 0.819, 0.0005);
}

// Kinetic energy never increases and the ball never leaves into the
// rail, over random impacts with any spin, restitution, friction and
// nose height, for the corrected laws.
TEST(CushionModels, RandomImpactsNeverGainEnergyNorEnterTheCushion) {
  std::mt19937_64 rng(2205);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (CushionModel m :
       {CushionModel::han_2005, CushionModel::mathavan_2010, CushionModel::impulse_frictional}) {
    const int count = m == CushionModel::mathavan_2010 ? 2000 : 20000;
    for (int i = 0; i < count; ++i) {
      CushionParams p;
      p.model = m;
      p.restitution = u01(rng);
      p.friction = 0.5 * u01(rng);
      p.cloth_friction = 0.5 * u01(rng);
      p.nose_height = 0.5 + 0.45 * u01(rng);
      const Vec2 n = unit(2.0 * kPi * u01(rng));
      const Vec2 ex = -n;
      const Vec2 ey = breakshot::perp(ex);
      const double V = 0.01 + 5.0 * u01(rng);
      const double inc = (u01(rng) * 2.0 - 1.0) * 89.0 * kDeg;
      const Vec2 v = ex * (V * std::cos(inc)) + ey * (V * std::sin(inc));
      const double wmax = 4.0 * V / kR;
      const Vec3 w{wmax * (2.0 * u01(rng) - 1.0), wmax * (2.0 * u01(rng) - 1.0),
                   wmax * (2.0 * u01(rng) - 1.0)};
      const CushionImpact r = cushion_impact(v, w, n, kMass, kR, p);
      const double before = energy(kMass, kR, v, w);
      const double after = energy(kMass, kR, r.velocity, r.spin);
      ASSERT_TRUE(std::isfinite(after));
      // Mathavan's explicit integration: within a part in 10^4.
      const double tol = m == CushionModel::mathavan_2010 ? 1e-4 : 1e-12;
      ASSERT_LE(after, before * (1.0 + tol)) << breakshot::cushion_model_name(m) << " " << i;
      ASSERT_GE(breakshot::dot(r.velocity, n), -1e-12 * V) << i;
    }
  }
}

// Mathavan 2010 on Fig. 8: "the rebound angle plots are identical for
// different ball speeds ... the rebound angle is influenced only by the
// incident angle for a rolling ball with no sidespin" (the paper's ball
// and constants, speeds up to its 2.5 m/s limit of the rigid cushion);
// and the rebound speed scales with the speed (the model is linear in it).
TEST(CushionModels, MathavanRollingReboundAngleDoesNotDependOnSpeed) {
  const CushionParams p = paper(CushionModel::mathavan_2010);
  for (double inc = 10.0; inc <= 80.0; inc += 10.0) {
    const Rebound ref = hit(p, 1.0, inc, 1.0, 0.0, kPaperR);
    for (double V : {0.25, 0.5, 1.5, 2.5}) {
      const Rebound r = hit(p, V, inc, 1.0, 0.0, kPaperR);
      EXPECT_NEAR(r.angle, ref.angle, 0.01) << inc << " " << V;
      EXPECT_NEAR(r.speed / V, ref.speed, 0.001) << inc << " " << V;
    }
  }
}

// Mathavan 2010 on Fig. 9: "The rebound angles are not greatly affected
// by the excessive topspin of the ball": k = 2 against rolling k = 1,
// within 5 degrees here (measured: 2.2 deg at 15, 4.7 at 30, 4.3 at 45,
// 2.5 at 60 deg); more topspin comes back faster.
TEST(CushionModels, MathavanExcessiveTopspin) {
  const CushionParams p = paper(CushionModel::mathavan_2010);
  for (double inc : {15.0, 30.0, 45.0, 60.0, 75.0}) {
    const Rebound roll = hit(p, 1.0, inc, 1.0, 0.0, kPaperR);
    const Rebound over = hit(p, 1.0, inc, 2.0, 0.0, kPaperR);
    EXPECT_NEAR(over.angle, roll.angle, 5.0) << inc;
    EXPECT_GT(over.speed, roll.speed) << inc;
  }
}

// Mathavan 2010 on Figs 10 and 11: with side spin of one sense "the
// rebound speed exceeds the value of the incident speed", and with the
// other "for incident angle values close to 90 deg [from the rail], the
// ball bounces back to the side from which it approached the cushion".
// Travelling along +ey, w_z < 0 is running english (the ball's surface at
// the rail moves back along it), w_z > 0 reverse.
TEST(CushionModels, MathavanSideSpin) {
  const CushionParams p = paper(CushionModel::mathavan_2010);
  for (double from_rail : {10.0, 30.0}) {
    const Rebound run = hit(p, 1.0, 90.0 - from_rail, 1.0, -2.0, kPaperR);
    EXPECT_GT(run.speed, 1.0) << from_rail;
  }
  for (double from_rail : {80.0, 85.0}) {
    const Rebound rev = hit(p, 1.0, 90.0 - from_rail, 1.0, 2.0, kPaperR);
    EXPECT_LT(rev.vt, 0.0) << from_rail;
    EXPECT_GT(rev.vn, 0.0);
  }
}

// The finding, measured: rolling balls leave the rail flatter
// (further from the normal) under the legacy law than under Mathavan's
// model. Each law at its scenario defaults, 1 m/s, incidence 30-50 deg:
// 13.0, 14.2 and 13.3 deg flatter (the issue: "9-14 degrees"); with the
// same constants (Mathavan's) 9.8, 10.9 and 10.4 deg. The corrected Han
// law with Mathavan's constants stays within 2.5 deg of Mathavan's model
// from 10 to 80 deg (it has no cloth friction during the impact).
TEST(CushionModels, RollingReboundAnglesAgainstMathavan) {
  const double at_defaults[] = {13.0, 14.2, 13.3};
  const double same_constants[] = {9.8, 10.9, 10.4};
  int i = 0;
  for (double inc : {30.0, 40.0, 50.0}) {
    const double md = hit(defaults(CushionModel::mathavan_2010), 1.0, inc, 1.0).angle;
    const double vd = hit(defaults(CushionModel::han_2005_v0), 1.0, inc, 1.0).angle;
    EXPECT_NEAR(vd - md, at_defaults[i], 0.05) << inc;
    const double mp = hit(paper(CushionModel::mathavan_2010), 1.0, inc, 1.0).angle;
    const double vp = hit(paper(CushionModel::han_2005_v0), 1.0, inc, 1.0).angle;
    EXPECT_NEAR(vp - mp, same_constants[i], 0.05) << inc;
    ++i;
  }
  for (double inc = 10.0; inc <= 80.0; inc += 10.0) {
    const double mp = hit(paper(CushionModel::mathavan_2010), 1.0, inc, 1.0).angle;
    const double hp = hit(paper(CushionModel::han_2005), 1.0, inc, 1.0).angle;
    EXPECT_NEAR(hp, mp, 2.5) << inc;
  }
}

// The default law against Mathavan's measurement-fitted model, each at its
// defaults, rolling at 1 m/s: the straight-in rebound is the same (0.912
// against 0.914; the default restitution 0.84 was chosen for it) and the
// rebound angle stays within 4.7 degrees of Mathavan's from 0 to 80
// degrees of incidence (the legacy law: up to 14.2).
TEST(CushionModels, TheDefaultLawTracksMathavanForRollingBalls) {
  EXPECT_NEAR(hit(defaults(CushionModel::han_2005), 1.0, 0.0, 1.0).speed,
              hit(defaults(CushionModel::mathavan_2010), 1.0, 0.0, 1.0).speed, 0.003);
  double worst = 0.0;
  for (double inc = 0.0; inc <= 80.0; inc += 5.0) {
    const double md = hit(defaults(CushionModel::mathavan_2010), 1.0, inc, 1.0).angle;
    const double hd = hit(defaults(CushionModel::han_2005), 1.0, inc, 1.0).angle;
    worst = std::max(worst, std::abs(hd - md));
  }
  EXPECT_LT(worst, 4.7);
  EXPECT_GT(worst, 3.0);  // not a copy of it: no cloth friction in the impact
  EXPECT_EQ(CushionParams{}.model, CushionModel::han_2005);
}

// A given impact is reproduced bit for bit, and the result does not
// depend on the cushion's orientation in the plane beyond round-off.
// (Convergence, measured while writing it: 500, 5000 and 50000 steps
// agree to 3 decimals in speed and 0.1 deg in angle over the Fig. 9 grid.)
TEST(CushionModels, MathavanIsDeterministicAndFrameIndependent) {
  const CushionParams p = paper(CushionModel::mathavan_2010);
  const Rebound a = hit(p, 1.4, 37.0, 0.3, -0.7, kR, 0.4);
  const Rebound b = hit(p, 1.4, 37.0, 0.3, -0.7, kR, 0.4);
  EXPECT_EQ(a.speed, b.speed);
  EXPECT_EQ(a.spin.z, b.spin.z);
  for (double na : {-2.0, 1.1, 2.9}) {
    const Rebound c = hit(p, 1.4, 37.0, 0.3, -0.7, kR, na);
    EXPECT_NEAR(c.speed, a.speed, 1e-9);
    EXPECT_NEAR(c.angle, a.angle, 1e-7);
    EXPECT_NEAR(c.spin.z, a.spin.z, 1e-7);
  }
}

// table.cushion_height against nose_height: for the default ball a height
// of 0.635 x 57.15 mm is the default nose, for every law; a smaller ball
// (snooker, 52.5 mm) meets the same rail higher on its surface, so at the
// same height it gets a steeper contact normal.
TEST(CushionModels, CushionHeightMatchesNoseHeightForTheDefaultBall) {
  for (CushionModel m : kModels) {
    CushionParams by_fraction = defaults(m);
    CushionParams by_height = by_fraction;
    by_height.height = by_fraction.nose_height * 2.0 * kR;
    for (double inc : {0.0, 25.0, 60.0}) {
      const Rebound a = hit(by_fraction, 1.2, inc, 1.0, 0.5);
      const Rebound b = hit(by_height, 1.2, inc, 1.0, 0.5);
      EXPECT_NEAR(a.vn, b.vn, 1e-9) << inc;
      EXPECT_NEAR(a.vt, b.vt, 1e-9) << inc;
      EXPECT_NEAR(a.spin.z, b.spin.z, 1e-6) << inc;
    }
    // The snooker ball (R = 26.25 mm) under a 36.29 mm nose: sin t =
    // 0.3825 instead of 0.27; the same as nose_height 0.69124.
    const double snooker_r = 0.02625;
    CushionParams as_fraction = by_fraction;
    as_fraction.nose_height = by_height.height / (2.0 * snooker_r);
    const Rebound sh = hit(by_height, 1.2, 25.0, 1.0, 0.0, snooker_r);
    const Rebound sf = hit(as_fraction, 1.2, 25.0, 1.0, 0.0, snooker_r);
    const Rebound s0 = hit(by_fraction, 1.2, 25.0, 1.0, 0.0, snooker_r);
    EXPECT_NEAR(sh.vn, sf.vn, 1e-9);
    // The height, not the fraction, counts (impulse_frictional's normal
    // velocity is -e v_x at any height: its friction depends on it).
    EXPECT_GT(std::abs(sh.vn - s0.vn) + std::abs(sh.vt - s0.vt), 1e-3);
  }
}

// ---------------------------------------------------------------------------
// impulse_frictional (src/physics/cushion.cpp, part 4).

CushionParams impulse(double e, double mu, double nose) {
  CushionParams p;
  p.model = CushionModel::impulse_frictional;
  p.restitution = e;
  p.friction = mu;
  p.nose_height = nose;
  return p;
}

/// The state in the cushion's local frame of hit(..., normal_angle = 0):
/// n = +x, so ex = -x and ey = perp(ex) = -y.
struct Local {
  double vx, vy, wx, wy, wz;
};
Local local(Vec2 v, Vec3 w) { return {-v.x, -v.y, -w.x, -w.y, w.z}; }

/// A ball coming along +ey at incidence inc (degrees) with velocity V,
/// spin k V / R about the rolling axis and side spin side V / R, against
/// the cushion with normal +x.
CushionImpact hit0(const CushionParams& p, double V, double inc, double k, double side, Vec2& v,
                   Vec3& w) {
  const Vec2 ex{-1.0, 0.0};
  const Vec2 ey = breakshot::perp(ex);
  v = ex * (V * std::cos(inc * kDeg)) + ey * (V * std::sin(inc * kDeg));
  const Vec2 wh = breakshot::perp(v) * (k / kR);
  w = {wh.x, wh.y, side * V / kR};
  return cushion_impact(v, w, {1.0, 0.0}, kMass, kR, p);
}

// Newton's restitution on the final normal velocity: the ball leaves at
// exactly -e times its normal velocity, whatever its spin and the
// friction (the friction's normal part is made up by the rail). Straight
// in with e = 1 and no friction it comes back at exactly its speed; a
// rolling ball straight in comes back at e V (han_2005: e + mu (1 + e)
// s / c = 0.819 of it at the defaults, since friction there pushes it).
TEST(CushionModels, ImpulseFrictionalNormalVelocityIsExactlyMinusE) {
  Vec2 v;
  Vec3 w;
  for (double nose : {0.5, 0.635, 0.7, 0.9}) {
    for (double k : {0.0, 1.0, -0.5}) {
      const CushionImpact r = hit0(impulse(1.0, 0.0, nose), 1.7, 0.0, k, 0.0, v, w);
      EXPECT_EQ(r.velocity.x, 1.7) << nose << " " << k;
      EXPECT_EQ(r.velocity.y, 0.0);
    }
    for (double e : {0.0, 0.3, 0.75, 0.98}) {
      for (double mu : {0.0, 0.14, 0.6}) {
        for (double inc : {0.0, 25.0, 70.0}) {
          for (double k : {-1.0, 0.0, 1.0, 2.0}) {
            const CushionImpact r = hit0(impulse(e, mu, nose), 1.3, inc, k, 0.7, v, w);
            EXPECT_EQ(r.velocity.x, -e * v.x) << e << " " << mu << " " << inc << " " << k;
          }
        }
      }
    }
  }
}

// Nose at the centre's height (t = 0): plain reflection, and the
// sphere's Coulomb friction at its equator in the tangent plane (y, z).
// The stopping impulse per unit mass is g = (u1 / (7/2), -R w_y / (5/2))
// with u1 = v_y + R w_z (the equator's slip along the rail) and -R w_y
// its vertical slip; the friction is -min(1, mu (1 + e) v_x / |g|) g.
// With w_y = 0 this is the textbook 2D result
//   v_y' = v_y - sign(u1) min(|u1| / (7/2), mu (1 + e) v_x),
//   w_z' = w_z + (5/2R) (v_y' - v_y).
TEST(CushionModels, ImpulseFrictionalAtCentreHeightIsReflectionWithCoulomb) {
  Vec2 v;
  Vec3 w;
  int stick = 0;
  int slide = 0;
  for (double e : {0.0, 0.5, 0.9}) {
    for (double mu : {0.05, 0.2, 1.0}) {
      for (double inc : {10.0, 40.0, 75.0}) {
        for (double k : {0.0, 1.0, -0.7}) {
          for (double side : {-1.5, 0.0, 0.4}) {
            const CushionImpact r = hit0(impulse(e, mu, 0.5), 1.1, inc, k, side, v, w);
            const Local a = local(v, w);
            const Local b = local(r.velocity, r.spin);
            const double u1 = a.vy + kR * a.wz;
            const double g1 = u1 / 3.5;
            const double g2 = -kR * a.wy / 2.5;
            const double size = std::sqrt(g1 * g1 + g2 * g2);
            const double cap = mu * (1.0 + e) * a.vx;
            const double f = size > cap ? cap / size : 1.0;
            (f < 1.0 ? slide : stick) += 1;
            const double p1 = -f * g1;
            const double p2 = -f * g2;
            const double q = 2.5 / kR;
            EXPECT_NEAR(b.vx, -e * a.vx, 1e-14);
            EXPECT_NEAR(b.vy, a.vy + p1, 1e-13);
            EXPECT_NEAR(b.wx, a.wx, 1e-10);
            EXPECT_NEAR(b.wy, a.wy - q * p2, 1e-10);
            EXPECT_NEAR(b.wz, a.wz + q * p1, 1e-10);
            if (k == 0.0) {  // the 2D textbook form
              const double dv = -std::copysign(std::min(std::abs(u1) / 3.5, cap), u1);
              EXPECT_NEAR(b.vy, a.vy + dv, 1e-13);
            }
          }
        }
      }
    }
  }
  EXPECT_GT(stick, 10);  // both cases are covered
  EXPECT_GT(slide, 10);
}

// A stick leaves the nose's contact point at rest: the slip
// u1 = v_y + R (w_z c - w_x s), u2 = -(v_x s + R w_y) is 0 after it.
// Rolling balls at a high friction stick (the stopping impulse is far
// below mu p_N, and with topspin the friction does no work against the
// separating speed); the same balls at a low friction slide, and keep
// slipping.
TEST(CushionModels, ImpulseFrictionalStickLeavesNoSlip) {
  Vec2 v;
  Vec3 w;
  for (double nose : {0.6, 0.635, 0.7}) {
    const double s = 2.0 * nose - 1.0;
    const double c = std::sqrt(1.0 - s * s);
    const auto slip = [&](const Local& b) {
      return std::hypot(b.vy + kR * (b.wz * c - b.wx * s), -(b.vx * s + kR * b.wy));
    };
    for (double inc : {0.0, 30.0, 60.0}) {
      for (double side : {-0.5, 0.0, 0.5}) {
        const CushionImpact r = hit0(impulse(0.75, 1.0, nose), 1.0, inc, 1.0, side, v, w);
        EXPECT_LT(slip(local(r.velocity, r.spin)), 1e-12) << nose << " " << inc << " " << side;
        const CushionImpact o = hit0(impulse(0.75, 0.02, nose), 1.0, inc, 1.0, side, v, w);
        EXPECT_GT(slip(local(o.velocity, o.spin)), 0.05) << nose << " " << inc << " " << side;
      }
    }
  }
}

// Newton's law with a sticking friction can create energy (Kane's
// paradox): a stun ball driven straight in with e = 1 would gain
// (e v s)^2 / 5 per unit mass from a full stick (src/physics/cushion.cpp,
// part 4). The law admits only as much friction as keeps the energy from
// rising, here none: the ball comes back at its speed with no spin. With
// e = 0.75 the same ball sticks (the stick's energy change
// -1/2 (1 - e^2) v^2 + (e v s)^2 / 5 is negative) and leaves with that
// energy exactly.
TEST(CushionModels, ImpulseFrictionalNeverCreatesEnergyByNewtonsLaw) {
  Vec2 v;
  Vec3 w;
  const double s = 2.0 * 0.635 - 1.0;
  const CushionImpact r = hit0(impulse(1.0, 1.0, 0.635), 2.0, 0.0, 0.0, 0.0, v, w);
  EXPECT_EQ(r.velocity.x, 2.0);
  EXPECT_EQ(r.spin.x, 0.0);
  EXPECT_EQ(r.spin.y, 0.0);
  EXPECT_EQ(r.spin.z, 0.0);
  const CushionImpact t = hit0(impulse(0.75, 1.0, 0.635), 2.0, 0.0, 0.0, 0.0, v, w);
  const double per_mass = 0.5 * 4.0;
  const double change =
      -0.5 * (1.0 - 0.75 * 0.75) * 4.0 + (0.75 * 2.0 * s) * (0.75 * 2.0 * s) / 5.0;
  EXPECT_NEAR(energy(1.0, kR, t.velocity, t.spin), per_mass + change, 1e-12);
  EXPECT_LT(change, 0.0);
}

}  // namespace

}  // namespace test_cushion_models
