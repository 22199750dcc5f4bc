// Error-free transformations (Knuth's two-sum, Veltkamp's split, Dekker's
// product): the exact result of one floating-point operation as the sum
// of two doubles. The root finders (roots.cpp) and the portable maths
// (detmath.cpp) both build on them. They need strict IEEE evaluation,
// which the build guarantees with -ffp-contract=off; Dekker's product is
// used rather than std::fma because without -mfma (and in wasm) the
// latter is a library call, and this is just as exact.
#pragma once

namespace breakshot::eft {

struct Pair {
  double hi, lo;  // the exact result is hi + lo
};

/// a + b = hi + lo exactly, whatever the magnitudes.
inline Pair two_sum(double a, double b) {
  const double s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  return {s, (a - av) + (b - bv)};
}

/// a = hi + lo with both halves of 26 bits (|a| < 2^995).
inline Pair split(double a) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double hi = c - (c - a);
  return {hi, a - hi};
}

/// a * b = hi + lo exactly, barring under- and overflow.
inline Pair two_prod(double a, double b) {
  const double p = a * b;
  const Pair x = split(a);
  const Pair y = split(b);
  return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}

}  // namespace breakshot::eft
