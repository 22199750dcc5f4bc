// Path geometry shared by the computer players (geometry.hpp).
#include "geometry.hpp"

#include <algorithm>
#include <cmath>

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

bool balls_clear(const Layout& lay, double R, Vec2 a, Vec2 b, int skip1, int skip2) {
  for (std::size_t n = 1; n < lay.on.size(); ++n) {
    const int num = static_cast<int>(n);
    if (!lay.on[n] || num == skip1 || num == skip2) continue;
    const Vec2 p = lay.pos[n];
    if (dot(p - a, b - a) <= 0.0 && norm(p - a) >= 2.0 * R) continue;
    if (segment_distance(p, a, b) < 2.0 * R + kBallMargin) return false;
  }
  return true;
}

bool walls_clear(const Table& table, double R, Vec2 a, Vec2 b) {
  for (const Wall& w : table.walls) {
    const double need = std::min({R + kWallMargin, wall_distance(w, a, a), wall_distance(w, b, b)});
    if (wall_distance(w, a, b) < need - 1e-9) return false;
  }
  return true;
}

std::optional<Approach> pocket_approach(const Table& table, double R, const Layout& lay,
                                        Vec2 from, int pocket, int skip1, int skip2) {
  const Pocket& pk = table.pockets[static_cast<std::size_t>(pocket)];
  const double dist = norm(pk.centre - from);
  if (dist <= pk.radius) return std::nullopt;
  const Vec2 toward = (pk.centre - from) / dist;
  const Vec2 across = perp(toward);
  std::optional<Approach> best;
  for (double off : {0.0, 0.4, -0.4}) {
    const Vec2 aim = pk.centre + across * (off * pk.radius);
    const Vec2 d = (aim - from) / norm(aim - from);
    const Vec2 f = from - pk.centre;
    const double half_b = dot(f, d);
    const double disc = half_b * half_b - (norm2(f) - pk.radius * pk.radius);
    if (disc <= 0.0) continue;
    const double s = -half_b - std::sqrt(disc);
    if (s <= 0.0) continue;
    const Vec2 end = from + d * s;
    if (!balls_clear(lay, R, from, end, skip1, skip2)) continue;
    if (!walls_clear(table, R, from, end)) continue;
    // Room: how far the path may shift sideways before it meets the jaws
    // (walls near the pocket only; the rails along the way were checked
    // above).
    double room = kInf;
    for (const Wall& w : table.walls) {
      if (wall_distance(w, pk.centre, pk.centre) > 0.2) continue;
      room = std::min(room, wall_distance(w, from, end) - R);
    }
    room = std::clamp(room, 0.002, 0.04);
    if (!best || room > best->room) best = Approach{aim, d, s, room};
  }
  return best;
}

}  // namespace breakshot::ai
