// Tests of the cue strike against closed forms: the centre-hit speed, the
// Leckie-Greenspan equations in their own frame, the natural-roll height,
// TP A-30's speed for an offset hit and TP A-31's squirt angle, plus the
// invariants every strike must keep (energy, aim rotation, no NaN).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "breakshot/pool.hpp"

namespace test_cue {

namespace {

using breakshot::CueParams;
using breakshot::CueStrike;
using breakshot::strike;
using breakshot::StrikeResult;
using breakshot::Vec2;
using breakshot::Vec3;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kMass = 0.170;     // WPA ball, 6 oz
constexpr double kRadius = 0.028575;  // 2.25 in diameter

CueStrike stroke(double speed, double phi = 0.0, double theta = 0.0, double a = 0.0,
                 double b = 0.0) {
  CueStrike c;
  c.speed = speed;
  c.phi = phi;
  c.theta = theta;
  c.a = a;
  c.b = b;
  return c;
}

CueParams no_squirt(CueParams p = {}) {
  p.end_mass = 0.0;
  return p;
}

Vec3 cross3(Vec3 u, Vec3 v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
double dot3(Vec3 u, Vec3 v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
Vec3 scale(Vec3 u, double s) { return {u.x * s, u.y * s, u.z * s}; }

double kinetic(const StrikeResult& r, double m, double radius) {
  const double inertia = 0.4 * m * radius * radius;
  return 0.5 * m * breakshot::norm2(r.velocity) + 0.5 * inertia * dot3(r.spin, r.spin);
}

// Velocity of the ball's point touching the cloth: v + w x (-R z).
Vec2 contact_velocity(const StrikeResult& r, double radius) {
  return {r.velocity.x - radius * r.spin.y, r.velocity.y + radius * r.spin.x};
}

bool all_finite(const StrikeResult& r) {
  return std::isfinite(r.velocity.x) && std::isfinite(r.velocity.y) &&
         std::isfinite(r.spin.x) && std::isfinite(r.spin.y) && std::isfinite(r.spin.z) &&
         std::isfinite(r.squirt);
}

void expect_at_rest(const StrikeResult& r) {
  EXPECT_EQ(r.velocity.x, 0.0);
  EXPECT_EQ(r.velocity.y, 0.0);
  EXPECT_EQ(r.spin.x, 0.0);
  EXPECT_EQ(r.spin.y, 0.0);
  EXPECT_EQ(r.spin.z, 0.0);
  EXPECT_EQ(r.squirt, 0.0);
}

// ---------------------------------------------------------------------------
// Centre hit.

TEST(Cue, CentreHitSpeedIsOnePlusEOverOnePlusMassRatio) {
  for (double cue_mass : {0.40, 0.510, 0.567, 0.624, 5.0}) {
    for (double ball_mass : {0.156, 0.170, 0.210}) {
      for (double e : {0.0, 0.5, 0.71, 0.75, 1.0}) {
        CueParams p;
        p.mass = cue_mass;
        p.tip_restitution = e;
        const double speed = 2.5;
        const StrikeResult r = strike(stroke(speed), ball_mass, kRadius, p);
        const double expected = (1.0 + e) * speed / (1.0 + ball_mass / cue_mass);
        EXPECT_FALSE(r.miscue);
        EXPECT_NEAR(r.velocity.x, expected, 1e-14 * expected)
            << "M=" << cue_mass << " m=" << ball_mass << " e=" << e;
        EXPECT_EQ(r.velocity.y, 0.0);
        EXPECT_EQ(r.spin.x, 0.0);
        EXPECT_EQ(r.spin.y, 0.0);
        EXPECT_EQ(r.spin.z, 0.0);
        EXPECT_EQ(r.squirt, 0.0);
      }
    }
  }
}

TEST(Cue, ElasticTipGivesLeckieGreenspanCentreSpeed) {
  // Leckie & Greenspan: v = 2 V / (1 + m/M) for a centre hit.
  CueParams p;
  p.tip_restitution = 1.0;
  const StrikeResult r = strike(stroke(3.0), kMass, kRadius, p);
  EXPECT_NEAR(r.velocity.x, 6.0 / (1.0 + kMass / p.mass), 1e-14);
}

TEST(Cue, EqualMassesAndElasticTipHandTheBallAllTheEnergy) {
  // Newton's cradle: M = m, e = 1, centre hit -> v = V, ball KE = cue KE.
  CueParams p;
  p.mass = kMass;
  p.tip_restitution = 1.0;
  const StrikeResult r = strike(stroke(2.0), kMass, kRadius, p);
  EXPECT_NEAR(r.velocity.x, 2.0, 1e-14);
  EXPECT_NEAR(kinetic(r, kMass, kRadius), 0.5 * kMass * 4.0, 1e-14);
}

// ---------------------------------------------------------------------------
// Offset hits, level cue (TP A-30).

TEST(Cue, OffsetHitSpeedMatchesTpA30) {
  // Level cue, offset x (fraction of R) in any direction:
  // v = (1 + e) V / (1 + m/M + 5/2 x^2).
  const CueParams p = no_squirt();
  const double speed = 2.0;
  for (double x : {0.0, 0.1, 0.25, 0.4, 0.5}) {
    const double expected =
        (1.0 + p.tip_restitution) * speed / (1.0 + kMass / p.mass + 2.5 * x * x);
    for (double angle : {0.0, 45.0, 90.0, 160.0, 270.0}) {
      const double a = x * std::cos(angle * kDeg);
      const double b = x * std::sin(angle * kDeg);
      const StrikeResult r = strike(stroke(speed, 0.0, 0.0, a, b), kMass, kRadius, p);
      EXPECT_NEAR(breakshot::norm(r.velocity), expected, 1e-14) << x << " " << angle;
    }
  }
}

TEST(Cue, MoreOffsetMeansLessSpeedMoreSpin) {
  const CueParams p = no_squirt();
  double last_speed = std::numeric_limits<double>::infinity();
  double last_spin = -1.0;
  for (double b = 0.0; b <= 0.5; b += 0.05) {
    const StrikeResult r = strike(stroke(2.0, 0.0, 0.0, 0.0, b), kMass, kRadius, p);
    const double spin = std::sqrt(dot3(r.spin, r.spin));
    EXPECT_LT(breakshot::norm(r.velocity), last_speed);
    EXPECT_GT(spin, last_spin);
    last_speed = breakshot::norm(r.velocity);
    last_spin = spin;
  }
}

TEST(Cue, NaturalRollHeightGivesRolling) {
  // The tip 2R/5 above the centre (7R/5 above the cloth) with a level cue:
  // w = v / R, and the point on the cloth does not slide.
  for (double phi : {0.0, 30.0, 90.0, 200.0, -45.0}) {
    const StrikeResult r = strike(stroke(1.7, phi, 0.0, 0.0, 0.4), kMass, kRadius, {});
    const double v = breakshot::norm(r.velocity);
    EXPECT_NEAR(v, kRadius * std::hypot(r.spin.x, r.spin.y), 1e-13);
    const Vec2 u = contact_velocity(r, kRadius);
    EXPECT_NEAR(u.x, 0.0, 1e-13) << phi;
    EXPECT_NEAR(u.y, 0.0, 1e-13) << phi;
    EXPECT_EQ(r.spin.z, 0.0);
  }
  // Aimed along +x: v_x = R w_y, w_x = 0.
  const StrikeResult r = strike(stroke(1.7, 0.0, 0.0, 0.0, 0.4), kMass, kRadius, {});
  EXPECT_GT(r.spin.y, 0.0);
  EXPECT_NEAR(r.velocity.x, kRadius * r.spin.y, 1e-13);
}

TEST(Cue, FollowIsTopspinDrawIsBackspinCentreIsStun) {
  const double phi = 37.0;
  const Vec2 f{std::cos(phi * kDeg), std::sin(phi * kDeg)};
  const Vec2 rolling_axis = breakshot::perp(f);  // z x f: the axis of forward roll
  for (double b : {0.1, 0.3, 0.5}) {
    const StrikeResult follow = strike(stroke(2.0, phi, 0.0, 0.0, b), kMass, kRadius, {});
    const StrikeResult draw = strike(stroke(2.0, phi, 0.0, 0.0, -b), kMass, kRadius, {});
    const double wf = follow.spin.x * rolling_axis.x + follow.spin.y * rolling_axis.y;
    const double wd = draw.spin.x * rolling_axis.x + draw.spin.y * rolling_axis.y;
    EXPECT_GT(wf, 0.0);
    EXPECT_LT(wd, 0.0);
    EXPECT_NEAR(wf, -wd, 1e-12);
    // Spin about the rolling axis only: no side or masse part.
    EXPECT_NEAR(follow.spin.x * f.x + follow.spin.y * f.y, 0.0, 1e-12);
    EXPECT_EQ(follow.spin.z, 0.0);
    // Backspin: the point on the cloth slides forward faster than the ball.
    const Vec2 u = contact_velocity(draw, kRadius);
    EXPECT_GT(breakshot::dot(u, f), breakshot::norm(draw.velocity));
  }
  const StrikeResult stun = strike(stroke(2.0, phi), kMass, kRadius, {});
  EXPECT_EQ(stun.spin.x, 0.0);
  EXPECT_EQ(stun.spin.y, 0.0);
}

TEST(Cue, RightEnglishSpinsCounterClockwiseSeenFromAbove) {
  // The tip pushes the ball's right side forward, which turns it
  // counter-clockwise seen from above: w_z > 0. Left english: w_z < 0.
  // Level cue: w_z = (5/2) v_axis a / R with v_axis the speed along the cue.
  const CueParams p = no_squirt();
  for (double a : {0.1, 0.3, 0.5}) {
    const StrikeResult right = strike(stroke(2.0, 10.0, 0.0, a, 0.0), kMass, kRadius, p);
    const StrikeResult left = strike(stroke(2.0, 10.0, 0.0, -a, 0.0), kMass, kRadius, p);
    EXPECT_GT(right.spin.z, 0.0);
    EXPECT_LT(left.spin.z, 0.0);
    EXPECT_NEAR(right.spin.z, -left.spin.z, 1e-12);
    EXPECT_NEAR(right.spin.z, 2.5 * breakshot::norm(right.velocity) * a / kRadius, 1e-10);
    EXPECT_NEAR(right.spin.x, 0.0, 1e-12);
    EXPECT_NEAR(right.spin.y, 0.0, 1e-12);
  }
}

// ---------------------------------------------------------------------------
// Elevated cue.

// Leckie & Greenspan eq. 1-3 written literally in their frame: the ball
// leaves along -y, +x is to the shooter's left, z up; (a, b, c) are the
// contact point's coordinates in metres with b its height above the centre.
// Returns the horizontal velocity and the spin in that frame (e = 1 there;
// we scale F by (1 + e) / 2).
struct LgResult {
  Vec3 v, w;
};
LgResult leckie_greenspan(double m, double M, double R, double V, double e, double theta,
                          double a, double b) {
  const double c = std::sqrt(R * R - a * a - b * b);
  const double ct = std::cos(theta);
  const double st = std::sin(theta);
  const double F = (1.0 + e) * m * V /
                   (1.0 + m / M +
                    5.0 / (2.0 * R * R) *
                        (a * a + b * b * ct * ct + c * c * st * st - 2.0 * b * c * ct * st));
  const double inertia = 0.4 * m * R * R;
  return {{0.0, -F / m * ct, -F / m * st},
          {(-c * F * st + b * F * ct) / inertia, a * F * st / inertia, -a * F * ct / inertia}};
}

TEST(Cue, ElevatedStrikeMatchesLeckieGreenspanEquations) {
  // Our offsets are perpendicular to the cue; Leckie-Greenspan's are the
  // contact point's coordinates in the level frame. Convert and compare.
  CueParams p = no_squirt();
  p.tip_restitution = 0.75;
  int compared = 0;
  for (double theta_deg : {0.0, 5.0, 20.0, 45.0, 70.0, 85.0}) {
    for (double a : {-0.4, -0.1, 0.0, 0.25}) {
      for (double b : {-0.3, 0.0, 0.2, 0.4}) {
        if (a * a + b * b > 0.25) continue;
        const double phi_deg = 123.0;
        const StrikeResult r =
            strike(stroke(3.0, phi_deg, theta_deg, a, b), kMass, kRadius, p);
        const double th = theta_deg * kDeg;
        const double k = std::sqrt(1.0 - a * a - b * b);
        const double a_lg = -a * kRadius;  // their +x is our left
        const double b_lg = (b * std::cos(th) + k * std::sin(th)) * kRadius;
        // Their c = sqrt(R^2 - a^2 - b^2) >= 0 puts the contact behind the
        // centre; a steep cue hitting high touches the ball ahead of it,
        // which their parametrisation does not cover.
        if (k * std::cos(th) - b * std::sin(th) < 0.0) continue;
        ++compared;
        const LgResult lg =
            leckie_greenspan(kMass, p.mass, kRadius, 3.0, p.tip_restitution, th, a_lg, b_lg);
        // Their frame to the table: -y -> f (aim), +x -> left, z -> z.
        const double phi = phi_deg * kDeg;
        const Vec2 f{std::cos(phi), std::sin(phi)};
        const Vec2 l{-f.y, f.x};
        const Vec2 v = f * (-lg.v.y) + l * lg.v.x;
        const Vec2 w = f * (-lg.w.y) + l * lg.w.x;
        const double tol_v = 1e-12;
        const double tol_w = 1e-9;
        EXPECT_NEAR(r.velocity.x, v.x, tol_v) << theta_deg << " " << a << " " << b;
        EXPECT_NEAR(r.velocity.y, v.y, tol_v) << theta_deg << " " << a << " " << b;
        EXPECT_NEAR(r.spin.x, w.x, tol_w) << theta_deg << " " << a << " " << b;
        EXPECT_NEAR(r.spin.y, w.y, tol_w) << theta_deg << " " << a << " " << b;
        EXPECT_NEAR(r.spin.z, lg.w.z, tol_w) << theta_deg << " " << a << " " << b;
      }
    }
  }
  EXPECT_GT(compared, 60);
}

TEST(Cue, SpinIsContactLeverArmCrossImpulse) {
  // w = Q x (J d) / I with Q the contact point and d the cue direction,
  // built here in table coordinates from the geometry alone.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-180.0, 180.0);
  std::uniform_real_distribution<double> elevation(0.0, 89.0);
  std::uniform_real_distribution<double> off(-0.35, 0.35);
  std::uniform_real_distribution<double> spd(0.1, 8.0);
  const CueParams p = no_squirt();
  for (int n = 0; n < 500; ++n) {
    const double phi = angle(rng) * kDeg;
    const double th = elevation(rng) * kDeg;
    const double a = off(rng);
    const double b = off(rng);
    const double speed = spd(rng);
    const StrikeResult r = strike(stroke(speed, phi / kDeg, th / kDeg, a, b), kMass, kRadius, p);
    const Vec3 f{std::cos(phi), std::sin(phi), 0.0};
    const Vec3 z{0.0, 0.0, 1.0};
    const Vec3 left = cross3(z, f);
    const Vec3 d = scale(f, std::cos(th)) + scale(z, -std::sin(th));
    const Vec3 up = scale(f, std::sin(th)) + scale(z, std::cos(th));
    const double k = std::sqrt(1.0 - a * a - b * b);
    const Vec3 q = scale(scale(left, -a) + scale(up, b) + scale(d, -k), kRadius);
    // Impulse per unit mass from the horizontal speed: J/m = v / cos(theta).
    const double j_over_m = breakshot::norm(r.velocity) / std::cos(th);
    const Vec3 w = scale(cross3(q, d), j_over_m / (0.4 * kRadius * kRadius));
    const double tol = 1e-9 * (1.0 + std::sqrt(dot3(w, w)));
    EXPECT_NEAR(r.spin.x, w.x, tol);
    EXPECT_NEAR(r.spin.y, w.y, tol);
    EXPECT_NEAR(r.spin.z, w.z, tol);
    // The velocity is horizontal along the aim (no squirt here).
    EXPECT_NEAR(r.velocity.x * f.y - r.velocity.y * f.x, 0.0, 1e-12);
    EXPECT_GT(r.velocity.x * f.x + r.velocity.y * f.y, 0.0);
  }
}

TEST(Cue, ElevationScalesHorizontalSpeedByCosTheta) {
  const CueParams p = no_squirt();
  const StrikeResult level = strike(stroke(2.0, 0.0, 0.0, 0.1, -0.2), kMass, kRadius, p);
  for (double theta : {10.0, 30.0, 60.0, 80.0}) {
    const StrikeResult r = strike(stroke(2.0, 0.0, theta, 0.1, -0.2), kMass, kRadius, p);
    EXPECT_NEAR(r.velocity.x, level.velocity.x * std::cos(theta * kDeg), 1e-13);
    // Draw spin about the cue-perpendicular horizontal axis is unchanged.
    EXPECT_NEAR(r.spin.y, level.spin.y, 1e-10);
  }
}

TEST(Cue, ElevatedEnglishTiltsTheSpinAxis) {
  // Masse: with english and an elevated cue the spin axis tilts toward the
  // aim line: w_f / w_z = tan(theta).
  const CueParams p = no_squirt();
  for (double theta : {15.0, 45.0, 75.0}) {
    const StrikeResult r = strike(stroke(2.0, 0.0, theta, 0.3, 0.0), kMass, kRadius, p);
    EXPECT_GT(r.spin.x, 0.0);
    EXPECT_GT(r.spin.z, 0.0);
    EXPECT_NEAR(r.spin.x / r.spin.z, std::tan(theta * kDeg), 1e-12);
    // The cloth contact slides sideways, so the ball will curve.
    EXPECT_GT(std::abs(contact_velocity(r, kRadius).y), 0.0);
  }
}

// ---------------------------------------------------------------------------
// Squirt (TP A-31).

TEST(Cue, SquirtMatchesTpA31) {
  // tan(alpha) = (5/2) a sqrt(1 - a^2) / (1 + m/m_e + (5/2)(1 - a^2)),
  // evaluated by hand for m/m_e = 10 (a heavy standard shaft), 17 (the
  // default 10 g end mass) and 30 (a low-squirt shaft; pooltool's default
  // end mass m/30).
  struct Case {
    double ratio, a, degrees;
  };
  const Case cases[] = {
      {10.0, 0.25, 2.5966470098407}, {10.0, 0.5, 4.806132620151086},
      {17.0, 0.1, 0.6960412254384338}, {17.0, 0.25, 1.7038416558143488},
      {17.0, 0.5, 3.117649035768133}, {30.0, 0.25, 1.0397433956357232},
      {30.0, 0.5, 1.8859953633529192},
  };
  for (const Case& c : cases) {
    CueParams p;
    p.end_mass = kMass / c.ratio;
    const StrikeResult r = strike(stroke(2.0, 0.0, 0.0, c.a, 0.0), kMass, kRadius, p);
    EXPECT_NEAR(r.squirt, c.degrees, 1e-9) << c.ratio << " " << c.a;
    EXPECT_NEAR(std::atan2(r.velocity.y, r.velocity.x) / kDeg, c.degrees, 1e-9);
  }
}

TEST(Cue, RightEnglishSquirtsLeft) {
  // Aimed along +y: right english sends the ball to the left (-x), a
  // counter-clockwise (positive) squirt; left english the other way.
  const StrikeResult right = strike(stroke(2.0, 90.0, 0.0, 0.3, 0.0), kMass, kRadius, {});
  const StrikeResult left = strike(stroke(2.0, 90.0, 0.0, -0.3, 0.0), kMass, kRadius, {});
  EXPECT_GT(right.squirt, 0.0);
  EXPECT_LT(right.velocity.x, 0.0);
  EXPECT_GT(right.velocity.y, 0.0);
  EXPECT_NEAR(left.squirt, -right.squirt, 1e-14);
  EXPECT_GT(left.velocity.x, 0.0);
  // Direction = phi + squirt.
  EXPECT_NEAR(std::atan2(right.velocity.y, right.velocity.x) / kDeg, 90.0 + right.squirt, 1e-12);
}

TEST(Cue, SquirtTypicalMagnitudes) {
  // Half-tip english is about a quarter of the radius (a 13 mm tip on a
  // 28.6 mm radius): 1-2 degrees with a low-squirt shaft, a little more with
  // the default end mass; 3 degrees and up at half the radius with a
  // standard shaft.
  CueParams ld;
  ld.end_mass = kMass / 30.0;
  const double half_tip = 0.25;
  const double ld_half = strike(stroke(2.0, 0.0, 0.0, half_tip), kMass, kRadius, ld).squirt;
  EXPECT_GT(ld_half, 0.8);
  EXPECT_LT(ld_half, 2.0);
  const double def_half = strike(stroke(2.0, 0.0, 0.0, half_tip), kMass, kRadius, {}).squirt;
  EXPECT_GT(def_half, 1.0);
  EXPECT_LT(def_half, 3.0);
  CueParams standard;
  standard.end_mass = kMass / 15.0;
  const double std_max = strike(stroke(2.0, 0.0, 0.0, 0.5), kMass, kRadius, standard).squirt;
  EXPECT_GT(std_max, 3.0);
  EXPECT_LT(std_max, 5.0);
}

TEST(Cue, SquirtDependsOnlyOnSideOffsetAndEndMass) {
  const double reference = strike(stroke(2.0, 0.0, 0.0, 0.3, 0.0), kMass, kRadius, {}).squirt;
  CueParams heavy;
  heavy.mass = 0.7;
  heavy.tip_restitution = 0.5;
  EXPECT_DOUBLE_EQ(strike(stroke(7.0, 45.0, 0.0, 0.3, 0.0), kMass, kRadius, heavy).squirt,
                   reference);
  EXPECT_DOUBLE_EQ(strike(stroke(0.3, 0.0, 0.0, 0.3, -0.3), kMass, kRadius, {}).squirt,
                   reference);
  // More end mass, more squirt; no end mass, none.
  CueParams more;
  more.end_mass = 0.02;
  EXPECT_GT(strike(stroke(2.0, 0.0, 0.0, 0.3), kMass, kRadius, more).squirt, reference);
  EXPECT_EQ(strike(stroke(2.0, 0.0, 0.0, 0.3), kMass, kRadius, no_squirt()).squirt, 0.0);
  // Squirt turns the velocity, it does not change the speed.
  const StrikeResult with = strike(stroke(2.0, 0.0, 0.0, 0.3), kMass, kRadius, {});
  const StrikeResult without = strike(stroke(2.0, 0.0, 0.0, 0.3), kMass, kRadius, no_squirt());
  EXPECT_NEAR(breakshot::norm(with.velocity), breakshot::norm(without.velocity), 1e-14);
  EXPECT_EQ(with.spin, without.spin);
}

// ---------------------------------------------------------------------------
// Miscue.

TEST(Cue, MiscueBeyondTheLimit) {
  const CueParams p;  // limit 0.5
  // Exactly at the limit still plays.
  for (const CueStrike& c : {stroke(2.0, 0.0, 0.0, 0.5, 0.0), stroke(2.0, 0.0, 0.0, 0.0, -0.5),
                             stroke(2.0, 0.0, 60.0, -0.5, 0.0)}) {
    const StrikeResult r = strike(c, kMass, kRadius, p);
    EXPECT_FALSE(r.miscue);
    EXPECT_GT(breakshot::norm(r.velocity), 0.0);
  }
  const double at = (1.0 - 1e-12) * p.miscue_limit / std::sqrt(2.0);
  const StrikeResult diag = strike(stroke(2.0, 0.0, 0.0, at, -at), kMass, kRadius, p);
  EXPECT_FALSE(diag.miscue);
  for (const CueStrike& c : {stroke(2.0, 0.0, 0.0, 0.0, 0.5001), stroke(2.0, 0.0, 0.0, -0.51, 0.0),
                             stroke(2.0, 30.0, 40.0, 0.36, 0.36)}) {
    const StrikeResult r = strike(c, kMass, kRadius, p);
    EXPECT_TRUE(r.miscue);
    expect_at_rest(r);
  }
  // A custom limit.
  CueParams loose;
  loose.miscue_limit = 0.7;
  EXPECT_FALSE(strike(stroke(2.0, 0.0, 0.0, 0.0, 0.6), kMass, kRadius, loose).miscue);
  EXPECT_TRUE(strike(stroke(2.0, 0.0, 0.0, 0.0, 0.71), kMass, kRadius, loose).miscue);
  // Whatever the limit, a tip a whole radius off misses the ball.
  CueParams any;
  any.miscue_limit = 5.0;
  EXPECT_TRUE(strike(stroke(2.0, 0.0, 0.0, 1.0, 0.0), kMass, kRadius, any).miscue);
  EXPECT_TRUE(strike(stroke(2.0, 0.0, 0.0, 0.8, 0.8), kMass, kRadius, any).miscue);
  EXPECT_FALSE(strike(stroke(2.0, 0.0, 0.0, 0.9, 0.0), kMass, kRadius, any).miscue);
}

// ---------------------------------------------------------------------------
// Aim, energy, speed.

TEST(Cue, AimRotatesVelocityAndSpin) {
  const StrikeResult up = strike(stroke(2.0, 90.0), kMass, kRadius, {});
  EXPECT_NEAR(up.velocity.x, 0.0, 1e-15);
  EXPECT_GT(up.velocity.y, 0.0);
  const StrikeResult back = strike(stroke(2.0, 180.0), kMass, kRadius, {});
  EXPECT_LT(back.velocity.x, 0.0);
  EXPECT_NEAR(back.velocity.y, 0.0, 1e-15);

  // Any stroke aimed at phi is the stroke aimed at 0 turned by phi.
  const StrikeResult base = strike(stroke(2.0, 0.0, 30.0, 0.2, -0.3), kMass, kRadius, {});
  for (double phi : {90.0, 135.0, -60.0, 270.0}) {
    const StrikeResult r = strike(stroke(2.0, phi, 30.0, 0.2, -0.3), kMass, kRadius, {});
    const double c = std::cos(phi * kDeg);
    const double s = std::sin(phi * kDeg);
    EXPECT_NEAR(r.velocity.x, c * base.velocity.x - s * base.velocity.y, 1e-13);
    EXPECT_NEAR(r.velocity.y, s * base.velocity.x + c * base.velocity.y, 1e-13);
    EXPECT_NEAR(r.spin.x, c * base.spin.x - s * base.spin.y, 1e-10);
    EXPECT_NEAR(r.spin.y, s * base.spin.x + c * base.spin.y, 1e-10);
    EXPECT_NEAR(r.spin.z, base.spin.z, 1e-10);
    EXPECT_DOUBLE_EQ(r.squirt, base.squirt);
  }
}

TEST(Cue, BallNeverGetsMoreEnergyThanTheCueHad) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < 5000; ++n) {
    CueParams p;
    p.mass = 0.1 + 1.0 * unit(rng);  // includes M < m
    p.tip_restitution = unit(rng);
    p.end_mass = 0.03 * unit(rng);
    p.miscue_limit = 0.9;
    const double ball_mass = 0.15 + 0.1 * unit(rng);
    const double r_off = 0.9 * std::sqrt(unit(rng));
    const double t = 2.0 * kPi * unit(rng);
    const CueStrike c = stroke(10.0 * unit(rng) + 1e-3, 360.0 * unit(rng), 89.0 * unit(rng),
                               r_off * std::cos(t), r_off * std::sin(t));
    const StrikeResult r = strike(c, ball_mass, kRadius, p);
    ASSERT_FALSE(r.miscue);
    ASSERT_TRUE(all_finite(r));
    const double cue_energy = 0.5 * p.mass * c.speed * c.speed;
    EXPECT_LE(kinetic(r, ball_mass, kRadius), cue_energy * (1.0 + 1e-12));
  }
}

TEST(Cue, LinearAndMonotonicInCueSpeed) {
  const CueStrike base = stroke(1.0, 20.0, 10.0, -0.2, 0.3);
  const StrikeResult one = strike(base, kMass, kRadius, {});
  double last = 0.0;
  for (double v : {0.01, 0.5, 1.0, 2.0, 4.0, 8.0}) {
    CueStrike c = base;
    c.speed = v;
    const StrikeResult r = strike(c, kMass, kRadius, {});
    const double speed = breakshot::norm(r.velocity);
    EXPECT_GT(speed, last);
    last = speed;
    EXPECT_NEAR(speed, v * breakshot::norm(one.velocity), 1e-12 * v);
    EXPECT_NEAR(r.spin.z, v * one.spin.z, 1e-9 * v);
    EXPECT_DOUBLE_EQ(r.squirt, one.squirt);
  }
}

// ---------------------------------------------------------------------------
// Inputs the equations do not cover: a ball at rest, never NaN.

TEST(Cue, InvalidStrokesLeaveTheBallAtRest) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const CueStrike& c :
       {stroke(0.0), stroke(-1.0), stroke(nan), stroke(inf), stroke(2.0, nan),
        stroke(2.0, inf), stroke(2.0, 0.0, nan), stroke(2.0, 0.0, -1.0), stroke(2.0, 0.0, 90.0),
        stroke(2.0, 0.0, 120.0), stroke(2.0, 0.0, 0.0, nan), stroke(2.0, 0.0, 0.0, 0.0, inf)}) {
    const StrikeResult r = strike(c, kMass, kRadius, {});
    EXPECT_FALSE(r.miscue);
    expect_at_rest(r);
  }
  EXPECT_FALSE(all_finite(StrikeResult{{nan, 0.0}, {}, 0.0, false}));  // the helper works
  const CueStrike ok = stroke(2.0);
  expect_at_rest(strike(ok, 0.0, kRadius, {}));
  expect_at_rest(strike(ok, kMass, -kRadius, {}));
  expect_at_rest(strike(ok, nan, kRadius, {}));
  CueParams bad;
  bad.mass = 0.0;
  expect_at_rest(strike(ok, kMass, kRadius, bad));
  bad = {};
  bad.tip_restitution = 1.5;
  expect_at_rest(strike(ok, kMass, kRadius, bad));
  bad = {};
  bad.end_mass = nan;
  expect_at_rest(strike(ok, kMass, kRadius, bad));
  // Overflow: at rest rather than inf or NaN.
  expect_at_rest(strike(stroke(1e308), kMass, kRadius, {}));
  expect_at_rest(strike(ok, kMass, 1e-320, {}));
  // An immovable cue is allowed: v = (1 + e) V.
  CueParams rigid;
  rigid.mass = inf;
  EXPECT_NEAR(strike(ok, kMass, kRadius, rigid).velocity.x, 2.0 * (1.0 + rigid.tip_restitution),
              1e-14);
}

TEST(Cue, DefaultsAreThePublishedOnes) {
  const CueParams p;
  EXPECT_GE(p.tip_restitution, 0.71);  // Alciatore: 0.71-0.75
  EXPECT_LE(p.tip_restitution, 0.75);
  EXPECT_NEAR(p.mass, 20.0 * 0.028349523125, 1e-3);  // 20 oz
  EXPECT_EQ(p.miscue_limit, 0.5);
}

}  // namespace

}  // namespace test_cue
