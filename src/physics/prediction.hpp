// What the searches for a ball's earliest event share (predict*.cpp): the
// ball's motion at the prediction origin, and the rules for keeping the
// best candidate.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "breakshot/vec.hpp"
#include "physics/event_queue.hpp"
#include "physics/motion.hpp"

namespace breakshot::detail {

// A ball's motion at the prediction origin, computed once per prediction.
struct Kinematics {
  Vec2 p, v, a;
  Vec2 box_lo, box_hi;
  double t_end = 0.0;
  double radius = 0.0;
  bool still = true;
  // In flight: height above the resting height, vertical velocity and
  // gravity at the origin (z(s) = z + vz s - g s^2 / 2).
  bool airborne = false;
  double z = 0.0, vz = 0.0, g = 0.0;
};

// Among a ball's candidate events at the same time the order is fixed by
// kind (ball, wall, pocket, stop, cell) and then by index, so the choice
// never depends on the order in which candidates were examined (cells
// list balls in arbitrary order).
inline void consider(Prediction& best, double t, EventKind kind, std::int32_t other,
                     std::uint64_t counter) {
  if (best.kind == EventKind::none || t < best.time ||
      (t == best.time && (kind < best.kind || (kind == best.kind && other < best.other)))) {
    best = {t, kind, other, counter};
  }
}

// The part of a window worth searching: a contact later than the best
// candidate so far can never be taken, so the search stops a little past
// it (the slack covers the rounding of t + tau; anything found beyond the
// best loses in `consider`).
inline double within_best(const Prediction& best, double t, double window) {
  const double left = best.time - t;
  return std::min(window, left + left * 1e-12 + best.time * 1e-15);
}

// Whether a centre at r(s) = dp + dv s + da s^2 / 2 from a point (another
// ball's centre, a corner) provably stays further than sigma from it for
// s in [0, w], with dp longer than sigma: two lower bounds on |r(s)|,
//   - along the line of centres, r(s).u with u = dp / |dp|, a quadratic
//     whose least value on [0, w] is cheap;
//   - across the relative velocity, |r(s).n| with n perpendicular to dv,
//     |dp.n + (da.n) s^2 / 2|, monotone in s (the miss distance of two
//     balls passing by, exact when da is along dv);
// each with a margin (1e-9 of the terms' size) far beyond the rounding of
// the quartic |r(s)|^2 - sigma^2 that the root finder would search. So
// true means the root finder would find no contact: skipping it leaves
// every result as it was, bit for bit.
inline bool stays_apart(Vec2 dp, Vec2 dv, Vec2 da, double len, double sigma, double w) {
  const double a1 = dot(dv, dp) / len;
  const double a2 = 0.5 * dot(da, dp) / len;
  double low = -kInf;  // least value of r(s).u on [0, w]
  if (a1 >= 0.0 && a2 >= 0.0) {
    low = len;  // rising from s = 0
  } else if (w < kInf) {
    low = std::min(len, len + a1 * w + a2 * w * w);
    if (a2 > 0.0 && a1 < 0.0 && -a1 < 2.0 * a2 * w) {
      const double s = -a1 / (2.0 * a2);  // the vertex, inside the window
      low = std::min(low, len + a1 * s + a2 * s * s);
    }
  }
  const double scale = len + (w < kInf ? std::fabs(a1) * w + std::fabs(a2) * w * w : 0.0);
  if (low > sigma + 1e-9 * scale) return true;
  const double vv = norm2(dv);
  if (!(vv > 0.0)) return false;
  const double inv = 1.0 / std::sqrt(vv);
  const Vec2 n{-dv.y * inv, dv.x * inv};
  const double h0 = dot(dp, n);
  const double h2 = 0.5 * dot(da, n);
  const double hw = w < kInf ? h0 + h2 * w * w : (h2 == 0.0 ? h0 : h2 * kInf);
  const double across = (h0 > 0.0 && hw > 0.0) || (h0 < 0.0 && hw < 0.0)
                            ? std::min(std::fabs(h0), std::fabs(hw))
                            : 0.0;
  const double scale2 = len + (w < kInf ? std::fabs(h2) * w * w : 0.0);
  return across > sigma + 1e-9 * scale2;
}

}  // namespace breakshot::detail
