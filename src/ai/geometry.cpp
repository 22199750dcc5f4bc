// Path geometry shared by the computer players (geometry.hpp).
#include "geometry.hpp"

#include <algorithm>
#include <array>
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

PathReach::PathReach(Vec2 a, Vec2 b, double reach) : a_(a), reach_(reach + 1e-7) {
  lo_ = {std::min(a.x, b.x) - reach_, std::min(a.y, b.y) - reach_};
  hi_ = {std::max(a.x, b.x) + reach_, std::max(a.y, b.y) + reach_};
  const double len = norm(b - a);
  u_ = len > 0.0 ? (b - a) / len : Vec2{};
}

bool PathReach::beyond(const Wall& w) const {
  // The wall's box: its segment, or its point grown by the arc's radius
  // (an arc's distance is the point's less the radius).
  const double rad = w.kind == WallKind::arc ? w.radius : 0.0;
  const Vec2 wa = w.a;
  const Vec2 wb = w.kind == WallKind::segment ? w.b : w.a;
  const Vec2 wlo{std::min(wa.x, wb.x) - rad, std::min(wa.y, wb.y) - rad};
  const Vec2 whi{std::max(wa.x, wb.x) + rad, std::max(wa.y, wb.y) + rad};
  if (wlo.x > hi_.x || whi.x < lo_.x || wlo.y > hi_.y || whi.y < lo_.y) return true;
  // Both ends on one side of the segment's line, further than the reach
  // (plus the radius) from it.
  if (u_.x == 0.0 && u_.y == 0.0) return false;
  const double sa = cross(u_, wa - a_);
  const double sb = cross(u_, wb - a_);
  const double far = reach_ + rad;
  return (sa > far && sb > far) || (sa < -far && sb < -far);
}

bool walls_clear(const Table& table, double R, Vec2 a, Vec2 b) {
  // A wall further than R + kWallMargin from the path passes the test
  // below, whose `need` is at most that: skipped, the answer is the same.
  const PathReach reach(a, b, R + kWallMargin);
  for (const Wall& w : table.walls) {
    if (reach.beyond(w)) continue;
    const double need = std::min({R + kWallMargin, wall_distance(w, a, a), wall_distance(w, b, b)});
    if (wall_distance(w, a, b) < need - 1e-9) return false;
  }
  return true;
}

namespace {

/// Whether the ball that strikes a ball at `from` toward `dir` fits at its
/// ghost ball's place (2R behind, on the line).
bool ghost_fits(const Table& table, double R, Vec2 from, Vec2 dir) {
  return disk_fits(table, from - dir * (2.0 * R), R);
}

/// The line from `from` toward the point `off` pocket radii across the
/// pocket's centre (`across` is the unit vector across), up to the
/// pocket's capture circle, if it passes every ball but the skipped ones
/// and keeps clear of the cushions and jaws (and, for a ball `at_rest`, if
/// the ball that strikes it fits at its ghost ball's place); its room is
/// how far it may shift sideways before it meets a jaw.
std::optional<Approach> approach_line(const Table& table, double R, const Layout& lay, Vec2 from,
                                      const Pocket& pk, Vec2 across, double off, int skip1,
                                      int skip2, bool at_rest) {
  const Vec2 aim = pk.centre + across * (off * pk.radius);
  const Vec2 d = (aim - from) / norm(aim - from);
  const Vec2 f = from - pk.centre;
  const double half_b = dot(f, d);
  const double disc = half_b * half_b - (norm2(f) - pk.radius * pk.radius);
  if (disc <= 0.0) return std::nullopt;
  const double s = -half_b - std::sqrt(disc);
  if (s <= 0.0) return std::nullopt;
  const Vec2 end = from + d * s;
  // A ball at rest is struck from its ghost ball's place, which must fit.
  if (at_rest && !ghost_fits(table, R, from, d)) return std::nullopt;
  if (!balls_clear(lay, R, from, end, skip1, skip2)) return std::nullopt;
  if (!walls_clear(table, R, from, end)) return std::nullopt;
  // Walls near the pocket only: the rails along the way were checked above.
  double room = kInf;
  const PathReach near_pocket(pk.centre, pk.centre, 0.2);
  for (const Wall& w : table.walls) {
    if (near_pocket.beyond(w)) continue;  // further than 0.2 m, proved cheaply
    if (wall_distance(w, pk.centre, pk.centre) > 0.2) continue;
    room = std::min(room, wall_distance(w, from, end) - R);
  }
  return Approach{aim, d, s, room};
}

/// A ball on or near a rail, run along it into the corner pocket at its
/// end: the line to a point kRailRunAim (at most; the ball's own gap when
/// less) off the rail just short of the pocket, so that the ball comes in
/// along the cushion, as a player plays it. The pocket's jaws turn such a
/// ball in even when its line meets the cushion on the way or never
/// crosses the pocket's capture circle, which is why the lines across the
/// mouth are all blocked (docs/experiments.md, "rail runs into the corners").
std::optional<Approach> rail_run(const Table& table, double R, const Layout& lay, Vec2 from,
                                 const Pocket& pk, int skip1, int skip2) {
  const double L = table.length;
  const double W = table.width;
  const bool corner =
      (pk.centre.x < 0.0 || pk.centre.x > L) && (pk.centre.y < 0.0 || pk.centre.y > W);
  if (!corner) return std::nullopt;
  // The two rails that meet at this corner: the short one (x fixed) and
  // the long one (y fixed).
  for (int axis = 0; axis < 2; ++axis) {
    const bool short_rail = axis == 0;
    const double across_from = short_rail ? from.x : from.y;
    const bool low = short_rail ? pk.centre.x < 0.0 : pk.centre.y < 0.0;
    const double nose = low ? 0.0 : (short_rail ? L : W);  // the cushion's line
    const double inward = low ? 1.0 : -1.0;                // from it into the table
    const double gap = (across_from - nose) * inward - R;
    // A negative gap: the ball is in the pocket's mouth, past the cushion.
    if (gap < -2.0 * R || gap > kRailRunGap) continue;
    const double along_from = short_rail ? from.y : from.x;
    const double along_pk = short_rail ? pk.centre.y : pk.centre.x;
    const double ahead = along_pk > along_from ? 1.0 : -1.0;
    double along_end = along_pk - ahead * (pk.radius + R);
    double across_end = nose + inward * (R + std::clamp(gap, 0.002, kRailRunAim));
    if ((along_end - along_from) * ahead < 2.0 * R) {
      // Already at the mouth: straight along the rail into the pocket.
      along_end = along_pk;
      across_end = across_from;
    }
    const Vec2 aim = short_rail ? Vec2{across_end, along_end} : Vec2{along_end, across_end};
    const double length = norm(aim - from);
    if (length < 1e-6) continue;
    const Vec2 dir = (aim - from) / length;
    // The cue ball (or the ball driving this one) must fit where it hits.
    if (!ghost_fits(table, R, from, dir)) continue;
    if (!balls_clear(lay, R, from, aim, skip1, skip2)) continue;
    if (!balls_clear(lay, R, aim, pk.centre, skip1, skip2)) continue;
    if (!walls_clear(table, R, from, aim)) continue;
    return Approach{aim, dir, length, kRailRunRoom};
  }
  return std::nullopt;
}

}  // namespace

std::optional<Approach> pocket_approach(const Table& table, double R, const Layout& lay,
                                        Vec2 from, int pocket, int skip1, int skip2,
                                        bool at_rest) {
  const Pocket& pk = table.pockets[static_cast<std::size_t>(pocket)];
  const double dist = norm(pk.centre - from);
  if (dist <= pk.radius) return std::nullopt;
  const Vec2 toward = (pk.centre - from) / dist;
  const Vec2 across = perp(toward);
  // The line to the centre and two a little to either side: the one with
  // the most room.
  std::optional<Approach> best;
  for (double off : {0.0, 0.4, -0.4}) {
    std::optional<Approach> a =
        approach_line(table, R, lay, from, pk, across, off, skip1, skip2, at_rest);
    if (a) a->room = std::clamp(a->room, 0.002, 0.04);
    if (a && (!best || a->room > best->room)) best = a;
  }
  if (best) return best;
  // All three blocked: a fan of lines across the whole mouth. A ball near
  // a rail going into a corner along it, or one coming in at a shallow
  // angle, has its open lines to one side, which the three above missed
  // (docs/experiments.md, "rail shots: lines across the whole pocket mouth").
  std::array<std::optional<Approach>, kApproachLines> lines;
  for (int i = 0; i < kApproachLines; ++i) {
    if (i == kApproachLines / 2) continue;  // the centre line, blocked above
    const double off = (i - kApproachLines / 2) * kApproachStep;
    lines[static_cast<std::size_t>(i)] =
        approach_line(table, R, lay, from, pk, across, off, skip1, skip2, at_rest);
  }
  // The widest run of open lines; of equal runs, the one nearer the centre.
  int lo = -1;
  int n = 0;
  const auto centre_gap = [](int first, int count) {
    return std::abs(2 * first + count - 1 - (kApproachLines - 1));
  };
  for (int i = 0; i < kApproachLines;) {
    if (!lines[static_cast<std::size_t>(i)]) {
      ++i;
      continue;
    }
    int j = i;
    while (j < kApproachLines && lines[static_cast<std::size_t>(j)]) ++j;
    if (j - i > n || (j - i == n && centre_gap(i, j - i) < centre_gap(lo, n))) {
      lo = i;
      n = j - i;
    }
    i = j;
  }
  if (n == 0) return at_rest ? rail_run(table, R, lay, from, pk, skip1, skip2) : std::nullopt;
  // Aim at the middle of the run: its middle line, or when the run is even
  // the line halfway between its two middle ones if that is open too.
  std::optional<Approach> a = lines[static_cast<std::size_t>(lo + n / 2)];
  if (n % 2 == 0) {
    const double mid = (lo + 0.5 * (n - 1) - kApproachLines / 2) * kApproachStep;
    if (std::optional<Approach> m =
            approach_line(table, R, lay, from, pk, across, mid, skip1, skip2, at_rest)) {
      a = m;
    }
  }
  // Room: the distance to the jaws, or half the open window when that is
  // wider (a line along a rail has a jaw close by, yet room to one side).
  const double half_window = 0.5 * (n - 1) * kApproachStep * pk.radius;
  a->room = std::clamp(std::max(a->room, half_window), 0.002, 0.04);
  return a;
}

}  // namespace breakshot::ai
