// The portable maths functions (src/physics/detmath.hpp): accuracy
// against the platform's libm over sweeps and fixed-seed random samples,
// special values, identities, values computed to high precision, and that
// each function is a pure function of its argument's bits (with a pinned
// digest of many outputs, which must be the same on every platform).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "physics/detmath.hpp"

namespace test_detmath {

namespace dm = breakshot::dm;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }
bool same_bits(double x, double y) { return bits(x) == bits(y); }

/// Fixed-seed SplitMix64 (no <random> distributions: the samples must be
/// the same everywhere).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(next() >> 11) * 0x1p-53);
  }
  /// Log-uniform magnitude in [2^lo, 2^hi), random sign if `sign`.
  double wide(int lo, int hi, bool sign) {
    const double m = uniform(1.0, 2.0);
    const int e = lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo));
    const double x = std::ldexp(m, e);
    return sign && (next() & 1) ? -x : x;
  }

 private:
  std::uint64_t state_;
};

/// |got - want| in units in the last place of `want`.
double ulps(double got, double want) {
  if (got == want) return 0.0;
  if (std::isnan(got) || std::isnan(want) || std::isinf(got) || std::isinf(want)) return 1e300;
  int e = 0;
  std::frexp(want, &e);
  const double ulp = std::max(std::ldexp(1.0, e - 53), 0x1p-1074);
  return std::fabs(got - want) / ulp;
}

/// Largest error of f against g over the samples `next()` makes.
template <class F, class G, class Next>
double max_ulps(F f, G g, Next next, int count, std::string* worst) {
  double max = 0.0;
  for (int i = 0; i < count; ++i) {
    const double x = next(i);
    const double err = ulps(f(x), g(x));
    if (err > max) {
      max = err;
      char buf[64];
      std::snprintf(buf, sizeof buf, "%a", x);
      *worst = buf;
    }
  }
  return max;
}

/// Libm's own error is up to about one ulp on some platforms, ours below
/// one (docs: under 0.8 ulp for sin and cos, about 0.5 for the others),
/// so two ulps between them is the bound.
constexpr double kMaxUlps = 2.0;

template <class F, class G, class Next>
void expect_close(const char* what, F f, G g, Next next, int count) {
  std::string worst;
  const double max = max_ulps(f, g, next, count, &worst);
  EXPECT_LE(max, kMaxUlps) << what << ": " << max << " ulps at x = " << worst;
  if (std::getenv("BREAKSHOT_PRINT_ULPS") != nullptr) {
    std::printf("%-40s max %.3f ulps vs libm (at %s)\n", what, max, worst.c_str());
  }
}

double dsin(double x) { return dm::sin(x); }
double dcos(double x) { return dm::cos(x); }
double dexp(double x) { return dm::exp(x); }
double dlog(double x) { return dm::log(x); }
double derf(double x) { return dm::erf(x); }
double lsin(double x) { return std::sin(x); }
double lcos(double x) { return std::cos(x); }
double lexp(double x) { return std::exp(x); }
double llog(double x) { return std::log(x); }
double lerf(double x) { return std::erf(x); }

}  // namespace

// ---------------------------------------------------------------------------
// Accuracy against libm.

TEST(DetMath, SinCosMatchLibmOverAFewTurnsAndBeyond) {
  constexpr int n = 200000;
  // A sweep over +-3 turns, which covers every angle the engine forms.
  const auto sweep = [](int i) { return -6.0 * kPi + 12.0 * kPi * i / (n - 1); };
  expect_close("sin, sweep over +-3 turns", dsin, lsin, sweep, n);
  expect_close("cos, sweep over +-3 turns", dcos, lcos, sweep, n);
  Rng rng(1);
  const auto small = [&](int) { return rng.uniform(-20.0, 20.0); };
  expect_close("sin, random in [-20, 20]", dsin, lsin, small, n);
  expect_close("cos, random in [-20, 20]", dcos, lcos, small, n);
  // Degrees turned into radians, as the engine does.
  const auto degrees = [&](int) { return rng.uniform(-720.0, 720.0) * (kPi / 180.0); };
  expect_close("sin, random degrees", dsin, lsin, degrees, n);
  expect_close("cos, random degrees", dcos, lcos, degrees, n);
  // Every binade, up to the largest doubles (the other reduction).
  const auto wide = [&](int) { return rng.wide(-30, 1024, true); };
  expect_close("sin, every binade", dsin, lsin, wide, n);
  expect_close("cos, every binade", dcos, lcos, wide, n);
  // Next to multiples of pi/2, where the reduction cancels most.
  const auto near_k = [&](int i) {
    const double x = (i % 2000 + 1) * (kPi / 2);
    return std::nextafter(x, (i & 1) ? kInf : 0.0);
  };
  expect_close("sin, next to multiples of pi/2", dsin, lsin, near_k, 4000);
  expect_close("cos, next to multiples of pi/2", dcos, lcos, near_k, 4000);
}

TEST(DetMath, ExpMatchesLibm) {
  constexpr int n = 200000;
  const auto sweep = [](int i) { return -50.0 + 100.0 * i / (n - 1); };
  expect_close("exp, sweep over [-50, 50]", dexp, lexp, sweep, n);
  Rng rng(2);
  const auto used = [&](int) { return rng.uniform(-50.0, 50.0); };
  expect_close("exp, random in [-50, 50]", dexp, lexp, used, n);
  const auto small = [&](int) { return rng.wide(-60, 2, true); };
  expect_close("exp, small arguments", dexp, lexp, small, n);
  // The whole range with normal results (subnormal ones may be a unit off).
  const auto full = [&](int) { return rng.uniform(-708.0, 709.78); };
  expect_close("exp, random in [-708, 709.78]", dexp, lexp, full, n);
}

TEST(DetMath, LogMatchesLibm) {
  constexpr int n = 200000;
  const auto sweep = [](int i) { return 1e-3 + 10.0 * i / (n - 1); };
  expect_close("log, sweep over (0, 10]", dlog, llog, sweep, n);
  Rng rng(3);
  const auto unit = [&](int) { return rng.uniform(0.0, 1.0) + 0x1p-60; };
  expect_close("log, random in (0, 1]", dlog, llog, unit, n);
  const auto near_one = [&](int) { return 1.0 + rng.uniform(-1e-3, 1e-3); };
  expect_close("log, random near 1", dlog, llog, near_one, n);
  const auto wide = [&](int) { return rng.wide(-1074, 1024, false); };
  expect_close("log, every binade (subnormals too)", dlog, llog, wide, n);
}

TEST(DetMath, Atan2MatchesLibmInEveryQuadrant) {
  constexpr int n = 200000;
  Rng rng(4);
  double y = 0.0;
  const auto f = [&](double x) { return dm::atan2(y, x); };
  const auto g = [&](double x) { return std::atan2(y, x); };
  // Around the circle.
  expect_close(
      "atan2, around the unit circle",
      [&](double t) { return dm::atan2(std::sin(t), std::cos(t)); },
      [&](double t) { return std::atan2(std::sin(t), std::cos(t)); },
      [](int i) { return -kPi + 2.0 * kPi * i / (n - 1); }, n);
  // Random points in a square, all four quadrants.
  expect_close("atan2, random in [-1, 1]^2", f, g,
               [&](int) {
                 y = rng.uniform(-1.0, 1.0);
                 return rng.uniform(-1.0, 1.0);
               },
               n);
  // Operands of very different sizes (results far from 1 and near pi/2).
  expect_close("atan2, magnitudes 2^-40 ... 2^40", f, g,
               [&](int) {
                 y = rng.wide(-40, 40, true);
                 return rng.wide(-40, 40, true);
               },
               n);
  expect_close("atan2, magnitudes 2^-900 ... 2^960", f, g,
               [&](int) {
                 y = rng.wide(-900, 960, true);
                 return y * rng.wide(-40, 40, true);
               },
               n);
}

TEST(DetMath, PowMatchesLibmForPositiveBases) {
  constexpr int n = 200000;
  Rng rng(5);
  double y = 0.0;
  const auto f = [&](double x) { return dm::pow(x, y); };
  const auto g = [&](double x) { return std::pow(x, y); };
  expect_close("pow, x in (0, 4], y in [-30, 30]", f, g,
               [&](int) {
                 y = rng.uniform(-30.0, 30.0);
                 return rng.uniform(0.0, 4.0) + 0x1p-30;
               },
               n);
  // Roots of numbers of every size (root_bound in src/physics/roots.cpp).
  expect_close("pow, x^(1/k), k = 2, 3, 4", f, g,
               [&](int i) {
                 y = 1.0 / (2 + i % 3);
                 return rng.wide(-1000, 1000, false);
               },
               n);
  // Results near the ends of the range.
  expect_close("pow, y log x in [-700, 700]", f, g,
               [&](int) {
                 const double x = rng.uniform(0.5, 2.0);
                 y = rng.uniform(-700.0, 700.0) / std::log(x);
                 return x;
               },
               n);
  // pow(x, 1.5) is x sqrt(x) to within an ulp or so.
  for (int i = 0; i < 1000; ++i) {
    const double x = rng.uniform(0.0, 1.0);
    EXPECT_LE(ulps(dm::pow(x, 1.5), x * std::sqrt(x)), 2.0) << x;
  }
}

TEST(DetMath, ErfMatchesLibm) {
  constexpr int n = 200000;
  const auto sweep = [](int i) { return -7.0 + 14.0 * i / (n - 1); };
  expect_close("erf, sweep over [-7, 7]", derf, lerf, sweep, n);
  Rng rng(6);
  const auto wide = [&](int) { return rng.wide(-40, 3, true); };
  expect_close("erf, magnitudes 2^-40 ... 8", derf, lerf, wide, n);
}

// ---------------------------------------------------------------------------
// Special values (as documented in the header; C99 Annex F).

TEST(DetMath, SpecialValues) {
  // sin, cos
  EXPECT_TRUE(same_bits(dm::sin(0.0), 0.0));
  EXPECT_TRUE(same_bits(dm::sin(-0.0), -0.0));
  EXPECT_EQ(dm::cos(0.0), 1.0);
  EXPECT_EQ(dm::cos(-0.0), 1.0);
  EXPECT_TRUE(std::isnan(dm::sin(kInf)));
  EXPECT_TRUE(std::isnan(dm::sin(-kInf)));
  EXPECT_TRUE(std::isnan(dm::cos(kInf)));
  EXPECT_TRUE(std::isnan(dm::sin(kNaN)));
  EXPECT_TRUE(std::isnan(dm::cos(kNaN)));
  EXPECT_TRUE(same_bits(dm::sin(0x1p-1074), 0x1p-1074));  // sin x = x for tiny x
  EXPECT_TRUE(same_bits(dm::sin(-1e-300), -1e-300));
  EXPECT_EQ(dm::cos(1e-300), 1.0);
  double s = 1.0;
  double c = 1.0;
  dm::sincos(-0.0, s, c);
  EXPECT_TRUE(same_bits(s, -0.0));
  EXPECT_EQ(c, 1.0);
  dm::sincos(kInf, s, c);
  EXPECT_TRUE(std::isnan(s) && std::isnan(c));

  // atan2
  const double pi = 0x1.921fb54442d18p+1;  // pi rounded
  EXPECT_TRUE(same_bits(dm::atan2(0.0, 1.0), 0.0));
  EXPECT_TRUE(same_bits(dm::atan2(-0.0, 1.0), -0.0));
  EXPECT_TRUE(same_bits(dm::atan2(0.0, 0.0), 0.0));
  EXPECT_TRUE(same_bits(dm::atan2(-0.0, 0.0), -0.0));
  EXPECT_EQ(dm::atan2(0.0, -0.0), pi);
  EXPECT_EQ(dm::atan2(-0.0, -0.0), -pi);
  EXPECT_EQ(dm::atan2(0.0, -1.0), pi);
  EXPECT_EQ(dm::atan2(-0.0, -1.0), -pi);
  EXPECT_EQ(dm::atan2(1.0, 0.0), pi / 2);
  EXPECT_EQ(dm::atan2(1.0, -0.0), pi / 2);
  EXPECT_EQ(dm::atan2(-1.0, 0.0), -pi / 2);
  EXPECT_EQ(dm::atan2(kInf, 1.0), pi / 2);
  EXPECT_EQ(dm::atan2(-kInf, -1.0), -pi / 2);
  EXPECT_EQ(dm::atan2(kInf, kInf), pi / 4);
  EXPECT_EQ(dm::atan2(-kInf, kInf), -pi / 4);
  EXPECT_EQ(dm::atan2(kInf, -kInf), 0x1.2d97c7f3321d2p+1);  // 3 pi/4 rounded
  EXPECT_EQ(dm::atan2(-kInf, -kInf), -0x1.2d97c7f3321d2p+1);
  EXPECT_TRUE(same_bits(dm::atan2(1.0, kInf), 0.0));
  EXPECT_TRUE(same_bits(dm::atan2(-1.0, kInf), -0.0));
  EXPECT_EQ(dm::atan2(1.0, -kInf), pi);
  EXPECT_EQ(dm::atan2(-1.0, -kInf), -pi);
  EXPECT_TRUE(std::isnan(dm::atan2(kNaN, 1.0)));
  EXPECT_TRUE(std::isnan(dm::atan2(1.0, kNaN)));
  EXPECT_EQ(dm::atan2(1.0, 1.0), pi / 4);
  EXPECT_EQ(dm::atan2(1e-300, 1e300), 0.0);  // underflows
  EXPECT_EQ(dm::atan2(1e300, 1e-300), pi / 2);

  // exp
  EXPECT_EQ(dm::exp(0.0), 1.0);
  EXPECT_EQ(dm::exp(-0.0), 1.0);
  EXPECT_EQ(dm::exp(kInf), kInf);
  EXPECT_TRUE(same_bits(dm::exp(-kInf), 0.0));
  EXPECT_TRUE(std::isnan(dm::exp(kNaN)));
  EXPECT_EQ(dm::exp(709.79), kInf);
  EXPECT_EQ(dm::exp(1000.0), kInf);
  EXPECT_LT(dm::exp(709.78), kInf);
  EXPECT_EQ(dm::exp(-746.0), 0.0);
  EXPECT_EQ(dm::exp(-745.0), 0x1p-1074);  // the least subnormal
  EXPECT_LE(ulps(dm::exp(-740.0), std::exp(-740.0)), 1.0);  // subnormal: one unit

  // log
  EXPECT_EQ(dm::log(1.0), 0.0);
  EXPECT_FALSE(std::signbit(dm::log(1.0)));
  EXPECT_EQ(dm::log(0.0), -kInf);
  EXPECT_EQ(dm::log(-0.0), -kInf);
  EXPECT_TRUE(std::isnan(dm::log(-1.0)));
  EXPECT_TRUE(std::isnan(dm::log(-kInf)));
  EXPECT_TRUE(std::isnan(dm::log(kNaN)));
  EXPECT_EQ(dm::log(kInf), kInf);
  EXPECT_LE(ulps(dm::log(0x1p-1074), std::log(0x1p-1074)), 0.5);
  EXPECT_LE(ulps(dm::log(0x1.fffffffffffffp+1023), std::log(0x1.fffffffffffffp+1023)), 0.5);

  // pow
  EXPECT_EQ(dm::pow(kNaN, 0.0), 1.0);
  EXPECT_EQ(dm::pow(kNaN, -0.0), 1.0);
  EXPECT_EQ(dm::pow(1.0, kNaN), 1.0);
  EXPECT_TRUE(std::isnan(dm::pow(kNaN, 1.0)));
  EXPECT_TRUE(std::isnan(dm::pow(2.0, kNaN)));
  EXPECT_TRUE(std::isnan(dm::pow(-2.0, 0.5)));
  EXPECT_EQ(dm::pow(-2.0, 3.0), -8.0);
  EXPECT_EQ(dm::pow(-2.0, 2.0), 4.0);
  EXPECT_EQ(dm::pow(-1.0, kInf), 1.0);
  EXPECT_EQ(dm::pow(0.5, kInf), 0.0);
  EXPECT_EQ(dm::pow(0.5, -kInf), kInf);
  EXPECT_EQ(dm::pow(2.0, kInf), kInf);
  EXPECT_EQ(dm::pow(2.0, -kInf), 0.0);
  EXPECT_EQ(dm::pow(0.0, 3.0), 0.0);
  EXPECT_TRUE(same_bits(dm::pow(-0.0, 3.0), -0.0));
  EXPECT_TRUE(same_bits(dm::pow(-0.0, 2.0), 0.0));
  EXPECT_EQ(dm::pow(0.0, -1.0), kInf);
  EXPECT_EQ(dm::pow(-0.0, -1.0), -kInf);
  EXPECT_EQ(dm::pow(-0.0, -2.0), kInf);
  EXPECT_EQ(dm::pow(kInf, 0.5), kInf);
  EXPECT_EQ(dm::pow(kInf, -0.5), 0.0);
  EXPECT_EQ(dm::pow(-kInf, 3.0), -kInf);
  EXPECT_TRUE(same_bits(dm::pow(-kInf, -3.0), -0.0));
  EXPECT_EQ(dm::pow(-kInf, 2.0), kInf);
  EXPECT_EQ(dm::pow(10.0, 400.0), kInf);
  EXPECT_EQ(dm::pow(10.0, -400.0), 0.0);
  EXPECT_EQ(dm::pow(2.0, 1e300), kInf);
  EXPECT_EQ(dm::pow(0.5, 1e300), 0.0);
  EXPECT_EQ(dm::pow(2.0, 10.0), 1024.0);
  EXPECT_EQ(dm::pow(2.0, -1074.0), 0x1p-1074);
  EXPECT_EQ(dm::pow(4.0, 0.5), 2.0);
  EXPECT_EQ(dm::pow(8.0, 1.0 / 3.0), 2.0);

  // Every NaN result has the same bits, whatever the hardware makes of
  // inf - inf or 0/0.
  const double nans[] = {dm::sin(kInf), dm::cos(-kInf), dm::sin(-kNaN), dm::atan2(kNaN, 1.0),
                         dm::exp(-kNaN), dm::log(-1.0), dm::log(-kNaN), dm::pow(-2.0, 0.5),
                         dm::pow(kNaN, 2.0), dm::erf(-kNaN)};
  for (const double v : nans) EXPECT_TRUE(same_bits(v, kNaN)) << std::hexfloat << v;

  // erf
  EXPECT_TRUE(same_bits(dm::erf(0.0), 0.0));
  EXPECT_TRUE(same_bits(dm::erf(-0.0), -0.0));
  EXPECT_EQ(dm::erf(kInf), 1.0);
  EXPECT_EQ(dm::erf(-kInf), -1.0);
  EXPECT_EQ(dm::erf(6.0), 1.0);
  EXPECT_EQ(dm::erf(-30.0), -1.0);
  EXPECT_TRUE(std::isnan(dm::erf(kNaN)));
  EXPECT_LE(ulps(dm::erf(1e-300), std::erf(1e-300)), 1.0);
}

// ---------------------------------------------------------------------------
// Identities.

TEST(DetMath, Identities) {
  Rng rng(7);
  for (int i = 0; i < 100000; ++i) {
    const double x = i < 50000 ? rng.uniform(-20.0, 20.0) : rng.wide(-20, 1024, true);
    const double s = dm::sin(x);
    const double c = dm::cos(x);
    // Symmetries hold exactly.
    ASSERT_TRUE(same_bits(dm::sin(-x), -s)) << x;
    ASSERT_TRUE(same_bits(dm::cos(-x), c)) << x;
    // One reduction gives the same bits as two.
    double s2 = 0.0;
    double c2 = 0.0;
    dm::sincos(x, s2, c2);
    ASSERT_TRUE(same_bits(s, s2) && same_bits(c, c2)) << x;
    // sin^2 + cos^2 = 1 up to the rounding of each (errors below an ulp).
    ASSERT_NEAR(s * s + c * c, 1.0, 4 * 0x1p-53) << x;
    ASSERT_LE(std::fabs(s), 1.0);
    ASSERT_LE(std::fabs(c), 1.0);
    // atan2 undoes them (x reduced to (-pi, pi]) and is odd in y.
    if (std::fabs(x) < kPi) {
      ASSERT_NEAR(dm::atan2(s, c), x, 4 * 0x1p-52 * std::max(1.0, std::fabs(x))) << x;
    }
    const double y = rng.uniform(-5.0, 5.0);
    ASSERT_TRUE(same_bits(dm::atan2(-y, x), -dm::atan2(y, x))) << y << " " << x;
    // exp and log invert each other (log v rounded to an ulp of |log v| <
    // 8 moves exp by 2^-50 relative, 8 ulps); exp(a + b) = exp(a) exp(b)
    // closely (a and b on a grid of 2^-20, so a + b is exact).
    const double a = std::floor(rng.uniform(-20.0, 20.0) * 0x1p20) * 0x1p-20;
    const double b = std::floor(rng.uniform(-20.0, 20.0) * 0x1p20) * 0x1p-20;
    ASSERT_NEAR(dm::log(dm::exp(a)), a, 2 * 0x1p-52 * std::max(1.0, std::fabs(a))) << a;
    const double v = rng.wide(-10, 10, false);
    ASSERT_LE(ulps(dm::exp(dm::log(v)), v), 10.0) << v;
    ASSERT_LE(ulps(dm::exp(a) * dm::exp(b), dm::exp(a + b)), 2.5) << a << " " << b;
    // pow agrees with exp and log, and erf is odd and within [-1, 1].
    ASSERT_LE(ulps(dm::pow(v, 0.5), std::sqrt(v)), 1.0) << v;
    const double e = dm::erf(y);
    ASSERT_TRUE(same_bits(dm::erf(-y), -e)) << y;
    ASSERT_LE(std::fabs(e), 1.0);
  }
  // Monotone on a fine grid.
  double prev = -1.0;
  for (int i = -1000; i <= 1000; ++i) {
    const double e = dm::erf(i * 0.006);
    ASSERT_GE(e, prev) << i;
    prev = e;
  }
}

// ---------------------------------------------------------------------------
// Values computed to high precision (60 digits, from the Taylor series and
// Machin's formula with Python's decimal module), rounded to double; our
// functions give these correctly rounded values.

TEST(DetMath, HighPrecisionReferenceValues) {
  struct Case {
    const char* what;
    double got;
    double want;
  };
  const Case cases[] = {
      {"sin(1)", dm::sin(1.0), 0x1.aed548f090ceep-1},             // 0.841470984807896506652...
      {"cos(1)", dm::cos(1.0), 0x1.14a280fb5068cp-1},             // 0.540302305868139717400...
      {"sin(0.5)", dm::sin(0.5), 0x1.eaee8744b05f0p-2},           // 0.479425538604203000273...
      {"cos(2)", dm::cos(2.0), -0x1.aa22657537205p-2},            // -0.416146836547142386997...
      {"sin(10)", dm::sin(10.0), -0x1.1689ef5f34f52p-1},          // -0.544021110889369813404...
      {"cos(100)", dm::cos(100.0), 0x1.b981dbf665fdfp-1},         // 0.862318872287683934101...
      {"sin(1e22)", dm::sin(1e22), -0x1.b453ab76bf397p-1},        // -0.852200849767188801772...
      {"cos(1e22)", dm::cos(1e22), 0x1.0be2cef01c8f4p-1},         // 0.523214785395138945497...
      {"exp(1)", dm::exp(1.0), 0x1.5bf0a8b145769p+1},             // 2.718281828459045235360...
      {"exp(-1)", dm::exp(-1.0), 0x1.78b56362cef38p-2},           // 0.367879441171442321595...
      {"exp(10)", dm::exp(10.0), 0x1.5829dcf950560p+14},          // 22026.4657948067165169...
      {"exp(-20.5)", dm::exp(-20.5), 0x1.57a3afeed00abp-30},      // 1.250152866386742628...e-9
      {"exp(0.001)", dm::exp(0.001), 0x1.0041919b7ee34p+0},       // 1.001000500166708341...
      {"log(2)", dm::log(2.0), 0x1.62e42fefa39efp-1},             // 0.693147180559945309417...
      {"log(10)", dm::log(10.0), 0x1.26bb1bbb55516p+1},           // 2.302585092994045684017...
      {"log(0.1)", dm::log(0.1), -0x1.26bb1bbb55515p+1},          // -2.30258509299404562850...
      {"log(1e-300)", dm::log(1e-300), -0x1.5963447f87fb5p+9},    // -690.775527898213705180...
      {"atan2(1, 2)", dm::atan2(1.0, 2.0), 0x1.dac670561bb4fp-2},  // 0.463647609000806116214...
      {"atan2(2, 1)", dm::atan2(2.0, 1.0), 0x1.1b6e192ebbe44p+0},  // 1.107148717794090503017...
      {"atan2(-1, -3)", dm::atan2(-1.0, -3.0), -0x1.68f095fdf593cp+1},  // -2.819842099193151045...
      {"pow(2, 0.5)", dm::pow(2.0, 0.5), 0x1.6a09e667f3bcdp+0},         // 1.414213562373095048801...
      {"pow(10, -3)", dm::pow(10.0, -3.0), 0x1.0624dd2f1a9fcp-10},      // 0.001
      {"pow(3, 1/3)", dm::pow(3.0, 1.0 / 3.0), 0x1.7137449123ef6p+0},   // 1.442249570307408353...
      {"pow(1.5, 100)", dm::pow(1.5, 100.0), 0x1.69194f299cddap+58},    // 406561177535215237.397...
      {"erf(0.5)", dm::erf(0.5), 0x1.0a7ef5c18edd2p-1},                 // 0.520499877813046537682...
      {"erf(1)", dm::erf(1.0), 0x1.af767a741088bp-1},                   // 0.842700792949714869341...
      {"erf(2)", dm::erf(2.0), 0x1.fd9ae142795e3p-1},                   // 0.995322265018952734162...
      {"erf(3.5)", dm::erf(3.5), 0x1.ffffe710d565ep-1},                 // 0.999999256901627658587...
  };
  for (const Case& c : cases) {
    EXPECT_TRUE(same_bits(c.got, c.want)) << c.what << " = " << std::hexfloat << c.got
                                          << ", correctly rounded " << c.want;
  }
}

// ---------------------------------------------------------------------------
// Pure functions of the bits, the same everywhere.

namespace {

/// FNV-1a over the bits of f at `count` fixed arguments.
template <class F>
std::uint64_t digest(F f, std::uint64_t seed, int count) {
  Rng rng(seed);
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (int i = 0; i < count; ++i) {
    const std::uint64_t b = bits(f(rng));
    for (int k = 0; k < 8; ++k) {
      h ^= (b >> (8 * k)) & 0xff;
      h *= 0x100000001b3ULL;
    }
  }
  return h;
}

struct Digests {
  std::uint64_t sin, cos, atan2, exp, log, pow, erf;
};

/// An angle as the engine forms them (half the time) or of any size.
double any_angle(Rng& r) { return r.next() & 1 ? r.uniform(-20.0, 20.0) : r.wide(-30, 1024, true); }

Digests digests() {
  constexpr int n = 20000;
  Digests d{};
  d.sin = digest([](Rng& r) { return dm::sin(any_angle(r)); }, 11, n);
  d.cos = digest([](Rng& r) { return dm::cos(any_angle(r)); }, 12, n);
  d.atan2 = digest(
      [](Rng& r) {
        const double y = r.wide(-60, 60, true);  // drawn first: argument order is unspecified
        return dm::atan2(y, r.wide(-60, 60, true));
      },
      13, n);
  d.exp = digest([](Rng& r) { return dm::exp(r.uniform(-745.0, 709.0)); }, 14, n);
  d.log = digest([](Rng& r) { return dm::log(r.wide(-1074, 1024, false)); }, 15, n);
  d.pow = digest(
      [](Rng& r) {
        const double x = r.wide(-20, 20, false);
        return dm::pow(x, r.uniform(-30.0, 30.0));
      },
      16, n);
  d.erf = digest([](Rng& r) { return dm::erf(r.uniform(-7.0, 7.0)); }, 17, n);
  return d;
}

}  // namespace

TEST(DetMath, SameArgumentSameBits) {
  Rng rng(8);
  for (int i = 0; i < 10000; ++i) {
    const double x = rng.uniform(-50.0, 50.0);
    const double y = rng.uniform(-50.0, 50.0);
    const double first[] = {dm::sin(x), dm::cos(x), dm::atan2(y, x), dm::exp(x),
                            dm::log(std::fabs(x)), dm::pow(std::fabs(x), y), dm::erf(x)};
    // Other calls in between change nothing (no hidden state).
    (void)dm::sin(y);
    (void)dm::exp(y);
    (void)dm::log(std::fabs(y));
    const double again[] = {dm::sin(x), dm::cos(x), dm::atan2(y, x), dm::exp(x),
                            dm::log(std::fabs(x)), dm::pow(std::fabs(x), y), dm::erf(x)};
    for (int k = 0; k < 7; ++k) ASSERT_TRUE(same_bits(first[k], again[k])) << k << " " << x;
  }
  const Digests a = digests();
  const Digests b = digests();
  EXPECT_EQ(a.sin, b.sin);
  EXPECT_EQ(a.erf, b.erf);
}

// The outputs at 20,000 fixed arguments per function, hashed. They are the
// same bits on every platform (native g++/glibc and clang/musl wasm alike):
// a change here means a change to the algorithms or to the floating-point
// semantics of the build (contraction, excess precision), and everything
// that uses these functions changes with it.
// Regenerate with: BREAKSHOT_PRINT_HASHES=1 build/release/tests/breakshot_tests
//   --gtest_filter=DetMath.*
TEST(DetMath, PinnedDigestsOfOutputs) {
  const Digests d = digests();
  if (std::getenv("BREAKSHOT_PRINT_HASHES") != nullptr) {
    std::printf("sin 0x%016llx\ncos 0x%016llx\natan2 0x%016llx\nexp 0x%016llx\n"
                "log 0x%016llx\npow 0x%016llx\nerf 0x%016llx\n",
                static_cast<unsigned long long>(d.sin), static_cast<unsigned long long>(d.cos),
                static_cast<unsigned long long>(d.atan2), static_cast<unsigned long long>(d.exp),
                static_cast<unsigned long long>(d.log), static_cast<unsigned long long>(d.pow),
                static_cast<unsigned long long>(d.erf));
  }
  EXPECT_EQ(d.sin, 0x91a80db64ff9638dull);
  EXPECT_EQ(d.cos, 0xde8053d5ce69674dull);
  EXPECT_EQ(d.atan2, 0x6cd15edab08ea4caull);
  EXPECT_EQ(d.exp, 0x371d4840fc1f2dcbull);
  EXPECT_EQ(d.log, 0x5911fbfeb8fcf696ull);
  EXPECT_EQ(d.pow, 0xb61fbd0d022d83e3ull);
  EXPECT_EQ(d.erf, 0x098d3f127780c27eull);
}

}  // namespace test_detmath
