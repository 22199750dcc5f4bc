// Rectangle and polygon tables: walls, reflex corners, containment.
#include "breakshot/table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace breakshot {

namespace {

double signed_area(const std::vector<Vec2>& v) {
  double a = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 p = v[k];
    const Vec2 q = v[(k + 1) % v.size()];
    a += cross(p, q);
  }
  return 0.5 * a;
}

// Orientation of the triple (p, q, r): +1 counter-clockwise, -1 clockwise,
// 0 collinear. Exact enough for validating user input: we only need to
// reject polygons that really cross themselves.
int orient(Vec2 p, Vec2 q, Vec2 r) {
  const double c = cross(q - p, r - p);
  return (c > 0.0) - (c < 0.0);
}

bool on_segment(Vec2 p, Vec2 q, Vec2 r) {
  // r collinear with p-q: is it within the bounding box of the segment?
  return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
         std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
}

bool segments_intersect(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
  const int o1 = orient(p1, p2, q1);
  const int o2 = orient(p1, p2, q2);
  const int o3 = orient(q1, q2, p1);
  const int o4 = orient(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(p1, p2, q1)) return true;
  if (o2 == 0 && on_segment(p1, p2, q2)) return true;
  if (o3 == 0 && on_segment(q1, q2, p1)) return true;
  if (o4 == 0 && on_segment(q1, q2, p2)) return true;
  return false;
}

Wall make_segment(Vec2 a, Vec2 b, Vec2 inward, std::string name) {
  Wall w;
  w.kind = WallKind::segment;
  w.a = a;
  w.b = b;
  w.normal = inward / norm(inward);
  w.name = std::move(name);
  return w;
}

}  // namespace

Table make_rectangle(Vec2 min, Vec2 max) {
  if (!(min.x < max.x && min.y < max.y)) {
    throw std::invalid_argument("min must be below and left of max");
  }
  Table t;
  t.shape = TableShape::rectangle;
  t.outline = {{min.x, min.y}, {max.x, min.y}, {max.x, max.y}, {min.x, max.y}};
  t.walls.push_back(make_segment({min.x, max.y}, {min.x, min.y}, {1, 0}, "left"));
  t.walls.push_back(make_segment({max.x, min.y}, {max.x, max.y}, {-1, 0}, "right"));
  t.walls.push_back(make_segment({min.x, min.y}, {max.x, min.y}, {0, 1}, "bottom"));
  t.walls.push_back(make_segment({max.x, max.y}, {min.x, max.y}, {0, -1}, "top"));
  t.min = min;
  t.max = max;
  return t;
}

Table make_polygon(const std::vector<Vec2>& v) {
  const std::size_t n = v.size();
  if (n < 3) throw std::invalid_argument("a polygon needs at least 3 vertices");
  for (const Vec2 p : v) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw std::invalid_argument("vertex coordinates must be finite");
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (v[i] == v[j]) {
        throw std::invalid_argument("vertices " + std::to_string(i) + " and " +
                                    std::to_string(j) + " are the same point");
      }
    }
  }
  // Edges that are not neighbours must not touch; neighbours share only
  // their common vertex (they must not fold back onto each other).
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a1 = v[i];
    const Vec2 a2 = v[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2 b1 = v[j];
      const Vec2 b2 = v[(j + 1) % n];
      const bool next = (j == i + 1);
      const bool wrap = (i == 0 && j == n - 1);
      if (next || wrap) {
        // Shared vertex: fold-back means the far end of one lies on the other.
        const Vec2 shared = next ? a2 : a1;
        const Vec2 other_a = next ? a1 : a2;
        const Vec2 other_b = next ? b2 : b1;
        if (orient(other_a, shared, other_b) == 0 &&
            dot(other_a - shared, other_b - shared) > 0.0) {
          throw std::invalid_argument("edges " + std::to_string(i) + " and " +
                                      std::to_string(j) + " overlap");
        }
        continue;
      }
      if (segments_intersect(a1, a2, b1, b2)) {
        throw std::invalid_argument("edges " + std::to_string(i) + " and " +
                                    std::to_string(j) + " cross: the polygon crosses itself");
      }
    }
  }

  // Checked after the crossings, so that a bow tie (zero net area) is
  // reported as crossing itself.
  const double area = signed_area(v);
  if (!(std::abs(area) > 0.0)) throw std::invalid_argument("the polygon has zero area");
  const double turn = area > 0.0 ? 1.0 : -1.0;  // +1 if counter-clockwise
  Table t;
  t.shape = TableShape::polygon;
  t.outline = v;
  if (turn < 0.0) std::reverse(t.outline.begin(), t.outline.end());
  t.min = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  t.max = -t.min;
  for (const Vec2 p : v) {
    t.min = {std::min(t.min.x, p.x), std::min(t.min.y, p.y)};
    t.max = {std::max(t.max.x, p.x), std::max(t.max.y, p.y)};
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = v[k];
    const Vec2 b = v[(k + 1) % n];
    // The interior lies to the left of each edge of a counter-clockwise
    // polygon, to the right of a clockwise one.
    t.walls.push_back(make_segment(a, b, perp(b - a) * turn, "edge" + std::to_string(k)));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 prev = v[(k + n - 1) % n];
    const Vec2 here = v[k];
    const Vec2 next = v[(k + 1) % n];
    // A vertex where the boundary turns away from the interior points
    // into the table: a ball can hit the point itself, not only the
    // edges' lines.
    if (cross(here - prev, next - here) * turn < 0.0) {
      Wall w;
      w.kind = WallKind::corner;
      w.a = here;
      w.b = here;
      w.name = "corner" + std::to_string(k);
      t.walls.push_back(w);
    }
  }
  return t;
}

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = norm2(ab);
  double s = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  return norm(p - (a + ab * s));
}

// How far p lies outside the box of segment wall w along the farther
// axis (negative inside): a lower bound on its distance to the wall.
static double box_gap(const Wall& w, Vec2 p) {
  const double gx = std::max(std::min(w.a.x, w.b.x) - p.x, p.x - std::max(w.a.x, w.b.x));
  const double gy = std::max(std::min(w.a.y, w.b.y) - p.y, p.y - std::max(w.a.y, w.b.y));
  return std::max(gx, gy);
}

bool disk_fits(const Table& table, Vec2 p, double r) {
  // wall_clearance(table, p, r) >= 0 holds exactly when p is inside and
  // every segment wall is at least r away (d - r >= 0 is d >= r for
  // doubles). A wall whose box lies further than r along an axis (with
  // room for rounding) is further than r.
  for (const Wall& w : table.walls) {
    if (w.kind != WallKind::segment) continue;
    if (box_gap(w, p) > r + 1e-7) continue;
    if (segment_distance(p, w.a, w.b) < r) return false;
  }
  return contains(table, p);
}

bool contains(const Table& table, Vec2 p) {
  // The bed of a pocket table lies inside its outline, which runs along
  // the cushion noses and out around the pockets (a test checks it against
  // the crossing-number test below): the common case without the walk
  // around the outline's hundreds of points.
  if ((table.shape == TableShape::pool || table.shape == TableShape::snooker ||
       table.shape == TableShape::carom) && p.x > 0.0 &&
      p.x < table.length && p.y > 0.0 && p.y < table.width) {
    return true;
  }
  // Crossing-number test on the outline.
  bool inside = false;
  const auto& v = table.outline;
  const std::size_t n = v.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = v[i];
    const Vec2 b = v[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

double wall_clearance(const Table& table, Vec2 p, double r) {
  double d = std::numeric_limits<double>::infinity();
  for (const Wall& w : table.walls) {
    if (w.kind != WallKind::segment) continue;
    // A wall whose box lies further along an axis than the nearest wall
    // so far (with room for rounding) cannot be nearer: skipped, the
    // least distance is the same.
    if (box_gap(w, p) > d + 1e-7) continue;
    d = std::min(d, segment_distance(p, w.a, w.b));
  }
  if (!contains(table, p)) return -d - r;
  return d - r;
}

}  // namespace breakshot
