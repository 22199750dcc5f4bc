// Path geometry shared by the computer players (geometry.hpp).
#include "geometry.hpp"

#include <algorithm>

namespace breakshot::ai {

bool segments_cross(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  const double d1 = cross(q1 - q0, p0 - q0);
  const double d2 = cross(q1 - q0, p1 - q0);
  const double d3 = cross(p1 - p0, q0 - p0);
  const double d4 = cross(p1 - p0, q1 - p0);
  return ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
         ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0));
}

double segments_distance(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  if (segments_cross(p0, p1, q0, q1)) return 0.0;
  return std::min({segment_distance(p0, q0, q1), segment_distance(p1, q0, q1),
                   segment_distance(q0, p0, p1), segment_distance(q1, p0, p1)});
}

double wall_distance(const Wall& w, Vec2 a, Vec2 b) {
  switch (w.kind) {
    case WallKind::segment:
      return segments_distance(a, b, w.a, w.b);
    case WallKind::corner:
      return segment_distance(w.a, a, b);
    case WallKind::arc:
      return std::max(segment_distance(w.a, a, b) - w.radius, 0.0);
  }
  return 0.0;
}

}  // namespace breakshot::ai
