// Pocket billiards tables (WPA): cushion noses, pocket jaws with rounded
// tips, and the pocket circles that capture a ball.
//
// Coordinates (docs/scenario.md): the origin is the lower-left corner of
// the playing surface at the cushion noses, x runs along the length L and
// y along the width W, so the playing surface is [0, L] x [0, W]. The head
// is the short rail at x = 0 (head spot (L/4, W/2)), the foot the short
// rail at x = L (foot spot (3L/4, W/2)).
//
// Pockets, by name, at the nominal corners of the playing surface:
//   bottom_left (0, 0)   side_bottom (L/2, 0)   bottom_right (L, 0)
//   top_left    (0, W)   side_top    (L/2, W)   top_right    (L, W)
// Cushion noses (straight walls between pockets):
//   rail_bottom_left   y = 0, from bottom_left to side_bottom
//   rail_bottom_right  y = 0, from side_bottom to bottom_right
//   rail_top_left      y = W, from top_left to side_top
//   rail_top_right     y = W, from side_top to top_right
//   rail_left          x = 0 (head rail), rail_right  x = L (foot rail)
// Jaws: every pocket mouth lies between two jaws. A corner pocket's jaws
// are <pocket>_jaw_x (the one on the long rail, along x) and
// <pocket>_jaw_y (on the short rail, along y); a side pocket's are
// <pocket>_jaw_left and <pocket>_jaw_right (smaller and larger x). Each
// jaw is a straight facing (a segment wall named after the jaw) and a
// rounded tip where the cushion nose turns into the facing (an arc wall
// named <jaw>_tip).
//
// Geometry (WPA Equipment Specifications, "Pocket Openings and
// Measurements"; docs/physics.md has the full derivation):
// - The mouth is measured between the two "pointed lips", the points where
//   the cushion nose line meets the facing line. Corner 4.5 in, side 5 in
//   (the smallest WPA values; WPA allows up to 4.625 and 5.125 in).
// - The horizontal cut angle, between the cushion nose (pointing away from
//   the pocket) and the facing (pointing into the pocket), measured through
//   the cushion, is 142 degrees at corner pockets and 104 degrees at side
//   pockets. So a corner facing is 38 degrees off its rail, 7 degrees
//   steeper than the 45-degree pocket axis, and a side facing is 14
//   degrees off the perpendicular: both pairs of facings converge into
//   the pocket.
// - The shelf (mouth line to the drop point of the slate, along the pocket
//   axis): corner 1.75 in (WPA 1 to 2.25 in; BCA 1 5/8 to 1 7/8 in), side
//   3/16 in (WPA and BCA 0 to 3/8 in).
// - The lip is rounded with a radius of 1/8 in (a modelling choice: WPA
//   calls the lip pointed; 1/8 in is the WPA-preferred facing thickness).
//   The arc is tangent to the nose and to the facing, so the nominal lip
//   point stays exactly where the mouth is measured.
// - Capture: a ball has fallen when its centre is over the slate hole,
//   modelled as a circle whose nearest point to the table lies on the
//   pocket axis at the shelf depth behind the mouth line and whose radius
//   is half the width between the facings at that depth. The facings run
//   on into the pocket until they leave that circle again, so the walls and
//   the pocket circles close the table: a ball centre can leave the
//   playing area only through a pocket circle.
// - The same pockets on every size (WPA gives one set of pocket
//   dimensions; it does not specify 7 ft tables).
// - The vertical pocket angle (12-15 degrees of back draft on the facings)
//   is a 3-D feature and is not modelled in the plan view.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "breakshot/table.hpp"

namespace breakshot {

namespace {

constexpr double kInch = 0.0254;

// cos and sin of the cut angles, written out so that the geometry is the
// same bit for bit whatever the maths library.
constexpr double kCos142 = -0.7880107536067219;
constexpr double kSin142 = 0.6156614753256584;
constexpr double kCos104 = -0.24192189559966779;
constexpr double kSin104 = 0.9702957262759965;

struct PocketSpec {
  double mouth;    ///< lip to lip (m)
  double cos_cut;  ///< cut angle between nose and facing, through the cushion
  double sin_cut;
  double shelf;  ///< mouth line to the drop point, along the axis (m)
};

constexpr PocketSpec kCorner{4.5 * kInch, kCos142, kSin142, 1.75 * kInch};
constexpr PocketSpec kSide{5.0 * kInch, kCos104, kSin104, 0.1875 * kInch};
constexpr double kTipRadius = 0.125 * kInch;

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

Tip round_lip(Vec2 lip, Vec2 d_in, Vec2 d_out, std::string name) {
  // Turning angle phi; the tangent points lie r tan(phi/2) from the lip.
  const double c = dot(d_in, d_out);
  const double s = -cross(d_in, d_out);  // > 0 for a right turn
  const double back = kTipRadius * (1.0 - c) / s;
  Tip tip;
  tip.t_in = lip - d_in * back;
  tip.t_out = lip + d_out * back;
  tip.wall.kind = WallKind::arc;
  tip.wall.a = tip.t_in + right_of(d_in) * kTipRadius;
  tip.wall.radius = kTipRadius;
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

    Tip tip1 = round_lip(lip1.point, -lip1.rail_dir, f1, lip1.jaw + "_tip");
    Tip tip2 = round_lip(lip2.point, -f2, lip2.rail_dir, lip2.jaw + "_tip");

    // The rail that ends at this pocket.
    if (started) {
      table.walls.push_back(segment_wall(pending, tip1.t_in, pending_rail));
    } else {
      first_rail_end = tip1.t_in;
      started = true;
    }
    auto& out = table.outline;
    out.push_back(tip1.t_in);
    arc_points(tip1.wall.a, kTipRadius, tip1.wall.normal, tip1.wall.b, 3, out);
    out.push_back(tip1.t_out);
    out.push_back(far1);
    const Vec2 u1 = unit(far1 - pocket.centre);
    const Vec2 u2 = unit(far2 - pocket.centre);
    arc_points(pocket.centre, pocket.radius, u1, e, 4, out);
    out.push_back(pocket.centre + e * pocket.radius);
    arc_points(pocket.centre, pocket.radius, e, u2, 4, out);
    out.push_back(far2);
    out.push_back(tip2.t_in);
    arc_points(tip2.wall.a, kTipRadius, tip2.wall.normal, tip2.wall.b, 3, out);
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

Table make_pool_table(const std::string& size) {
  double L = 0.0;
  double W = 0.0;
  // Playing surfaces as the scenario contract gives them (WPA: 9 ft 100 x
  // 50 in; 8 ft 92 x 46 in; 7 ft tables, 78 x 39 in, are not WPA sizes).
  if (size == "9ft") {
    L = 2.54;
    W = 1.27;
  } else if (size == "8ft") {
    L = 2.34;
    W = 1.17;
  } else if (size == "7ft") {
    L = 1.98;
    W = 0.99;
  } else {
    throw std::invalid_argument("unknown pool table size \"" + size +
                                "\" (expected \"7ft\", \"8ft\" or \"9ft\")");
  }

  // Corner lips lie a from the nominal corner along each rail, so that
  // the lip-to-lip distance a * sqrt(2) is the mouth.
  const double a = kCorner.mouth / std::sqrt(2.0);
  const double hs = 0.5 * kSide.mouth;
  const Vec2 px{1, 0};
  const Vec2 mx{-1, 0};
  const Vec2 py{0, 1};
  const Vec2 my{0, -1};

  Builder b;
  // Counter-clockwise around the table from the bottom-left corner.
  b.pocket("bottom_left", {{0, a}, py, px, "bottom_left_jaw_y"},
           {{a, 0}, px, py, "bottom_left_jaw_x"}, kCorner, "rail_bottom_left");
  b.pocket("side_bottom", {{0.5 * L - hs, 0}, mx, py, "side_bottom_jaw_left"},
           {{0.5 * L + hs, 0}, px, py, "side_bottom_jaw_right"}, kSide, "rail_bottom_right");
  b.pocket("bottom_right", {{L - a, 0}, mx, py, "bottom_right_jaw_x"},
           {{L, a}, py, mx, "bottom_right_jaw_y"}, kCorner, "rail_right");
  b.pocket("top_right", {{L, W - a}, my, mx, "top_right_jaw_y"},
           {{L - a, W}, mx, my, "top_right_jaw_x"}, kCorner, "rail_top_right");
  b.pocket("side_top", {{0.5 * L + hs, W}, px, my, "side_top_jaw_right"},
           {{0.5 * L - hs, W}, mx, my, "side_top_jaw_left"}, kSide, "rail_top_left");
  b.pocket("top_left", {{a, W}, px, my, "top_left_jaw_x"}, {{0, W - a}, my, px, "top_left_jaw_y"},
           kCorner, "rail_left");
  b.close();

  Table t = std::move(b.table);
  t.shape = "pool";
  t.length = L;
  t.width = W;
  t.head_spot = {0.25 * L, 0.5 * W};
  t.foot_spot = {0.75 * L, 0.5 * W};
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

}  // namespace breakshot
