// Tests of the ball-ball impact with friction (src/physics/ball_impact.cpp)
// against closed forms, conservation laws, and Alciatore's throw model.
//
// Throw references (Alciatore, billiards.colostate.edu):
// - TP A.14, "The effects of cut angle, speed, and spin on object ball
//   throw": for equal balls and e = 1 the throw angle is
//     tan(theta) = min(mu(v_rel) v cos(phi) / v_rel, 1/7) (v sin(phi) - R wz) / (v cos(phi)),
//     v_rel = sqrt((v sin(phi) - R wz)^2 + (R wx cos(phi))^2),
//   cut angle phi, cue ball speed v, follow wx, sidespin wz (his signs).
//   Its plots use slow = 1 mph (0.447 m/s), medium = 3 mph (1.341 m/s),
//   fast = 7 mph (3.129 m/s). (Read here from a summary of TP A.14; the
//   figure values below are recomputed from the formula, and they agree
//   with what the plots and the tutorial say.)
// - TP A.28, "Throw plots for all types of shots": mu(v) = a + b exp(-c v)
//   fitted to Marlow's data (The Physics of Pocket Billiards, 1995, table
//   10): mu = 0.11, 0.06, 0.01 at v = 0.1, 1, 10 times sin(45 deg) m/s,
//   giving a = 9.951e-3, b = 0.108, c = 1.088.
// - Tutorial "Adjusting aim for throw": throw is largest for slow stun
//   shots near and beyond a half-ball hit (30 deg cut), "about 1 inch per
//   foot of CB travel" (atan(1/12) = 4.8 deg); slow roll shots throw about
//   half of that; fast shots throw little; gearing outside english
//   removes throw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "breakshot/pool.hpp"

namespace test_ball_impact {

namespace {

using breakshot::ball_ball_impact;
using breakshot::BallFriction;
using breakshot::BallImpact;
using breakshot::Vec2;
using breakshot::Vec3;

constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.028575;  // 2.25 in ball
constexpr double kM = 0.17;      // 6 oz
constexpr double kSlow = 0.447;  // 1 mph
constexpr double kMedium = 1.341;  // 3 mph
constexpr double kFast = 3.129;  // 7 mph

double deg(double rad) { return rad * 180.0 / kPi; }
double rad(double deg) { return deg * kPi / 180.0; }

double dot3(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross3(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm3(Vec3 a) { return std::sqrt(dot3(a, a)); }
bool finite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }
bool finite(Vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

struct Ball {
  Vec2 p;
  Vec2 v;
  Vec3 w;
  double m = kM;
  double r = kR;
  double inertia() const { return 0.4 * m * r * r; }
  double energy() const {
    return 0.5 * m * breakshot::norm2(v) + 0.5 * inertia() * dot3(w, w);
  }
};

BallImpact hit(const Ball& a, const Ball& b, double e, const BallFriction& f = {}) {
  return ball_ball_impact(a.p, a.v, a.w, a.m, a.r, b.p, b.v, b.w, b.m, b.r, e, f);
}

// Reproducible random numbers straight from the raw 64-bit output.
struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double uniform() { return static_cast<double>(g() >> 11) * 0x1p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
};

// Two touching balls with random masses, radii, velocities and spins.
void random_pair(Rng& rng, Ball& a, Ball& b) {
  a.m = rng.uniform(0.05, 2.0);
  b.m = rng.uniform(0.05, 2.0);
  a.r = rng.uniform(0.02, 0.04);
  b.r = rng.uniform(0.02, 0.04);
  a.p = {rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)};
  const double angle = rng.uniform(0.0, 2.0 * kPi);
  b.p = a.p + Vec2{std::cos(angle), std::sin(angle)} * (a.r + b.r);
  a.v = {rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0)};
  b.v = {rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0)};
  const double s = 200.0;  // rad/s: up to 5 m/s at the surface
  a.w = {rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s)};
  b.w = {rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s)};
}

// Cue ball at the origin moving at speed v at cut angle phi (radians)
// onto an object ball at rest at (2R, 0): the line of centres is +x and
// the cue ball's tangential motion is +y. `follow` is the spin about the
// horizontal axis perpendicular to the cue ball's path (v / R is natural
// roll), `side` the z spin (> 0 counter-clockwise from above, which is
// right english).
struct CutShot {
  Ball cue, object;
};

CutShot cut_shot(double v, double phi, double follow, double side) {
  CutShot s;
  const Vec2 dir{std::cos(phi), std::sin(phi)};
  s.cue.p = {0.0, 0.0};
  s.cue.v = dir * v;
  s.cue.w = {-follow * dir.y, follow * dir.x, side};  // follow (z x dir) + side z
  s.object.p = {2.0 * kR, 0.0};
  return s;
}

// The object ball's direction off the line of centres, degrees, > 0
// toward the cue ball's tangential motion (+y).
double throw_angle(const BallImpact& r) { return deg(std::atan2(r.v2.y, r.v2.x)); }

// Alciatore's TP A-14 throw angle (degrees) in this file's signs: his
// sidespin wz is -side here (his v sin(phi) - R wz is the slip toward +y,
// which here is v sin(phi) + R side).
double tp_a14_throw(double v, double phi, double follow, double side,
                    const BallFriction& mu = {}) {
  const double st = v * std::sin(phi) + kR * side;
  const double sz = kR * follow * std::cos(phi);
  const double vrel = std::hypot(st, sz);
  if (vrel == 0.0) return 0.0;
  const double vn = v * std::cos(phi);
  const double ratio = std::min(mu(vrel) * vn / vrel, 1.0 / 7.0);
  return deg(std::atan(ratio * st / vn));
}

// ---------------------------------------------------------------------------

TEST(BallFrictionTest, FitsMarlowDataPoints) {
  const BallFriction mu;
  const double s45 = std::sin(rad(45.0));
  EXPECT_NEAR(mu(0.1 * s45), 0.11, 5e-4);
  EXPECT_NEAR(mu(1.0 * s45), 0.06, 5e-4);
  EXPECT_NEAR(mu(10.0 * s45), 0.01, 5e-4);
  EXPECT_DOUBLE_EQ(mu(0.0), mu.a + mu.b);
  EXPECT_DOUBLE_EQ(mu(-0.7), mu(0.7));  // depends on the slip speed only
  EXPECT_EQ((BallFriction{0.0, 0.0, 0.0})(0.3), 0.0);
}

TEST(BallBallImpact, FrictionlessMatchesClosedForm) {
  Rng rng(20240611);
  const BallFriction none{0.0, 0.0, 0.0};
  int approaching = 0;
  for (int k = 0; k < 3000; ++k) {
    Ball a, b;
    random_pair(rng, a, b);
    const double e = rng.uniform();
    const BallImpact r = hit(a, b, e, none);
    const Vec2 n = (b.p - a.p) / breakshot::norm(b.p - a.p);
    const double v1n = dot(a.v, n);
    const double v2n = dot(b.v, n);
    Vec2 x1 = a.v, x2 = b.v;  // expected
    if (v1n - v2n > 0.0) {
      ++approaching;
      const double m = a.m + b.m;
      const double v1n_after = ((a.m - e * b.m) * v1n + (1.0 + e) * b.m * v2n) / m;
      const double v2n_after = ((b.m - e * a.m) * v2n + (1.0 + e) * a.m * v1n) / m;
      x1 = a.v + n * (v1n_after - v1n);
      x2 = b.v + n * (v2n_after - v2n);
    }
    const double tol = 1e-12 * (breakshot::norm(a.v) + breakshot::norm(b.v));
    EXPECT_NEAR(r.v1.x, x1.x, tol);
    EXPECT_NEAR(r.v1.y, x1.y, tol);
    EXPECT_NEAR(r.v2.x, x2.x, tol);
    EXPECT_NEAR(r.v2.y, x2.y, tol);
    EXPECT_EQ(r.w1, a.w);  // no friction, no torque
    EXPECT_EQ(r.w2, b.w);
  }
  EXPECT_GT(approaching, 1000);
}

TEST(BallBallImpact, FrictionlessElasticConservesEnergy) {
  Rng rng(7);
  for (int k = 0; k < 1000; ++k) {
    Ball a, b;
    random_pair(rng, a, b);
    const BallImpact r = hit(a, b, 1.0, BallFriction{0.0, 0.0, 0.0});
    const double before = a.energy() + b.energy();
    Ball a2 = a, b2 = b;
    a2.v = r.v1;
    b2.v = r.v2;
    EXPECT_NEAR(a2.energy() + b2.energy(), before, 1e-12 * before);
  }
}

TEST(BallBallImpact, HeadOnStunCueBallStops) {
  // Full hit, no spin, e = 1, equal masses: the cue ball stops dead and the
  // object ball leaves with its velocity; no slip, so no throw and no spin.
  const CutShot s = cut_shot(2.0, 0.0, 0.0, 0.0);
  const BallImpact r = hit(s.cue, s.object, 1.0);
  EXPECT_NEAR(r.v1.x, 0.0, 1e-15);
  EXPECT_EQ(r.v1.y, 0.0);
  EXPECT_NEAR(r.v2.x, 2.0, 1e-15);
  EXPECT_EQ(r.v2.y, 0.0);
  EXPECT_EQ(r.w1, (Vec3{}));
  EXPECT_EQ(r.w2, (Vec3{}));
}

TEST(BallBallImpact, HeadOnWithRestitution) {
  const double e = 0.95;  // Alciatore's property constants: 0.92-0.98
  const CutShot s = cut_shot(2.0, 0.0, 0.0, 0.0);
  const BallImpact r = hit(s.cue, s.object, e);
  EXPECT_NEAR(r.v1.x, 0.5 * (1.0 - e) * 2.0, 1e-15);
  EXPECT_NEAR(r.v2.x, 0.5 * (1.0 + e) * 2.0, 1e-15);
  EXPECT_EQ(r.v2.y, 0.0);
}

TEST(BallBallImpact, SeparatingGrazingOrCoincidentIsUnchanged) {
  Ball a, b;
  a.p = {0.0, 0.0};
  b.p = {2.0 * kR, 0.0};
  a.w = {1.0, 2.0, 3.0};
  b.w = {-4.0, 5.0, -6.0};
  for (const Vec2 va : {Vec2{-1.0, 0.3}, Vec2{0.0, 2.0}}) {  // moving apart, sliding past
    a.v = va;
    const BallImpact r = hit(a, b, 0.9);
    EXPECT_EQ(r.v1, a.v);
    EXPECT_EQ(r.v2, b.v);
    EXPECT_EQ(r.w1, a.w);
    EXPECT_EQ(r.w2, b.w);
  }
  a.v = {1.0, 0.0};
  Ball c = b;
  c.p = a.p;  // coincident centres: no line of centres
  const BallImpact r = hit(a, c, 0.9);
  EXPECT_EQ(r.v1, a.v);
  EXPECT_EQ(r.w2, b.w);
  for (const double bad : {0.0, -1.0}) {  // masses or radii not > 0
    Ball d = b;
    d.m = bad;
    EXPECT_EQ(hit(a, d, 0.9).v1, a.v);
    d = b;
    d.r = bad;
    EXPECT_EQ(hit(a, d, 0.9).v1, a.v);
  }
  const BallImpact ok = hit(a, b, 0.9);  // and the valid one does something
  EXPECT_NE(ok.v1, a.v);
}

TEST(BallBallImpact, RandomImpactsConserveMomentumAndNeverGainEnergy) {
  Rng rng(42);
  const BallFriction mu;
  int approaching = 0, sticking = 0, sliding = 0;
  for (int k = 0; k < 5000; ++k) {
    Ball a, b;
    random_pair(rng, a, b);
    // Some impacts with a strong friction so that both regimes are common.
    const BallFriction f = (k % 2 == 0) ? mu : BallFriction{0.3, 0.2, 1.0};
    const double e = rng.uniform();
    const BallImpact r = hit(a, b, e, f);
    ASSERT_TRUE(finite(r.v1) && finite(r.v2) && finite(r.w1) && finite(r.w2));
    const Vec2 n = (b.p - a.p) / breakshot::norm(b.p - a.p);
    const double vn = dot(a.v - b.v, n);
    if (!(vn > 0.0)) continue;
    ++approaching;
    const double scale_p = a.m * breakshot::norm(a.v) + b.m * breakshot::norm(b.v);

    // Linear momentum on the table plane.
    const Vec2 p0 = a.v * a.m + b.v * b.m;
    const Vec2 p1 = r.v1 * a.m + r.v2 * b.m;
    EXPECT_NEAR(p1.x, p0.x, 1e-13 * scale_p);
    EXPECT_NEAR(p1.y, p0.y, 1e-13 * scale_p);

    // Restitution along the line of centres.
    EXPECT_NEAR(dot(r.v1 - r.v2, n), -e * vn, 1e-12 * (1.0 + vn));

    // Angular momentum about the vertical axis through the contact point,
    // each ball; and of both balls about the origin.
    const Vec2 c = a.p + n * a.r;
    auto lz = [](const Ball& ball, Vec2 v, Vec3 w, Vec2 o) {
      return ball.inertia() * w.z + ball.m * breakshot::cross(ball.p - o, v);
    };
    const double scale_l = scale_p * (a.r + b.r + 2.0);
    EXPECT_NEAR(lz(a, r.v1, r.w1, c), lz(a, a.v, a.w, c), 1e-13 * scale_l);
    EXPECT_NEAR(lz(b, r.v2, r.w2, c), lz(b, b.v, b.w, c), 1e-13 * scale_l);
    const Vec2 o{0.0, 0.0};
    EXPECT_NEAR(lz(a, r.v1, r.w1, o) + lz(b, r.v2, r.w2, o),
                lz(a, a.v, a.w, o) + lz(b, b.v, b.w, o), 1e-13 * scale_l);

    // The spin changes come from one impulse at one point: about the same
    // axis (perpendicular to n), in the ratio r / I, and none about n.
    const Vec3 n3{n.x, n.y, 0.0};
    const Vec3 dw1 = r.w1 - a.w;
    const Vec3 dw2 = r.w2 - b.w;
    const double scale_w = norm3(a.w) + norm3(b.w) + 1.0;
    EXPECT_NEAR(dot3(dw1, n3), 0.0, 1e-13 * scale_w);
    EXPECT_NEAR(dot3(dw2, n3), 0.0, 1e-13 * scale_w);
    const Vec3 k1 = dw1 * (a.inertia() / a.r);
    const Vec3 k2 = dw2 * (b.inertia() / b.r);
    EXPECT_NEAR(k1.x, k2.x, 1e-13 * scale_p);
    EXPECT_NEAR(k1.y, k2.y, 1e-13 * scale_p);
    EXPECT_NEAR(k1.z, k2.z, 1e-13 * scale_p);

    // Kinetic energy never increases.
    Ball a2 = a, b2 = b;
    a2.v = r.v1;
    a2.w = r.w1;
    b2.v = r.v2;
    b2.w = r.w2;
    const double before = a.energy() + b.energy();
    EXPECT_LE(a2.energy() + b2.energy(), before * (1.0 + 1e-13));

    // The friction impulse on ball 2, from the spin change:
    // dw1 = -(r1 / I1) n x Jt, so Jt = (I1 / r1) n x dw1. Its horizontal
    // part is what ball 2 got besides the normal impulse.
    const double jn = (1.0 + e) * a.m * b.m / (a.m + b.m) * vn;
    const Vec3 jt = cross3(n3, dw1) * (a.inertia() / a.r);
    const Vec2 jt_h = (r.v2 - b.v) * b.m - n * jn;
    EXPECT_NEAR(jt.x, jt_h.x, 1e-12 * scale_p);
    EXPECT_NEAR(jt.y, jt_h.y, 1e-12 * scale_p);

    // Friction: at most mu Jn, and the slip shrinks without reversing. The
    // slip is that of the impact itself, before the cloth takes the
    // vertical velocities -Jt.z / m1 and Jt.z / m2 away.
    auto slip = [&](Vec3 v1, Vec3 w1, Vec3 v2, Vec3 w2) {
      const Vec3 u = v1 + cross3(w1, n3 * a.r) - (v2 + cross3(w2, n3 * (-b.r)));
      return u - n3 * dot3(u, n3);
    };
    const Vec3 s0 = slip({a.v.x, a.v.y, 0.0}, a.w, {b.v.x, b.v.y, 0.0}, b.w);
    const Vec3 s1 = slip({r.v1.x, r.v1.y, -jt.z / a.m}, r.w1, {r.v2.x, r.v2.y, jt.z / b.m}, r.w2);
    // Round-off: the spins are large, their changes small.
    const double tol_j = 1e-13 * (a.inertia() / a.r) * scale_w;
    const double tol_u = 1e-13 * ((a.r + b.r) * scale_w + scale_p / std::min(a.m, b.m));
    const double mu0 = f(norm3(s0));
    EXPECT_LE(norm3(jt), mu0 * jn * (1.0 + 1e-12) + tol_j);
    EXPECT_LE(norm3(s1), norm3(s0) + tol_u);
    EXPECT_GE(dot3(s1, s0), -tol_u * norm3(s0));
    // Parallel to the slip: it stops the slip or has the full mu Jn.
    EXPECT_NEAR(norm3(cross3(s1, s0)), 0.0, tol_u * norm3(s0));
    if (norm3(s1) <= 10.0 * tol_u) {
      ++sticking;
    } else {
      ++sliding;
      EXPECT_NEAR(norm3(jt), mu0 * jn, 1e-12 * jn + tol_j);
    }
  }
  EXPECT_GT(approaching, 2000);
  EXPECT_GT(sticking, 200);
  EXPECT_GT(sliding, 200);
}

TEST(BallBallImpact, SwappingTheBallsGivesTheSameResult) {
  Rng rng(99);
  for (int k = 0; k < 500; ++k) {
    Ball a, b;
    random_pair(rng, a, b);
    const BallImpact r = hit(a, b, 0.93);
    const BallImpact q = hit(b, a, 0.93);
    const double tv = 1e-12 * (breakshot::norm(a.v) + breakshot::norm(b.v) + 1.0);
    const double tw = 1e-12 * (norm3(a.w) + norm3(b.w) + 1.0);
    EXPECT_NEAR(r.v1.x, q.v2.x, tv);
    EXPECT_NEAR(r.v1.y, q.v2.y, tv);
    EXPECT_NEAR(r.v2.x, q.v1.x, tv);
    EXPECT_NEAR(r.w1.x, q.w2.x, tw);
    EXPECT_NEAR(r.w1.z, q.w2.z, tw);
    EXPECT_NEAR(r.w2.y, q.w1.y, tw);
  }
}

// ---------------------------------------------------------------------------
// Throw.

TEST(BallBallImpact, ThrowMatchesTpA14Formula) {
  // Equal balls, e = 1 (TP A-14's assumptions): the object ball's angle
  // off the line of centres equals Alciatore's closed form for every cut
  // angle, speed, follow/draw and sidespin.
  for (const double v : {kSlow, kMedium, kFast}) {
    for (const double roll : {-1.0, 0.0, 0.25, 0.5, 1.0}) {       // draw ... natural roll
      for (const double srf : {-1.25, -0.5, 0.0, 0.5, 1.25}) {  // sidespin, x v/R
        for (int cut = 0; cut <= 85; cut += 5) {
          const double phi = rad(cut);
          const double follow = roll * v / kR;
          const double side = srf * v / kR;
          const CutShot s = cut_shot(v, phi, follow, side);
          const BallImpact r = hit(s.cue, s.object, 1.0);
          EXPECT_NEAR(throw_angle(r), tp_a14_throw(v, phi, follow, side), 1e-9)
              << "v " << v << " roll " << roll << " srf " << srf << " cut " << cut;
          // The object ball leaves along n at v cos(phi) (e = 1).
          EXPECT_NEAR(r.v2.x, v * std::cos(phi), 1e-14);
        }
      }
    }
  }
}

// TP A-14's theory with clean-ball friction set explicitly: the curve
// Alciatore fitted to Marlow's data (TP A-28, kThrowFitTPA28). The throw
// measured on real balls is 2-3 times larger (TP B-3, tests/test_throw.cpp);
// these figures are the theory's, for this curve.
TEST(BallBallImpact, CutInducedThrowWithCleanBallFrictionMatchesTpA14) {
  const BallFriction clean{breakshot::kThrowFitTPA28.a, breakshot::kThrowFitTPA28.b,
                           breakshot::kThrowFitTPA28.c};
  auto stun = [&](double v, double cut) {
    const CutShot s = cut_shot(v, rad(cut), 0.0, 0.0);
    return throw_angle(hit(s.cue, s.object, 1.0, clean));
  };
  auto roll = [&](double v, double cut) {
    const CutShot s = cut_shot(v, rad(cut), v / kR, 0.0);
    return throw_angle(hit(s.cue, s.object, 1.0, clean));
  };

  // A slow stun shot at a half-ball hit (30 deg cut) is thrown toward the
  // cue ball's direction by about 4.7 deg (TP A-14: 4-6 deg for slow stun
  // near 30 deg; tutorial: "about 1 inch per foot", 4.8 deg).
  EXPECT_NEAR(stun(kSlow, 30.0), 4.72, 0.05);
  EXPECT_GT(stun(kSlow, 30.0), 0.0);

  // Slow stun: the largest throw, 5.3 deg at a 33 deg cut, where the two
  // limits meet; below that the "stop the slip" limit binds,
  // tan(throw) = tan(cut) / 7, the same at every speed.
  double best = 0.0;
  int best_cut = 0;
  for (int cut = 1; cut < 90; ++cut) {
    const double t = stun(kSlow, cut);
    if (t > best) {
      best = t;
      best_cut = cut;
    }
  }
  EXPECT_NEAR(best, 5.3, 0.05);
  EXPECT_GE(best_cut, 30);
  EXPECT_LE(best_cut, 40);
  for (const int cut : {5, 10, 15, 20}) {
    const double limit = deg(std::atan(std::tan(rad(cut)) / 7.0));
    EXPECT_NEAR(stun(kSlow, cut), limit, 1e-9) << cut;
    EXPECT_NEAR(stun(kMedium, cut), limit, 1e-9) << cut;
  }

  // Faster shots throw less at large cuts: about 2.8 deg at medium speed
  // and 1.1 deg at fast speed at 45 deg (friction-limited, tan = mu).
  EXPECT_NEAR(stun(kMedium, 45.0), 2.77, 0.05);
  EXPECT_NEAR(stun(kFast, 45.0), 1.13, 0.05);
  for (const int cut : {35, 45, 60, 75}) {
    EXPECT_GT(stun(kSlow, cut), stun(kMedium, cut)) << cut;
    EXPECT_GT(stun(kMedium, cut), stun(kFast, cut)) << cut;
  }

  // Natural roll throws less than stun near a half-ball hit: about half
  // (tutorial: slow roll shots about half the maximum throw), 2.2 deg.
  EXPECT_NEAR(roll(kSlow, 30.0), 2.19, 0.05);
  EXPECT_LT(roll(kSlow, 30.0), 0.6 * stun(kSlow, 30.0));
  // ... and it keeps growing toward thin cuts (4-5 deg for slow roll).
  EXPECT_NEAR(roll(kSlow, 80.0), 4.3, 0.1);
}

TEST(BallBallImpact, SpinInducedThrowOppositeTheEnglish) {
  // Full hit along +x: right english (side > 0, hit right of centre) throws
  // the object ball to the left (+y), left english to the right.
  for (const double v : {kSlow, kMedium, kFast}) {
    for (const double srf : {0.25, 0.5, 1.0}) {
      const double side = srf * v / kR;
      const CutShot right = cut_shot(v, 0.0, 0.0, side);
      const CutShot left = cut_shot(v, 0.0, 0.0, -side);
      const BallImpact rr = hit(right.cue, right.object, 1.0);
      const BallImpact rl = hit(left.cue, left.object, 1.0);
      EXPECT_GT(rr.v2.y, 0.0);
      EXPECT_LT(rl.v2.y, 0.0);
      EXPECT_NEAR(rr.v2.y, -rl.v2.y, 1e-15);
      // A few degrees at most (TP A-14: about 4 deg at the most for stun).
      EXPECT_LT(throw_angle(rr), 6.0);
      // The cue ball goes the other way (momentum) and keeps most english.
      EXPECT_LT(rr.v1.y, 0.0);
      EXPECT_GT(rr.w1.z, 0.5 * side);
    }
  }
}

TEST(BallBallImpact, GearingOutsideEnglishGivesNoThrow) {
  // Outside english with side = -v sin(phi) / R makes the contact points
  // roll on each other: no horizontal slip, no throw, no spin transfer.
  for (const double v : {kSlow, kMedium, kFast}) {
    for (const int cut : {10, 20, 30, 45, 60}) {
      const double phi = rad(cut);
      const double gear = -v * std::sin(phi) / kR;
      const CutShot s = cut_shot(v, phi, 0.0, gear);
      const BallImpact r = hit(s.cue, s.object, 1.0);
      EXPECT_NEAR(r.v2.y, 0.0, 1e-15) << cut;
      EXPECT_NEAR(r.w2.z, 0.0, 1e-12) << cut;
      EXPECT_NEAR(norm3(r.w2), 0.0, 1e-12) << cut;
      // Less outside english than gearing: the throw keeps the cut-induced
      // direction; more than gearing: it is reversed. (Less slip does not
      // always mean less throw: where friction limits, mu grows as the
      // slip falls.)
      const CutShot under = cut_shot(v, phi, 0.0, 0.5 * gear);
      const CutShot over = cut_shot(v, phi, 0.0, 2.0 * gear);
      const double t_under = throw_angle(hit(under.cue, under.object, 1.0));
      const double t_over = throw_angle(hit(over.cue, over.object, 1.0));
      EXPECT_GT(t_under, 0.0) << cut;
      EXPECT_LT(t_over, 0.0) << cut;
    }
  }
}

TEST(BallBallImpact, SpinTransferSidespin) {
  // English on the cue ball gives the object ball a smaller spin the
  // other way round (gear-like), Delta w = (5/2) j / (m R) for both balls.
  const double v = kMedium;
  const double side = 0.5 * v / kR;
  const CutShot s = cut_shot(v, 0.0, 0.0, side);
  const BallImpact r = hit(s.cue, s.object, 1.0);
  EXPECT_LT(r.w2.z, 0.0);
  // At most 5/14 of the english: the stop-slip impulse m R side / 7 times
  // (5/2) / (m R).
  EXPECT_LE(-r.w2.z, 5.0 / 14.0 * side);
  EXPECT_NEAR(r.w1.z - side, r.w2.z, 1e-12);  // same change for equal balls
  // Closed form: slip R side, sliding regime j = mu Jn with Jn = m v.
  const double slip = kR * side;
  const double j = std::min(BallFriction{}(slip) * kM * v, kM * slip / 7.0);
  EXPECT_NEAR(r.w2.z, -2.5 * j / (kM * kR), 1e-9);
  EXPECT_NEAR(r.v2.y, j / kM, 1e-14);
}

TEST(BallBallImpact, SpinTransferFollowAndDraw) {
  // Full hit along +x (rolling along +x is w.y > 0). A follow shot rubs the
  // object ball downward and gives it a little draw; a draw shot gives it a
  // little follow. No throw (the slip is vertical).
  const double v = kMedium;
  for (const double roll : {1.0, -1.0}) {
    const CutShot s = cut_shot(v, 0.0, roll * v / kR, 0.0);
    const BallImpact r = hit(s.cue, s.object, 1.0);
    EXPECT_EQ(r.v2.y, 0.0);
    EXPECT_NEAR(r.v2.x, v, 1e-14);
    EXPECT_NEAR(r.v1.x, 0.0, 1e-14);
    EXPECT_LT(r.w2.y * roll, 0.0);
    EXPECT_LT(std::abs(r.w2.y), 0.12 * v / kR);
    // The cue ball keeps almost all of its follow or draw: that is what
    // makes it follow or draw after a full hit.
    EXPECT_GT(r.w1.y * roll, 0.85 * v / kR);
    EXPECT_EQ(r.w1.x, 0.0);
    EXPECT_EQ(r.w2.z, 0.0);
  }
}

TEST(BallBallImpact, StraightHitOnMovingBallKeepsItsSpin) {
  // FastFiz lost the spin when the balls were exactly aligned (physics.md
  // pitfalls). Here: a rolling cue ball with english catches a slower
  // rolling object ball on a perfectly straight line.
  const double va = 2.0;
  const double vb = 0.5;
  Ball a, b;
  a.p = {0.3, 0.4};
  b.p = a.p + Vec2{2.0 * kR, 0.0};
  a.v = {va, 0.0};
  b.v = {vb, 0.0};
  a.w = {0.0, va / kR, 30.0};
  b.w = {0.0, vb / kR, 0.0};
  const double e = 0.95;
  const BallImpact r = hit(a, b, e);
  ASSERT_TRUE(finite(r.v1) && finite(r.w1) && finite(r.v2) && finite(r.w2));
  // Normal velocities as without friction.
  EXPECT_NEAR(r.v1.x, 0.5 * ((1.0 - e) * va + (1.0 + e) * vb), 1e-14);
  EXPECT_NEAR(r.v2.x, 0.5 * ((1.0 + e) * va + (1.0 - e) * vb), 1e-14);
  // Spins change by at most the friction limit mu Jn: a few percent.
  const double jn = (1.0 + e) * 0.5 * kM * (va - vb);
  const double dw_max = 2.5 * BallFriction{}(0.0) * jn / (kM * kR);
  EXPECT_LE(norm3(r.w1 - a.w), dw_max * (1.0 + 1e-12));
  EXPECT_GT(r.w1.y, 0.9 * a.w.y);
  EXPECT_GT(r.w1.z, 0.9 * a.w.z);
  EXPECT_GT(r.w2.y, 0.5 * b.w.y);
  EXPECT_EQ(r.w1.x, 0.0);  // no spin about the line of centres appears
  EXPECT_EQ(r.w2.x, 0.0);
  // Slight spin-induced throw of the object ball to the left of right
  // english, and a little opposite english for it.
  EXPECT_GT(r.v2.y, 0.0);
  EXPECT_LT(r.w2.z, 0.0);

  // Straight hit with no slip at all (both stun): exact frictionless result.
  a.w = {};
  b.w = {};
  const BallImpact q = hit(a, b, e);
  EXPECT_EQ(q.w1, (Vec3{}));
  EXPECT_EQ(q.w2, (Vec3{}));
  EXPECT_EQ(q.v2.y, 0.0);
}

TEST(BallBallImpact, SmallCutStopsTheSlip) {
  // At a small cut the "stop the slip" limit binds: after the impact the
  // contact points no longer slide, and the object ball's tangential speed
  // is v sin(phi) / 7 (equal balls).
  const double v = kMedium;
  const double phi = rad(10.0);
  const CutShot s = cut_shot(v, phi, 0.0, 0.0);
  const BallImpact r = hit(s.cue, s.object, 0.9);
  const Vec3 n3{1.0, 0.0, 0.0};
  const Vec3 u = Vec3{r.v1.x, r.v1.y, 0.0} + cross3(r.w1, n3 * kR) -
                 (Vec3{r.v2.x, r.v2.y, 0.0} + cross3(r.w2, n3 * (-kR)));
  EXPECT_NEAR(u.y, 0.0, 1e-14);
  EXPECT_NEAR(u.z, 0.0, 1e-14);
  EXPECT_NEAR(r.v2.y, v * std::sin(phi) / 7.0, 1e-14);
}

TEST(BallBallImpact, UnequalBallsUseTheirOwnInertia) {
  // A light small ball hits a heavy big one at a small cut (slip stopped):
  // the stop-slip impulse uses 1/M_t = 7/2 (1/m1 + 1/m2), whatever radii.
  Ball a, b;
  a.m = 0.12;
  a.r = 0.025;
  b.m = 0.4;
  b.r = 0.035;
  a.p = {0.0, 0.0};
  b.p = {a.r + b.r, 0.0};
  const double v = 1.0;
  const double phi = rad(8.0);
  a.v = Vec2{std::cos(phi), std::sin(phi)} * v;
  const BallImpact r = hit(a, b, 1.0);
  const double mt = 1.0 / (3.5 * (1.0 / a.m + 1.0 / b.m));
  EXPECT_NEAR(r.v2.y, mt * v * std::sin(phi) / b.m, 1e-14);
  EXPECT_NEAR(r.v1.y, v * std::sin(phi) - mt * v * std::sin(phi) / a.m, 1e-14);
  EXPECT_NEAR(r.w2.z, -b.r * mt * v * std::sin(phi) / b.inertia(), 1e-12);
}

// ---------------------------------------------------------------------------
// Mathavan, Jackson, Parkin 2014 (ball_ball_impact_mathavan).

// The cue ball's (or object ball's) velocity once it rolls: a sliding ball
// keeps the direction of its slip u = v + w x (-R z) and ends rolling at
// v - (2/7) u (physics.md, "Motion between events").
Vec2 rolling_velocity(Vec2 v, Vec3 w, double r) {
  const Vec2 u{v.x - r * w.y, v.y + r * w.x};
  return v - u * (2.0 / 7.0);
}

TEST(MathavanImpact, ReproducesThePapersTablesOneAndTwo) {
  // Mathavan, Jackson, Parkin 2014, Tables 1 and 2: five shots with a
  // rolling cue ball (speed V, topspin V/R, cut angle phi) on snooker
  // balls (R = 26.25 mm, M = 140.6 g), e = 0.89, mu_s = 0.21, mu_b = 0.05;
  // the model's speeds of the cue and object balls once they roll again and
  // their angles off the cue ball's initial direction. The values are as
  // transcribed in pooltool's tests
  // (tests/physics/resolve/ball_ball/test_frictional_mathavan.py), which
  // hold pooltool's implementation to 1 %; the same tolerance here.
  struct Shot {
    double v, topspin, cut;                        // m/s, rad/s, degrees
    double cue_speed, object_speed, cue_angle, object_angle;  // m/s, degrees
  };
  const Shot shots[] = {
      {1.539, 58.63, 33.83, 0.914, 0.831, 31.93, 32.20},
      {1.032, 39.31, 26.36, 0.520, 0.599, 32.45, 25.07},
      {1.364, 51.96, 40.52, 0.917, 0.676, 29.91, 38.62},
      {1.731, 65.94, 46.50, 1.280, 0.780, 27.32, 44.38},
      {0.942, 35.89, 18.05, 0.383, 0.579, 29.47, 17.15},
  };
  const double R = 0.02625, M = 0.1406;
  for (const Shot& k : shots) {
    const double c = std::cos(rad(k.cut)), s = std::sin(rad(k.cut));
    const Vec2 v{k.v * c, k.v * s};
    const Vec3 w{-k.topspin * s, k.topspin * c, 0.0};
    const BallImpact r = breakshot::ball_ball_impact_mathavan(
        {0.0, 0.0}, v, w, M, R, {2.0 * R, 0.0}, {}, {}, M, R, 0.89,
        BallFriction{0.05, 0.0, 0.0}, 0.21);
    const Vec2 cue = rolling_velocity(r.v1, r.w1, R);
    const Vec2 obj = rolling_velocity(r.v2, r.w2, R);
    const double cue_angle = std::abs(deg(std::atan(cue.y / cue.x)) - k.cut);
    const double obj_angle = std::abs(deg(std::atan(obj.y / obj.x)) - k.cut);
    EXPECT_NEAR(breakshot::norm(cue), k.cue_speed, 0.01 * k.cue_speed) << k.v;
    EXPECT_NEAR(breakshot::norm(obj), k.object_speed, 0.01 * k.object_speed) << k.v;
    EXPECT_NEAR(cue_angle, k.cue_angle, 0.01 * k.cue_angle) << k.v;
    EXPECT_NEAR(obj_angle, k.object_angle, 0.01 * k.object_angle) << k.v;
  }
}

TEST(MathavanImpact, WithoutFrictionIsNewtonsRestitution) {
  // No friction anywhere: Stronge's energetic restitution equals Newton's
  // (v_n' = -e v_n), up to the step of the integration (1/1000 of the
  // impulse here).
  Rng rng(11);
  for (int k = 0; k < 300; ++k) {
    Ball a, b;
    random_pair(rng, a, b);
    const double e = rng.uniform(0.5, 1.0);
    const BallImpact r = breakshot::ball_ball_impact_mathavan(
        a.p, a.v, a.w, a.m, a.r, b.p, b.v, b.w, b.m, b.r, e, BallFriction{0.0, 0.0, 0.0}, 0.2);
    const BallImpact x = hit(a, b, e, BallFriction{0.0, 0.0, 0.0});
    const double scale = breakshot::norm(a.v) + breakshot::norm(b.v);
    EXPECT_NEAR(r.v1.x, x.v1.x, 1e-2 * scale);
    EXPECT_NEAR(r.v1.y, x.v1.y, 1e-2 * scale);
    EXPECT_NEAR(r.v2.x, x.v2.x, 1e-2 * scale);
    EXPECT_NEAR(r.v2.y, x.v2.y, 1e-2 * scale);
    EXPECT_EQ(r.w1, a.w);
    EXPECT_EQ(r.w2, b.w);
  }
}

TEST(MathavanImpact, StunThrowAgreesWithTheOneStepImpact) {
  // A stun cut: no vertical slip at the contact, so the cloth takes no part
  // and the slip keeps its direction; with a constant mu the integrated
  // impulse is the one-step one whenever friction does not stop the slip
  // (cuts beyond the no-slip limit), up to the integration step.
  const BallFriction mu{0.06, 0.0, 0.0};
  for (const double cut : {35.0, 45.0, 60.0}) {
    const CutShot s = cut_shot(kMedium, rad(cut), 0.0, 0.0);
    const BallImpact a = hit(s.cue, s.object, 1.0, mu);
    const BallImpact b = breakshot::ball_ball_impact_mathavan(
        s.cue.p, s.cue.v, s.cue.w, kM, kR, s.object.p, s.object.v, s.object.w, kM, kR, 1.0, mu,
        0.2);
    EXPECT_NEAR(throw_angle(b), throw_angle(a), 0.01) << cut;
  }
}

TEST(MathavanImpact, NeverGainsEnergyAndIsRepeatable) {
  Rng rng(2014);
  for (int k = 0; k < 300; ++k) {
    Ball a, b;
    random_pair(rng, a, b);
    const double e = rng.uniform();
    const BallFriction mu{rng.uniform(0.0, 0.1), rng.uniform(0.0, 0.1), 1.0};
    const BallImpact r = breakshot::ball_ball_impact_mathavan(
        a.p, a.v, a.w, a.m, a.r, b.p, b.v, b.w, b.m, b.r, e, mu, 0.2);
    Ball a2 = a, b2 = b;
    a2.v = r.v1;
    a2.w = r.w1;
    b2.v = r.v2;
    b2.w = r.w2;
    const double before = a.energy() + b.energy();
    // The work-based restitution ends on a step: allow one step's worth.
    EXPECT_LE(a2.energy() + b2.energy(), before * (1.0 + 1e-3)) << k;
    ASSERT_TRUE(finite(r.v1) && finite(r.v2) && finite(r.w1) && finite(r.w2));
    const BallImpact again = breakshot::ball_ball_impact_mathavan(
        a.p, a.v, a.w, a.m, a.r, b.p, b.v, b.w, b.m, b.r, e, mu, 0.2);
    EXPECT_EQ(again.v1, r.v1);
    EXPECT_EQ(again.w2, r.w2);
  }
}

}  // namespace

}  // namespace test_ball_impact
