// Tests of the cushion rebound (Han 2005 model, src/physics/cushion.cpp)
// against closed forms derived by hand for special cases, conservation
// laws that follow from Euler's laws alone, and the published statements
// of Mathavan, Jackson and Parkin, "A theoretical analysis of billiard
// ball dynamics under cushion impacts", Proc. IMechE C 224 (2010)
// 1863-1873 (quoted below as "Mathavan 2010").
//
// About the published figures. Mathavan 2010's rebound-angle-vs-incident-
// angle curves (Figs 8-10) exist only as images; their values could not be
// retrieved, so no digitized point is compared here. What is compared is
// what the paper states in its text about those figures: the rolling
// ball's rebound angle does not depend on its speed (Fig. 8); excessive
// topspin hardly changes the rebound angle (Fig. 9); right spin can make
// the rebound faster than the incoming ball, and left spin near a straight
// hit sends the ball back to the side it came from (Figs 10, 11). Which
// of right/left is "running" depends on the side the ball comes from; here
// the tests say running/reverse directly.
//
// Local frame used below for a cushion with inward normal n: ex = -n
// (towards the rail), ey = perp(ex) (along the rail), z up; incidence and
// rebound angles are measured from the normal, positive towards +ey.
#include "breakshot/pool.hpp"
#include "breakshot/vec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace test_cushion {

namespace {

using breakshot::cushion_impact;
using breakshot::CushionImpact;
using breakshot::CushionParams;
using breakshot::Vec2;
using breakshot::Vec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMass = 0.17;      // kg, a pool ball
constexpr double kR = 0.028575;     // m, 2.25 in diameter
constexpr double kDeg = kPi / 180.0;

Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

struct Frame {
  Vec2 n;   // into the table
  Vec2 ex;  // towards the rail
  Vec2 ey;  // along the rail
  explicit Frame(double normal_angle)
      : n(unit(normal_angle)), ex(-n), ey(breakshot::perp(-n)) {}
  Vec2 vec(double x, double y) const { return ex * x + ey * y; }
  Vec3 spin(double wx, double wy, double wz) const {
    const Vec2 h = ex * wx + ey * wy;
    return {h.x, h.y, wz};
  }
  double x(Vec2 v) const { return breakshot::dot(v, ex); }
  double y(Vec2 v) const { return breakshot::dot(v, ey); }
  double x(Vec3 w) const { return breakshot::dot(Vec2{w.x, w.y}, ex); }
  double y(Vec3 w) const { return breakshot::dot(Vec2{w.x, w.y}, ey); }
};

// A ball rolling on the cloth (contact point at rest) with velocity v:
// w = z x v / R, plus side spin wz.
Vec3 rolling_spin(Vec2 v, double wz, double topspin = 1.0) {
  const Vec2 h = breakshot::perp(v) * (topspin / kR);
  return {h.x, h.y, wz};
}

double energy(Vec2 v, Vec3 w) {
  const double inertia = 0.4 * kMass * kR * kR;
  return 0.5 * kMass * breakshot::norm2(v) + 0.5 * inertia * (w.x * w.x + w.y * w.y + w.z * w.z);
}

// The law these tests derive by hand is han_2005_v0 (breakshot 0.1's),
// at its own restitution; the default law is checked in
// test_cushion_models.cpp.
struct LegacyParams : CushionParams {
  LegacyParams() {
    model = breakshot::CushionModel::han_2005_v0;
    restitution = breakshot::default_cushion_restitution(model);
  }
};

double sin_t(const CushionParams& p) { return 2.0 * p.nose_height - 1.0; }
double cos_t(const CushionParams& p) { return std::sqrt(1.0 - sin_t(p) * sin_t(p)); }

// Rebound angle from the normal, degrees, positive towards +ey.
double rebound_angle(const Frame& f, Vec2 v) {
  return std::atan2(f.y(v), breakshot::dot(v, f.n)) / kDeg;
}

// ---------------------------------------------------------------------------

// With the nose at the height of the ball's centre (contact normal
// horizontal) and no friction, the impulse is horizontal, through the
// centre, along n: plain reflection v' = v - (1 + e)(v.n) n, spin untouched,
// whatever the angle and the spin.
TEST(Cushion, FrictionlessAtCentreHeightIsReflectionWithRestitution) {
  for (double e : {1.0, 0.9, 0.5, 0.0}) {
    LegacyParams p;
    p.nose_height = 0.5;
    p.friction = 0.0;
    p.restitution = e;
    for (double na = 0.0; na < 360.0; na += 37.0) {
      const Frame f(na * kDeg);
      for (double inc = -85.0; inc <= 85.0; inc += 5.0) {
        const Vec2 v = f.vec(std::cos(inc * kDeg), std::sin(inc * kDeg)) * 1.7;
        const Vec3 w{31.0, -17.0, 55.0};
        const CushionImpact r = cushion_impact(v, w, f.n, kMass, kR, p);
        const Vec2 expect = v - f.n * ((1.0 + e) * breakshot::dot(v, f.n));
        EXPECT_NEAR(r.velocity.x, expect.x, 1e-14) << e << " " << na << " " << inc;
        EXPECT_NEAR(r.velocity.y, expect.y, 1e-14) << e << " " << na << " " << inc;
        EXPECT_NEAR(r.spin.x, w.x, 1e-12);
        EXPECT_NEAR(r.spin.y, w.y, 1e-12);
        EXPECT_EQ(r.spin.z, w.z);
      }
    }
  }
}

// A straight hit with top or back spin only (spin about the rail's axis)
// is symmetric under the mirror y -> -y: no sideways velocity and no side
// spin can come out, whatever the nose height, friction or restitution.
TEST(Cushion, StraightHitWithoutSideSpinStaysStraight) {
  for (double nose : {0.5, 0.635, 0.7, 0.8}) {
    for (double mu : {0.0, 0.14, 0.5}) {
      for (double k : {-3.0, -1.0, 0.0, 0.27, 1.0, 2.0, 3.0}) {
        LegacyParams p;
        p.nose_height = nose;
        p.friction = mu;
        const Frame f(1.1);
        const Vec2 v = f.vec(2.0, 0.0);
        const Vec3 w = f.spin(0.0, k * 2.0 / kR, 0.0);
        const CushionImpact r = cushion_impact(v, w, f.n, kMass, kR, p);
        EXPECT_NEAR(f.y(r.velocity), 0.0, 1e-14) << nose << " " << mu << " " << k;
        EXPECT_GE(breakshot::dot(r.velocity, f.n), -1e-15);
        EXPECT_NEAR(f.x(r.spin), 0.0, 1e-12);
        EXPECT_NEAR(r.spin.z, 0.0, 1e-12);
      }
    }
  }
}

// Topspin on a straight hit, against the model's closed form worked out by
// hand for this case. Speed V into the rail, spin w_y = k V / R about the
// rail's axis (k = 1 rolling, k < 0 draw), s = sin t, c = cos t. The slip
// of the contact point is up the ball with u2 = -V (s + k); it sticks iff
// (2/7)|s + k| <= mu (1 + e) c. Rebound speed V' and new spin:
//   stick: V' = V ((1 + e) c^2 + (2/7) s (s + k) - 1),
//          w_y' = (V / R) (2k - 5s) / 7;
//   slide: with g = sign(s + k),
//          V' = V ((1 + e) c^2 + g mu (1 + e) c s - 1),
//          w_y' = (V / R) (k - 5/2 g mu (1 + e) c).
// So while the ball slides on the nose (most topspins) the rebound speed
// does not depend on the topspin, only the spin does; in the sticking
// band around k = -s it does.
TEST(Cushion, TopspinStraightHitMatchesClosedForm) {
  LegacyParams high_friction;
  high_friction.friction = 0.5;
  LegacyParams snooker_nose;  // Mathavan's h = 7R/5
  snooker_nose.nose_height = 0.7;
  int sticks = 0;
  int slides = 0;
  for (const CushionParams& p : {LegacyParams{}, high_friction, snooker_nose}) {
    const double s = sin_t(p);
    const double c = cos_t(p);
    const double e = p.restitution;
    const double mu = p.friction;
    for (double k : {-2.0, -1.0, -0.5, -0.27, 0.0, 0.3, 0.5, 1.0, 2.0, 3.0}) {
      const double V = 1.3;
      const Frame f(-0.4);
      const CushionImpact r =
          cushion_impact(f.vec(V, 0.0), f.spin(0.0, k * V / kR, 0.0), f.n, kMass, kR, p);
      double back = 0.0;
      double wy = 0.0;
      if (2.0 / 7.0 * std::abs(s + k) <= mu * (1.0 + e) * c) {
        ++sticks;
        back = V * ((1.0 + e) * c * c + 2.0 / 7.0 * s * (s + k) - 1.0);
        wy = V / kR * (2.0 * k - 5.0 * s) / 7.0;
      } else {
        ++slides;
        const double g = s + k > 0.0 ? 1.0 : -1.0;
        back = V * ((1.0 + e) * c * c + g * mu * (1.0 + e) * c * s - 1.0);
        wy = V / kR * (k - 2.5 * g * mu * (1.0 + e) * c);
      }
      ASSERT_GT(back, 0.0);
      EXPECT_NEAR(breakshot::dot(r.velocity, f.n), back, 1e-13) << p.friction << " " << k;
      EXPECT_NEAR(f.y(r.spin), wy, 1e-10) << p.friction << " " << k;
    }
  }
  EXPECT_GT(sticks, 3);  // both branches are exercised
  EXPECT_GT(slides, 3);
}

// The defaults: a rolling ball hitting straight on comes back at 0.6-0.7
// of its speed (inside Alciatore's ball-rail restitution range 0.6-0.9,
// "pool physics property constants"),
// exactly (1 + e) c (c + mu s) - 1 = 0.6863 since it slides on the nose.
TEST(Cushion, DefaultRollingStraightHitReboundRatio) {
  const LegacyParams p;
  const Frame f(0.3);
  for (double V : {0.5, 1.0, 2.0}) {
    const Vec2 v = f.vec(V, 0.0);
    const CushionImpact r = cushion_impact(v, rolling_spin(v, 0.0), f.n, kMass, kR, p);
    const double ratio = breakshot::norm(r.velocity) / V;
    const double s = sin_t(p);
    const double c = cos_t(p);
    EXPECT_NEAR(ratio, (1.0 + p.restitution) * c * (c + p.friction * s) - 1.0, 1e-13);
    EXPECT_GT(ratio, 0.6);
    EXPECT_LT(ratio, 0.7);
  }
}

// Side spin on a straight hit. Right english (cue tip right of centre)
// spins the ball counter-clockwise seen from above (w_z > 0, see
// src/physics/cue.cpp) and a straight-on ball then rebounds to the
// shooter's right; left english to the left, by the same amount. For a
// rolling ball with w_z = k V / R hitting straight on, the slip is
// (u1, u2) = V (k c, -(1 + s)); when sliding, the sideways speed is
//   mu (1 + e) c V k c / sqrt(k^2 c^2 + (1 + s)^2).
TEST(Cushion, SideSpinOnStraightHitDeflectsToTheEnglishSide) {
  const LegacyParams p;
  const double s = sin_t(p);
  const double c = cos_t(p);
  const double mu = p.friction;
  const double e = p.restitution;
  for (double k : {0.5, 1.0, 2.0}) {
    const double V = 1.5;
    const Frame f(2.0);
    const Vec2 d = f.ex;  // shooter's aim, straight at the rail
    const Vec2 right{d.y, -d.x};
    const Vec2 v = d * V;
    const CushionImpact rr = cushion_impact(v, rolling_spin(v, k * V / kR), f.n, kMass, kR, p);
    const CushionImpact rl = cushion_impact(v, rolling_spin(v, -k * V / kR), f.n, kMass, kR, p);
    const double side = mu * (1.0 + e) * c * V * k * c / std::sqrt(k * k * c * c + (1 + s) * (1 + s));
    ASSERT_GT(2.0 / 7.0 * V * std::sqrt(k * k * c * c + (1 + s) * (1 + s)), mu * (1 + e) * c * V);
    EXPECT_NEAR(breakshot::dot(rr.velocity, right), side, 1e-13) << k;
    EXPECT_NEAR(breakshot::dot(rl.velocity, right), -side, 1e-13) << k;
    EXPECT_NEAR(breakshot::dot(rr.velocity, f.n), breakshot::dot(rl.velocity, f.n), 1e-14);
    // The rail's friction takes side spin off.
    EXPECT_LT(rr.spin.z, k * V / kR);
    EXPECT_GT(rr.spin.z, 0.0);
  }
}

// Side spin at an angle. Running english (the ball's surface at the rail
// moves backwards along the rail, so friction pushes the ball on) speeds
// the ball along the rail and, up to about 40 deg from the normal, widens
// the rebound; reverse english does the opposite. Nearer the rail the
// angle hardly moves (under 1 deg beyond 50 deg for |w_z| = V/R; reverse
// english can even widen it a hair): the sliding friction has the fixed
// size mu p_N, and the less of it side spin leaves along the rail, the
// more goes into the up-and-away direction set by the topspin, which
// pushes the ball off the rail a little faster. The along-rail speed
// still follows the english.
// Mathavan 2010 (Figs 10 and 11 and their text): with side spin of one
// sense "the rebound speed exceeds the value of the incident speed", and
// with the other "for incident angle values close to 90 deg [from the
// rail], the ball bounces back to the side from which it approached the
// cushion".
TEST(Cushion, RunningAndReverseEnglishChangeTheReboundAngle) {
  const LegacyParams p;
  const Frame f(-2.5);
  const double V = 1.0;
  for (double inc : {10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 75.0}) {
    // Travel along +ey: the surface at the rail moves with R c w_z along
    // +ey, so w_z < 0 is running english, w_z > 0 reverse.
    const Vec2 v = f.vec(V * std::cos(inc * kDeg), V * std::sin(inc * kDeg));
    const CushionImpact none = cushion_impact(v, rolling_spin(v, 0.0), f.n, kMass, kR, p);
    const CushionImpact run = cushion_impact(v, rolling_spin(v, -V / kR), f.n, kMass, kR, p);
    const CushionImpact rev = cushion_impact(v, rolling_spin(v, V / kR), f.n, kMass, kR, p);
    if (inc <= 40.0) {
      EXPECT_GT(rebound_angle(f, run.velocity), rebound_angle(f, none.velocity) + 1.0) << inc;
      EXPECT_LT(rebound_angle(f, rev.velocity), rebound_angle(f, none.velocity) - 1.0) << inc;
    }
    EXPECT_GT(f.y(run.velocity), f.y(none.velocity)) << inc;
    EXPECT_LT(f.y(rev.velocity), f.y(none.velocity)) << inc;
  }
  // Strong running english (|w_z| = 2 V / R), shallow approach (10 and 30
  // deg from the rail): faster out than in.
  for (double from_rail : {10.0, 30.0}) {
    const double inc = 90.0 - from_rail;
    const Vec2 v = f.vec(V * std::cos(inc * kDeg), V * std::sin(inc * kDeg));
    const CushionImpact run = cushion_impact(v, rolling_spin(v, -2.0 * V / kR), f.n, kMass, kR, p);
    EXPECT_GT(breakshot::norm(run.velocity), V) << from_rail;
  }
  // Strong reverse english, nearly straight on (80 and 85 deg from the
  // rail): the ball comes back on the side it came from.
  for (double from_rail : {80.0, 85.0}) {
    const double inc = 90.0 - from_rail;
    const Vec2 v = f.vec(V * std::cos(inc * kDeg), V * std::sin(inc * kDeg));
    const CushionImpact rev = cushion_impact(v, rolling_spin(v, 2.0 * V / kR), f.n, kMass, kR, p);
    EXPECT_LT(f.y(rev.velocity), 0.0) << from_rail;
    EXPECT_GT(breakshot::dot(rev.velocity, f.n), 0.0);
  }
}

// A rolling ball without side spin, at incidence phi from the normal. Its
// slip on the nose is V (1 + s)(sin phi, -cos phi), which with the
// defaults always slides ((2/7)(1 + s) > mu (1 + e) c), so by hand
//   v_y' = V sin phi (1 - mu (1 + e) c cos phi),
//   v_n' = V cos phi ((1 + e) c (c + mu s cos phi) - 1),
// and tan(rebound) = v_y' / v_n'. It comes off wider than it came in.
// Mathavan 2010 on Fig. 8: "the rebound angle plots are identical for
// different ball speeds ... the rebound angle is influenced only by the
// incident angle for a rolling ball with no sidespin"; on Fig. 9: "The
// rebound angles are not greatly affected by the excessive topspin of the
// ball" (k = 2 against rolling k = 1: within 2.5 deg here).
TEST(Cushion, RollingBallReboundAngleAgainstIncidence) {
  const LegacyParams p;
  const double s = sin_t(p);
  const double c = cos_t(p);
  const double e = p.restitution;
  const double mu = p.friction;
  ASSERT_GT(2.0 / 7.0 * (1.0 + s), mu * (1.0 + e) * c);
  const Frame f(0.9);
  double previous = -1.0;
  for (double inc = 5.0; inc <= 85.0; inc += 5.0) {
    const double ph = inc * kDeg;
    const double vy = std::sin(ph) * (1.0 - mu * (1.0 + e) * c * std::cos(ph));
    const double vn = std::cos(ph) * ((1.0 + e) * c * (c + mu * s * std::cos(ph)) - 1.0);
    const double expect = std::atan2(vy, vn) / kDeg;
    double first = 0.0;
    for (double V : {0.25, 1.0, 2.5, 6.0}) {
      const Vec2 v = f.vec(V * std::cos(ph), V * std::sin(ph));
      const CushionImpact r = cushion_impact(v, rolling_spin(v, 0.0), f.n, kMass, kR, p);
      const double a = rebound_angle(f, r.velocity);
      EXPECT_NEAR(a, expect, 1e-9) << inc << " " << V;
      if (V == 0.25) first = a;
      EXPECT_NEAR(a, first, 1e-9) << "speed-independent " << inc;
      const CushionImpact r2 = cushion_impact(v, rolling_spin(v, 0.0, 2.0), f.n, kMass, kR, p);
      EXPECT_NEAR(rebound_angle(f, r2.velocity), a, 2.5) << "k = 2 at " << inc;
    }
    EXPECT_GT(first, inc);       // wider than it came in
    EXPECT_GT(first, previous);  // and monotone in the incidence
    previous = first;
  }
}

// Kinetic energy (translation + rotation) never increases and the ball
// never leaves moving into the cushion, over many random impacts with any
// spin, including extreme parameters (restitution 0, nose near the top,
// high friction) where the last guard of the model is needed.
TEST(Cushion, RandomImpactsNeverGainEnergyNorEnterTheCushion) {
  std::mt19937_64 rng(20240601);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int guarded = 0;
  for (int i = 0; i < 20000; ++i) {
    LegacyParams p;
    p.restitution = u01(rng);
    p.friction = 0.8 * u01(rng);
    p.nose_height = 0.5 + 0.45 * u01(rng);
    const Frame f(2.0 * kPi * u01(rng));
    const double V = 0.01 + 5.0 * u01(rng);
    const double inc = (u01(rng) * 2.0 - 1.0) * 89.0 * kDeg;
    const Vec2 v = f.vec(V * std::cos(inc), V * std::sin(inc));
    const double wmax = 4.0 * V / kR;
    const Vec3 w{wmax * (2.0 * u01(rng) - 1.0), wmax * (2.0 * u01(rng) - 1.0),
                 wmax * (2.0 * u01(rng) - 1.0)};
    const CushionImpact r = cushion_impact(v, w, f.n, kMass, kR, p);
    const double before = energy(v, w);
    const double after = energy(r.velocity, r.spin);
    ASSERT_TRUE(std::isfinite(after));
    ASSERT_LE(after, before * (1.0 + 1e-12)) << i;
    ASSERT_GE(breakshot::dot(r.velocity, f.n), -1e-12 * V) << i;
    if (breakshot::dot(r.velocity, f.n) < 1e-12 * V) ++guarded;
  }
  EXPECT_GT(guarded, 0);  // the extreme cases did reach the guard
}

// Every impulse the rail gives acts at the nose contact r, so the angular
// momentum about r, L = I w - m r x v, does not change, except through the
// vertical velocity that the cloth removes. Its x and z components
// (normal to the rail, vertical) do not involve v_z:
//   L_x = I w_x + m R s v_y,   L_z = I w_z - m R c v_y.
TEST(Cushion, AngularMomentumAboutTheContactIsKept) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double inertia = 0.4 * kMass * kR * kR;
  for (int i = 0; i < 5000; ++i) {
    LegacyParams p;  // ranges in which the last guard cannot act
    p.restitution = 0.5 + 0.5 * u01(rng);
    p.friction = 0.4 * u01(rng);
    p.nose_height = 0.5 + 0.2 * u01(rng);
    const double s = sin_t(p);
    const double c = cos_t(p);
    const Frame f(2.0 * kPi * u01(rng));
    const double V = 0.1 + 3.0 * u01(rng);
    const double inc = (u01(rng) * 2.0 - 1.0) * 85.0 * kDeg;
    const Vec2 v = f.vec(V * std::cos(inc), V * std::sin(inc));
    const double wmax = 3.0 * V / kR;
    const Vec3 w{wmax * (2.0 * u01(rng) - 1.0), wmax * (2.0 * u01(rng) - 1.0),
                 wmax * (2.0 * u01(rng) - 1.0)};
    const CushionImpact r = cushion_impact(v, w, f.n, kMass, kR, p);
    const double lx0 = inertia * f.x(w) + kMass * kR * s * f.y(v);
    const double lz0 = inertia * w.z - kMass * kR * c * f.y(v);
    const double lx1 = inertia * f.x(r.spin) + kMass * kR * s * f.y(r.velocity);
    const double lz1 = inertia * r.spin.z - kMass * kR * c * f.y(r.velocity);
    const double scale = kMass * kR * V * 4.0;
    EXPECT_NEAR(lx1, lx0, 1e-13 * scale) << i;
    EXPECT_NEAR(lz1, lz0, 1e-13 * scale) << i;
  }
}

// The same impact seen in a rotated table frame gives the rotated result;
// the mirror image (across the normal line) gives the mirrored result,
// with the spin transformed as an axial vector. This pins the signs of the
// side spin terms.
TEST(Cushion, RotationAndMirrorSymmetry) {
  const LegacyParams p;
  const Vec2 n = unit(0.7);
  const Vec2 v = unit(0.7 + kPi + 0.5) * 1.2;  // into the rail, 0.5 rad off
  const Vec3 w{-20.0, 35.0, 44.0};
  const CushionImpact r = cushion_impact(v, w, n, kMass, kR, p);
  auto rot = [](Vec2 a, double b) {
    return Vec2{a.x * std::cos(b) - a.y * std::sin(b), a.x * std::sin(b) + a.y * std::cos(b)};
  };
  for (double b : {0.3, 1.9, -2.4}) {
    const Vec2 wh = rot({w.x, w.y}, b);
    const CushionImpact rb = cushion_impact(rot(v, b), {wh.x, wh.y, w.z}, rot(n, b), kMass, kR, p);
    const Vec2 ev = rot(r.velocity, b);
    const Vec2 ew = rot({r.spin.x, r.spin.y}, b);
    EXPECT_NEAR(rb.velocity.x, ev.x, 1e-13);
    EXPECT_NEAR(rb.velocity.y, ev.y, 1e-13);
    EXPECT_NEAR(rb.spin.x, ew.x, 1e-11);
    EXPECT_NEAR(rb.spin.y, ew.y, 1e-11);
    EXPECT_NEAR(rb.spin.z, r.spin.z, 1e-11);
  }
  // Mirror across the line through the normal: a -> 2 (a.n) n - a for
  // vectors; the horizontal part of an axial vector gets the extra sign of
  // the reflection, and w_z flips.
  auto mirror = [&](Vec2 a) { return n * (2.0 * breakshot::dot(a, n)) - a; };
  const Vec2 wm = mirror({w.x, w.y}) * -1.0;
  const CushionImpact rm = cushion_impact(mirror(v), {wm.x, wm.y, -w.z}, n, kMass, kR, p);
  const Vec2 ev = mirror(r.velocity);
  const Vec2 ew = mirror({r.spin.x, r.spin.y}) * -1.0;
  EXPECT_NEAR(rm.velocity.x, ev.x, 1e-13);
  EXPECT_NEAR(rm.velocity.y, ev.y, 1e-13);
  EXPECT_NEAR(rm.spin.x, ew.x, 1e-11);
  EXPECT_NEAR(rm.spin.y, ew.y, 1e-11);
  EXPECT_NEAR(rm.spin.z, -r.spin.z, 1e-11);
}

// A ball moving along or away from the cushion is left alone; the mass
// cancels out of the rebound.
TEST(Cushion, NoImpactWhenNotApproachingAndMassCancels) {
  const LegacyParams p;
  const Vec2 n{0.0, 1.0};
  const Vec3 w{3.0, -4.0, 5.0};
  for (Vec2 v : {Vec2{1.0, 0.0}, Vec2{1.0, 0.5}, Vec2{0.0, 0.0}}) {
    const CushionImpact r = cushion_impact(v, w, n, kMass, kR, p);
    EXPECT_EQ(r.velocity, v);
    EXPECT_EQ(r.spin, w);
  }
  const Vec2 v{0.4, -1.1};
  const CushionImpact a = cushion_impact(v, w, n, 0.17, kR, p);
  const CushionImpact b = cushion_impact(v, w, n, 0.21, kR, p);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.spin, b.spin);
}

}  // namespace

}  // namespace test_cushion
