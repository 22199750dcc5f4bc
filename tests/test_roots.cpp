// Tests of the root finders against references computed in __float128.
//
// The reference takes the double coefficients exactly (every double is a
// __float128) and finds every root by plain bisection in 113-bit
// arithmetic, with the same rules as first_contact (monotone pieces from
// the critical points, decreasing pieces only). Its roots are exact to
// ~1e-33 relative, so the difference from first_contact is the latter's
// own error, which we measure in ulps. At the end, first_contact is also
// compared bit for bit with a frozen copy of its full method (see there).
#include "physics/roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace test_roots {

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

// ---------------------------------------------------------------------------
// The fast paths of first_contact against the full method, bit for bit.
//
// first_contact settles most calls with cheap proofs (no contact, or the
// contact at a given double) and leaves the rest to its full method. Its
// results must not change by a single bit (the simulation's determinism
// hashes depend on them), so the test below compares it with a frozen
// copy of first_contact as it was before the fast paths, on a few hundred
// thousand realistic and adversarial inputs. The copy is test code: keep
// it as it is (it is the reference, not the implementation).

namespace frozen {

int solve_quadratic(double a, double b, double c, double roots[2]);

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kUnit = 0x1p-53;  // unit roundoff of double
// Bound factor for the rounding error of Horner's rule (value and first
// derivative) at degree <= 4: gamma_8 ~ 8u, with a safety factor of 4.
constexpr double kGamma = 32.0 * kUnit;
// The solver needs at most 64 halvings of the bit pattern (every other
// fallback step) plus a few Newton steps; this cap only guards against
// pathological input.
constexpr int kMaxIter = 200;

// --- Error-free transformations (Knuth, Dekker). They need strict IEEE
// --- evaluation, which the build guarantees with -ffp-contract=off.

struct Pair {
  double hi, lo;  // the exact result is hi + lo
};

inline Pair two_sum(double a, double b) {
  const double s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  return {s, (a - av) + (b - bv)};
}

// Veltkamp's split: a = hi + lo with both halves of 26 bits.
inline Pair split(double a) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double hi = c - (c - a);
  return {hi, a - hi};
}

// Dekker's product. We use it rather than std::fma because without
// -mfma the latter is a library call, and this is just as exact.
inline Pair two_prod(double a, double b) {
  const double p = a * b;
  const Pair x = split(a);
  const Pair y = split(b);
  return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}

// --- Stepping through doubles. Times are never negative here, and for
// --- non-negative doubles the bit pattern is monotone in the value.

inline std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }
inline double from_bits(std::uint64_t b) { return std::bit_cast<double>(b); }
inline double next_up(double x) { return from_bits(bits(x) + 1); }      // x >= +0
inline double next_down(double x) { return from_bits(bits(x) - 1); }    // x > 0
inline double ulp_of(double x) { return next_up(x) - x; }                // x >= +0
// Midpoint of the bit patterns: roughly the geometric mean when lo and
// hi are orders of magnitude apart, the arithmetic one when they are
// close, so any bracket shrinks to adjacent doubles in <= 64 halvings.
inline double bit_mid(double lo, double hi) {
  const std::uint64_t a = bits(lo);
  return from_bits(a + (bits(hi) - a) / 2);
}

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// --- The polynomial and its derivative.

template <int N>
struct Poly {
  double p[N + 1];  // f
  double d[N];      // f' = sum (d[k] + dl[k]) t^k, exactly: 3 c3 needs
  double dl[N];     // a low part, the other multiples are exact.

  explicit Poly(const double* c) {
    for (int k = 0; k <= N; ++k) p[k] = c[k];
    for (int k = 0; k < N; ++k) {
      d[k] = static_cast<double>(k + 1) * p[k + 1];
      dl[k] = 0.0;
    }
    if constexpr (N >= 3) {
      const Pair m = two_sum(2.0 * p[3], p[3]);  // 3 c3, exactly
      d[2] = m.hi;
      dl[2] = m.lo;
    }
  }
};

// Plain Horner at x: f and its first three derivatives, with bounds on the
// rounding errors of f and f' (Higham, Accuracy and Stability, ch. 5).
struct Sample {
  double x;
  double f, f1, f2, f3;
  double ef, ef1;
};

template <int N>
inline Sample sample(const Poly<N>& P, double x) {
  double r0 = P.p[N], r1 = 0.0, r2 = 0.0, r3 = 0.0;
  const double ax = std::fabs(x);
  double b0 = std::fabs(P.p[N]), b1 = 0.0;
#pragma GCC unroll 4
  for (int k = N - 1; k >= 0; --k) {
    r3 = r3 * x + r2;
    r2 = r2 * x + r1;
    r1 = r1 * x + r0;
    r0 = r0 * x + P.p[k];
    b1 = b1 * ax + b0;
    b0 = b0 * ax + std::fabs(P.p[k]);
  }
  return {x, r0, r1, 2.0 * r2, 6.0 * r3, kGamma * b0, kGamma * b1};
}

// Compensated Horner (Graillat, Langlois, Louvet 2005): the rounding error
// of every step is captured exactly and summed in a second Horner
// recurrence, together with the low parts of the coefficients if any.
template <int N, bool WithLow>
double compensated(const double* c, const double* cl, double x) {
  double s = c[N];
  double e = WithLow ? cl[N] : 0.0;
#pragma GCC unroll 4
  for (int k = N - 1; k >= 0; --k) {
    const Pair pr = two_prod(s, x);
    const Pair sm = two_sum(pr.hi, c[k]);
    s = sm.hi;
    e = e * x + ((pr.lo + sm.lo) + (WithLow ? cl[k] : 0.0));
  }
  return s + e;
}

// f(x) with a reliable sign and, near a root, full accuracy: Horner's
// value when it is well clear of its error bound (relative error below
// 2^-20), the compensated value otherwise. The accuracy near the root is
// what makes the solver's last step land on the right ulp.
constexpr double kClear = 0x1p20;

template <int N>
double exact_f(const Poly<N>& P, const Sample& s) {
  if (std::fabs(s.f) > kClear * s.ef) return s.f;
  const double v = compensated<N, false>(P.p, nullptr, s.x);
  return std::isfinite(v) ? v : s.f;
}

// f'(x) likewise; the compensated pass uses the exact coefficients of f'.
template <int N>
double exact_f1(const Poly<N>& P, const Sample& s) {
  if (std::fabs(s.f1) > kClear * s.ef1) return s.f1;
  const double v = compensated<N - 1, true>(P.d, P.dl, s.x);
  return std::isfinite(v) ? v : s.f1;
}

// --- The bracketed solver. Level 0 solves f = 0 (contacts), level 1
// --- solves f' = 0 (critical points of f).

struct Probe {
  Sample s;
  double g;  // reliable value of the level's function at s.x
};

template <int N, int L>
double level_g(const Poly<N>& P, const Sample& s) {
  if constexpr (L == 0) {
    return exact_f(P, s);
  } else {
    return exact_f1(P, s);
  }
}
template <int L>
double level_g1(const Sample& s) {
  return L == 0 ? s.f1 : s.f2;
}
template <int L>
double level_g2(const Sample& s) {
  return L == 0 ? s.f2 : s.f3;
}

// At a probe x where f was evaluated with compensated Horner (nearly
// exactly), is f on the other side of zero at the adjacent double x + h
// towards the root? First-order Taylor with rigorous bounds on every
// error: of the compensated value (Graillat et al.: u |f| + gamma_2n^2
// sum |c_k| |x|^k, with gamma_8^2 < 65 u^2), of Horner's f' (ef1), and
// of the second-order term. Saves the last probe of most solves.
inline bool neighbour_crosses(const Probe& pr, bool is_lo) {
  const Sample& s = pr.s;
  if (!(std::fabs(s.f) <= kClear * s.ef)) return false;  // not compensated
  const double h = (is_lo ? next_up(s.x) : next_down(s.x)) - s.x;
  const double predicted = pr.g + s.f1 * h;
  const double terms = s.ef / kGamma;  // sum |c_k| |x|^k
  const double err = 2.0 * kUnit * std::fabs(pr.g) + 128.0 * kUnit * kUnit * terms +
                     s.ef1 * std::fabs(h) + (std::fabs(s.f2) + std::fabs(s.f3)) * h * h;
  return std::fabs(predicted) > err && (predicted > 0.0) != (pr.g > 0.0);
}

// Halley's correction at a probe: x - step is the next estimate. Where the
// curvature term is large (far from the root) it falls back to Newton's.
template <int L>
double halley_step(const Probe& p) {
  const double g1 = level_g1<L>(p.s);
  const double newton = p.g / g1;
  const double h = 0.5 * newton * level_g2<L>(p.s) / g1;
  return std::fabs(h) < 0.5 ? newton / (1.0 - h) : newton;
}

// Step u > 0 from a bracket end along dir (+1 or -1) to the nearest root
// of the second-order Taylor model g + dir g1 u + g2 u^2 / 2 there. For a
// quadratic g the model is exact, and near a critical point of g (where
// a first-order step is useless) it is the right model. NaN if none.
// Only a starting point, so the plain stable formula will do.
template <int L>
double taylor_guess(const Probe& e, double dir) {
  const double a = 0.5 * level_g2<L>(e.s), b = dir * level_g1<L>(e.s), c = e.g;
  double u;
  if (a == 0.0) {
    u = -c / b;
  } else {
    const double disc = b * b - 4.0 * a * c;
    if (!(disc >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = q / a, r2 = c / q;
    u = r1 > 0.0 && (r1 < r2 || !(r2 > 0.0)) ? r1 : r2;
  }
  return u > 0.0 ? e.s.x + dir * u : std::numeric_limits<double>::quiet_NaN();
}

struct Refined {
  Probe lo, hi;  // adjacent doubles unless stopped (or the cap was hit)
  bool stopped;  // the caller's stop test accepted `at`
  Probe at;
};

// Halving, alternately of the value and of the bit pattern. The latter
// guarantees progress however far apart lo and hi are in magnitude (the
// bracket shrinks to adjacent doubles in <= 64 of them) and the former is
// faster when the root is not much closer to lo than to hi, as usual.
inline double halve(double lo, double hi, bool& by_bits) {
  double x = by_bits ? bit_mid(lo, hi) : lo + 0.5 * (hi - lo);
  by_bits = !by_bits;
  if (!(x > lo && x < hi)) x = bit_mid(lo, hi);
  return x;
}

struct NeverStop {
  bool operator()(const Sample&) const { return false; }
};

// Root of g (level L) in [lo, hi] where g(lo) and g(hi) are on opposite
// sides: g > 0 on one end, g <= 0 on the other. Probes keep that
// invariant, so the bracket always holds the crossing.
template <int N, int L, class Stop>
Refined refine(const Poly<N>& P, Probe lo, Probe hi, Stop stop) {
  const bool pos_lo = lo.g > 0.0;
  if (!(next_up(lo.s.x) < hi.s.x)) return {lo, hi, false, lo};

  // Start from the Taylor model at the end where g is smaller (the root
  // is most likely near it), else at the other end, else from the secant.
  const bool from_lo = std::fabs(lo.g) <= std::fabs(hi.g);
  double x = taylor_guess<L>(from_lo ? lo : hi, from_lo ? 1.0 : -1.0);
  if (!(x > lo.s.x && x < hi.s.x)) x = taylor_guess<L>(from_lo ? hi : lo, from_lo ? -1.0 : 1.0);
  if (!(x > lo.s.x && x < hi.s.x)) x = lo.s.x + (hi.s.x - lo.s.x) * (lo.g / (lo.g - hi.g));
  bool by_bits = false;
  if (!(x > lo.s.x && x < hi.s.x)) x = halve(lo.s.x, hi.s.x, by_bits);

  double step_old = kInf;
  double nudge = 0.0;
  for (int it = 0; it < kMaxIter; ++it) {
    Probe pr{sample<N>(P, x), 0.0};
    if (stop(pr.s)) return {lo, hi, true, pr};  // before the costlier exact g
    pr.g = level_g<N, L>(P, pr.s);
    const bool is_lo = (pr.g > 0.0) == pos_lo;
    if (is_lo) {
      lo = pr;
    } else {
      hi = pr;
    }
    if (!(next_up(lo.s.x) < hi.s.x)) break;
    if constexpr (L == 0) {
      if (neighbour_crosses(pr, is_lo)) {
        // The adjacent double towards the root is on the other side: the
        // bracket is closed without evaluating there.
        if (is_lo) {
          hi.s.x = next_up(x);
        } else {
          lo.s.x = next_down(x);
        }
        break;
      }
    }

    // Halley's step (third order: we have g'' for free) from the end where
    // it is shorter (near a flat end g may be small but its step is long)
    // is taken if it stays inside the bracket and is at most a quarter of
    // the previous step, or a few ulps: that holds once convergence sets
    // in; otherwise (far from the root, or creeping towards it linearly as
    // from far out on a cubic) halving is faster.
    const double d_lo = halley_step<L>(lo);
    const double d_hi = halley_step<L>(hi);
    const bool at_lo = std::fabs(d_lo) <= std::fabs(d_hi) || std::isnan(d_hi);
    const double bx = at_lo ? lo.s.x : hi.s.x;
    const double xn = bx - (at_lo ? d_lo : d_hi);
    const double step = std::fabs(xn - bx);
    const bool close = step <= 16.0 * ulp_of(bx);
    double next;
    if (xn > lo.s.x && xn < hi.s.x && (step <= 0.25 * step_old || close)) {
      next = xn;
      nudge = 0.0;
    } else if (close) {
      // Converged onto this end of the bracket, but the root is on the
      // other side of it: creep inwards by 1, 2, 4... ulps.
      nudge = nudge == 0.0 ? ulp_of(bx) : 2.0 * nudge;
      next = at_lo ? bx + nudge : bx - nudge;
      if (!(next > lo.s.x && next < hi.s.x)) next = halve(lo.s.x, hi.s.x, by_bits);
    } else {
      next = halve(lo.s.x, hi.s.x, by_bits);
      nudge = 0.0;
    }
    step_old = std::fabs(next - bx);
    x = next;
  }
  return {lo, hi, false, lo};
}

// The contact root in a piece where f(lo) > 0 >= f(hi): the first double
// at which f (evaluated exactly) is <= 0, so at or just after the root.
template <int N>
double contact_root(const Poly<N>& P, const Probe& lo, const Probe& hi) {
  return refine<N, 0>(P, lo, hi, NeverStop{}).hi.s.x;
}

// The critical point of f in [a, b], where f' changes sign (a and b carry
// f' as g). Returns the point with f there as g.
//
// It is enough to locate the critical point as precisely as the caller's
// decision needs, so the solver stops early when:
// - at a minimum, f < 0 at a probe: the minimum is below zero, and the
//   probe is as good an end for the contact bracket as the minimum (f only
//   rises from the minimum to the probe, staying <= 0);
// - at a minimum, f > 0 at a probe and the quadratic model around the
//   probe proves, with a margin of 8, that f stays > 0 down to the minimum;
// - at a maximum, f > 0 at a probe: the maximum is higher still.
// Otherwise (a grazing minimum, or a maximum at or below zero, where the
// maximum itself is the answer) it runs to the last bit, and we keep the
// lower (at a minimum) or higher (at a maximum) of the two adjacent doubles.
template <int N>
Probe critical_point(const Poly<N>& P, const Probe& a, const Probe& b) {
  if constexpr (N == 2) {
    // The vertex of the parabola, correctly rounded: the double nearest
    // to the exact minimum or maximum is also where f is lowest or highest.
    const Sample s = sample<N>(P, std::clamp(-P.p[1] / (2.0 * P.p[2]), a.s.x, b.s.x));
    return {s, exact_f(P, s)};
  }
  const bool is_min = a.g < 0.0;
  const auto stop = [is_min](const Sample& s) {
    if (!is_min) return s.f > s.ef;
    if (s.f < -s.ef) return true;
    if (s.f > s.ef && s.f2 > 0.0) {
      const double dist = std::fabs(s.f1) / s.f2;  // Newton's estimate of |x - x_min|
      return dist * std::fabs(s.f3) <= 0.5 * s.f2 && s.f - s.ef > 4.0 * std::fabs(s.f1) * dist;
    }
    return false;
  };
  const Refined r = refine<N, 1>(P, a, b, stop);
  if (r.stopped) return {r.at.s, r.at.s.f};  // its sign is certain, which is all we need
  const Probe lo{r.lo.s, exact_f(P, r.lo.s)};
  const Probe hi{r.hi.s, exact_f(P, r.hi.s)};
  if (is_min) return hi.g < lo.g ? hi : lo;
  return hi.g >= lo.g ? hi : lo;
}

// first_contact for a polynomial of exact degree N (c[N] != 0).
template <int N>
double first_contact_n(const double* c, double t_max) {
  const Poly<N> P(c);
  // At t = 0 the values are the coefficients themselves, exactly (c is
  // padded with zeros to 5 entries).
  const Sample s0{0.0, c[0], c[1], 2.0 * c[2], 6.0 * c[3], 0.0, 0.0};

  // Roots of f'' inside (0, t_max): f' is monotone between them.
  double brk[2];
  int nb = 0;
  if constexpr (N == 3) {
    const double r = -P.p[2] / (3.0 * P.p[3]);
    if (r > 0.0 && r < t_max) brk[nb++] = r;
  } else if constexpr (N == 4) {
    double r[2];
    const int k = solve_quadratic(6.0 * P.p[4], 3.0 * P.p[3], P.p[2], r);
    for (int i = 0; i < k; ++i) {
      if (r[i] > 0.0 && r[i] < t_max) brk[nb++] = r[i];
    }
  }

  // Walk the monotone pieces of f, found lazily from left to right.
  // `start` begins the current piece of f (g = f there), `dir` is the sign
  // of f' inside it (0 while unknown: f' may vanish at t = 0).
  Probe start{s0, P.p[0]};
  int dir = 0;
  Probe a{s0, P.p[1]};  // left end of the current piece of f' (g = f')
  int sa = sign_of(a.g);
  for (int i = 0; i <= nb; ++i) {
    const Sample sb = sample<N>(P, i < nb ? brk[i] : t_max);
    const Probe b{sb, exact_f1(P, sb)};
    const int sgb = sign_of(b.g);
    if (sa != 0 && sgb != 0 && sa != sgb) {
      // f' changes sign inside (a, b): a critical point ends this piece.
      dir = sa;
      if (dir < 0 && start.g <= 0.0) return start.s.x;  // overlap closing
      const Probe crit = critical_point<N>(P, a, b);
      if (dir < 0 && crit.g <= 0.0) return contact_root<N>(P, start, crit);
      start = crit;
      dir = sgb;
    } else if (const int inside = sa != 0 ? sa : sgb; inside != 0) {
      if (dir != 0 && inside != dir) {
        // f' vanishes exactly at the breakpoint a and changes sign there.
        const Probe at{a.s, exact_f(P, a.s)};
        if (dir < 0) {
          if (start.g <= 0.0) return start.s.x;
          if (at.g <= 0.0) return contact_root<N>(P, start, at);
        }
        start = at;
      }
      dir = inside;
    }
    a = b;
    sa = sgb;
  }
  // The last piece ends at t_max.
  if (dir < 0) {
    if (start.g <= 0.0) return start.s.x;
    const Probe end{a.s, exact_f(P, a.s)};
    if (end.g <= 0.0) return contact_root<N>(P, start, end);
  }
  return kInf;
}

// Fujiwara's bound on the moduli of the roots of f (and so of f', f'' by
// Gauss-Lucas), enlarged a little against rounding: no piece boundary or
// contact lies beyond it, so it can replace a longer or infinite window.
double root_bound(const double* p, int n) {
  const double lead = std::fabs(p[n]);
  double r = 0.0;
  for (int k = 1; k <= n; ++k) {
    // |c_{n-k} / c_n|^(1/k), with the powers taken apart so that the
    // ratio cannot overflow.
    const double q = std::fabs(p[n - k]) * (k == n ? 0.5 : 1.0);
    r = std::max(r, k == 1 ? q / lead : std::pow(q, 1.0 / k) / std::pow(lead, 1.0 / k));
  }
  r *= 2.0 * (1.0 + 0x1p-20);
  return std::isfinite(r) ? r : std::numeric_limits<double>::max();
}

double reference_first_contact(const double* c, int degree, double t_max) {
  if (c == nullptr || degree < 0 || degree > 4 || !(t_max >= 0.0)) return kInf;
  double p[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  int n = 0;
  double big = 0.0;
  for (int k = 0; k <= degree; ++k) {
    if (!std::isfinite(c[k])) return kInf;
    p[k] = c[k];
    if (c[k] != 0.0) n = k;
    big = std::max(big, std::fabs(c[k]));
  }
  if (n == 0) return kInf;                        // constant: never closing
  if (p[0] <= 0.0 && p[1] < 0.0) return 0.0;      // touching and closing now
  bool falls = false;                              // can f' be < 0 for t > 0?
  for (int k = 1; k <= n; ++k) falls = falls || p[k] < 0.0;
  if (!falls) return kInf;

  // The largest term of f over the window, and how much the negative
  // terms can remove from f(0) at most.
  double T = t_max + 0.0;  // turns -0 into +0
  double top = 0.0, drop = 0.0;
  const auto measure = [&] {
    double tk = 1.0;
    top = std::fabs(p[0]);
    drop = 0.0;
    for (int k = 1; k <= n; ++k) {
      tk *= T;
      const double term = p[k] * tk;
      top = std::max(top, std::fabs(term));
      if (term < 0.0) drop -= term;
    }
  };
  measure();
  if (!(top <= 0x1p+400)) {
    // A huge (or infinite) window: nothing happens beyond the roots of f,
    // f' and f'', so we may cut it down to a bound on them.
    T = std::min(T, root_bound(p, n));
    measure();
  }
  if (T == 0.0) {
    // Only t = 0 is allowed: a contact if f <= 0 and the first nonzero
    // derivative is negative (p[1] < 0 was handled above; p[1] > 0 means
    // the contact is opening).
    if (p[0] > 0.0) return kInf;
    for (int k = 1; k <= n; ++k) {
      if (p[k] != 0.0) return p[k] < 0.0 ? 0.0 : kInf;
    }
    return kInf;
  }
  // If the terms are so large or small that Horner's intermediates (or the
  // compensated evaluation's error terms) could overflow or go subnormal,
  // rescale time and f by powers of two (exact, so the answer is the same
  // double): t = 2^m s with 2^m ~ T, and f divided by 2^e ~ its largest
  // term over the window (from the exponents, which cannot overflow). Then
  // s runs over [0, 2) and every coefficient is at most 32; terms too
  // small to matter may underflow.
  int m = 0;
  const bool apart = p[0] > 0.0;
  if (!(top >= 0x1p-400 && top <= 0x1p+400)) {
    m = std::ilogb(T);
    int e = std::numeric_limits<int>::min();
    for (int k = 0; k <= n; ++k) {
      if (p[k] != 0.0) e = std::max(e, std::ilogb(p[k]) + m * k);
    }
    for (int k = 0; k <= n; ++k) p[k] = std::ldexp(p[k], m * k - e);
    // A positive constant term too small to survive is still "apart".
    if (apart && p[0] == 0.0) p[0] = std::numeric_limits<double>::denorm_min();
    T = std::ldexp(T, -m);
    measure();
  }
  // Cheap rejection: f stays above p[0] - drop > 0 on [0, T]. The margin
  // covers the rounding of `drop` (a few ulps).
  if (p[0] > drop * (1.0 + 1e-14)) return kInf;

  double s = kInf;
  switch (n) {
    case 1: s = first_contact_n<1>(p, T); break;
    case 2: s = first_contact_n<2>(p, T); break;
    case 3: s = first_contact_n<3>(p, T); break;
    default: s = first_contact_n<4>(p, T); break;
  }
  if (m == 0) return s;
  s = std::ldexp(s, m);
  // Apart at t = 0 means a contact strictly later, even if it underflows.
  return apart && s == 0.0 ? std::numeric_limits<double>::denorm_min() : s;
}

int solve_quadratic(double a, double b, double c, double roots[2]) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return 0;
  if (a == 0.0) {
    if (b == 0.0) return 0;  // constant: no root (or every x if c == 0)
    roots[0] = -c / b + 0.0;
    return 1;
  }
  // Scaling by a power of two keeps b^2 and ac finite and normal.
  const double big = std::max({std::fabs(a), std::fabs(b), std::fabs(c)});
  if (big > 0x1p+480 || big < 0x1p-480) {
    const int e = std::ilogb(big);
    a = std::ldexp(a, -e);
    b = std::ldexp(b, -e);
    c = std::ldexp(c, -e);
  }
  const double bb = b * b;
  const double ac4 = 4.0 * (a * c);
  double disc = bb - ac4;
  if (3.0 * std::fabs(disc) < bb + std::fabs(ac4)) {
    // Near a double root b^2 and 4ac cancel: compute the discriminant
    // exactly from the error-free products (Kahan). The difference of the
    // high parts is exact by Sterbenz's lemma.
    const Pair x = two_prod(b, b);
    const Pair y = two_prod(a, c);
    disc = (x.hi - 4.0 * y.hi) + (x.lo - 4.0 * y.lo);
  }
  if (disc < 0.0) return 0;
  if (disc == 0.0) {
    roots[0] = -b / (2.0 * a) + 0.0;
    return 1;
  }
  // q has the sign of -b and no cancellation; the roots are q/a and c/q.
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double r1 = q / a;
  double r2 = c / q;
  if (r2 < r1) std::swap(r1, r2);
  roots[0] = r1 + 0.0;
  roots[1] = r2 + 0.0;
  return 2;
}

}  // namespace frozen

// Compares first_contact with the frozen copy, memcmp of the doubles
// (+inf included); keeps the first mismatch for the message.
struct BitCompare {
  long cases = 0;
  long mismatches = 0;
  std::string first;
  void operator()(const char* family, const double* c, int degree, double t_max) {
    double cc[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k <= degree && k < 5; ++k) cc[k] = c[k];
    const double want = frozen::reference_first_contact(cc, degree, t_max);
    const double got = first_contact(cc, degree, t_max);
    ++cases;
    if (std::memcmp(&want, &got, sizeof want) != 0 && mismatches++ == 0) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " [%s]: %a instead of %a", family, got, want);
      first = dump(cc, degree, t_max) + buf;
    }
  }
};

// f(t) by Horner in double (for the generators only).
double horner_d(const double* c, int n, double t) {
  double r = c[n];
  for (int k = n - 1; k >= 0; --k) r = r * t + c[k];
  return r;
}

// sum g_j (t - a)^j in powers of t, in long double.
void shifted_poly(const long double* g, long double a, long double* c) {
  const long double binom[5][5] = {
      {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
  for (int k = 0; k < 5; ++k) c[k] = 0;
  for (int j = 0; j <= 4; ++j) {
    long double ap = 1;
    for (int k = j; k >= 0; --k) {
      c[k] += g[j] * binom[j][k] * ap;
      ap *= -a;
    }
  }
}

TEST(FirstContact, FastPathsMatchFullMethodBitForBit) {
  Rng rng(0x5eed000c);
  BitCompare check;
  // Ball pairs on the table and aimed at each other, over the window until
  // a ball stops, and with no window at all; the same with the window
  // ending exactly at, just before and just after the contact.
  for (int i = 0; i < 60000; ++i) {
    const Quartic q = ball_pair(rng, (i & 1) != 0);
    check("ball pair", q.c, 4, q.t_max);
    if (i % 8 == 0) check("ball pair, no window", q.c, 4, kInf);
    const double t = frozen::reference_first_contact(q.c, 4, q.t_max);
    if (t < kInf && t > 0.0) {
      check("window at contact", q.c, 4, t);
      check("window before contact", q.c, 4, std::nextafter(t, 0.0));
      check("window after contact", q.c, 4, std::nextafter(t, kInf));
    }
  }
  // Pairs touching after a collision: c0 ~ round-off either way, opening
  // (or not at all), maybe pulled back together by friction.
  for (int i = 0; i < 30000; ++i) {
    Quartic q = ball_pair(rng, true);
    q.c[0] = rng.sign() * rng.pow10(-40.0, -9.0);
    q.c[1] = std::fabs(q.c[1]) * (rng.uniform() < 0.2 ? rng.pow10(-8.0, 0.0) : 1.0);
    if (rng.uniform() < 0.5) q.c[2] = -std::fabs(q.c[2]);
    if (rng.uniform() < 0.2) q.c[1] = 0.0;
    check("touching pair", q.c, 4, q.t_max);
  }
  // Grazing pairs: c0 moved so that the minimum of f over the window is
  // zero or +-1e-6 .. 1e-18 of c0.
  for (int i = 0; i < 10000; ++i) {
    Quartic q = ball_pair(rng, true);
    double best = kInf, tb = 0.0;
    for (int j = 0; j <= 64; ++j) {
      const double t = q.t_max * j / 64.0;
      if (horner_d(q.c, 4, t) < best) {
        best = horner_d(q.c, 4, t);
        tb = t;
      }
    }
    double a = std::max(0.0, tb - q.t_max / 64.0), b = std::min(q.t_max, tb + q.t_max / 64.0);
    for (int j = 0; j < 80; ++j) {
      const double m1 = a + (b - a) * 0.382, m2 = a + (b - a) * 0.618;
      if (horner_d(q.c, 4, m1) < horner_d(q.c, 4, m2)) {
        b = m2;
      } else {
        a = m1;
      }
    }
    const double fmin = horner_d(q.c, 4, 0.5 * (a + b));
    const double c0 = q.c[0];
    q.c[0] = c0 - fmin;
    check("grazing pair", q.c, 4, q.t_max);
    q.c[0] = c0 - fmin + rng.sign() * rng.pow10(-18.0, -6.0) * (std::fabs(c0) + 1e-3);
    check("grazing pair", q.c, 4, q.t_max);
  }
  // Pairs at power-of-two scales of f and of time, up to absurd ones (the
  // full method's own rescaling and root bound, and coefficients spanning
  // more than 2^800).
  for (int i = 0; i < 10000; ++i) {
    const Quartic q = ball_pair(rng, (i & 1) != 0);
    double c[5];
    const int e = rng.below(1201) - 600, te = rng.below(401) - 200;
    for (int k = 0; k < 5; ++k) c[k] = std::ldexp(q.c[k], e);
    check("scaled pair", c, 4, q.t_max);
    check("scaled pair, huge window", c, 4, 1e300);
    for (int k = 0; k < 5; ++k) c[k] = std::ldexp(q.c[k], -te * k);
    check("time-scaled pair", c, 4, std::ldexp(q.t_max, te));
  }
  // A decelerating ball and a cushion line (degree 2): apart, just
  // reaching it as it stops, and touching after a bounce.
  for (int i = 0; i < 30000; ++i) {
    const double speed = rng.pow10(-1.5, 0.8), decel = rng.uniform() < 0.5 ? 0.0981 : 1.962;
    const double along = rng.uniform(-1.0, 1.0) * speed;
    const double t_max = speed / decel;
    double c[3] = {rng.uniform(0.0, 1.0), -along, 0.5 * decel * along / speed};
    check("cushion", c, 2, t_max);
    const double t = frozen::reference_first_contact(c, 2, t_max);
    if (t < kInf && t > 0.0) {
      check("cushion, window at contact", c, 2, t);
      check("cushion, window before contact", c, 2, std::nextafter(t, 0.0));
    }
    c[0] = 0.5 * std::fabs(along) * speed / decel * (1.0 + rng.sign() * rng.pow10(-17.0, -1.0));
    check("cushion, stopping at it", c, 2, t_max);
    c[0] = rng.sign() * rng.pow10(-18.0, -10.0);
    c[1] = std::fabs(along) * rng.sign();
    c[2] = -0.5 * decel * c[1] / speed;
    check("cushion, touching", c, 2, t_max);
  }
  // Exact grazing parabolas (dips down to 1e-30 either way) in time and
  // coefficient scales.
  for (int i = 0; i < 300; ++i) {
    const Grazing g = grazing_parabola(rng.sign() * rng.pow10(-30.0, -5.0));
    const int te = rng.below(41) - 20, ce = rng.below(41) - 20;
    const double c[3] = {std::ldexp(g.c[0], ce), std::ldexp(g.c[1], ce - te),
                         std::ldexp(g.c[2], ce - 2 * te)};
    check("grazing parabola", c, 2, std::ldexp(2.0, te));
    const double c4[5] = {0.0, 0.0, g.c[0], g.c[1], 1.0};
    check("grazing parabola", c4, 4, 2.0);
  }
  // The test families above: products of roots, random and broad
  // coefficients, wild input, near-double roots.
  for (int i = 0; i < 20000; ++i) {
    double c[5];
    const int degree = product_poly(rng, c);
    const double t_max = rng.uniform(0.0, 3.5);
    check("product of roots", c, degree, t_max);
    const double t = frozen::reference_first_contact(c, degree, t_max);
    if (t < kInf && t > 0.0) {
      check("product of roots, window at contact", c, degree, t);
      check("product of roots, window before contact", c, degree, std::nextafter(t, 0.0));
    }
    for (int k = 0; k <= 4; ++k) c[k] = k <= degree ? rng.sign() * rng.pow10(-3.0, 3.0) : 0.0;
    check("random coefficients", c, degree, rng.pow10(-2.0, 2.0));
    for (int k = 0; k <= 4; ++k) {
      c[k] = k <= degree && rng.uniform() >= 0.1 ? rng.sign() * rng.pow10(-100.0, 100.0) : 0.0;
    }
    check("broad scales", c, degree, rng.pow10(-20.0, 20.0));
    const int wild = rng.below(5);
    for (int k = 0; k <= 4; ++k) {
      c[k] = k <= wild && rng.uniform() >= 0.1 ? rng.sign() * rng.pow10(-300.0, 300.0) : 0.0;
    }
    check("wild", c, wild, rng.uniform() < 0.1 ? kInf : rng.pow10(-300.0, 300.0));
    // ((t - r)^2 + dip r^2) times a positive quadratic, or alone.
    const double r = rng.uniform(0.1, 2.0);
    const double dip = rng.sign() * rng.pow10(-18.0, -2.0) * r * r;
    const double x = rng.uniform(-2.0, 3.0), y = rng.pow10(-1.0, 0.5);
    const Q a[3] = {static_cast<Q>(r) * r + dip, -2 * static_cast<Q>(r), 1};
    const Q b[3] = {static_cast<Q>(x) * x + static_cast<Q>(y) * y, -2 * static_cast<Q>(x), 1};
    const bool quartic = (i & 1) != 0;
    for (int k = 0; k <= 4; ++k) {
      Q s = 0;
      for (int j = 0; j <= 2; ++j) {
        if (k - j >= 0 && k - j <= 2) s += a[j] * (quartic ? b[k - j] : (k == j ? 1 : 0));
      }
      c[k] = static_cast<double>(s);
    }
    check("near-double root", c, quartic ? 4 : 2, rng.uniform(r, 2.0 * r + 1.0));
  }
  // Flat spots: clustered roots and near-inflections of f, f' and f''
  // around the contact, e.g. (t - a)^3 + e1 (t - a) + e0 with tiny e_k.
  for (int i = 0; i < 20000; ++i) {
    const long double a = rng.uniform(0.0, 2.0);
    const auto tiny = [&](double lo) { return static_cast<long double>(rng.sign() * rng.pow10(lo, 0.0)); };
    long double g[5] = {0, 0, 0, 0, 0};
    switch (rng.below(4)) {
      case 0: g[3] = -1; g[1] = tiny(-16.0); g[0] = tiny(-16.0); break;
      case 1: g[4] = 1; g[2] = tiny(-16.0); g[1] = tiny(-16.0); g[0] = tiny(-16.0); break;
      case 2: g[4] = 1; g[3] = tiny(-12.0); g[2] = tiny(-16.0); g[1] = tiny(-16.0); g[0] = tiny(-16.0); break;
      default: g[2] = 1; g[1] = tiny(-12.0); g[0] = tiny(-16.0); break;
    }
    long double cl[5];
    shifted_poly(g, a, cl);
    const int degree = g[4] != 0 ? 4 : g[3] != 0 ? 3 : 2;
    const double s = rng.sign() * rng.pow10(-2.0, 2.0);
    double c[5];
    for (int k = 0; k < 5; ++k) c[k] = static_cast<double>(cl[k] * s);
    check("flat spot", c, degree, rng.uniform(0.0, 3.0));
    c[0] = -c[0];
    check("flat spot", c, degree, rng.uniform(0.0, 3.0));
  }
  std::printf("  [bit-identical to the full method] %ld cases\n", check.cases);
  EXPECT_GT(check.cases, 300000);
  EXPECT_EQ(check.mismatches, 0) << check.mismatches << " mismatches, the first: " << check.first;
}

}  // namespace

}  // namespace test_roots
