// What the searches for a ball's earliest event share (predict*.cpp): the
// ball's motion at the prediction origin, and the rules for keeping the
// best candidate.
#pragma once

#include <algorithm>
#include <cstdint>

#include "breakshot/vec.hpp"
#include "physics/event_queue.hpp"

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

}  // namespace breakshot::detail
