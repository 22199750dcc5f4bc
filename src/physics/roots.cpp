// Root finders for event times.
//
// first_contact finds the earliest collision of a contact function
// f(t) = sum c[k] t^k (degree <= 4, positive apart, negative overlapping).
// The method, in short:
//   1. The roots of f'' (a quadratic, closed form) cut [0, T] into pieces
//      on which f' is monotone, so each piece holds at most one root of f'.
//   2. Those roots (found by the bracketed solver below) are the critical
//      points of f; they cut [0, T] into pieces on which f is monotone.
//   3. Walking the pieces of f from t = 0: an increasing piece is skipped
//      (an opening overlap is never a contact); a decreasing piece [ta, tb]
//      is a contact at ta if f(ta) <= 0, and holds the contact root if
//      f(ta) > 0 >= f(tb), found by the same bracketed solver.
//   4. The bracketed solver starts from a second-order Taylor model at a
//      bracket end, iterates Halley's method (third order; f'' comes for
//      free with Horner), and falls back on halving the bracket, alternately
//      by value and by bit pattern (so that any bracket of doubles closes in
//      at most 128 fallback steps). It runs until the bracket is two
//      adjacent doubles and returns the first double at which f <= 0: the
//      contact time is at or just after the exact root (within one ulp),
//      never before it, so the balls touch or overlap by round-off there.
//   5. Every sign that decides an outcome (f at piece ends, f' at piece
//      ends, f at the solver's probes) is exact in practice: when Horner's
//      result is within its rounding-error bound of zero we re-evaluate
//      with compensated Horner (error-free transformations), which is as
//      accurate as evaluating in twice the working precision. So grazing
//      contacts are found however shallow the dip, down to dips of about
//      1e-30 relative to the size of the terms, and near-double roots are
//      located to the last bit. No absolute tolerance on f is used
//      anywhere, so the results do not depend on the scale of f (scaling
//      f by a power of two gives bit-identical results).
//   6. Fast paths (below, "Fast paths with certificates") come first and
//      settle almost every call with a cheap proof instead: no contact
//      (f clear of zero, or rising, over the window, from the Bernstein
//      form of f), or the contact at a given double x (f > 0 up to the
//      double before x, f < 0 at x, both by a margin). The answer they
//      prove is the one steps 1-5 give, bit for bit; whatever they cannot
//      prove (grazing contacts, near-double roots, ...) goes to steps 1-5.
//
// Everything is on the stack and the polynomial degree is a template
// parameter, so the loops unroll; this runs about 30 times per event.
#include "physics/roots.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "physics/detmath.hpp"
#include "physics/error_free.hpp"

namespace breakshot {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kUnit = 0x1p-53;  // unit roundoff of double
// Bound factor for the rounding error of Horner's rule (value and first
// derivative) at degree <= 4: gamma_8 ~ 8u, with a safety factor of 4.
constexpr double kGamma = 32.0 * kUnit;
// The solver needs at most 64 halvings of the bit pattern (every other
// fallback step) plus a few Newton steps; this cap only guards against
// pathological input.
constexpr int kMaxIter = 200;

// --- Error-free transformations (src/physics/error_free.hpp).

using eft::Pair;
using eft::split;
using eft::two_prod;
using eft::two_sum;

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

  // Only f, for the fast paths (f' is not needed there).
  struct ValuesOnly {};
  Poly(const double* c, ValuesOnly) : d{}, dl{} {
    for (int k = 0; k <= N; ++k) p[k] = c[k];
  }

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
double first_contact_n(const Poly<N>& P, const double* c, double t_max) {
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

// --- Fast paths with certificates.
//
// The method above is exact but it always locates every critical point
// and runs its bracketed solver to the last bit. Most calls have an
// answer that can be proven much more cheaply, and since its result is a
// function of f alone wherever its sign decisions are right (they are,
// wherever |f| is above its evaluation error, ~1e-30 relative), a proof
// of the same answer gives the same double:
// - no contact: f > 0 on [0, T] by a margin far above every evaluation
//   error (so every probe of the method above would see f > 0 too), or f
//   increasing on [0, T] likewise (no decreasing piece at all);
// - contact at x: f > 0 on [0, x-] and f(x) < 0 (x- is the double before
//   x), both by the margin kMargin, which also dwarfs how far f can move
//   against the direction the method above assigns to a monotone piece
//   (~u^2 relative, where f' is within its rounding error of zero). Then
//   that method returns x: it returns only doubles at which f <= 0, so
//   none before x; x lies in a piece it takes as decreasing, with f <= 0
//   at its end, and every double of that piece has f > 0 up to x- and
//   f < 0 from x on, so its bracket closes on (x-, x). (This needs the
//   method above to be as exact as it claims, which it is unless products
//   of the coefficients under- or overflow: see all_tame.)
// The proofs use the Bernstein form of f on [0, T] and on halves of it
// (de Casteljau): its coefficients bound f, their differences bound f'
// and their second differences f'', with rounding errors bounded
// rigorously in units of Q = sum |c_k| T^k. f > 0 up to x- follows from
// the spans before x's being clear of zero and from the shape of f on
// x's span: decreasing, rising then falling, or convex with f'(x) < 0.
// Near the root, f is evaluated with compensated Horner and the values
// at neighbouring doubles follow from Taylor bounds. Degree 2 has closed
// forms instead (fast_quadratic). Whenever a proof fails, the method
// above decides.

// Bound on the rounding error of any Bernstein coefficient (and so of
// their differences' parts), in units of Q: the conversion costs about
// 13 u and every halving level 4 u (four averages); kMaxDepth levels stay
// far below 2^-44.
constexpr double kErrB = 0x1p-44;
// The margin by which f must clear zero at a contact's end points, in
// units of Q: far above the evaluation errors of the method above (about
// 2^-100 Q) and far below the values of f at the doubles next to a root
// (about 2^-52 |f'| t), so that it rarely stops a proof.
constexpr double kMargin = 0x1p-90;
constexpr int kMaxDepth = 6;
// Slack for underflow in the error bounds of Horner's rule.
constexpr double kTiny = 0x1p-1000;

enum class Verdict { unknown, none, contact };

// Bernstein coefficients of f(T s) on [0, 1] from q_k = c_k T^k.
template <int N>
void to_bernstein(const double* q, double* b) {
  if constexpr (N == 2) {
    b[0] = q[0];
    b[1] = q[0] + 0.5 * q[1];
    b[2] = q[0] + q[1] + q[2];
  } else if constexpr (N == 3) {
    b[0] = q[0];
    b[1] = q[0] + q[1] / 3.0;
    b[2] = q[0] + (2.0 * q[1] + q[2]) / 3.0;
    b[3] = q[0] + q[1] + q[2] + q[3];
  } else {
    b[0] = q[0];
    b[1] = q[0] + 0.25 * q[1];
    b[2] = q[0] + 0.5 * q[1] + q[2] / 6.0;
    b[3] = q[0] + 0.75 * q[1] + 0.5 * q[2] + 0.25 * q[3];
    b[4] = q[0] + q[1] + q[2] + q[3] + q[4];
  }
}

// Halves of a Bernstein polygon (de Casteljau at 1/2).
template <int N>
void split_half(const double* b, double* left, double* right) {
  double w[N + 1];
  for (int i = 0; i <= N; ++i) w[i] = b[i];
  left[0] = w[0];
  right[N] = w[N];
  for (int r = 1; r <= N; ++r) {
    for (int i = 0; i <= N - r; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
    left[r] = w[0];
    right[N - r] = w[N - r];
  }
}

// An upper bound on |f''| / 2 over [0, z]: sum C(k, 2) |c_k| z^(k-2).
template <int N>
double half_f2_bound(const Poly<N>& P, double z) {
  double r = 0.0;
  for (int k = N; k >= 2; --k) r = r * z + 0.5 * static_cast<double>(k * (k - 1)) * std::fabs(P.p[k]);
  return r * (1.0 + 0x1p-40);
}

// In one pass at x >= 0: f(x) by compensated Horner, with an error of
// at most u |f| + gamma_2n^2 sum |c_k| x^k (Graillat et al.; gamma_8^2 <
// 2^-99.9), and f'(x) by Horner with its error bound.
struct Exact {
  double v;      // f(x)
  double ev;     // bound on |v - f(x)| (with slack for underflow)
  double f1;     // f'(x)
  double ef1;    // bound on |f1 - f'(x)|
};

template <int N>
inline Exact exact_sample(const Poly<N>& P, double x) {
  double s = P.p[N], e = 0.0, r1 = 0.0;
  double b0 = std::fabs(P.p[N]), b1 = 0.0;
#pragma GCC unroll 4
  for (int k = N - 1; k >= 0; --k) {
    r1 = r1 * x + s;
    b1 = b1 * x + b0;
    const Pair pr = two_prod(s, x);
    const Pair sm = two_sum(pr.hi, P.p[k]);
    s = sm.hi;
    e = e * x + (pr.lo + sm.lo);
    b0 = b0 * x + std::fabs(P.p[k]);
  }
  const double v = s + e;
  return {v, 0x1p-52 * std::fabs(v) + 0x1p-98 * b0 + kTiny, r1, kGamma * b1 + kTiny};
}

// Plain Horner for f, f', f'', f''' and sum |c_k| x^k (x >= 0), for the
// iterations that only need to get close.
struct Plain {
  double f, f1, f2, f3, fa;
};

template <int N>
inline Plain horner4(const Poly<N>& P, double x) {
  double r0 = P.p[N], r1 = 0.0, r2 = 0.0, r3 = 0.0, a = std::fabs(P.p[N]);
#pragma GCC unroll 4
  for (int k = N - 1; k >= 0; --k) {
    r3 = r3 * x + r2;
    r2 = r2 * x + r1;
    r1 = r1 * x + r0;
    r0 = r0 * x + P.p[k];
    a = a * x + std::fabs(P.p[k]);
  }
  return {r0, r1, 2.0 * r2, 6.0 * r3, a};
}

// The smallest u > 0 with c + b u + a u^2 = 0, or NaN: of the roots
// q / a and c / q, the latter is the smaller in magnitude.
inline double model_root(double c, double b, double a) {
  if (a == 0.0) return -c / b;
  const double disc = b * b - 4.0 * a * c;
  if (!(disc >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  return (c > 0.0) == (q > 0.0) ? c / q : q / a;
}

// Pins down the contact near y: x, the first double with f(x) <= 0,
// proving f(x-) > margin and f(x) < -margin, for x in (0, cap]. It is
// known that f > 0 on [0, y0] for some y0 < x and that f is quasi-concave
// on [y0, cap] (f' changes sign at most once there, from + to -, and
// f(y0) > margin), or, with `convex`, that f is convex on [y0, cap]; then
// f' < 0 at x is checked here, so that f decreases on [y0, x]. Either way
// f >= min(f(y0), f(x-)) on [y0, x-], so f > 0 up to x- follows.
// Each step evaluates f at y (nearly) exactly and takes Newton's step
// from there, which lands within an ulp of the root when y is within
// ~1e-10 of it; the value of f at the doubles there follows from the
// Taylor expansion at y, with rigorous bounds on every error.
template <int N>
Verdict pin_contact(const Poly<N>& P, double Q, double y, double cap, bool convex, double& out) {
  const double M = kMargin * Q;
  for (int it = 0; it < 6; ++it) {
    if (!(y > 0.0 && y <= cap)) return Verdict::unknown;
    const Exact s = exact_sample<N>(P, y);
    const double v = s.v, ev = s.ev;
    if (!std::isfinite(v) || !(s.f1 < 0.0)) return Verdict::unknown;
    const double f1_hi = s.f1 + s.ef1, f1_lo = s.f1 - s.ef1;
    // f(t) = f(y) + f'(y) d + f''(xi) d^2 / 2 with d = t - y.
    const double up = next_up(y), down = next_down(y);
    const double h = up - y, hd = y - down;      // hd <= h
    double f2b = half_f2_bound<N>(P, up);        // |f''| / 2 up to y+
    if (v <= 0.0) {
      // Usually y is the contact: f(y-) > 0 (by the margin).
      if (v - ev - f1_hi * hd - f2b * hd * hd > M && v + ev < -M &&
          (!convex || f1_hi < -0x1p-50 * std::fabs(s.f1))) {
        out = y;
        return Verdict::contact;
      }
    } else if (v + ev + f1_hi * h + f2b * h * h < -M && v - ev > M &&
               (!convex || f1_hi + 2.0 * f2b * h < -0x1p-50 * std::fabs(s.f1)) && up <= cap) {
      // Or the double after it.
      out = up;
      return Verdict::contact;
    }
    // Else Newton's step from the (nearly) exact value lands within an
    // ulp of the root if y was within ~1e-10 of it; f there follows from
    // the same expansion at y (the slack covers the bounds' rounding).
    const double z = y - v / s.f1;
    if (!(z > 0.0 && z <= cap) || z == y) return Verdict::unknown;
    f2b = half_f2_bound<N>(P, next_up(next_up(std::max(y, z))));
    const auto bound = [&](double t, bool upper) {
      const double d = t - y;
      const double lin = (d >= 0.0) == upper ? f1_hi * d : f1_lo * d;
      const double quad = f2b * d * d;
      const double slack = 0x1p-50 * (std::fabs(v) + std::fabs(lin) + quad);
      return upper ? v + ev + lin + quad + slack : v - ev + lin - quad - slack;
    };
    for (int k = 0; k < 2; ++k) {
      const double x = k == 0 ? z : next_up(z);
      if (x <= cap && bound(x, true) < -M && bound(next_down(x), false) > M &&
          (!convex || f1_hi + 2.0 * f2b * std::fabs(x - y) < -0x1p-50 * std::fabs(s.f1))) {
        out = x;
        return Verdict::contact;
      }
    }
    y = z;
  }
  return Verdict::unknown;
}

// The contact root in [lo, hi] (f(lo) > 0 > f(hi), lo >= y0 of
// pin_contact): first close in with Halley's method (plain Horner),
// safeguarded by the bracket, then pin it down. Halley starts from the
// quadratic Taylor model at the end where |f| is smaller (free at t = 0),
// else from the secant.
template <int N>
Verdict contact_in(const Poly<N>& P, double Q, double lo, double hi, double flo, double fhi,
                   double cap, bool convex, double& out) {
  double y;
  {
    const bool from_lo = flo <= -fhi;
    const double e = from_lo ? lo : hi;
    double f, f1, f2;
    if (e == 0.0) {
      f = P.p[0];
      f1 = P.p[1];
      f2 = 2.0 * P.p[2];
    } else {
      const Plain h = horner4<N>(P, e);
      f = h.f;
      f1 = h.f1;
      f2 = h.f2;
    }
    const double u = model_root(f, from_lo ? f1 : -f1, 0.5 * f2);
    y = from_lo ? e + u : e - u;
    if (!(y > lo && y < hi)) y = lo + (hi - lo) * (flo / (flo - fhi));
    if (!(y > lo && y < hi)) y = lo + 0.5 * (hi - lo);
  }
  for (int it = 0;; ++it) {
    if (it == 40) return Verdict::unknown;
    const Plain h = horner4<N>(P, y);
    const double f = h.f, f1 = h.f1, f2 = h.f2;
    if (f > 0.0) {
      lo = y;
    } else {
      hi = y;
    }
    const double den = 2.0 * f1 * f1 - f * f2;
    const double step = den > 0.0 ? 2.0 * f * f1 / den : f / f1;
    const double yn = y - step;
    const bool inside = yn > lo && yn < hi;
    // Close enough for the final Newton step: Halley's error after a
    // step is about K step^3 with K = (f'' / 2f')^2 - f''' / 6f'; take the
    // step and stop once that is below ~1e-11 relative. Or as close as
    // plain Horner can tell.
    const double as = std::fabs(step);
    const double k_f1f1 = 0.25 * f2 * f2 + std::fabs(h.f3 * f1) * (1.0 / 6.0);  // >= |K| f'^2
    if (k_f1f1 * (as * as * as) <= 0x1p-36 * y * (f1 * f1) || as <= 0x1p-40 * y ||
        std::fabs(f) <= 0x1p-50 * h.fa) {
      if (inside) y = yn;
      break;
    }
    if (!(next_up(lo) < hi)) break;
    y = inside ? yn : lo + 0.5 * (hi - lo);
  }
  return pin_contact<N>(P, Q, y, cap, convex, out);
}

// Degree 2 directly: f = c0 + c1 t + c2 t^2 is convex or concave, its
// minimum over [0, T] and its first root have closed forms.
Verdict fast_quadratic(const Poly<2>& P, const double* q, double Q, double T, double& out) {
  const double eb = kErrB * Q;
  const double M = kMargin * Q;
  const double c0 = P.p[0], c1 = P.p[1], c2 = P.p[2];
  const double fT = q[0] + q[1] + q[2];  // f(T), error < 3 u Q
  const double dT = q[1] + 2.0 * q[2];   // T f'(T), error < 3 u Q
  if (!(c0 > 0.0)) {
    // Touching or overlapping and opening (c1 > 0): no contact if f rises
    // over the whole window (f' is linear: f'(0) > 0 and f'(T) > 0), or
    // if it is concave and f(T) > 0: then f stays above f(T) from its
    // maximum on, where the only decreasing piece starts.
    if (c1 > 0.0 && (dT > 4.0 * eb || (c2 < 0.0 && fT > 2.0 * eb))) return Verdict::none;
    return Verdict::unknown;
  }
  bool convex = c2 > 0.0;
  if (convex) {
    if (dT < -4.0 * eb) {
      // Decreasing over the whole window: the minimum is f(T).
      if (fT > 2.0 * eb) return Verdict::none;
      if (!(fT < -2.0 * eb)) return Verdict::unknown;
    } else {
      // Below the tangent at T: f(t) >= f(T) + f'(T) (t - T) on [0, T].
      if (fT - std::max(dT, 0.0) > 2.0 * eb) return Verdict::none;
      // The vertex value is -disc / (4 q2) with disc = q1^2 - 4 q0 q2; the
      // rounding error of disc (with that of the q_k) is below 16 u
      // (q1^2 + 4 q0 q2) plus underflow (q2 normal keeps that tiny).
      const double a = q[1] * q[1], b = 4.0 * (q[0] * q[2]);
      const double disc = a - b;
      if (q[2] > 0x1p-1000 && -disc - 0x1p-48 * (a + b) - 0x1p-1060 > 8.0 * q[2] * M) {
        return Verdict::none;
      }
      if (!(disc > 0x1p-48 * (a + b))) return Verdict::unknown;
      if (!(c1 < 0.0)) return Verdict::unknown;
    }
    // The first root is the smaller one (convex, c0 > 0, c1 < 0).
  } else {
    // Concave (c2 < 0): f >= min(f(0), f(t)) on [0, t].
    if (!(c0 > M)) return Verdict::unknown;
    if (fT > 2.0 * eb) return Verdict::none;
    if (!(fT < -2.0 * eb)) return Verdict::unknown;
    // The positive root (c0 > 0 > c2: one root of each sign).
  }
  // The stable closed form, with Kahan's exact discriminant where b^2
  // and 4ac nearly cancel.
  const double bb = c1 * c1;
  const double ac4 = 4.0 * (c0 * c2);
  double disc = bb - ac4;
  if (3.0 * std::fabs(disc) < bb + std::fabs(ac4)) {
    const Pair x = two_prod(c1, c1);
    const Pair z = two_prod(c0, c2);
    disc = (x.hi - 4.0 * z.hi) + (x.lo - 4.0 * z.lo);
  }
  if (!(disc >= 0.0)) return Verdict::unknown;
  const double qq = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  // Roots qq / c2 and c0 / qq. Convex with c1 < 0: qq > 0, both roots
  // positive, the smaller is c0 / qq. Concave: the positive one.
  double y = convex ? c0 / qq : (c1 >= 0.0 ? qq / c2 : c0 / qq);
  if (!(y > 0.0)) return Verdict::unknown;
  y = std::min(y, T);
  return pin_contact<2>(P, Q, y, T, convex, out);
}

template <int N>
struct Span {
  double b[N + 1];  // Bernstein coefficients of f on [T sa, T sb]
  double sa, sb;    // dyadic, so T sa and T sb are exact reals
  int depth;
};

// The first contact of f (c_0 > 0 or c_0 <= 0 <= c_1) on [0, T], if it
// can be proven cheaply; q_k = c_k T^k, Q = sum |q_k|. The spans are
// visited from left to right (depth first, left halves first), so when
// one holds a contact, f > 0 on all of [0, T sa] is already proven.
template <int N>
Verdict fast_contact(const Poly<N>& P, const double* q, double Q, double T, double& out) {
  const double eb = kErrB * Q;  // bounds every coefficient's error
  const double M = kMargin * Q;
  Span<N> cur;
  to_bernstein<N>(q, cur.b);
  {
    // f increasing on the whole window (every difference > 0): no
    // decreasing piece, no contact whatever c_0.
    bool up = true;
#pragma GCC unroll 4
    for (int i = 0; i < N; ++i) up = up && cur.b[i + 1] - cur.b[i] > 4.0 * eb;
    if (up) return Verdict::none;
  }
  if (!(P.p[0] > 0.0)) return Verdict::unknown;
  cur.sa = 0.0;
  cur.sb = 1.0;
  cur.depth = 0;
  Span<N> pending[kMaxDepth];  // right halves still to visit
  int npending = 0;
  for (;;) {
    const double* b = cur.b;
    double bmin = b[0];
#pragma GCC unroll 4
    for (int i = 1; i <= N; ++i) bmin = std::min(bmin, b[i]);
    bool done = bmin > 2.0 * eb;  // f > 0 here
    if (!done) {
      // f at the left end: c_0 itself on the first span.
      const bool left_ok = cur.sa == 0.0 ? P.p[0] > M : b[0] > 2.0 * eb;
      // Signs of the differences (f') and second differences (f'').
      int dneg = 0, epos = 0, eneg = 0;
      bool qconc = true;  // differences + ... + - ... -, all clear
      double d[N];
#pragma GCC unroll 4
      for (int i = 0; i < N; ++i) {
        d[i] = b[i + 1] - b[i];
        if (d[i] > 4.0 * eb) {
          qconc = qconc && dneg == 0;
        } else if (d[i] < -4.0 * eb) {
          ++dneg;
        } else {
          qconc = false;
        }
      }
#pragma GCC unroll 4
      for (int i = 0; i + 1 < N; ++i) {
        const double e = d[i + 1] - d[i];
        epos += e > 8.0 * eb;
        eneg += e < -8.0 * eb;
      }
      const bool convex = epos == N - 1, concave = eneg == N - 1;
      const bool falling = dneg == N;  // f decreasing on the span
      const double ta = T * cur.sa, tb = T * cur.sb;  // rounded ends
      // Any x <= cap has x- < T sb (cap = T on the last span, exact).
      const double cap = cur.sb == 1.0 ? T : tb;
      if (falling || ((qconc || concave) && left_ok)) {
        // Decreasing, or rising then falling: f is above the lower of its
        // end values up to any point.
        if (b[N] < -2.0 * eb) return contact_in<N>(P, Q, ta, tb, b[0], b[N], cap, false, out);
        done = b[N] > 2.0 * eb;
      } else if (convex) {
        // One minimum. Find it (Newton on f'), then either bound f below
        // by the tangent there, or find the contact before it, where
        // f' < 0. The probes stay inside [T sa, T sb].
        const double lo = cur.sa == 0.0 ? 0.0 : next_up(ta);
        const double hi = cur.sb == 1.0 ? T : next_down(tb);
        if (!(lo < hi)) return Verdict::unknown;
        const double w = (hi - lo) * (1.0 + 0x1p-40) + 0x1p-50 * T;  // >= any distance inside
        double x = lo + (hi - lo) * (d[0] / (d[0] - d[N - 1]));
        if (!(x >= lo && x <= hi)) x = lo + 0.5 * (hi - lo);
        Sample s = sample<N>(P, x);
        double lower = 0.0, upper = 0.0;
        for (int it = 0;; ++it) {
          // f(t) >= f(x) + f'(x) (t - x) (convexity); the slack covers the
          // rounding of this bound.
          const double slope = (std::fabs(s.f1) + s.ef1 + kTiny) * w;
          lower = s.f - (s.ef + kTiny) - slope - 0x1p-50 * (std::fabs(s.f) + slope);
          upper = s.f + s.ef + kTiny;
          if (lower > M || upper < -M || it == 8 || !(s.f2 > 0.0)) break;
          const double xn = std::clamp(x - s.f1 / s.f2, lo, hi);
          if (xn == x) break;
          x = xn;
          s = sample<N>(P, x);
        }
        if (upper < -M) return contact_in<N>(P, Q, ta, x, b[0], s.f, std::min(cap, x), true, out);
        done = lower > M;
      }
    }
    if (done) {
      if (npending == 0) return Verdict::none;
      cur = pending[--npending];
      continue;
    }
    if (cur.depth == kMaxDepth) return Verdict::unknown;
    Span<N>& right = pending[npending++];
    double left[N + 1];
    split_half<N>(cur.b, left, right.b);
    const double mid = 0.5 * (cur.sa + cur.sb);
    right.sa = mid;
    right.sb = cur.sb;
    right.depth = cur.depth + 1;
#pragma GCC unroll 5
    for (int i = 0; i <= N; ++i) cur.b[i] = left[i];
    cur.sb = mid;
    cur.depth += 1;
  }
}

// Exact degree N: the fast paths, else the full method.
// Is |c| zero or in [2^-400, 2^400] (on the bit patterns of |c|, which
// are monotone in the value; NaN and infinity lie above every finite
// value)?
inline bool tame(double c) {
  constexpr std::uint64_t lo = std::bit_cast<std::uint64_t>(0x1p-400);
  constexpr std::uint64_t hi = std::bit_cast<std::uint64_t>(0x1p+400);
  const std::uint64_t a = bits(c) & ~(std::uint64_t{1} << 63);
  return (a == 0) | (a - lo <= hi - lo);
}

template <int N>
bool all_tame(const double* p) {
  bool ok = true;
  for (int k = 0; k <= N; ++k) ok = ok && tame(p[k]);
  return ok;
}

// Exact degree N: the fast paths, else (or if they cannot decide) steps
// 1-5.
template <int N>
double solve_n(const double* p, const double* q, double Q, double T) {
  if constexpr (N >= 2) {
    if (Q > 0.0) {
      const Poly<N> P(p, typename Poly<N>::ValuesOnly{});
      double out = kInf;
      Verdict v;
      if constexpr (N == 2) {
        v = fast_quadratic(P, q, Q, T, out);
      } else {
        v = fast_contact<N>(P, q, Q, T, out);
      }
      if (v == Verdict::none) return kInf;
      if (v == Verdict::contact) {
        // A proven contact is also the answer of steps 1-5 if they are as
        // exact as they claim. That holds unless products of coefficients
        // under- or overflow (as in solve_quadratic for the roots of f''
        // when the coefficients span more than ~2^500, possible only for
        // absurd time scales): then steps 1-5 decide, as ever. (A proof of
        // no contact needs no such care: wherever steps 1-5 look, f > 0.)
        if (all_tame<N>(p)) return out;
      }
    }
  } else {
    (void)q;
    (void)Q;
  }
  return first_contact_n<N>(Poly<N>(p), p, T);
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
    r = std::max(r, k == 1 ? q / lead : dm::pow(q, 1.0 / k) / dm::pow(lead, 1.0 / k));
  }
  r *= 2.0 * (1.0 + 0x1p-20);
  return std::isfinite(r) ? r : std::numeric_limits<double>::max();
}

// first_contact in general.
double first_contact_any(const double* c, int degree, double t_max) {
  if (c == nullptr || degree < 0 || degree > 4 || !(t_max >= 0.0)) return kInf;
  double p[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  int n = 0;
  for (int k = 0; k <= degree; ++k) {
    if (!std::isfinite(c[k])) return kInf;
    p[k] = c[k];
    if (c[k] != 0.0) n = k;
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
  double q[5] = {0.0, 0.0, 0.0, 0.0, 0.0};  // the terms c_k T^k
  double tk = 1.0;                             // T^n
  const auto measure = [&] {
    tk = 1.0;
    top = std::fabs(p[0]);
    drop = 0.0;
    q[0] = p[0];
    for (int k = 1; k <= n; ++k) {
      tk *= T;
      const double term = p[k] * tk;
      q[k] = term;
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

  // The fast paths' error bounds need the powers of T to be normal
  // numbers (an underflowing T^k times a huge c_k would be far off).
  double Q = 0.0;
  if (tk >= 0x1p-1000) {
    for (int k = 0; k <= n; ++k) Q += std::fabs(q[k]);
  }
  double s = kInf;
  switch (n) {
    case 1: s = solve_n<1>(p, q, Q, T); break;
    case 2: s = solve_n<2>(p, q, Q, T); break;
    case 3: s = solve_n<3>(p, q, Q, T); break;
    default: s = solve_n<4>(p, q, Q, T); break;
  }
  if (m == 0) return s;
  s = std::ldexp(s, m);
  // Apart at t = 0 means a contact strictly later, even if it underflows.
  return apart && s == 0.0 ? std::numeric_limits<double>::denorm_min() : s;
}

// The same for degree exactly N (c[N] != 0) where no rescaling is
// needed, the usual case, with the loops unrolled; it hands everything
// else to first_contact_any, which then gives the same results.
template <int N>
double first_contact_fixed(const double* c, double t_max) {
  double p[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  bool finite = true, falls = false;
#pragma GCC unroll 5
  for (int k = 0; k <= N; ++k) {
    p[k] = c[k];
    finite = finite && std::isfinite(p[k]);
    if (k > 0) falls = falls || p[k] < 0.0;
  }
  if (!finite) return kInf;
  if (p[0] <= 0.0 && p[1] < 0.0) return 0.0;
  if (!falls) return kInf;
  const double T = t_max + 0.0;
  double q[5] = {p[0], 0.0, 0.0, 0.0, 0.0};
  double tk = 1.0, top = std::fabs(p[0]), drop = 0.0;
#pragma GCC unroll 4
  for (int k = 1; k <= N; ++k) {
    tk *= T;
    const double term = p[k] * tk;
    q[k] = term;
    top = std::max(top, std::fabs(term));
    if (term < 0.0) drop -= term;
  }
  if (!(top >= 0x1p-400 && top <= 0x1p+400) || T == 0.0) return first_contact_any(c, N, t_max);
  if (p[0] > drop * (1.0 + 1e-14)) return kInf;
  double Q = 0.0;
  if (tk >= 0x1p-1000) {
#pragma GCC unroll 5
    for (int k = 0; k <= N; ++k) Q += std::fabs(q[k]);
  }
  return solve_n<N>(p, q, Q, T);
}

}  // namespace

double first_contact(const double* c, int degree, double t_max) {
  if (c != nullptr && t_max >= 0.0) {
    if (degree == 4 && c[4] != 0.0) return first_contact_fixed<4>(c, t_max);
    if (degree == 2 && c[2] != 0.0) return first_contact_fixed<2>(c, t_max);
  }
  return first_contact_any(c, degree, t_max);
}

double first_contact_quadratic(double c, double b, double a) {
  if (!(b < 0.0)) return kInf;  // receding, tangent (or NaN)
  if (!std::isfinite(c) || !std::isfinite(b) || !std::isfinite(a)) return kInf;
  if (c <= 0.0) return 0.0;     // overlapping by round-off and closing
  const double bb = b * b;
  const double ac = a * c;
  double disc = bb - ac;
  if (3.0 * std::fabs(disc) < bb + std::fabs(ac)) {
    // b^2 and ac nearly cancel (balls far apart relative to their size,
    // or grazing): Kahan's exact discriminant, so that the grazing
    // decision and the time keep full precision.
    const Pair x = two_prod(b, b);
    const Pair y = two_prod(a, c);
    disc = (x.hi - y.hi) + (x.lo - y.lo);
  }
  if (!(disc >= 0.0)) return kInf;  // the paths miss
  // The smaller root c / q with q = -b + sqrt(disc): both terms positive,
  // so there is no cancellation.
  return c / (std::sqrt(disc) - b);
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

}  // namespace breakshot
