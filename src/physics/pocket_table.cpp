// The six-pocket table shared by the pool and snooker tables: see
// pocket_table.hpp for the coordinates, the names and the geometry.
#include "physics/pocket_table.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace breakshot::pocket_table {

namespace {

Vec2 unit(Vec2 v) { return v / norm(v); }

/// The vector turned a quarter turn clockwise.
Vec2 right_of(Vec2 d) { return {d.y, -d.x}; }

/// One side of a pocket mouth, as given.
struct LipSpec {
  Vec2 point;     ///< the nominal (pointed) lip on the nose line
  Vec2 rail_dir;  ///< unit, along the nose away from the pocket
  Vec2 rail_in;   ///< the rail's unit normal into the table
  std::string jaw;
};

/// The facing direction: the rail direction turned by the cut angle to
/// the side away from the table.
Vec2 facing_direction(const LipSpec& lip, const PocketSpec& spec) {
  const Vec2 r = lip.rail_dir;
  const Vec2 ccw{spec.cos_cut * r.x - spec.sin_cut * r.y, spec.sin_cut * r.x + spec.cos_cut * r.y};
  const Vec2 cw{spec.cos_cut * r.x + spec.sin_cut * r.y, -spec.sin_cut * r.x + spec.cos_cut * r.y};
  return dot(ccw, lip.rail_in) < 0.0 ? ccw : cw;
}

/// Points strictly between the unit directions u and v (less than half a
/// turn apart) on a circle, from u to v, by repeated bisection: 2^depth - 1
/// points. Only arithmetic and square roots, so the outline is the same
/// everywhere.
void arc_points(Vec2 centre, double radius, Vec2 u, Vec2 v, int depth, std::vector<Vec2>& out) {
  if (depth == 0) return;
  const Vec2 m = unit(u + v);
  arc_points(centre, radius, u, m, depth - 1, out);
  out.push_back(centre + m * radius);
  arc_points(centre, radius, m, v, depth - 1, out);
}

Wall segment_wall(Vec2 a, Vec2 b, std::string name) {
  Wall w;
  w.kind = WallKind::segment;
  w.a = a;
  w.b = b;
  w.normal = perp(unit(b - a));  // left of a -> b: into the table
  w.name = std::move(name);
  return w;
}

/// A rounded lip: where the boundary, followed counter-clockwise around
/// the table, comes in along d_in and leaves along d_out (a right turn).
struct Tip {
  Vec2 t_in;   ///< where the arc meets the incoming straight
  Vec2 t_out;  ///< where it meets the outgoing straight
  Wall wall;
};

Tip round_lip(Vec2 lip, Vec2 d_in, Vec2 d_out, double radius, std::string name) {
  // Turning angle phi; the tangent points lie r tan(phi/2) from the lip.
  const double c = dot(d_in, d_out);
  const double s = -cross(d_in, d_out);  // > 0 for a right turn
  const double back = radius * (1.0 - c) / s;
  Tip tip;
  tip.t_in = lip - d_in * back;
  tip.t_out = lip + d_out * back;
  tip.wall.kind = WallKind::arc;
  tip.wall.a = tip.t_in + right_of(d_in) * radius;
  tip.wall.radius = radius;
  // Contact directions run clockwise from the incoming straight's normal
  // to the outgoing one's, so counter-clockwise from b = n_out to n_in.
  tip.wall.b = perp(d_out);
  tip.wall.normal = perp(d_in);
  tip.wall.name = std::move(name);
  return tip;
}

struct Builder {
  Table table;
  Vec2 pending;  ///< where the next rail starts (the last tip's t_out)
  std::string pending_rail;
  Vec2 first_rail_end;  ///< closes the loop
  bool started = false;

  /// Adds the pocket whose lips are lip1 then lip2 in counter-clockwise
  /// order around the table, and the rail that leads to it.
  void pocket(const std::string& name, const LipSpec& lip1, const LipSpec& lip2,
              const PocketSpec& spec, const std::string& next_rail) {
    const Vec2 f1 = facing_direction(lip1, spec);
    const Vec2 f2 = facing_direction(lip2, spec);
    // Pocket axis, pointing away from the table; the lips lie on the mouth
    // line, which is perpendicular to it.
    const Vec2 e = unit(-(lip1.rail_in + lip2.rail_in));
    const Vec2 mouth_mid = (lip1.point + lip2.point) * 0.5;
    // Width between the facings at the drop point.
    const Vec2 x1 = lip1.point + f1 * (spec.shelf / dot(f1, e));
    const Vec2 x2 = lip2.point + f2 * (spec.shelf / dot(f2, e));
    Pocket pocket;
    pocket.radius = 0.5 * norm(x2 - x1);
    pocket.centre = mouth_mid + e * (spec.shelf + pocket.radius);
    pocket.name = name;

    // Where each facing line leaves the pocket circle again.
    auto far_point = [&](Vec2 lip, Vec2 f) {
      const Vec2 d = lip - pocket.centre;
      const double b = dot(f, d);
      const double c = norm2(d) - pocket.radius * pocket.radius;
      return lip + f * (-b + std::sqrt(b * b - c));
    };
    const Vec2 far1 = far_point(lip1.point, f1);
    const Vec2 far2 = far_point(lip2.point, f2);

    Tip tip1 = round_lip(lip1.point, -lip1.rail_dir, f1, spec.tip_radius, lip1.jaw + "_tip");
    Tip tip2 = round_lip(lip2.point, -f2, lip2.rail_dir, spec.tip_radius, lip2.jaw + "_tip");

    // A round piece too large for the pocket would end behind the point
    // where its facing leaves the capture circle: the walls would no longer
    // close the table.
    if (!(dot(far1 - tip1.t_out, f1) > 0.0 && dot(far2 - tip2.t_in, f2) > 0.0)) {
      throw std::logic_error("pocket " + name + ": the round jaw runs past the pocket circle");
    }

    // The rail that ends at this pocket.
    if (started) {
      table.walls.push_back(segment_wall(pending, tip1.t_in, pending_rail));
    } else {
      first_rail_end = tip1.t_in;
      started = true;
    }
    auto& out = table.outline;
    out.push_back(tip1.t_in);
    arc_points(tip1.wall.a, spec.tip_radius, tip1.wall.normal, tip1.wall.b, spec.tip_depth, out);
    out.push_back(tip1.t_out);
    out.push_back(far1);
    const Vec2 u1 = unit(far1 - pocket.centre);
    const Vec2 u2 = unit(far2 - pocket.centre);
    arc_points(pocket.centre, pocket.radius, u1, e, 4, out);
    out.push_back(pocket.centre + e * pocket.radius);
    arc_points(pocket.centre, pocket.radius, e, u2, 4, out);
    out.push_back(far2);
    out.push_back(tip2.t_in);
    arc_points(tip2.wall.a, spec.tip_radius, tip2.wall.normal, tip2.wall.b, spec.tip_depth, out);
    out.push_back(tip2.t_out);

    table.walls.push_back(std::move(tip1.wall));
    table.walls.push_back(segment_wall(tip1.t_out, far1, lip1.jaw));
    table.walls.push_back(segment_wall(far2, tip2.t_in, lip2.jaw));
    table.walls.push_back(std::move(tip2.wall));
    table.pockets.push_back(std::move(pocket));
    pending = tip2.t_out;
    pending_rail = next_rail;
  }

  void close() { table.walls.push_back(segment_wall(pending, first_rail_end, pending_rail)); }
};

}  // namespace

Table six_pocket_table(double L, double W, const PocketSpec& corner, const PocketSpec& side) {
  // Corner lips lie a from the nominal corner along each rail, so that
  // the lip-to-lip distance a * sqrt(2) is the mouth.
  const double a = corner.mouth / std::sqrt(2.0);
  const double hs = 0.5 * side.mouth;
  const Vec2 px{1, 0};
  const Vec2 mx{-1, 0};
  const Vec2 py{0, 1};
  const Vec2 my{0, -1};

  Builder b;
  // Counter-clockwise around the table from the bottom-left corner.
  b.pocket("bottom_left", {{0, a}, py, px, "bottom_left_jaw_y"},
           {{a, 0}, px, py, "bottom_left_jaw_x"}, corner, "rail_bottom_left");
  b.pocket("side_bottom", {{0.5 * L - hs, 0}, mx, py, "side_bottom_jaw_left"},
           {{0.5 * L + hs, 0}, px, py, "side_bottom_jaw_right"}, side, "rail_bottom_right");
  b.pocket("bottom_right", {{L - a, 0}, mx, py, "bottom_right_jaw_x"},
           {{L, a}, py, mx, "bottom_right_jaw_y"}, corner, "rail_right");
  b.pocket("top_right", {{L, W - a}, my, mx, "top_right_jaw_y"},
           {{L - a, W}, mx, my, "top_right_jaw_x"}, corner, "rail_top_right");
  b.pocket("side_top", {{0.5 * L + hs, W}, px, my, "side_top_jaw_right"},
           {{0.5 * L - hs, W}, mx, my, "side_top_jaw_left"}, side, "rail_top_left");
  b.pocket("top_left", {{a, W}, px, my, "top_left_jaw_x"}, {{0, W - a}, my, px, "top_left_jaw_y"},
           corner, "rail_left");
  b.close();

  Table t = std::move(b.table);
  t.length = L;
  t.width = W;
  constexpr double inf = std::numeric_limits<double>::infinity();
  t.min = {inf, inf};
  t.max = {-inf, -inf};
  auto grow = [&t](Vec2 lo, Vec2 hi) {
    t.min = {std::fmin(t.min.x, lo.x), std::fmin(t.min.y, lo.y)};
    t.max = {std::fmax(t.max.x, hi.x), std::fmax(t.max.y, hi.y)};
  };
  for (const Vec2 p : t.outline) grow(p, p);
  for (const Pocket& p : t.pockets) {
    const Vec2 r{p.radius, p.radius};
    grow(p.centre - r, p.centre + r);
  }
  return t;
}

}  // namespace breakshot::pocket_table
