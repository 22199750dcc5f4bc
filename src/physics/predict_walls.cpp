// Prediction against the walls: segments (a quadratic in time for the
// distance to the wall's line, the contact counting only on the segment),
// corners (points) and arcs (the round jaw tips of pool pockets), with
// boxes around the walls and runs of walls to skip the ones a ball's path
// never nears.
#include <algorithm>
#include <cmath>

#include "physics/engine.hpp"
#include "physics/prediction.hpp"
#include "physics/roots.hpp"

namespace breakshot::detail {

namespace {

// A wall contact counts if the foot of the ball's centre on the wall's
// line lies on the segment, with this much slack (as a fraction of the
// segment's length) so that a ball arriving exactly at the junction of
// two walls is caught by one of them.
constexpr double kSegmentSlack = 1e-9;

}  // namespace

void Engine::set_up_walls() {
  // Corner walls exist exactly where a polygon has a reflex vertex.
  convex_ = std::none_of(scenario_.table.walls.begin(), scenario_.table.walls.end(),
                         [](const Wall& w) { return w.kind != WallKind::segment; });

  // Boxes around the walls, to skip the ones a ball's path never nears.
  wall_box_.reserve(scenario_.table.walls.size());
  for (const Wall& w : scenario_.table.walls) {
    Box b;
    if (w.kind == WallKind::segment) {
      b.lo = {std::min(w.a.x, w.b.x), std::min(w.a.y, w.b.y)};
      b.hi = {std::max(w.a.x, w.b.x), std::max(w.a.y, w.b.y)};
    } else {
      const double rad = w.kind == WallKind::arc ? w.radius : 0.0;
      b.lo = w.a - Vec2{rad, rad};
      b.hi = w.a + Vec2{rad, rad};
    }
    const double margin = 1e-9 * (1.0 + std::abs(b.lo.x) + std::abs(b.hi.x) + std::abs(b.lo.y) +
                                  std::abs(b.hi.y));
    b.lo -= Vec2{margin, margin};
    b.hi += Vec2{margin, margin};
    wall_box_.push_back(b);
  }
  // Runs of consecutive walls (tables list them around the boundary, so
  // a run is a pocket's jaw pieces or a stretch of a polygon) under one
  // box: a ball far from a run skips all its walls with one test.
  Box all{{kInf, kInf}, {-kInf, -kInf}};
  for (const Box& b : wall_box_) {
    all.lo = {std::min(all.lo.x, b.lo.x), std::min(all.lo.y, b.lo.y)};
    all.hi = {std::max(all.hi.x, b.hi.x), std::max(all.hi.y, b.hi.y)};
  }
  const double run_size = norm(all.hi - all.lo) / 16.0;
  wall_runs_.reserve(wall_box_.size());
  for (std::size_t w = 0; w < wall_box_.size(); ++w) {
    const Box& b = wall_box_[w];
    if (!wall_runs_.empty()) {
      WallRun& run = wall_runs_.back();
      const Box merged{{std::min(run.box.lo.x, b.lo.x), std::min(run.box.lo.y, b.lo.y)},
                       {std::max(run.box.hi.x, b.hi.x), std::max(run.box.hi.y, b.hi.y)}};
      if (norm(merged.hi - merged.lo) <= run_size) {
        run.box = merged;
        run.end = static_cast<std::uint32_t>(w + 1);
        continue;
      }
    }
    wall_runs_.push_back({b, static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(w + 1)});
  }
}

void Engine::predict_walls(const Kinematics& ki, Prediction& best) const {
  if (ki.still) return;
  const double t = origin_;
  const double r = ki.radius;
  for (const WallRun& run : wall_runs_) {
    const Box& rb = run.box;
    if (rb.lo.x - ki.box_hi.x > r || ki.box_lo.x - rb.hi.x > r || rb.lo.y - ki.box_hi.y > r ||
        ki.box_lo.y - rb.hi.y > r) {
      continue;  // the ball's path never comes within reach of these walls
    }
    for (std::size_t w = run.begin; w < run.end; ++w) {
      const double window = within_best(best, t, std::max(0.0, ki.t_end - t));
      if (ki.airborne) {
        predict_wall_airborne(ki, w, window, best);  // engine_airborne.cpp
      } else {
        predict_wall(ki, w, window, best);
      }
    }
  }
}

void Engine::predict_wall(const Kinematics& ki, std::size_t w, double window,
                          Prediction& best) const {
  const double t = origin_;
  const Vec2 p = ki.p;
  const Vec2 v = ki.v;
  const Vec2 a = ki.a;
  const double r = ki.radius;
  const Wall& wall = scenario_.table.walls[w];
  const Box& wb = wall_box_[w];
  if (wb.lo.x - ki.box_hi.x > r || ki.box_lo.x - wb.hi.x > r || wb.lo.y - ki.box_hi.y > r ||
      ki.box_lo.y - wb.hi.y > r) {
    return;  // the ball's path never comes within reach of this wall
  }
  double tau = kInf;
  if (wall.kind == WallKind::segment) {
    const Vec2 n = wall.normal;
    const double c1 = dot(n, v);
    const double c2 = 0.5 * dot(n, a);
    if (c2 == 0.0 && c1 >= 0.0) return;  // moving away or along
    const double c0 = dot(n, p - wall.a) - r;
    if (c2 == 0.0) {
      tau = c0 <= 0.0 ? 0.0 : -c0 / c1;
    } else {
      const double c[3] = {c0, c1, c2};
      tau = first_contact(c, 2, window);
    }
    if (!(tau <= window)) return;
    // Is the contact on the segment itself, not on its line's extension?
    // In a convex table the earliest crossing of any wall's line always
    // is, and the later ones never win, so there is nothing to check.
    if (convex_) {
      consider(best, t + tau, EventKind::wall, static_cast<std::int32_t>(w), 0);
      return;
    }
    const Vec2 q = p + v * tau + a * (0.5 * tau * tau);
    const Vec2 ab = wall.b - wall.a;
    const double s = dot(q - wall.a, ab) / norm2(ab);
    if (s < -kSegmentSlack || s > 1.0 + kSegmentSlack) return;
  } else {
    // A corner is a point; an arc is a circle of its radius, hit from
    // outside. Either way: the centre's distance to wall.a reaches
    // r (+ the arc's radius).
    const double reach = r + (wall.kind == WallKind::arc ? wall.radius : 0.0);
    const Vec2 d = p - wall.a;
    if (a.x == 0.0 && a.y == 0.0) {
      const double b = dot(d, v);
      if (b >= 0.0) return;
      tau = first_contact_quadratic(norm2(d) - reach * reach, b, norm2(v));
    } else {
      // Bounds on the distance that prove no contact (prediction.hpp).
      const double d2 = norm2(d);
      if (d2 > reach * reach && stays_apart(d, v, a, std::sqrt(d2), reach, window)) return;
      const double c[5] = {norm2(d) - reach * reach, 2.0 * dot(d, v), norm2(v) + dot(d, a),
                           dot(v, a), 0.25 * norm2(a)};
      tau = first_contact(c, 4, window);
    }
    if (!(tau <= window)) return;
    if (wall.kind == WallKind::arc) {
      // Only the part of the circle between the directions b and normal
      // (counter-clockwise) is there.
      const Vec2 q = p + v * tau + a * (0.5 * tau * tau) - wall.a;
      const double slack = kSegmentSlack * norm(q);
      if (cross(wall.b, q) < -slack || cross(q, wall.normal) < -slack) return;
    }
  }
  consider(best, t + tau, EventKind::wall, static_cast<std::int32_t>(w), 0);
}

}  // namespace breakshot::detail
