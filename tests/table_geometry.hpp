// Geometry helpers for the six-pocket table tests (test_pool_table.cpp,
// test_snooker_table.cpp): walls and pockets by name, the lips and jaws of
// a pocket, distances to the walls, and a first contact found by casting
// a ball along a straight line, written independently of the engine's own
// prediction so that the tests check the tables against plain geometry.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/table.hpp"

namespace breakshot::table_geometry {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline const Wall& wall_named(const Table& t, const std::string& name) {
  for (const Wall& w : t.walls) {
    if (w.name == name) return w;
  }
  throw std::runtime_error("no wall " + name);
}

inline const Pocket& pocket_named(const Table& t, const std::string& name) {
  for (const Pocket& p : t.pockets) {
    if (p.name == name) return p;
  }
  throw std::runtime_error("no pocket " + name);
}

inline Vec2 unit(Vec2 v) { return v / norm(v); }

/// Intersection of the lines through the two segments.
inline Vec2 line_meet(const Wall& s1, const Wall& s2) {
  const Vec2 d1 = s1.b - s1.a;
  const Vec2 d2 = s2.b - s2.a;
  const double t = cross(s2.a - s1.a, d2) / cross(d1, d2);
  return s1.a + d1 * t;
}

/// The rail a jaw belongs to.
inline std::string rail_of(const std::string& jaw) {
  if (jaw == "bottom_left_jaw_x" || jaw == "side_bottom_jaw_left") return "rail_bottom_left";
  if (jaw == "bottom_right_jaw_x" || jaw == "side_bottom_jaw_right") return "rail_bottom_right";
  if (jaw == "top_left_jaw_x" || jaw == "side_top_jaw_left") return "rail_top_left";
  if (jaw == "top_right_jaw_x" || jaw == "side_top_jaw_right") return "rail_top_right";
  if (jaw == "bottom_left_jaw_y" || jaw == "top_left_jaw_y") return "rail_left";
  return "rail_right";
}

inline std::vector<std::string> jaws_of(const std::string& pocket) {
  if (pocket.rfind("side", 0) == 0) return {pocket + "_jaw_left", pocket + "_jaw_right"};
  return {pocket + "_jaw_x", pocket + "_jaw_y"};
}

/// The pointed lip: where the nose line meets the facing line.
inline Vec2 lip(const Table& t, const std::string& jaw) {
  return line_meet(wall_named(t, rail_of(jaw)), wall_named(t, jaw));
}

/// Distance from p to an arc wall.
inline double arc_distance(Vec2 p, const Wall& w) {
  const Vec2 d = p - w.a;
  if (cross(w.b, d) >= 0.0 && cross(d, w.normal) >= 0.0) return std::abs(norm(d) - w.radius);
  return std::min(norm(p - (w.a + w.b * w.radius)), norm(p - (w.a + w.normal * w.radius)));
}

/// Distance from p to the nearest wall of any kind.
inline double wall_distance(const Table& t, Vec2 p) {
  double d = kInf;
  for (const Wall& w : t.walls) {
    if (w.kind == WallKind::segment) d = std::min(d, segment_distance(p, w.a, w.b));
    if (w.kind == WallKind::arc) d = std::min(d, arc_distance(p, w));
    if (w.kind == WallKind::corner) d = std::min(d, norm(p - w.a));
  }
  return d;
}

inline bool in_a_pocket(const Table& t, Vec2 p) {
  for (const Pocket& k : t.pockets) {
    if (norm(p - k.centre) < k.radius) return true;
  }
  return false;
}

/// First t >= 0 at which p + t v reaches distance `reach` from c, coming
/// from outside; slightly inside counts as touching now.
inline double circle_entry(Vec2 p, Vec2 v, Vec2 c, double reach) {
  const Vec2 d = p - c;
  const double b = dot(d, v);
  if (b >= 0.0) return kInf;  // not approaching
  const double a = norm2(v);
  const double cc = norm2(d) - reach * reach;
  if (cc < 0.0) return cc > -1e-9 * reach ? 0.0 : kInf;  // inside: not a contact from outside
  const double disc = b * b - a * cc;
  if (disc < 0.0) return kInf;
  return std::max(0.0, (-b - std::sqrt(disc)) / a);
}

struct Hit {
  double t = kInf;
  int wall = -1;    ///< index into walls, or
  int pocket = -1;  ///< index into pockets
  Vec2 normal;      ///< contact normal into the table (walls)
};

/// The first contact of a ball of radius r whose centre moves from p
/// along v: a wall contact as the simulator defines it (a segment only
/// between its ends, an arc only within its directions) or a capture.
inline Hit cast(const Table& t, Vec2 p, Vec2 v, double r) {
  Hit h;
  for (std::size_t i = 0; i < t.walls.size(); ++i) {
    const Wall& w = t.walls[i];
    double tau = kInf;
    Vec2 n;
    if (w.kind == WallKind::segment) {
      const double vn = dot(v, w.normal);
      if (vn >= 0.0) continue;
      const double d0 = dot(p - w.a, w.normal);
      if (d0 < r - 1e-9) continue;  // behind the line
      tau = std::max(0.0, (d0 - r) / -vn);
      const Vec2 q = p + v * tau;
      const double s = dot(q - w.a, w.b - w.a) / norm2(w.b - w.a);
      if (s < 0.0 || s > 1.0) continue;
      n = w.normal;
    } else if (w.kind == WallKind::arc || w.kind == WallKind::corner) {
      const double reach = r + (w.kind == WallKind::arc ? w.radius : 0.0);
      tau = circle_entry(p, v, w.a, reach);
      if (tau == kInf) continue;
      const Vec2 q = p + v * tau - w.a;
      if (w.kind == WallKind::arc && (cross(w.b, q) < 0.0 || cross(q, w.normal) < 0.0)) continue;
      n = unit(q);
    }
    if (tau < h.t) {
      h.t = tau;
      h.wall = static_cast<int>(i);
      h.pocket = -1;
      h.normal = n;
    }
  }
  for (std::size_t k = 0; k < t.pockets.size(); ++k) {
    const Pocket& pk = t.pockets[k];
    const Vec2 d = p - pk.centre;
    double tau = kInf;
    if (norm2(d) < pk.radius * pk.radius) {
      tau = 0.0;
    } else {
      const double b = dot(d, v);
      const double disc = b * b - norm2(v) * (norm2(d) - pk.radius * pk.radius);
      if (b < 0.0 && disc >= 0.0) tau = (-b - std::sqrt(disc)) / norm2(v);
    }
    if (tau < h.t) {
      h.t = tau;
      h.wall = -1;
      h.pocket = static_cast<int>(k);
    }
  }
  return h;
}

inline bool in_box(const Table& t, Vec2 p) {
  return p.x >= t.min.x && p.x <= t.max.x && p.y >= t.min.y && p.y <= t.max.y;
}

inline bool segments_cross(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
  auto orient = [](Vec2 a, Vec2 b, Vec2 c) {
    const double x = cross(b - a, c - a);
    return (x > 0.0) - (x < 0.0);
  };
  const int o1 = orient(p1, p2, q1);
  const int o2 = orient(p1, p2, q2);
  const int o3 = orient(q1, q2, p1);
  const int o4 = orient(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  auto on = [](Vec2 a, Vec2 b, Vec2 c) {
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
  };
  return (o1 == 0 && on(p1, p2, q1)) || (o2 == 0 && on(p1, p2, q2)) ||
         (o3 == 0 && on(q1, q2, p1)) || (o4 == 0 && on(q1, q2, p2));
}

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// A random place where a centre of a ball of radius `ball_r` may be: on
/// the table side of every wall, clear of them, not yet pocketed. Half of
/// the samples are within `near` of a pocket's centre (in x and in y).
inline Vec2 random_free_point(const Table& t, std::mt19937_64& rng, double ball_r, double near) {
  const bool near_pocket = (rng() & 1U) != 0;
  for (;;) {
    Vec2 p;
    if (near_pocket) {
      const Pocket& k = t.pockets[rng() % t.pockets.size()];
      p = {uniform(rng, k.centre.x - near, k.centre.x + near),
           uniform(rng, k.centre.y - near, k.centre.y + near)};
    } else {
      p = {uniform(rng, t.min.x, t.max.x), uniform(rng, t.min.y, t.max.y)};
    }
    if (contains(t, p) && !in_a_pocket(t, p) && wall_distance(t, p) >= ball_r) return p;
  }
}

inline Vec2 random_direction(std::mt19937_64& rng) {
  for (;;) {
    const Vec2 v{uniform(rng, -1, 1), uniform(rng, -1, 1)};
    const double n = norm(v);
    if (n > 0.1 && n < 1.0) return v / n;
  }
}

}  // namespace breakshot::table_geometry
