// Tests of the root finders against references computed in __float128.
//
// The reference takes the double coefficients exactly (every double is a
// __float128) and finds every root by plain bisection in 113-bit
// arithmetic, with the same rules as first_contact (monotone pieces from
// the critical points, decreasing pieces only). Its roots are exact to
// ~1e-33 relative, so the difference from first_contact is the latter's
// own error, which we measure in ulps.
#include "breakshot/roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using breakshot::first_contact;
using breakshot::first_contact_quadratic;
using breakshot::solve_quadratic;

__extension__ typedef __float128 Q;
__extension__ typedef unsigned __int128 U128;

constexpr double kInf = std::numeric_limits<double>::infinity();
const Q kQInf = static_cast<Q>(kInf);

// ---------------------------------------------------------------------------
// Reproducible random numbers straight from the raw 64-bit output.

struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double uniform() { return static_cast<double>(g() >> 11) * 0x1p-53; }  // [0, 1)
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  double pow10(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
  int below(int n) { return static_cast<int>(g() % static_cast<std::uint64_t>(n)); }
  double sign() { return (g() & 1U) != 0U ? 1.0 : -1.0; }
};

// ---------------------------------------------------------------------------
// The __float128 reference.

Q horner_q(const Q* c, int n, Q t) {
  Q r = c[n];
  for (int k = n - 1; k >= 0; --k) r = r * t + c[k];
  return r;
}

// The point where the sign class (f > 0 or f <= 0) flips in [lo, hi],
// to full precision; returns the end on the side of hi.
Q bisect_q(const Q* c, int n, Q lo, Q hi) {
  const bool pos_lo = horner_q(c, n, lo) > 0;
  for (int i = 0; i < 20000; ++i) {
    const Q mid = (lo + hi) / 2;
    if (!(mid > lo && mid < hi)) break;
    if ((horner_q(c, n, mid) > 0) == pos_lo) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return hi;
}

// Appends, in ascending order, the points of (a, b) where the polynomial
// changes sign, found recursively from the sign changes of its derivative.
void crossings_q(const Q* c, int n, Q a, Q b, std::vector<Q>& out) {
  while (n > 0 && c[n] == 0) --n;
  if (n < 1) return;
  Q d[4];
  for (int k = 0; k < n; ++k) d[k] = static_cast<Q>(k + 1) * c[k + 1];
  std::vector<Q> pts{a};
  crossings_q(d, n - 1, a, b, pts);
  pts.push_back(b);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Q f0 = horner_q(c, n, pts[i]);
    const Q f1 = horner_q(c, n, pts[i + 1]);
    if ((f0 > 0 && f1 < 0) || (f0 < 0 && f1 > 0)) out.push_back(bisect_q(c, n, pts[i], pts[i + 1]));
  }
}

// `crossing` tells whether the contact is a root of f (rather than the
// start of a decreasing piece where f <= 0 already).
Q ref_first_contact(const double* c, int degree, double t_max, bool* crossing = nullptr) {
  Q q[5] = {0, 0, 0, 0, 0};
  int n = 0;
  for (int k = 0; k <= degree; ++k) {
    q[k] = c[k];
    if (c[k] != 0.0) n = k;
  }
  if (n == 0) return kQInf;
  Q d[4];
  for (int k = 0; k < n; ++k) d[k] = static_cast<Q>(k + 1) * q[k + 1];
  const Q T = t_max;
  std::vector<Q> pts{0};
  crossings_q(d, n - 1, 0, T, pts);
  pts.push_back(T);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Q ta = pts[i], tb = pts[i + 1];
    if (!(tb > ta)) continue;
    if (horner_q(d, n - 1, (ta + tb) / 2) < 0) {
      if (horner_q(q, n, ta) <= 0) return ta;
      if (horner_q(q, n, tb) <= 0) {
        if (crossing != nullptr) *crossing = true;
        return bisect_q(q, n, ta, tb);
      }
    }
  }
  return kQInf;
}

Q sqrt_q(Q v) {
  if (v <= 0) return 0;
  Q x = std::sqrt(static_cast<double>(v));
  for (int i = 0; i < 3; ++i) x = (x + v / x) / 2;
  return x;
}

Q abs_q(Q x) { return x < 0 ? -x : x; }

double ulp_at(double x) {
  x = std::fabs(x);
  return std::nextafter(x, kInf) - x;
}

// How far the root t of f can move when every coefficient is perturbed
// by a relative u: u sum |c_k| t^k / |f'(t)| (first order).
double sensitivity(const double* c, int degree, double t) {
  Q terms = 0, slope = 0, tk = 1;
  for (int k = 0; k <= degree; ++k) {
    terms += abs_q(static_cast<Q>(c[k])) * tk;
    if (k + 1 <= degree) slope += static_cast<Q>(k + 1) * c[k + 1] * tk;
    tk *= t;
  }
  return static_cast<double>(0x1p-53 * terms / abs_q(slope));
}

std::string dump(const double* c, int degree, double t_max) {
  std::string s = "c = {";
  char buf[64];
  for (int k = 0; k <= degree; ++k) {
    std::snprintf(buf, sizeof buf, "%s%a", k ? ", " : "", c[k]);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "}, t_max = %a", t_max);
  return s + buf;
}

// Running statistics of one family of random polynomials.
struct Stats {
  int contacts = 0;
  int misses = 0;
  double max_ulps = 0.0;
  void print(const char* name) const {
    std::printf("  [%s] %d contacts, %d misses, max error %.2f ulp\n", name, contacts, misses,
                max_ulps);
  }
};

// first_contact agrees with the reference: both find no contact, or the
// times differ by at most 1e-12 relative and max_ulps ulps.
::testing::AssertionResult agrees(const double* c, int degree, double t_max, Stats& st,
                                  double max_ulps = 2.0) {
  const double t = first_contact(c, degree, t_max);
  bool crossing = false;
  const Q r = ref_first_contact(c, degree, t_max, &crossing);
  if (r == kQInf) {
    ++st.misses;
    if (t == kInf) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "no contact expected, got t = " << t << " for "
                                         << dump(c, degree, t_max);
  }
  ++st.contacts;
  const double rd = static_cast<double>(r);
  if (!(t >= 0.0 && t <= t_max)) {
    return ::testing::AssertionFailure() << "contact at " << rd << " expected, got " << t
                                         << " for " << dump(c, degree, t_max);
  }
  if (crossing) {
    // The documented result: the first double at which f <= 0.
    Q q[5] = {0, 0, 0, 0, 0};
    for (int k = 0; k <= degree; ++k) q[k] = c[k];
    const double before = std::nextafter(t, 0.0);
    if (!(horner_q(q, degree, t) <= 0 && (t == 0.0 || horner_q(q, degree, before) > 0))) {
      return ::testing::AssertionFailure() << "t = " << t << " is not the first double with f <= 0"
                                           << " for " << dump(c, degree, t_max);
    }
  }
  const double err = static_cast<double>(abs_q(static_cast<Q>(t) - r));
  const double ulps = err / ulp_at(rd);
  st.max_ulps = std::max(st.max_ulps, ulps);
  if (err <= 1e-12 * rd + std::numeric_limits<double>::denorm_min() && ulps <= max_ulps) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "contact at " << rd << " expected, got " << t << " ("
                                       << ulps << " ulp) for " << dump(c, degree, t_max);
}

// ---------------------------------------------------------------------------
// Generators.

constexpr double kSigma = 2.0 * 0.028575;  // two pool balls, 57.15 mm

struct Quartic {
  double c[5];
  double t_max;
};

// Two balls decelerating along their own velocities (rolling or sliding
// friction), as in the friction model: d(t) = dp + dv t + da t^2 / 2 and
// f = |d|^2 - sigma^2, over the window until the first ball stops. With
// `aimed` the relative position is chosen so that the balls pass within
// 1.5 sigma of each other at a random time, so most pairs collide.
Quartic ball_pair(Rng& rng, bool aimed) {
  double v[2][2], a[2][2];
  double window = kInf;
  for (int i = 0; i < 2; ++i) {
    const bool moving = i == 0 || rng.uniform() < 0.7;
    const double speed = moving ? rng.pow10(-1.5, 0.8) : 0.0;
    const double angle = rng.uniform(0.0, 6.283185307179586);
    const double decel = rng.uniform() < 0.5 ? 0.0981 : 1.962;
    v[i][0] = speed * std::cos(angle);
    v[i][1] = speed * std::sin(angle);
    a[i][0] = moving ? -decel * std::cos(angle) : 0.0;
    a[i][1] = moving ? -decel * std::sin(angle) : 0.0;
    if (moving) window = std::min(window, speed / decel);
  }
  const double dv[2] = {v[1][0] - v[0][0], v[1][1] - v[0][1]};
  const double da[2] = {a[1][0] - a[0][0], a[1][1] - a[0][1]};
  double dp[2];
  if (aimed) {
    const double tau = rng.uniform(0.0, 1.2) * window;
    const double w[2] = {dv[0] + da[0] * tau, dv[1] + da[1] * tau};  // velocity at tau
    const double wn = std::hypot(w[0], w[1]);
    const double miss = rng.uniform(-1.5, 1.5) * kSigma;
    const double nx = wn > 0.0 ? -w[1] / wn : 1.0, ny = wn > 0.0 ? w[0] / wn : 0.0;
    dp[0] = miss * nx - dv[0] * tau - 0.5 * da[0] * tau * tau;
    dp[1] = miss * ny - dv[1] * tau - 0.5 * da[1] * tau * tau;
  } else {
    dp[0] = rng.uniform(-2.5, 2.5);
    dp[1] = rng.uniform(-1.25, 1.25);
  }
  Quartic q{};
  q.c[0] = dp[0] * dp[0] + dp[1] * dp[1] - kSigma * kSigma;
  q.c[1] = 2.0 * (dp[0] * dv[0] + dp[1] * dv[1]);
  q.c[2] = dv[0] * dv[0] + dv[1] * dv[1] + (dp[0] * da[0] + dp[1] * da[1]);
  q.c[3] = dv[0] * da[0] + dv[1] * da[1];
  q.c[4] = 0.25 * (da[0] * da[0] + da[1] * da[1]);
  q.t_max = window;
  return q;
}

// s * prod (t - r_i) with real roots and complex pairs, degree 1..4.
int product_poly(Rng& rng, double c[5]) {
  const int degree = 1 + rng.below(4);
  Q q[5] = {1, 0, 0, 0, 0};
  int n = 0;
  auto multiply = [&](Q c0, Q c1, Q c2, int dn) {  // by c0 + c1 t + c2 t^2
    Q r[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i <= n; ++i) {
      r[i] += q[i] * c0;
      if (i + 1 <= 4) r[i + 1] += q[i] * c1;
      if (i + 2 <= 4 && dn == 2) r[i + 2] += q[i] * c2;
    }
    std::copy(r, r + 5, q);
    n += dn;
  };
  while (n < degree) {
    if (degree - n >= 2 && rng.uniform() < 0.4) {
      const double x = rng.uniform(-1.0, 3.0), y = rng.pow10(-3.0, 0.3);
      multiply(static_cast<Q>(x) * x + static_cast<Q>(y) * y, -2 * static_cast<Q>(x), 1, 2);
    } else {
      multiply(-static_cast<Q>(rng.uniform(-1.0, 3.0)), 1, 0, 1);
    }
  }
  const double s = rng.sign() * rng.pow10(-2.0, 2.0);
  for (int k = 0; k <= 4; ++k) c[k] = k <= degree ? static_cast<double>(q[k] * s) : 0.0;
  return degree;
}

// Scaling the time axis: g(t) = f(t * s) has the roots of f divided by s.
void scale_time(const double* c, int degree, double s, double* out) {
  double sk = 1.0;
  for (int k = 0; k <= degree; ++k) {
    out[k] = c[k] * sk;
    sk *= s;
  }
}

// ---------------------------------------------------------------------------
// Exactly representable grazing parabolas.
//
// With r = 1 + m 2^-52 we have r^2 = 1 + m 2^-51 + m^2 2^-104, so
// f = t^2 - 2 r t + c0 with c0 = 1 + m 2^-51 + j 2^-52 (a double) has its
// minimum f(r) = c0 - r^2 = (2^52 j - m^2) 2^-104 exactly. Choosing m as a
// square root of -s or +s modulo 2^52 makes that dip +s 2^-104 or
// -s 2^-104: as small as we like, about 5e-32 s relative to f's terms.

// Odd x with x^2 = a (mod 2^52) for a = 1 (mod 8), by Hensel lifting.
std::uint64_t sqrt_mod_2_52(std::uint64_t a) {
  std::uint64_t x = 1;
  for (int i = 3; i < 52; ++i) {  // x^2 = a (mod 2^i) here
    const std::uint64_t mask = (std::uint64_t{1} << (i + 1)) - 1;
    if (((x * x) ^ a) & mask) x += std::uint64_t{1} << (i - 1);
  }
  return x;
}

struct Grazing {
  double c[3];
  double r;    // the minimum
  double dip;  // f(r) relative to r^2 (exact up to the rounding of this double)
};

// dip_rel > 0: stays apart by dip_rel r^2; < 0: overlaps by that much.
Grazing grazing_parabola(double dip_rel) {
  const double mag = std::fabs(dip_rel);
  Grazing g{};
  if (mag > 1e-14) {
    // Large enough to set directly: c0 = r^2 (1 + dip), rounded; the dip
    // of the rounded polynomial is within 1e-16 of the intended one.
    g.r = 1.2345678901234567;
    g.c[0] = g.r * g.r * (1.0 + dip_rel);
  } else {
    std::uint64_t s = static_cast<std::uint64_t>(std::llround(mag * 0x1p104));
    s = s - s % 8 + (dip_rel > 0 ? 7 : 1);  // +dip: m^2 = -s, -dip: m^2 = +s (mod 2^52)
    const std::uint64_t two52 = std::uint64_t{1} << 52;
    const std::uint64_t a = dip_rel > 0 ? two52 - s : s;
    std::uint64_t m = sqrt_mod_2_52(a) % (two52 / 2);
    m = std::min(m, two52 / 2 - m);  // the four roots are +-x, +-x + 2^51
    const U128 m2 = static_cast<U128>(m) * m;
    const std::uint64_t j =
        static_cast<std::uint64_t>((dip_rel > 0 ? m2 + s : m2 - s) >> 52);
    g.r = 1.0 + std::ldexp(static_cast<double>(m), -52);
    g.c[0] = 1.0 + std::ldexp(static_cast<double>(2 * m + j), -52);
  }
  g.c[1] = -2.0 * g.r;
  g.c[2] = 1.0;
  const Q exact_dip = static_cast<Q>(g.c[0]) - static_cast<Q>(g.r) * g.r;
  g.dip = static_cast<double>(exact_dip / (static_cast<Q>(g.r) * g.r));
  return g;
}

// ---------------------------------------------------------------------------
// first_contact: random families against the reference.

TEST(FirstContact, RandomBallPairsMatchReference) {
  Rng rng(0x5eed0001);
  Stats aimed, loose;
  for (int i = 0; i < 3000; ++i) {
    const Quartic q = ball_pair(rng, true);
    ASSERT_TRUE(agrees(q.c, 4, q.t_max, aimed)) << "case " << i;
  }
  for (int i = 0; i < 1000; ++i) {
    const Quartic q = ball_pair(rng, false);
    ASSERT_TRUE(agrees(q.c, 4, q.t_max, loose)) << "case " << i;
  }
  aimed.print("aimed ball pairs");
  loose.print("random ball pairs");
  EXPECT_GT(aimed.contacts, 1000);  // the family really exercises contacts
  EXPECT_GT(aimed.misses, 300);
}

TEST(FirstContact, RandomProductsOfRootsMatchReference) {
  Rng rng(0x5eed0002);
  Stats st;
  for (int i = 0; i < 3000; ++i) {
    double c[5];
    const int degree = product_poly(rng, c);
    const double t_max = rng.uniform(0.0, 3.5);
    ASSERT_TRUE(agrees(c, degree, t_max, st)) << "case " << i;
  }
  st.print("products of roots");
  EXPECT_GT(st.contacts, 500);
}

TEST(FirstContact, RandomCoefficientsMatchReference) {
  Rng rng(0x5eed0003);
  Stats st;
  for (int i = 0; i < 3000; ++i) {
    const int degree = 1 + rng.below(4);
    double c[5] = {0, 0, 0, 0, 0};
    for (int k = 0; k <= degree; ++k) c[k] = rng.sign() * rng.pow10(-3.0, 3.0);
    const double t_max = rng.pow10(-2.0, 2.0);
    ASSERT_TRUE(agrees(c, degree, t_max, st)) << "case " << i;
  }
  st.print("random coefficients");
  EXPECT_GT(st.contacts, 500);
}

// Random near-double roots: ((t - r)^2 + dip r^2) times a positive
// quadratic, with dips from 1e-2 down to 1e-16 either way. Near a double
// root the root is ill-conditioned (an error of u in f moves it by
// sqrt(u)), so these exercise the compensated evaluation.
TEST(FirstContact, RandomNearDoubleRootsMatchReference) {
  Rng rng(0x5eed0004);
  Stats st;
  for (int i = 0; i < 2000; ++i) {
    const double r = rng.uniform(0.1, 2.0);
    const double dip = rng.sign() * rng.pow10(-16.0, -2.0) * r * r;
    const double x = rng.uniform(-2.0, 3.0), y = rng.pow10(-1.0, 0.5);
    const Q a[3] = {static_cast<Q>(r) * r + dip, -2 * static_cast<Q>(r), 1};
    const Q b[3] = {static_cast<Q>(x) * x + static_cast<Q>(y) * y, -2 * static_cast<Q>(x), 1};
    const bool quartic = (i & 1) != 0;
    double c[5];
    for (int k = 0; k <= 4; ++k) {
      Q s = 0;
      for (int j = 0; j <= 2; ++j) {
        if (k - j >= 0 && k - j <= 2) s += a[j] * (quartic ? b[k - j] : (k == j ? 1 : 0));
      }
      c[k] = static_cast<double>(s);
    }
    const double t_max = rng.uniform(r, 2.0 * r + 1.0);
    ASSERT_TRUE(agrees(c, quartic ? 4 : 2, t_max, st)) << "case " << i;
  }
  st.print("near-double roots");
}

// ---------------------------------------------------------------------------
// Grazing: a minimum that dips below zero by any amount is a contact; one
// that stays above zero by any amount is not.

TEST(FirstContact, GrazingDipsBelowZeroAreFound) {
  for (const double rel : {1e-10, 1e-20, 1e-30}) {
    const Grazing g = grazing_parabola(-rel);
    ASSERT_LT(g.dip, 0.0);
    EXPECT_NEAR(g.dip / -rel, 1.0, 0.5) << rel;
    Stats st;
    EXPECT_TRUE(agrees(g.c, 2, 2.0, st, 1.0)) << rel;
    const double t = first_contact(g.c, 2, 2.0);
    EXPECT_LT(t, g.r) << rel;
    // The contact is sqrt(|dip|) r before the minimum.
    EXPECT_NEAR((g.r - t) / g.r, std::sqrt(-g.dip), 1e-6 * std::sqrt(-g.dip) + 2.3e-16) << rel;
    // The same embedded in a quartic: t^2 (t^2 - 2 r t + c0) dips to
    // r^2 f(r) near t = r after a maximum near r / 2.
    const double c4[5] = {0.0, 0.0, g.c[0], g.c[1], 1.0};
    EXPECT_TRUE(agrees(c4, 4, 2.0, st, 1.0)) << rel;
    EXPECT_LT(first_contact(c4, 4, 2.0), g.r) << rel;
  }
}

TEST(FirstContact, GrazingAboveZeroIsNoContact) {
  for (const double rel : {1e-10, 1e-20, 1e-30}) {
    const Grazing g = grazing_parabola(rel);
    ASSERT_GT(g.dip, 0.0);
    EXPECT_NEAR(g.dip / rel, 1.0, 0.5) << rel;
    EXPECT_EQ(first_contact(g.c, 2, 2.0), kInf) << rel;
    EXPECT_EQ(first_contact(g.c, 2, kInf), kInf) << rel;
    const double c4[5] = {0.0, 0.0, g.c[0], g.c[1], 1.0};
    EXPECT_EQ(first_contact(c4, 4, 2.0), kInf) << rel;
  }
}

// Power-of-two rescaling keeps the grazing polynomials exact: time scales
// of 2^-30 (1e-9 s) and 2^20 (1e6 s), coefficient scales of 2^-660 and
// 2^+660 (1e-200, 1e+200).
TEST(FirstContact, GrazingIsScaleInvariant) {
  for (const double rel : {-1e-10, -1e-20, -1e-30, 1e-10, 1e-20, 1e-30}) {
    const Grazing g = grazing_parabola(rel);
    const double t1 = first_contact(g.c, 2, 2.0);
    for (const int te : {-30, 20}) {
      for (const int ce : {-660, 0, 660}) {
        // g(t) = 2^ce f(t 2^-te): roots scaled by 2^te.
        const double c[3] = {std::ldexp(g.c[0], ce), std::ldexp(g.c[1], ce - te),
                             std::ldexp(g.c[2], ce - 2 * te)};
        const double t = first_contact(c, 2, std::ldexp(2.0, te));
        if (rel > 0) {
          EXPECT_EQ(t, kInf) << rel << " " << te << " " << ce;
        } else {
          EXPECT_EQ(t, std::ldexp(t1, te)) << rel << " " << te << " " << ce;
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------
// Touching, overlapping and the collision just handled.

TEST(FirstContact, TouchingExactly) {
  // c = 0: approaching is a contact now, receding is none.
  const double approach[5] = {0.0, -0.2, 1.0, 0.01, 0.001};
  const double recede[5] = {0.0, 0.2, 1.0, -0.01, 0.001};
  EXPECT_EQ(first_contact(approach, 4, 1.0), 0.0);
  EXPECT_EQ(first_contact(recede, 4, 1.0), kInf);
  EXPECT_EQ(first_contact(approach, 2, 1.0), 0.0);
  EXPECT_EQ(first_contact(recede, 2, 1.0), kInf);
  EXPECT_EQ(first_contact_quadratic(0.0, -0.1, 1.0), 0.0);
  EXPECT_EQ(first_contact_quadratic(0.0, 0.1, 1.0), kInf);
  EXPECT_EQ(first_contact_quadratic(0.0, 0.0, 1.0), kInf);  // tangent
  // Touching with f'(0) = 0: the first nonzero derivative decides.
  const double closing[3] = {0.0, 0.0, -1.0};
  const double opening[3] = {0.0, 0.0, 1.0};
  const double closing3[4] = {0.0, 0.0, 0.0, -1.0};
  EXPECT_EQ(first_contact(closing, 2, 1.0), 0.0);
  EXPECT_EQ(first_contact(opening, 2, 1.0), kInf);
  EXPECT_EQ(first_contact(closing3, 3, 1.0), 0.0);
  EXPECT_EQ(first_contact(closing, 2, 0.0), 0.0);
  EXPECT_EQ(first_contact(opening, 2, 0.0), kInf);
}

TEST(FirstContact, TinyOverlap) {
  // Overlapping by round-off: receding is not a contact, closing is one now.
  const double recede[5] = {-1e-18, 1e-3, 1.0, 0.0, 0.01};
  const double close[5] = {-1e-18, -1e-3, 1.0, 0.0, 0.01};
  EXPECT_EQ(first_contact(recede, 4, 10.0), kInf);
  EXPECT_EQ(first_contact(close, 4, 10.0), 0.0);
  EXPECT_EQ(first_contact_quadratic(-1e-18, 1e-3, 1.0), kInf);
  EXPECT_EQ(first_contact_quadratic(-1e-18, -1e-3, 1.0), 0.0);
  // Receding from an overlap, then closing again while still overlapping
  // (f = -1 + 2 t - t^2 peaks at f(1) = 0): the contact is at the peak.
  const double peak[3] = {-1.0, 2.0, -1.0};
  EXPECT_EQ(first_contact(peak, 2, 3.0), 1.0);
  const double below[3] = {-1.0, 2.0, -1.5};  // peak f = -1/3 at t = 2/3
  EXPECT_NEAR(first_contact(below, 2, 3.0), 2.0 / 3.0, 2.3e-16);
}

TEST(FirstContact, CollisionJustHandledIsNotFoundAgain) {
  // After a collision the pair touches and recedes; here deceleration
  // brings it back (f = 2t - t^2): the next contact is at t = 2, not 0.
  const double c[3] = {0.0, 2.0, -1.0};
  EXPECT_EQ(first_contact(c, 2, 5.0), 2.0);
  // Same with round-off overlap at t = 0.
  const double c2[3] = {-1e-17, 2.0, -1.0};
  Stats st;
  EXPECT_TRUE(agrees(c2, 2, 5.0, st));
  EXPECT_GT(first_contact(c2, 2, 5.0), 1.9);
}

TEST(FirstContact, RootsInIncreasingPiecesAreSkipped) {
  // f = -(t - 1)(t - 3): overlapping and opening until t = 1 (a root while
  // increasing), apart until t = 3, where the contact is.
  const double c[3] = {-3.0, 4.0, -1.0};
  EXPECT_EQ(first_contact(c, 2, 5.0), 3.0);
  EXPECT_EQ(first_contact(c, 2, 2.5), kInf);
  // Quartic: f = (t - 1)(t - 2)(t - 3)(t - 4) = t^4 - 10t^3 + 35t^2 - 50t + 24
  // crosses down at 1, up at 2, down at 3.
  const double q[5] = {24.0, -50.0, 35.0, -10.0, 1.0};
  EXPECT_EQ(first_contact(q, 4, 5.0), 1.0);
  // From inside the first overlap: opening at 1.5, next contact at 3.
  const double s[5] = {-0.9375, 1.0, 3.5, -4.0, 1.0};  // roots -0.5, 0.5, 1.5, 2.5
  EXPECT_EQ(first_contact(s, 4, 3.5), 1.5);
  EXPECT_EQ(first_contact(s, 4, 1.4), kInf);
}

TEST(FirstContact, RootExactlyAtTmax) {
  const double c[3] = {3.0, -4.0, 1.0};  // (t - 1)(t - 3)
  EXPECT_EQ(first_contact(c, 2, 1.0), 1.0);
  EXPECT_EQ(first_contact(c, 2, std::nextafter(1.0, 0.0)), kInf);
  const double q[5] = {3.0, -4.0, 4.0, -4.0, 1.0};  // (t - 1)(t - 3)(t^2 + 1)
  EXPECT_EQ(first_contact(q, 4, 1.0), 1.0);
  EXPECT_EQ(first_contact(q, 4, std::nextafter(1.0, 0.0)), kInf);
  const double lin[2] = {1.0, -1.0};
  EXPECT_EQ(first_contact(lin, 1, 1.0), 1.0);
  EXPECT_EQ(first_contact(lin, 1, std::nextafter(1.0, 0.0)), kInf);
}

// ---------------------------------------------------------------------------
// Real ball motion.

// f for two balls on a line: d(t) = d0 - v t + a t^2 / 2 (a > 0: the
// closing speed decreases) with a perpendicular offset h.
Quartic line_pair(double d0, double v, double a, double h, double t_max) {
  Quartic q{};
  const double dp[2] = {d0, h}, dv[2] = {-v, 0.0}, da[2] = {a, 0.0};
  q.c[0] = dp[0] * dp[0] + dp[1] * dp[1] - kSigma * kSigma;
  q.c[1] = 2.0 * (dp[0] * dv[0] + dp[1] * dv[1]);
  q.c[2] = dv[0] * dv[0] + dv[1] * dv[1] + (dp[0] * da[0] + dp[1] * da[1]);
  q.c[3] = dv[0] * da[0] + dv[1] * da[1];
  q.c[4] = 0.25 * (da[0] * da[0] + da[1] * da[1]);
  q.t_max = t_max;
  return q;
}

TEST(FirstContact, HeadOnAndGlancingBallMotion) {
  Stats st;
  // Head-on: contact when d0 - v t + a t^2 / 2 = sigma, i.e.
  // t = (v - sqrt(v^2 - 2 a (d0 - sigma))) / a.
  for (const double a : {0.0981, 1.962, 4.0}) {
    const double d0 = 1.0, v = 3.0;
    const Quartic q = line_pair(d0, v, a, 0.0, v / a);
    const double expect = (v - std::sqrt(v * v - 2.0 * a * (d0 - kSigma))) / a;
    EXPECT_NEAR(first_contact(q.c, 4, q.t_max), expect, 1e-14) << a;
    EXPECT_TRUE(agrees(q.c, 4, q.t_max, st)) << a;
  }
  // Stopping just short (the ball stops at d0 - v^2 / 2a = sigma + 1e-6).
  {
    const double v = 1.0, a = 1.962;
    const double d0 = kSigma + 1e-6 + v * v / (2.0 * a);
    const Quartic q = line_pair(d0, v, a, 0.0, v / a);
    EXPECT_EQ(first_contact(q.c, 4, q.t_max), kInf);
    EXPECT_TRUE(agrees(q.c, 4, q.t_max, st));
  }
  // Glancing: offsets just inside and just outside sigma.
  for (const double h : {0.5 * kSigma, 0.999 * kSigma, 0.999999 * kSigma, 1.000001 * kSigma,
                         1.001 * kSigma}) {
    const Quartic q = line_pair(0.8, 2.0, 0.0981, h, 2.0 / 0.0981);
    const double t = first_contact(q.c, 4, q.t_max);
    EXPECT_EQ(t < kInf, h < kSigma) << h;
    EXPECT_TRUE(agrees(q.c, 4, q.t_max, st)) << h;
  }
  st.print("line pairs");
}

// ---------------------------------------------------------------------------
// Scales.

TEST(FirstContact, CoefficientScaleInvariance) {
  Rng rng(0x5eed0005);
  Stats st;
  for (int i = 0; i < 500; ++i) {
    const Quartic q = ball_pair(rng, true);
    const double t = first_contact(q.c, 4, q.t_max);
    for (const double s : {1e-200, 1e+200}) {
      double c[5];
      for (int k = 0; k < 5; ++k) c[k] = q.c[k] * s;
      ASSERT_TRUE(agrees(c, 4, q.t_max, st)) << "case " << i << " scale " << s;
      const double ts = first_contact(c, 4, q.t_max);
      // Scaling rounds the coefficients, which moves the root by up to its
      // sensitivity to relative perturbations of u.
      if (t == kInf) continue;
      EXPECT_NEAR(ts, t, 4.0 * sensitivity(q.c, 4, t) + 2.0 * ulp_at(t))
          << "case " << i << " scale " << s;
    }
    // Powers of two are exact: bit-identical results.
    double c[5];
    for (int k = 0; k < 5; ++k) c[k] = std::ldexp(q.c[k], -900);
    EXPECT_EQ(first_contact(c, 4, q.t_max), t) << "case " << i;
    for (int k = 0; k < 5; ++k) c[k] = std::ldexp(q.c[k], 900);
    EXPECT_EQ(first_contact(c, 4, q.t_max), t) << "case " << i;
  }
  st.print("scaled coefficients");
}

TEST(FirstContact, TimeScaleInvariance) {
  Rng rng(0x5eed0006);
  Stats st;
  for (int i = 0; i < 500; ++i) {
    double c[5];
    const int degree = product_poly(rng, c);
    const double t_max = rng.uniform(0.0, 3.5);
    const double t = first_contact(c, degree, t_max);
    for (const double s : {1e9, 1e-6}) {  // time scales 1e-9 s and 1e6 s
      double cs[5];
      scale_time(c, degree, s, cs);
      ASSERT_TRUE(agrees(cs, degree, t_max / s, st)) << "case " << i << " scale " << s;
      const double ts = first_contact(cs, degree, t_max / s);
      if (t == kInf || ts == kInf) continue;  // the window may clip differently
      EXPECT_NEAR(ts * s, t, 4.0 * sensitivity(c, degree, t) + 4.0 * ulp_at(t))
          << "case " << i << " scale " << s;
    }
  }
  st.print("scaled time");
}

// ---------------------------------------------------------------------------
// Degenerate input.

TEST(FirstContact, LeadingZerosAndLowDegrees) {
  const double lin[5] = {1.0, -2.0, 0.0, 0.0, 0.0};  // degree 4 in name only
  EXPECT_EQ(first_contact(lin, 4, 1.0), 0.5);
  EXPECT_EQ(first_contact(lin, 1, 1.0), 0.5);
  const double quad[5] = {0.75, -2.0, 1.0, 0.0, 0.0};  // (t - 0.5)(t - 1.5)
  EXPECT_EQ(first_contact(quad, 4, 1.0), 0.5);
  const double cubic[4] = {-6.0, 11.0, -6.0, 1.0};  // (t - 1)(t - 2)(t - 3)
  EXPECT_EQ(first_contact(cubic, 3, 5.0), 2.0);
  const double constant[3] = {-1.0, 0.0, 0.0};  // overlapping but not closing
  EXPECT_EQ(first_contact(constant, 2, 1.0), kInf);
  EXPECT_EQ(first_contact(constant, 0, 1.0), kInf);
  const double zero[5] = {0, 0, 0, 0, 0};
  EXPECT_EQ(first_contact(zero, 4, 1.0), kInf);
  // Tiny but nonzero leading coefficient: effectively lower degree.
  // f(0.5) = 1e-300 / 16 > 0, so the contact is the next double.
  const double tiny[5] = {1.0, -2.0, 0.0, 0.0, 1e-300};
  EXPECT_EQ(first_contact(tiny, 4, 1.0), std::nextafter(0.5, 1.0));
}

TEST(FirstContact, HorizonEdgeCases) {
  const double c[3] = {3.0, -4.0, 1.0};  // roots 1 and 3
  EXPECT_EQ(first_contact(c, 2, 0.0), kInf);
  EXPECT_EQ(first_contact(c, 2, -1.0), kInf);
  EXPECT_EQ(first_contact(c, 2, kInf), 1.0);
  EXPECT_EQ(first_contact(c, 2, std::numeric_limits<double>::quiet_NaN()), kInf);
  // An infinite horizon still finds far contacts (and no false ones).
  const double far[3] = {1e12, -2e6, 0.5};  // roots near 5e5 and 4e6
  Stats st;
  EXPECT_TRUE(agrees(far, 2, 1e7, st));
  EXPECT_EQ(first_contact(far, 2, kInf), first_contact(far, 2, 1e7));
  const double never[3] = {1.0, -1.0, 1.0};
  EXPECT_EQ(first_contact(never, 2, kInf), kInf);
  // Huge finite windows are cut to the root bound, without overflow.
  EXPECT_EQ(first_contact(c, 2, 1e300), 1.0);
  const double q[5] = {3.0, -4.0, 4.0, -4.0, 1.0};  // (t - 1)(t - 3)(t^2 + 1)
  EXPECT_EQ(first_contact(q, 4, 1e300), 1.0);
  EXPECT_EQ(first_contact(q, 4, kInf), 1.0);
  const double down[3] = {0.0, 0.0, -1.0};  // touching and closing: root bound 0
  EXPECT_EQ(first_contact(down, 2, kInf), 0.0);
  EXPECT_EQ(first_contact(down, 2, 1e300), 0.0);
  const double falling[2] = {1e-3, -1e-300};  // root near 1e297
  EXPECT_TRUE(agrees(falling, 1, 1e298, st));
  EXPECT_EQ(first_contact(falling, 1, kInf), first_contact(falling, 1, 1e298));
}

TEST(FirstContact, NonFiniteInputIsNoContact) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 5; ++k) {
    for (const double bad : {nan, kInf, -kInf}) {
      double c[5] = {1.0, -2.0, 1.0, 0.1, 0.01};
      c[k] = bad;
      EXPECT_EQ(first_contact(c, 4, 1.0), kInf) << k << " " << bad;
    }
  }
  EXPECT_EQ(first_contact(nullptr, 2, 1.0), kInf);
  const double c[5] = {1.0, -2.0, 1.0, 0.1, 0.01};
  EXPECT_EQ(first_contact(c, 5, 1.0), kInf);
  EXPECT_EQ(first_contact(c, -1, 1.0), kInf);
  EXPECT_EQ(first_contact_quadratic(nan, -1.0, 1.0), kInf);
  EXPECT_EQ(first_contact_quadratic(1.0, nan, 1.0), kInf);
  EXPECT_EQ(first_contact_quadratic(1.0, -1.0, nan), kInf);
  EXPECT_EQ(first_contact_quadratic(1.0, -kInf, 1.0), kInf);
}

// Coefficients over 100 orders of magnitude either way and windows over
// 40: still exact to the ulp.
TEST(FirstContact, BroadScalesMatchReference) {
  Rng rng(0x5eed0007);
  Stats st;
  for (int i = 0; i < 3000; ++i) {
    const int degree = 1 + rng.below(4);
    double c[5] = {0, 0, 0, 0, 0};
    for (int k = 0; k <= degree; ++k) {
      c[k] = rng.uniform() < 0.1 ? 0.0 : rng.sign() * rng.pow10(-100.0, 100.0);
    }
    const double t_max = rng.pow10(-20.0, 20.0);
    ASSERT_TRUE(agrees(c, degree, t_max, st)) << "case " << i;
  }
  st.print("broad scales");
}

// Wild input: coefficients and windows over 600 orders of magnitude, so
// that f over the window need not be representable at all. Whatever the
// answer, it must come back (no endless loop), inside [0, t_max] or +inf.
TEST(FirstContact, WildInputTerminatesWithValidAnswers) {
  Rng rng(0x5eed000b);
  int contacts = 0;
  for (int i = 0; i < 20000; ++i) {
    const int degree = rng.below(5);
    double c[5] = {0, 0, 0, 0, 0};
    for (int k = 0; k <= degree; ++k) {
      c[k] = rng.uniform() < 0.1 ? 0.0 : rng.sign() * rng.pow10(-300.0, 300.0);
    }
    const double t_max = rng.uniform() < 0.1 ? kInf : rng.pow10(-300.0, 300.0);
    const double t = first_contact(c, degree, t_max);
    ASSERT_TRUE(t == kInf || (t >= 0.0 && t <= t_max)) << dump(c, degree, t_max) << " -> " << t;
    contacts += t < kInf;
  }
  EXPECT_GT(contacts, 1000);
}

// ---------------------------------------------------------------------------
// first_contact_quadratic.

TEST(FirstContactQuadratic, MatchesReferenceAndGeneralSolver) {
  Rng rng(0x5eed0008);
  double worst = 0.0;
  int contacts = 0;
  for (int i = 0; i < 5000; ++i) {
    // Ideal model: constant velocities; aim at a random miss distance.
    const double speed = rng.pow10(-2.0, 1.0), angle = rng.uniform(0.0, 6.283185307179586);
    const double dv[2] = {speed * std::cos(angle), speed * std::sin(angle)};
    const double tau = rng.pow10(-3.0, 1.0), miss = rng.uniform(-1.5, 1.5) * kSigma;
    const double dp[2] = {-dv[0] * tau - miss * std::sin(angle),
                          -dv[1] * tau + miss * std::cos(angle)};
    const double c = dp[0] * dp[0] + dp[1] * dp[1] - kSigma * kSigma;
    const double b = dp[0] * dv[0] + dp[1] * dv[1];
    const double a = dv[0] * dv[0] + dv[1] * dv[1];
    const double t = first_contact_quadratic(c, b, a);
    // Reference: the smaller root of c + 2 b t + a t^2 in __float128.
    const Q qc = c, qb = b, qa = a;
    const Q disc = qb * qb - qa * qc;
    if (b >= 0.0 || disc < 0) {
      EXPECT_EQ(t, kInf) << i;
    } else if (c <= 0.0) {
      EXPECT_EQ(t, 0.0) << i;
    } else {
      ++contacts;
      const Q r = qc / (sqrt_q(disc) - qb);
      const double rd = static_cast<double>(r);
      const double ulps = static_cast<double>(abs_q(static_cast<Q>(t) - r)) / ulp_at(rd);
      worst = std::max(worst, ulps);
      EXPECT_LE(ulps, 2.0) << i << " t = " << t << " ref = " << rd;
    }
    // The general solver on the same polynomial agrees to an ulp or so.
    const double cc[3] = {c, 2.0 * b, a};
    const double tg = first_contact(cc, 2, kInf);
    if (t == kInf || tg == kInf) {
      EXPECT_EQ(t, tg) << i;
    } else {
      EXPECT_LE(std::fabs(t - tg), 2.0 * ulp_at(t)) << i;
    }
  }
  std::printf("  [first_contact_quadratic] %d contacts, max error %.2f ulp\n", contacts, worst);
  EXPECT_GT(contacts, 1500);
}

TEST(FirstContactQuadratic, GrazingDecidedExactly) {
  // Miss distance just below / above sigma on a long approach: b^2 and ac
  // agree to 1e-10 and the decision rests on the exact discriminant.
  for (const double m : {0.999999, 1.000001}) {
    const double dp[2] = {-10.0, m * kSigma}, dv[2] = {1.0, 0.0};
    const double c = dp[0] * dp[0] + dp[1] * dp[1] - kSigma * kSigma;
    const double b = dp[0] * dv[0] + dp[1] * dv[1];
    const double a = 1.0;
    const Q disc = static_cast<Q>(b) * b - static_cast<Q>(a) * c;
    EXPECT_EQ(first_contact_quadratic(c, b, a) < kInf, disc >= 0) << m;
  }
}

// ---------------------------------------------------------------------------
// solve_quadratic.

// Roots of the double coefficients in __float128 (exact up to ~1e-33).
int ref_quadratic(double a, double b, double c, Q roots[2]) {
  const Q qa = a, qb = b, qc = c;
  const Q disc = qb * qb - 4 * qa * qc;  // exact: 106-bit products
  if (disc < 0) return 0;
  const Q s = sqrt_q(disc);
  const Q q = qb >= 0 ? -(qb + s) / 2 : -(qb - s) / 2;
  roots[0] = q / qa;
  roots[1] = qc / q;
  if (roots[1] < roots[0]) std::swap(roots[0], roots[1]);
  return disc == 0 ? 1 : 2;
}

::testing::AssertionResult quadratic_agrees(double a, double b, double c, double max_ulps) {
  double r[2];
  Q ref[2];
  const int n = solve_quadratic(a, b, c, r);
  const int nr = ref_quadratic(a, b, c, ref);
  if (n != nr) {
    return ::testing::AssertionFailure()
           << n << " roots instead of " << nr << " for " << a << ", " << b << ", " << c;
  }
  for (int i = 0; i < n; ++i) {
    const double rd = static_cast<double>(ref[i]);
    const double ulps = static_cast<double>(abs_q(static_cast<Q>(r[i]) - ref[i])) / ulp_at(rd);
    if (!(ulps <= max_ulps)) {
      return ::testing::AssertionFailure() << "root " << i << " = " << r[i] << ", expected " << rd
                                           << " (" << ulps << " ulp) for " << a << ", " << b
                                           << ", " << c;
    }
  }
  return ::testing::AssertionSuccess();
}

TEST(SolveQuadratic, CancellationProneInputs) {
  // b^2 >> 4ac: the textbook formula loses the small root entirely.
  EXPECT_TRUE(quadratic_agrees(1.0, -1e8, 1.0, 1.0));
  EXPECT_TRUE(quadratic_agrees(1.0, 1e8, 1.0, 1.0));
  EXPECT_TRUE(quadratic_agrees(1e-10, -1.0, 1e-10, 1.0));
  EXPECT_TRUE(quadratic_agrees(3.0, 1e150, -7.0, 1.0));
  EXPECT_TRUE(quadratic_agrees(1e-300, 1.0, 1e-300, 1.0));  // roots 1e-300 and 1e300
  double r[2];
  ASSERT_EQ(solve_quadratic(1.0, -1e8, 1.0, r), 2);
  EXPECT_DOUBLE_EQ(r[0], 1e-8);
  EXPECT_DOUBLE_EQ(r[1], 1e8);
  Rng rng(0x5eed0009);
  for (int i = 0; i < 5000; ++i) {
    const double a = rng.sign() * rng.pow10(-5.0, 5.0), c = rng.sign() * rng.pow10(-5.0, 5.0);
    const double b = rng.sign() * rng.pow10(0.0, 100.0) * std::sqrt(std::fabs(a * c));
    ASSERT_TRUE(quadratic_agrees(a, b, c, 2.0)) << i;
  }
}

TEST(SolveQuadratic, NearDoubleRoots) {
  // (x - r)^2 - e for tiny e: the discriminant cancels; Kahan's exact
  // discriminant keeps the roots as accurate as their conditioning allows.
  Rng rng(0x5eed000a);
  for (int i = 0; i < 5000; ++i) {
    const double r = rng.sign() * rng.pow10(-3.0, 3.0);
    const double e = rng.sign() * rng.pow10(-15.0, -3.0) * r * r;
    const double a = rng.pow10(-2.0, 2.0);
    const double b = -2.0 * r * a, c = (r * r - e) * a;
    // With the textbook discriminant the error would be sqrt(u) ~ 1e-8
    // relative; with the exact one it is a few ulps.
    double out[2];
    Q ref[2];
    const int n = solve_quadratic(a, b, c, out);
    const int nr = ref_quadratic(a, b, c, ref);
    ASSERT_EQ(n, nr) << i;
    for (int k = 0; k < n; ++k) {
      const double rd = static_cast<double>(ref[k]);
      EXPECT_LE(static_cast<double>(abs_q(static_cast<Q>(out[k]) - ref[k])), 4.0 * ulp_at(rd))
          << i;
    }
  }
}

TEST(SolveQuadratic, DegenerateCases) {
  double r[2] = {0.0, 0.0};
  ASSERT_EQ(solve_quadratic(0.0, 2.0, -1.0, r), 1);  // linear
  EXPECT_EQ(r[0], 0.5);
  EXPECT_EQ(solve_quadratic(0.0, 0.0, 1.0, r), 0);  // constant
  ASSERT_EQ(solve_quadratic(1.0, -2.0, 1.0, r), 1);  // double root
  EXPECT_EQ(r[0], 1.0);
  EXPECT_EQ(solve_quadratic(1.0, 0.0, 1.0, r), 0);  // complex
  ASSERT_EQ(solve_quadratic(2.0, 0.0, -8.0, r), 2);  // b = 0
  EXPECT_EQ(r[0], -2.0);
  EXPECT_EQ(r[1], 2.0);
  ASSERT_EQ(solve_quadratic(1.0, -3.0, 0.0, r), 2);  // c = 0: a root at +0
  EXPECT_EQ(r[0], 0.0);
  EXPECT_FALSE(std::signbit(r[0]));
  EXPECT_EQ(r[1], 3.0);
  ASSERT_EQ(solve_quadratic(-1.0, 0.0, 4.0, r), 2);  // a < 0: still ascending
  EXPECT_EQ(r[0], -2.0);
  EXPECT_EQ(r[1], 2.0);
  ASSERT_EQ(solve_quadratic(1e300, -3e300, 2e300, r), 2);  // would overflow b^2
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  EXPECT_DOUBLE_EQ(r[1], 2.0);
  EXPECT_EQ(solve_quadratic(std::numeric_limits<double>::quiet_NaN(), 1.0, 1.0, r), 0);
}

}  // namespace
