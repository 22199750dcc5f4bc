// Portable transcendental functions (src/physics/detmath.hpp).
//
// Everything here is + - * /, std::frexp, std::ldexp, std::floor,
// std::fabs, comparisons and integer arithmetic, evaluated in a fixed
// order; the build turns floating-point contraction off, so each line is
// the same IEEE operation on every platform and the results are the same
// bits everywhere.
//
// Accuracy comes from carrying the parts that matter in double-double
// (an unevaluated sum hi + lo, with the error-free transformations of
// Knuth and Dekker below) and rounding to double once, at the end. The
// tables and constants were computed for this file with exact rational
// and 120-digit decimal arithmetic (Python's fractions and decimal):
// each constant is the double nearest the true value, a "hi, lo" pair is
// the nearest double hi and the double nearest the remainder, and 2/pi is
// its exact binary expansion. The polynomial coefficients are the Taylor
// coefficients, rounded to double.
#include "physics/detmath.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "physics/error_free.hpp"

namespace breakshot::dm {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// --- Double-double arithmetic ----------------------------------------------

// The value hi + lo; the error-free transformations are in
// src/physics/error_free.hpp, shared with the root finders.
using DD = eft::Pair;
using eft::split;
using eft::two_prod;
using eft::two_sum;

// --- Constants -------------------------------------------------------------

constexpr DD kPiO2{0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};
constexpr DD kPi{0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};
constexpr double kPiO4 = 0x1.921fb54442d18p-1;   // nearest double to pi/4
constexpr double k3PiO4 = 0x1.2d97c7f3321d2p+1;  // nearest double to 3pi/4

// 2/pi in binary: word j holds bits 32 j + 1 ... 32 j + 32 after the point.
// The largest doubles need words up to 37 (see reduce); 44 are stored.
constexpr std::uint32_t kTwoOverPi[44] = {
    0xa2f9836e, 0x4e441529, 0xfc2757d1, 0xf534ddc0, 0xdb629599, 0x3c439041,
    0xfe5163ab, 0xdebbc561, 0xb7246e3a, 0x424dd2e0, 0x06492eea, 0x09d1921c,
    0xfe1deb1c, 0xb129a73e, 0xe88235f5, 0x2ebb4484, 0xe99c7026, 0xb45f7e41,
    0x3991d639, 0x835339f4, 0x9c845f8b, 0xbdf9283b, 0x1ff897ff, 0xde05980f,
    0xef2f118b, 0x5a0a6d1f, 0x6d367ecf, 0x27cb09b7, 0x4f463f66, 0x9e5fea2d,
    0x7527bac7, 0xebe5f17b, 0x3d0739f7, 0x8a5292ea, 0x6bfb5fb1, 0x1f8d5d08,
    0x56033046, 0xfc7b6bab, 0xf0cfbc20, 0x9af4361d, 0xa9e39161, 0x5ee61b08,
    0x6599855f, 0x14a06840,
};

// --- sin and cos -------------------------------------------------------------

// x = (4 n + q) pi/2 + (hi + lo) with |hi + lo| <= pi/4 (a hair more).
struct Reduced {
  int q;
  double hi, lo;
};

// Payne and Hanek's reduction, in exact integer arithmetic. For ax > 0
// finite, ax = M 2^E with M < 2^53 an integer, and ax 2/pi is M times the
// bits of 2/pi shifted by E. Only the bits of 2/pi that give the product
// from 2^1 (the quadrant) down to far below the point matter: the earlier
// ones make multiples of 4, and 256 bits of 2/pi from there leave an error
// below 2^-170 in ax 2/pi, while no double comes closer to a multiple of
// pi/2 than about 2^-61 relative (so the remainder keeps > 106 good bits).
Reduced reduce(double ax) {
  int ex = 0;
  const double m = std::frexp(ax, &ex);  // ax = m 2^ex, m in [0.5, 1)
  const auto M = static_cast<std::uint64_t>(std::ldexp(m, 53));
  const int E = ex - 53;
  // First word j0 whose lowest bit, times 2^E, weighs at most 2^1.
  const int j0 = E > 33 ? (E - 2) / 32 : 0;
  // The window of eight words as 32-bit limbs, least significant first,
  // times M's two limbs: P = M * window, at most 309 bits.
  std::uint64_t win[8];
  for (int k = 0; k < 8; ++k) win[k] = kTwoOverPi[j0 + 7 - k];
  const std::uint64_t ml[2] = {M & 0xffffffffu, M >> 32};
  std::uint32_t p[10] = {};
  for (int i = 0; i < 2; ++i) {
    std::uint64_t carry = 0;
    for (int k = 0; k < 8; ++k) {
      const std::uint64_t t = ml[i] * win[k] + p[i + k] + carry;  // < 2^64
      p[i + k] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    p[i + 8] = static_cast<std::uint32_t>(carry);
  }
  // ax 2/pi = P 2^-b: bit b of P weighs 2^0 (b in [223, 309]).
  const int b = 32 * (j0 + 8) - E;
  const auto bit = [&](int pos) { return (p[pos >> 5] >> (pos & 31)) & 1u; };
  // 32 bits of P whose lowest is bit `pos`.
  const auto bits32 = [&](int pos) {
    const int w = pos >> 5;
    std::uint64_t v = p[w];
    if (w + 1 < 10) v |= static_cast<std::uint64_t>(p[w + 1]) << 32;
    return static_cast<std::uint32_t>(v >> (pos & 31));
  };
  int q = static_cast<int>(bit(b) + 2 * bit(b + 1));
  // The fraction f in [0, 1): 192 bits in six words, most significant first.
  std::uint32_t c[6];
  for (int k = 0; k < 6; ++k) c[k] = bits32(b - 32 * (k + 1));
  const bool negative = (c[0] >> 31) != 0;  // f >= 1/2: take f - 1 instead
  if (negative) {
    ++q;
    // 2^192 - f in two's complement.
    std::uint64_t carry = 1;
    for (int k = 5; k >= 0; --k) {
      const std::uint64_t t = static_cast<std::uint64_t>(~c[k]) + carry;
      c[k] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
  }
  // |f| in double-double: the words are exact doubles, all >= 0.
  double hi = static_cast<double>(c[0]) * 0x1p-32;
  double lo = 0.0;
  double scale = 0x1p-32;
  for (int k = 1; k < 6; ++k) {
    scale *= 0x1p-32;
    const DD s = two_sum(hi, static_cast<double>(c[k]) * scale);
    hi = s.hi;
    lo += s.lo;
  }
  const DD f = two_sum(hi, lo);
  // r = f pi/2.
  const DD r0 = two_prod(f.hi, kPiO2.hi);
  const DD r = two_sum(r0.hi, r0.lo + (f.hi * kPiO2.lo + f.lo * kPiO2.hi));
  if (negative) return {q & 3, -r.hi, -r.lo};
  return {q & 3, r.hi, r.lo};
}

// pi/2 = kPiO2A + kPiO2B + kPiO2C + kPiO2D to about 2^-152; A, B and C
// have 33 bits, so k times each is exact for k < 2^20.
constexpr double kTwoOverPiD = 0x1.45f306dc9c883p-1;
constexpr double kPiO2A = 0x1.921fb54400000p+0;
constexpr double kPiO2B = 0x1.0b4611a600000p-34;
constexpr double kPiO2C = 0x1.3198a2e000000p-69;
constexpr double kPiO2D = 0x1.b839a252049c1p-104;

// Cody and Waite's reduction for ax < 2^20, in double-double: r = ax - k
// pi/2 with the four parts above, each subtraction exact (two_sum) but
// the last. No double below 2^20 comes within 2^-60.5 of a multiple of
// pi/2 (the closest is 45.5..., next to 29 pi/2), and the error is below
// 2^-125, so even the smallest r keeps more than 64 good bits.
Reduced reduce_medium(double ax) {
  const double kd = std::floor(ax * kTwoOverPiD + 0.5);
  const DD t = two_sum(ax, -kd * kPiO2A);
  const DD u = two_sum(t.hi, -kd * kPiO2B);
  const DD v = two_sum(u.hi, -kd * kPiO2C);
  const DD r = two_sum(v.hi, ((t.lo + u.lo) + v.lo) - kd * kPiO2D);
  return {static_cast<int>(kd) & 3, r.hi, r.lo};
}

Reduced reduce_signless(double ax) {
  if (ax <= kPiO4) return {0, ax, 0.0};
  if (ax < 0x1p20) return reduce_medium(ax);
  return reduce(ax);
}

// sin(h + l) for |h + l| <= pi/4 (a hair more), |l| <= ulp(h):
// h + (h z P(z) + l (1 - z/2)) with z = h^2 and the Taylor polynomial
// P(z) = -1/3! + z/5! - ... + z^8/19! (the next term is below 1e-22 h).
double sin_kernel(double h, double l) {
  const double z = h * h;
  double p = -0x1.2f49b46814157p-57;  // -1/19!
  p = p * z + 0x1.952c77030ad4ap-49;  // 1/17!
  p = p * z - 0x1.ae7f3e733b81fp-41;  // -1/15!
  p = p * z + 0x1.6124613a86d09p-33;  // 1/13!
  p = p * z - 0x1.ae64567f544e4p-26;  // -1/11!
  p = p * z + 0x1.71de3a556c734p-19;  // 1/9!
  p = p * z - 0x1.a01a01a01a01ap-13;  // -1/7!
  p = p * z + 0x1.1111111111111p-7;   // 1/5!
  p = p * z - 0x1.5555555555555p-3;   // -1/3!
  return h + ((h * z) * p + (l - (0.5 * z) * l));
}

// cos(h + l) likewise: 1 - z/2 in double-double (z = h^2 exactly, by
// Dekker's product), minus h l, plus z^2 Q(z) with the Taylor polynomial
// Q(z) = 1/4! - z/6! + ... + z^8/20!.
double cos_kernel(double h, double l) {
  const DD z = two_prod(h, h);
  double p = 0x1.e542ba4020225p-62;   // 1/20!
  p = p * z.hi - 0x1.6827863b97d97p-53;  // -1/18!
  p = p * z.hi + 0x1.ae7f3e733b81fp-45;  // 1/16!
  p = p * z.hi - 0x1.93974a8c07c9dp-37;  // -1/14!
  p = p * z.hi + 0x1.1eed8eff8d898p-29;  // 1/12!
  p = p * z.hi - 0x1.27e4fb7789f5cp-22;  // -1/10!
  p = p * z.hi + 0x1.a01a01a01a01ap-16;  // 1/8!
  p = p * z.hi - 0x1.6c16c16c16c17p-10;  // -1/6!
  p = p * z.hi + 0x1.5555555555555p-5;   // 1/4!
  const DD w = two_sum(1.0, -0.5 * z.hi);  // exact
  return w.hi + (w.lo - 0.5 * z.lo - h * l + (z.hi * z.hi) * p);
}

double sin_of(const Reduced& r) {
  switch (r.q) {
    case 0: return sin_kernel(r.hi, r.lo);
    case 1: return cos_kernel(r.hi, r.lo);
    case 2: return -sin_kernel(r.hi, r.lo);
    default: return -cos_kernel(r.hi, r.lo);
  }
}

double cos_of(const Reduced& r) {
  switch (r.q) {
    case 0: return cos_kernel(r.hi, r.lo);
    case 1: return -sin_kernel(r.hi, r.lo);
    case 2: return -cos_kernel(r.hi, r.lo);
    default: return sin_kernel(r.hi, r.lo);
  }
}

// --- atan2 -----------------------------------------------------------------

// atan(i/16) for i = 0 ... 16, hi and lo.
constexpr DD kAtanTable[17] = {
    {0x0.0p+0, 0x0.0p+0},
    {0x1.ff55bb72cfdeap-5, -0x1.c934d86d23f1dp-60},
    {0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59},
    {0x1.7b97b4bce5b02p-3, 0x1.347b0b4f881cap-58},
    {0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
    {0x1.362773707ebccp-2, -0x1.963a544b672d8p-57},
    {0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56},
    {0x1.a64eec3cc23fdp-2, -0x1.24dec1b50b7ffp-56},
    {0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
    {0x1.0657e94db30d0p-1, -0x1.d5b495f6349e6p-56},
    {0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58},
    {0x1.345f01cce37bbp-1, 0x1.1021137c71102p-55},
    {0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
    {0x1.5d58987169b18p-1, 0x1.0028e4bc5e7cap-57},
    {0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56},
    {0x1.819d0b7158a4dp-1, -0x1.bf76229d3b917p-56},
    {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55},
};

// atan(t) for t = th + tl in [0, 1], in double-double: with c = i/16 the
// nearest sixteenth, atan t = atan c + atan u, u = (t - c) / (1 + t c),
// |u| <= 1/32, and atan u = u - u^3/3 + ... - u^15/15 + ... (the terms
// after u^13/13 are below 2^-70 u).
DD atan_dd(double th, double tl) {
  const int i = static_cast<int>(th * 16.0 + 0.5);
  const double c = static_cast<double>(i) * 0.0625;
  const DD n = two_sum(th - c, tl);  // th - c is exact (Sterbenz)
  const DD tc = two_prod(th, c);
  DD d = two_sum(1.0, tc.hi);
  d.lo += tc.lo + tl * c;
  // u = n / d in double-double.
  const double uh = n.hi / d.hi;
  const DD e = two_prod(uh, d.hi);
  const double ul = (((n.hi - e.hi) - e.lo) + n.lo - uh * d.lo) / d.hi;
  const double z = uh * uh;
  double p = 0x1.3b13b13b13b14p-4;   // 1/13
  p = p * z - 0x1.745d1745d1746p-4;  // -1/11
  p = p * z + 0x1.c71c71c71c71cp-4;  // 1/9
  p = p * z - 0x1.2492492492492p-3;  // -1/7
  p = p * z + 0x1.999999999999ap-3;  // 1/5
  p = p * z - 0x1.5555555555555p-2;  // -1/3
  const double tail = ul + (uh * z) * p;
  const DD& a = kAtanTable[i];
  const DD s = two_sum(a.hi, uh);
  return two_sum(s.hi, s.lo + (a.lo + tail));
}

// --- exp -------------------------------------------------------------------

// 2^(j/32) for j = 0 ... 31, hi and lo.
constexpr DD kExp2Table[32] = {
    {0x1.0000000000000p+0, 0x0.0p+0},
    {0x1.059b0d3158574p+0, 0x1.d73e2a475b465p-55},
    {0x1.0b5586cf9890fp+0, 0x1.8a62e4adc610bp-54},
    {0x1.11301d0125b51p+0, -0x1.6c51039449b3ap-54},
    {0x1.172b83c7d517bp+0, -0x1.19041b9d78a76p-55},
    {0x1.1d4873168b9aap+0, 0x1.e016e00a2643cp-54},
    {0x1.2387a6e756238p+0, 0x1.9b07eb6c70573p-54},
    {0x1.29e9df51fdee1p+0, 0x1.612e8afad1255p-55},
    {0x1.306fe0a31b715p+0, 0x1.6f46ad23182e4p-55},
    {0x1.371a7373aa9cbp+0, -0x1.63aeabf42eae2p-54},
    {0x1.3dea64c123422p+0, 0x1.ada0911f09ebcp-55},
    {0x1.44e086061892dp+0, 0x1.89b7a04ef80d0p-59},
    {0x1.4bfdad5362a27p+0, 0x1.d4397afec42e2p-56},
    {0x1.5342b569d4f82p+0, -0x1.07abe1db13cadp-55},
    {0x1.5ab07dd485429p+0, 0x1.6324c054647adp-54},
    {0x1.6247eb03a5585p+0, -0x1.383c17e40b497p-54},
    {0x1.6a09e667f3bcdp+0, -0x1.bdd3413b26456p-54},
    {0x1.71f75e8ec5f74p+0, -0x1.16e4786887a99p-55},
    {0x1.7a11473eb0187p+0, -0x1.41577ee04992fp-55},
    {0x1.82589994cce13p+0, -0x1.d4c1dd41532d8p-54},
    {0x1.8ace5422aa0dbp+0, 0x1.6e9f156864b27p-54},
    {0x1.93737b0cdc5e5p+0, -0x1.75fc781b57ebcp-57},
    {0x1.9c49182a3f090p+0, 0x1.c7c46b071f2bep-56},
    {0x1.a5503b23e255dp+0, -0x1.d2f6edb8d41e1p-54},
    {0x1.ae89f995ad3adp+0, 0x1.7a1cd345dcc81p-54},
    {0x1.b7f76f2fb5e47p+0, -0x1.5584f7e54ac3bp-56},
    {0x1.c199bdd85529cp+0, 0x1.11065895048ddp-55},
    {0x1.cb720dcef9069p+0, 0x1.503cbd1e949dbp-56},
    {0x1.d5818dcfba487p+0, 0x1.2ed02d75b3707p-55},
    {0x1.dfc97337b9b5fp+0, -0x1.1a5cd4f184b5cp-54},
    {0x1.ea4afa2a490dap+0, -0x1.e9c23179c2893p-54},
    {0x1.f50765b6e4540p+0, 0x1.9d3e12dd8a18bp-54},
};

constexpr double kInvLn2O32 = 0x1.71547652b82fep+5;  // 32/ln 2
// ln2/32 = kLn2O32A + kLn2O32B + kLn2O32C; A has 37 bits, so n A is exact
// for |n| < 2^16.
constexpr double kLn2O32A = 0x1.62e42fefa0000p-6;
constexpr double kLn2O32B = 0x1.cf79abc9e3b3ap-45;
constexpr double kLn2O32C = -0x1.ff0342542fc33p-99;

// e^(ah + al) for |al| <= ulp(ah) (al is a correction, it may be 0).
double exp_dd(double ah, double al) {
  if (ah != ah) return kNaN;
  if (ah > 709.79) return kInf;  // e^709.79 > DBL_MAX (and +inf)
  if (ah < -745.14) return 0.0;  // below half the least subnormal (and -inf)
  // ah = n ln2/32 + r, n = 32 k + j.
  const double nd = std::floor(ah * kInvLn2O32 + 0.5);
  const int n = static_cast<int>(nd);
  const int j = n & 31;
  const int k = (n - j) / 32;
  const DD t = two_sum(ah, -nd * kLn2O32A);
  const DD u = two_sum(t.hi, -nd * kLn2O32B);
  const DD r = two_sum(u.hi, ((u.lo + t.lo) + al) - nd * kLn2O32C);
  // e^r - 1 for |r| <= ln2/64 (a hair more): r + r^2 P(r), P the Taylor
  // polynomial 1/2! + r/3! + ... + r^5/7! (the rest is below 2^-66).
  const double rh = r.hi;
  double p = 0x1.a01a01a01a01ap-13;   // 1/7!
  p = p * rh + 0x1.6c16c16c16c17p-10;  // 1/6!
  p = p * rh + 0x1.1111111111111p-7;   // 1/5!
  p = p * rh + 0x1.5555555555555p-5;   // 1/4!
  p = p * rh + 0x1.5555555555555p-3;   // 1/3!
  p = p * rh + 0.5;
  const double s = rh + (r.lo + (rh * rh) * p);
  const DD& T = kExp2Table[j];
  const double v = T.hi + (T.lo + T.hi * s);
  return std::ldexp(v, k);
}

// --- log -------------------------------------------------------------------

// For i = 45 ... 91: the double nearest 64/i, and -log of that double.
struct LogEntry {
  double inv_c, log_hi, log_lo;
};
constexpr LogEntry kLogTable[47] = {
    {0x1.6c16c16c16c17p+0, -0x1.68ac83e9c6a15p-2, 0x1.acd8a9145ff44p-57},   // 45/64
    {0x1.642c8590b2164p+0, -0x1.522ae0738a3d7p-2, -0x1.3840b263acb43p-56},  // 46/64
    {0x1.5c9882b931057p+0, -0x1.3c25277333183p-2, -0x1.152d81af5713ap-56},  // 47/64
    {0x1.5555555555555p+0, -0x1.269621134db91p-2, -0x1.e0efadd9db02ap-56},  // 48/64
    {0x1.4e5e0a72f0539p+0, -0x1.1178e8227e47ap-2, -0x1.b8ce2d07f1cb7p-56},  // 49/64
    {0x1.47ae147ae147bp+0, -0x1.f991c6cb3b37ap-3, -0x1.ecca0cdf30143p-58},  // 50/64
    {0x1.4141414141414p+0, -0x1.d1037f2655e7bp-3, 0x1.3f3adb7b71cbcp-58},   // 51/64
    {0x1.3b13b13b13b14p+0, -0x1.a93ed3c8ad9e5p-3, -0x1.bcafa9de97202p-57},  // 52/64
    {0x1.3521cfb2b78c1p+0, -0x1.823c16551a3c0p-3, -0x1.6dcd318f4187ep-57},  // 53/64
    {0x1.2f684bda12f68p+0, -0x1.5bf406b543db0p-3, 0x1.1f5b44c0df7f7p-61},   // 54/64
    {0x1.29e4129e4129ep+0, -0x1.365fcb0159014p-3, -0x1.bea08d2dca256p-57},  // 55/64
    {0x1.2492492492492p+0, -0x1.1178e8227e47ap-3, 0x1.0e63a5f01c693p-58},   // 56/64
    {0x1.1f7047dc11f70p+0, -0x1.da7276384469ep-4, -0x1.401fa71733017p-58},  // 57/64
    {0x1.1a7b9611a7b96p+0, -0x1.9335e5d594988p-4, 0x1.478a85704ccb7p-58},   // 58/64
    {0x1.15b1e5f75270dp+0, -0x1.4d3115d207eacp-4, -0x1.da7d0b1e10b2fp-60},  // 59/64
    {0x1.1111111111111p+0, -0x1.08598b59e3a06p-4, 0x1.dd7009902bf32p-58},   // 60/64
    {0x1.0c9714fbcda3bp+0, -0x1.894aa149fb34bp-5, 0x1.2ba0b44cfaee5p-59},   // 61/64
    {0x1.0842108421084p+0, -0x1.0415d89e74440p-5, -0x1.c05cf1d753621p-59},  // 62/64
    {0x1.0410410410410p+0, -0x1.0205658935837p-6, -0x1.27c8e8416e717p-60},  // 63/64
    {0x1.0000000000000p+0, 0x0.0p+0, 0x0.0p+0},                             // 64/64
    {0x1.f81f81f81f820p-1, 0x1.fc0a8b0fc03c4p-7, -0x1.83092c5964281p-62},   // 65/64
    {0x1.f07c1f07c1f08p-1, 0x1.f829b0e7832f8p-6, 0x1.33e3f04f1ef25p-60},    // 66/64
    {0x1.e9131abf0b767p-1, 0x1.77458f632dcffp-5, 0x1.8d3ca87b92968p-63},    // 67/64
    {0x1.e1e1e1e1e1e1ep-1, 0x1.f0a30c01162a8p-5, 0x1.85f325c5bbacdp-59},    // 68/64
    {0x1.dae6076b981dbp-1, 0x1.341d7961bd1d0p-4, -0x1.3599f227becbbp-58},   // 69/64
    {0x1.d41d41d41d41dp-1, 0x1.6f0d28ae56b4ep-4, -0x1.20db323097324p-59},   // 70/64
    {0x1.cd85689039b0bp-1, 0x1.a926d3a4ad562p-4, -0x1.d7a16eab1e2adp-59},   // 71/64
    {0x1.c71c71c71c71cp-1, 0x1.e27076e2af2eap-4, -0x1.61578001e015ap-60},   // 72/64
    {0x1.c0e070381c0e0p-1, 0x1.0d77e7cd08e5bp-3, 0x1.9a5dc5e9030adp-57},    // 73/64
    {0x1.bacf914c1bad0p-1, 0x1.29552f81ff521p-3, 0x1.301771c407dc0p-57},    // 74/64
    {0x1.b4e81b4e81b4fp-1, 0x1.44d2b6ccb7d1cp-3, 0x1.7d3d950f87e23p-59},    // 75/64
    {0x1.af286bca1af28p-1, 0x1.5ff3070a793d6p-3, -0x1.bc60efafc6f6cp-58},   // 76/64
    {0x1.a98ef606a63bep-1, 0x1.7ab890210d907p-3, -0x1.1072534a57e7dp-57},   // 77/64
    {0x1.a41a41a41a41ap-1, 0x1.9525a9cf456b6p-3, -0x1.26fb3e2b1d1dap-57},   // 78/64
    {0x1.9ec8e951033d9p-1, 0x1.af3c94e80bff3p-3, 0x1.a3398064df33ep-57},    // 79/64
    {0x1.999999999999ap-1, 0x1.c8ff7c79a9a20p-3, -0x1.4f689f8434011p-57},   // 80/64
    {0x1.948b0fcd6e9e0p-1, 0x1.e27076e2af2e8p-3, -0x1.61578001e015ep-59},   // 81/64
    {0x1.8f9c18f9c18fap-1, 0x1.fb9186d5e3e29p-3, 0x1.355519b0de535p-57},    // 82/64
    {0x1.8acb90f6bf3aap-1, 0x1.0a324e27390e2p-2, 0x1.bdcfde8061c03p-56},    // 83/64
    {0x1.8618618618618p-1, 0x1.1675cababa60fp-2, 0x1.ce63eab883727p-61},    // 84/64
    {0x1.8181818181818p-1, 0x1.22941fbcf7966p-2, -0x1.dbd7ac258a2bdp-58},   // 85/64
    {0x1.7d05f417d05f4p-1, 0x1.2e8e2bae11d31p-2, -0x1.1e99b72bd7bf2p-57},   // 86/64
    {0x1.78a4c8178a4c8p-1, 0x1.3a64c556945eap-2, 0x1.cbcd735d03424p-60},    // 87/64
    {0x1.745d1745d1746p-1, 0x1.4618bc21c5ec2p-2, -0x1.7a42642661c62p-61},   // 88/64
    {0x1.702e05c0b8170p-1, 0x1.51aad872df82ep-2, -0x1.d8db0a7cc1543p-56},   // 89/64
    {0x1.6c16c16c16c17p-1, 0x1.5d1bdbf5809cap-2, -0x1.7dc9c7c23801fp-56},   // 90/64
    {0x1.6816816816817p-1, 0x1.686c81e9b14adp-2, 0x1.710af840538e3p-56},    // 91/64
};

// ln 2 = kLn2A + kLn2B; A has 42 bits, so e A is exact for |e| < 2^11.
constexpr double kLn2A = 0x1.62e42fefa3800p-1;
constexpr double kLn2B = 0x1.ef35793c76730p-45;
constexpr double kSqrtHalf = 0x1.6a09e667f3bcdp-1;

// log x for x > 0 finite, in double-double (relative error below 2^-65).
// x = 2^e m with m in [sqrt(1/2), sqrt(2)), i the nearest integer to 64 m,
// c = 64/i rounded: log x = e ln2 - log c + log1p(r) with r = m c - 1
// (exact in double-double by Dekker's product), |r| < 0.0112, and
// log1p(r) = r - r^2/2 + r^3/3 - ... - r^12/12 (the rest is below 2^-80 r).
DD log_dd(double x) {
  int e = 0;
  double m = std::frexp(x, &e);  // exact, subnormals included
  if (m < kSqrtHalf) {
    m *= 2.0;
    --e;
  }
  const int i = static_cast<int>(m * 64.0 + 0.5);
  const LogEntry& c = kLogTable[i - 45];
  const DD pm = two_prod(m, c.inv_c);
  const DD r = two_sum(pm.hi - 1.0, pm.lo);  // pm.hi - 1 is exact (Sterbenz)
  const double rh = r.hi;
  const DD r2 = two_prod(rh, rh);
  double p = -0x1.5555555555555p-4;   // -1/12
  p = p * rh + 0x1.745d1745d1746p-4;  // 1/11
  p = p * rh - 0x1.999999999999ap-4;  // -1/10
  p = p * rh + 0x1.c71c71c71c71cp-4;  // 1/9
  p = p * rh - 0x1.0000000000000p-3;  // -1/8
  p = p * rh + 0x1.2492492492492p-3;  // 1/7
  p = p * rh - 0x1.5555555555555p-3;  // -1/6
  p = p * rh + 0x1.999999999999ap-3;  // 1/5
  p = p * rh - 0x1.0000000000000p-2;  // -1/4
  p = p * rh + 0x1.5555555555555p-2;  // 1/3
  const double small = (r.lo - rh * r.lo) - 0.5 * r2.lo + (rh * r2.hi) * p;
  const double de = static_cast<double>(e);
  const DD s1 = two_sum(de * kLn2A, c.log_hi);
  const DD s2 = two_sum(s1.hi, rh);
  const DD s3 = two_sum(s2.hi, -0.5 * r2.hi);
  const double lo = ((s1.lo + s2.lo) + s3.lo) + ((de * kLn2B + c.log_lo) + small);
  return two_sum(s3.hi, lo);
}

// --- erf -------------------------------------------------------------------

// For x0 = i/4, i = 0 ... 24: erf(x0) and its derivative 2/sqrt(pi) e^(-x0^2).
struct ErfNode {
  DD value, slope;
};
constexpr ErfNode kErfTable[25] = {
    {{0x0.0p+0, 0x0.0p+0},  // 0
     {0x1.20dd750429b6dp+0, 0x1.1ae3a914fed80p-56}},
    {{0x1.1af54e232d609p-2, -0x1.bee921fa4172bp-56},  // 0.25
     {0x1.0f5d1602f7e41p+0, -0x1.3e41778d4b1eep-55}},
    {{0x1.0a7ef5c18edd2p-1, 0x1.5e809f1a31a28p-56},  // 0.5
     {0x1.c1efca49a5011p-1, 0x1.4c081d7f49500p-55}},
    {{0x1.6c1c9759d0e5fp-1, 0x1.b1432f2cbc455p-55},  // 0.75
     {0x1.492e42d78d2c5p-1, -0x1.8bd386a7ba3f6p-55}},
    {{0x1.af767a741088bp-1, -0x1.c97f778122797p-56},  // 1
     {0x1.a911f096fbc26p-2, -0x1.086a09f735b33p-56}},
    {{0x1.d8865d98abe01p-1, -0x1.fcec4afb974d9p-55},  // 1.25
     {0x1.e4652fadcb6b2p-3, -0x1.e950836901024p-61}},
    {{0x1.eea5557137ae0p-1, -0x1.385e445f2c96dp-55},  // 1.5
     {0x1.e723726b824a9p-4, -0x1.2203197eea764p-59}},
    {{0x1.f92d077f8d56dp-1, 0x1.8b55ef493fce7p-56},  // 1.75
     {0x1.b055303221015p-5, 0x1.cba9ea60ed019p-59}},
    {{0x1.fd9ae142795e3p-1, 0x1.972801904b9a3p-56},  // 2
     {0x1.529b9e8cf9a1ep-6, 0x1.b47becf12c4e4p-61}},
    {{0x1.ff404760319b4p-1, 0x1.f142071432025p-56},  // 2.25
     {0x1.d4143a9dfe965p-8, -0x1.6eec3c35c7ed7p-63}},
    {{0x1.ffcaa8f4c9beap-1, 0x1.b0cee160116f9p-55},  // 2.5
     {0x1.1d83170fbf6fbp-9, 0x1.ea3671efbb74ap-63}},
    {{0x1.fff2cfb0453d9p-1, 0x1.9a913686042a3p-55},  // 2.75
     {0x1.3360ccd23db3ap-11, 0x1.39e15444e9dddp-69}},
    {{0x1.fffd1ac4135f9p-1, 0x1.eeafa1ecd6cefp-55},  // 3
     {0x1.2408e9ba3327fp-13, -0x1.7e1d81587040cp-67}},
    {{0x1.ffff6f9f67e55p-1, 0x1.e1e4483ba034bp-55},  // 3.25
     {0x1.e9b5e8d00ce77p-16, -0x1.cbbe2ecd1cfacp-70}},
    {{0x1.ffffe710d565ep-1, 0x1.c9ea52d76dc04p-55},  // 3.5
     {0x1.6a597219a93dap-18, -0x1.cbf8fbc2cd5cdp-72}},
    {{0x1.fffffc2f171e3p-1, 0x1.85edd0395f475p-55},  // 3.75
     {0x1.d9371e2ff7c35p-21, 0x1.0aed0951e078dp-75}},
    {{0x1.ffffff7b91176p-1, 0x1.0b2865615db40p-56},  // 4
     {0x1.10b1488aeb235p-23, -0x1.cd75b4828c0c0p-81}},
    {{0x1.fffffff01a8b6p-1, 0x1.23370eca5ca6ap-60},  // 4.25
     {0x1.155a09065d4f7p-26, -0x1.7c5d6c7140f80p-81}},
    {{0x1.fffffffe4fa30p-1, 0x1.d166bcb681c7bp-57},  // 4.5
     {0x1.f1e3523b41d7dp-30, -0x1.7303536c50b37p-84}},
    {{0x1.ffffffffd759dp-1, 0x1.f7bee7eb23420p-55},  // 4.75
     {0x1.8a61745ec7d1dp-33, 0x1.9d509f787b50ep-88}},
    {{0x1.fffffffffc9e8p-1, -0x1.a759f7738935fp-56},  // 5
     {0x1.13af4f04f9998p-36, -0x1.0532e647cd418p-90}},
    {{0x1.ffffffffffc05p-1, 0x1.07ba96a6b2e1ap-55},  // 5.25
     {0x1.5422ef5d8949dp-40, 0x1.ff62258857350p-96}},
    {{0x1.fffffffffffbep-1, -0x1.182b326b228dcp-55},  // 5.5
     {0x1.7258610b3b233p-44, -0x1.60bc7761ca394p-101}},
    {{0x1.ffffffffffffcp-1, 0x1.8115fd1b12786p-56},  // 5.75
     {0x1.63daf8b4b1e0cp-48, 0x1.f38800a69fe98p-105}},
    {{0x1.0000000000000p+0, -0x1.8cf81557d20b6p-56},  // 6
     {0x1.2dc119095729fp-52, -0x1.1566d13fe4564p-106}},
};

bool is_integer(double y) { return std::floor(y) == y; }
bool is_odd_integer(double y) {
  if (!is_integer(y)) return false;
  const double h = 0.5 * y;
  return std::floor(h) != h;
}

}  // namespace

double sin(double x) {
  if (x == 0.0) return x;  // +-0
  if (!(std::fabs(x) < kInf)) return kNaN;  // +-inf and NaN
  const double v = sin_of(reduce_signless(std::fabs(x)));
  return x < 0.0 ? -v : v;
}

double cos(double x) {
  if (!(std::fabs(x) < kInf)) return kNaN;
  return cos_of(reduce_signless(std::fabs(x)));
}

void sincos(double x, double& s, double& c) {
  if (x == 0.0) {
    s = x;
    c = 1.0;
    return;
  }
  if (!(std::fabs(x) < kInf)) {
    s = c = kNaN;
    return;
  }
  const Reduced r = reduce_signless(std::fabs(x));
  const double v = sin_of(r);
  s = x < 0.0 ? -v : v;
  c = cos_of(r);
}

double atan2(double y, double x) {
  if (x != x || y != y) return kNaN;
  const bool neg_y = std::signbit(y);
  const double pi_sign = neg_y ? -kPi.hi : kPi.hi;
  const double pio2_sign = neg_y ? -kPiO2.hi : kPiO2.hi;
  const double ay = std::fabs(y);
  const double ax = std::fabs(x);
  if (ay == 0.0) return std::signbit(x) ? pi_sign : y;
  if (ax == 0.0) return pio2_sign;
  if (ay == kInf) {
    if (ax == kInf) return neg_y ? (x < 0.0 ? -k3PiO4 : -kPiO4) : (x < 0.0 ? k3PiO4 : kPiO4);
    return pio2_sign;
  }
  if (ax == kInf) return x < 0.0 ? pi_sign : (neg_y ? -0.0 : 0.0);
  // t = min/max in [0, 1], in double-double; the ratio depends only on the
  // operands' quotient, so both are scaled to put the larger in [1/2, 1).
  const bool swap = ay > ax;
  double num = swap ? ax : ay;
  double den = swap ? ay : ax;
  int e = 0;
  den = std::frexp(den, &e);
  num = std::ldexp(num, -e);
  const double th = num / den;
  const DD pq = two_prod(th, den);
  const double tl = ((num - pq.hi) - pq.lo) / den;
  DD a = atan_dd(th, tl);
  if (swap) {  // pi/2 - a
    const DD s = two_sum(kPiO2.hi, -a.hi);
    a = two_sum(s.hi, s.lo + (kPiO2.lo - a.lo));
  }
  if (x < 0.0) {  // pi - a
    const DD s = two_sum(kPi.hi, -a.hi);
    a = two_sum(s.hi, s.lo + (kPi.lo - a.lo));
  }
  return neg_y ? -a.hi : a.hi;
}

double exp(double x) { return exp_dd(x, 0.0); }

double log(double x) {
  if (x != x || x < 0.0) return kNaN;
  if (x == 0.0) return -kInf;
  if (x == kInf) return x;
  return log_dd(x).hi;
}

double pow(double x, double y) {
  if (y == 0.0 || x == 1.0) return 1.0;
  if (x != x || y != y) return kNaN;
  const double ax = std::fabs(x);
  if (std::fabs(y) == kInf) {
    if (ax == 1.0) return 1.0;  // x = -1
    return (ax < 1.0) == (y > 0.0) ? 0.0 : kInf;
  }
  const bool odd = is_odd_integer(y);
  const bool negative = x < 0.0 || (x == 0.0 && std::signbit(x));
  if (x < 0.0 && !is_integer(y)) return kNaN;
  const double sign = negative && odd ? -1.0 : 1.0;
  if (ax == 0.0) return sign * (y > 0.0 ? 0.0 : kInf);
  if (ax == kInf) return sign * (y > 0.0 ? kInf : 0.0);
  // |x|^y = e^(y log|x|), the product in double-double.
  const DD l = log_dd(ax);
  const double ph = y * l.hi;
  if (!(std::fabs(ph) < 1000.0)) return sign * (ph > 0.0 ? kInf : 0.0);
  const DD p = two_prod(y, l.hi);
  return sign * exp_dd(p.hi, p.lo + y * l.lo);
}

double erf(double x) {
  if (x != x) return kNaN;
  if (x == 0.0) return x;  // +-0
  const double ax = std::fabs(x);
  double v = 1.0;          // 1 - erfc(6) rounds to 1 (erfc(6) < 2.2e-17)
  if (ax < 6.0) {
    // Taylor's series about the nearest node x0 = i/4, |h| <= 1/8: with
    // B = 2/sqrt(pi) e^(-x0^2) and H_k the Hermite polynomials,
    //   erf(x0 + h) = erf x0 + B sum_{n>=1} (-1)^(n-1) H_{n-1}(x0) h^n / n!
    //               = erf x0 + B h (1 + sum_{n>=2} (-1)^(n-1) g_{n-1} / n),
    // g_k = H_k(x0) h^k / k!, so that g_0 = 1, g_1 = 2 x0 h and
    // g_{k+1} = (2 x0 h g_k - 2 h^2 g_{k-1}) / (k + 1). Once two
    // consecutive g are below 2^-60 all later ones are (|2 x0 h| <= 1.5,
    // 2 h^2 <= 1/32), and the sum stops.
    const int i = static_cast<int>(ax * 4.0 + 0.5);
    const ErfNode& node = kErfTable[i];
    const double h = ax - 0.25 * static_cast<double>(i);  // exact
    const double a = (0.5 * static_cast<double>(i)) * h;  // 2 x0 h
    const double b = 2.0 * h * h;
    double g0 = 1.0;
    double g1 = a;
    double sum = -0.5 * g1;  // n = 2
    for (int k = 1; k < 40; ++k) {
      const double g2 = (a * g1 - b * g0) / static_cast<double>(k + 1);
      const double term = g2 / static_cast<double>(k + 2);
      sum = (k % 2 == 1) ? sum + term : sum - term;  // (-1)^(n-1), n = k + 2
      if (std::fabs(g1) < 0x1p-60 && std::fabs(g2) < 0x1p-60) break;
      g0 = g1;
      g1 = g2;
    }
    const DD bh = two_prod(node.slope.hi, h);
    const DD s = two_sum(node.value.hi, bh.hi);
    v = s.hi + (s.lo + ((node.value.lo + bh.lo) + (node.slope.lo * h + bh.hi * sum)));
  }
  return x < 0.0 ? -v : v;
}

}  // namespace breakshot::dm
