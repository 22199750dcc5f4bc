// The engine's part of balls that leave the cloth (physics.airborne;
// docs/physics.md, "Airborne balls"): starting a flight, the landing,
// the walls met in flight (the rail's face below its nose, the nose from
// above, and the line of the nose crossed above it: the ball leaves the
// table), and impacts of two balls whose centres are not level. The
// impulses themselves are in airborne.cpp (src/physics/airborne.hpp).
//
// A rail in three dimensions. Every wall of the table is a rail whose
// nose, at height h above the slate (table.cushion_height, else
// nose_height x 2R), is a horizontal edge along the wall's line, with
// the rail's face below it and its top level with it behind it. For a
// ball of radius R whose centre is d from the wall's line (inside the
// table) and c = R + z above the slate, with e = c - h:
//   e <= 0: the ball meets the face when d = R (as on the cloth);
//   e > 0:  it meets the edge when d^2 + e^2 = R^2 (a quartic in time in
//           flight: d is linear, e a parabola);
//   a ball that crosses the line (d = 0) without meeting either has
//   e >= R: it passes above the rail and leaves the table (off_table).
// Corners and the round tips of pocket jaws are vertical posts of their
// radius and of the same height: the face when e <= 0 (only the arc's
// own directions, as on the cloth), and for e > 0 the top all round,
// taken as the point on the post's axis at height h, reached at the
// distance R + radius (exact for a corner; for a jaw tip of radius 1/8 in
// the ball meets it up to that radius higher than a rounded rim would).
// The top all round also stands for the ends of the neighbouring noses,
// which lie on the tip's circle: a ball above a nose's line but beyond
// its end meets the rail there.
// In flight the ball meets a pocket's hole only while its bottom is below
// the rail's top (else it flies over it), and a ball that lands inside a
// pocket's circle drops in; one that lands outside the table has left it.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/airborne.hpp"
#include "physics/engine.hpp"
#include "physics/prediction.hpp"
#include "physics/roots.hpp"

namespace breakshot::detail {

namespace {

// A ball whose flight rises higher than this has left the cloth (the
// result then reports every ball's height, "z").
constexpr double kRisen = 1e-9;

// A wall contact counts where the foot of the centre lies on the segment,
// with the slack of the walls on the cloth (predict_walls.cpp).
constexpr double kSegmentSlack = 1e-9;

// Rounds of a ball pressed between another and the slate (see
// collide_airborne_balls); the last one is plastic.
constexpr int kPressRounds = 32;

// The parting nudges after an impact in flight start at a few ulps of the
// speed and double: 24 steps reach about 1e-8 of it, plenty for rounding,
// and never enough to matter to the energy.
constexpr int kPartingSteps = 24;

Vec3 lift(Vec2 v, double z) { return {v.x, v.y, z}; }
Vec2 flat(Vec3 v) { return {v.x, v.y}; }
double dot3(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }


}  // namespace

double Engine::rail_height(std::int32_t i) const {
  return cushion_nose_height(scenario_.table.cushion, radius_[static_cast<std::size_t>(i)]);
}

void Engine::set_motion3(std::int32_t i, Vec2 v, double vz, Vec3 w) {
  const PhysicsParams& ph = scenario_.physics;
  const auto ui = static_cast<std::size_t>(i);
  Trajectory& tr = traj_[ui];
  if (!ph.airborne) {
    set_motion(i, v, w);
    return;
  }
  // The trajectory starts now (the caller moved it here): its height now.
  const double z = tr.state == MotionState::airborne ? tr.z0 : 0.0;
  if (!(z > 0.0) && vz < 0.0) {
    // Pushed into the slate: it throws the ball back (airborne.cpp).
    const Motion3 m = fixed_contact_impact({lift(v, vz), w}, {0.0, 0.0, 1.0}, radius_[ui],
                                           ph.slate_restitution, ph.sliding_friction);
    v = flat(m.velocity);
    vz = m.velocity.z;
    w = m.spin;
  }
  const bool flies = z > 0.0 || (vz > 0.0 && vz * vz >= 2.0 * ph.gravity * ph.min_bounce_height);
  if (!flies) {
    set_motion(i, v, w);
    return;
  }
  const bool was_active = !resting(tr.state);
  start_airborne(tr, v, vz, std::max(z, 0.0), w, ph);
  sync_sweep(ui);
  if (!was_active) ++moving_;
  const double apex = z + (vz > 0.0 ? vz * vz / (2.0 * ph.gravity) : 0.0);
  if (apex > kRisen) left_cloth_ = true;
}

// A ball out of play over a rail (or landed off the table): at rest and
// never predicted again, where it left.
void Engine::take_off_table(std::int32_t i, double t) {
  Trajectory& tr = traj_[static_cast<std::size_t>(i)];
  move_to(tr, t);
  tr.z0 = 0.0;
  tr.vz0 = 0.0;
  if (tr.state == MotionState::airborne) tr.state = MotionState::sliding;  // z = 0 from here
  set_motion(i, {}, {});
  tr.state = MotionState::off_table;
  update_box(tr);
  sync_sweep(static_cast<std::size_t>(i));
  if (grid_.used()) grid_.unlink(i);
}

// The end of a flight at t: the ball reaches the slate (z = 0 exactly)
// over a pocket's hole (it drops in), outside the table (it has left
// it), or on the cloth, which throws it back up or keeps it.
void Engine::take_landing(std::int32_t i, double t, Event& ev) {
  const auto ui = static_cast<std::size_t>(i);
  Trajectory& tr = traj_[ui];
  const Vec2 v = velocity_at(tr, tr.t_end);
  const Vec3 w = spin_at(tr, tr.t_end);
  const double vz = vz_at(tr, tr.t_end);
  tr.p0 = position_at(tr, tr.t_end);
  tr.t0 = t;
  tr.z0 = 0.0;
  tr.vz0 = 0.0;
  tr.state = MotionState::sliding;  // on the slate, still counted as moving
  const auto& pockets = scenario_.table.pockets;
  for (std::size_t k = 0; k < pockets.size(); ++k) {
    if (norm2(tr.p0 - pockets[k].centre) < pockets[k].radius * pockets[k].radius) {
      take_pocket(i, t);
      ev.type = EventType::ball_pocket;
      ev.pocket = static_cast<std::int32_t>(k);
      return;
    }
  }
  if (!contains(scenario_.table, tr.p0)) {
    take_off_table(i, t);
    ev.type = EventType::ball_off_table;
    ev.wall = -1;
    return;
  }
  set_motion3(i, v, vz, w);
  ev.type = EventType::ball_slate;
  ev.from = MotionState::airborne;
  ev.to = tr.state;
}

void Engine::predict_wall_airborne(const Kinematics& ki, std::size_t w, double window,
                                   Prediction& best) const {
  const double t = origin_;
  const Vec2 p = ki.p;
  const Vec2 v = ki.v;  // no horizontal force acts in flight
  const double r = ki.radius;
  const Wall& wall = scenario_.table.walls[w];
  const Box& wb = wall_box_[w];
  if (wb.lo.x - ki.box_hi.x > r || ki.box_lo.x - wb.hi.x > r || wb.lo.y - ki.box_hi.y > r ||
      ki.box_lo.y - wb.hi.y > r) {
    return;
  }
  // Height of the centre above the nose: e(s) = e0 + e1 s + e2 s^2.
  const double h = cushion_nose_height(scenario_.table.cushion, r);
  const double e0 = r + ki.z - h;
  const double e1 = ki.vz;
  const double e2 = -0.5 * ki.g;
  const auto above = [&](double s) { return e0 + e1 * s + e2 * s * s; };
  const auto kind = static_cast<std::int32_t>(w);
  if (wall.kind == WallKind::segment) {
    const Vec2 n = wall.normal;
    const double d0 = dot(n, p - wall.a);
    const double dv = dot(n, v);
    const Vec2 ab = wall.b - wall.a;
    const auto on_segment = [&](double s) {
      const double f = dot(p + v * s - wall.a, ab) / norm2(ab);
      return f >= -kSegmentSlack && f <= 1.0 + kSegmentSlack;
    };
    // The face, below the nose.
    if (dv < 0.0 && d0 >= r) {
      const double s = (d0 - r) / -dv;
      if (s <= window && above(s) <= 0.0 && on_segment(s)) {
        consider(best, t + s, EventKind::wall, kind, 0);
      }
    }
    // The nose's edge, searched only while the foot of the centre is on
    // the segment: a ball that lands in a pocket's mouth can lie within R
    // of a nose's line beyond its end, and the contact that counts comes
    // later, once it is over the nose itself.
    const double fa = dot(p - wall.a, ab) / norm2(ab);
    const double fb = dot(v, ab) / norm2(ab);
    double lo = 0.0;
    double hi = window;
    if (fb != 0.0) {
      const double s1 = (-kSegmentSlack - fa) / fb;
      const double s2 = (1.0 + kSegmentSlack - fa) / fb;
      lo = std::max(lo, std::min(s1, s2));
      hi = std::min(hi, std::max(s1, s2));
    } else if (fa < -kSegmentSlack || fa > 1.0 + kSegmentSlack) {
      hi = -1.0;
    }
    if (lo <= hi) {
      // The distance to the edge from lo on: d = dl + dv u, e = el + el1 u + e2 u^2.
      const double dl = d0 + dv * lo;
      const double el = above(lo);
      const double el1 = e1 + 2.0 * e2 * lo;
      const double c[5] = {dl * dl + el * el - r * r, 2.0 * (dl * dv + el * el1),
                           dv * dv + el1 * el1 + 2.0 * el * e2, 2.0 * el1 * e2, e2 * e2};
      double s = kInf;
      if (lo > 0.0 && c[0] <= 0.0) {
        s = lo;  // it comes over the nose's end already within reach: the end
      } else {
        const double u = first_contact(c, 4, hi - lo);
        if (u <= hi - lo) s = lo + u;
      }
      if (s <= window && above(s) > 0.0 && d0 + dv * s >= 0.0) {
        consider(best, t + s, EventKind::wall, kind, 0);
      }
    }
    // Over the rail: the centre crosses the nose's line above it.
    if (dv < 0.0 && d0 >= 0.0) {
      const double s3 = d0 / -dv;
      if (s3 <= window && above(s3) > 0.0 && on_segment(s3)) {
        consider(best, t + s3, EventKind::off, kind, 0);
      }
    }
    return;
  }
  const double reach = r + (wall.kind == WallKind::arc ? wall.radius : 0.0);
  const Vec2 d = p - wall.a;
  const double c[5] = {norm2(d) + e0 * e0 - reach * reach, 2.0 * (dot(d, v) + e0 * e1),
                       norm2(v) + e1 * e1 + 2.0 * e0 * e2, 2.0 * e1 * e2, e2 * e2};
  const auto on_arc = [&](double s) {
    if (wall.kind != WallKind::arc) return true;
    const Vec2 q = p + v * s - wall.a;
    const double slack = kSegmentSlack * norm(q);
    return cross(wall.b, q) >= -slack && cross(q, wall.normal) >= -slack;
  };
  // The post's side below its top: the horizontal distance reaches reach.
  if (dot(d, v) < 0.0) {
    const double s = first_contact_quadratic(norm2(d) - reach * reach, dot(d, v), norm2(v));
    if (s <= window && above(s) <= 0.0 && on_arc(s))
      consider(best, t + s, EventKind::wall, kind, 0);
  }
  // The top, all round: where the arc's directions end, the nearest
  // points of the rail are the ends of the neighbouring noses, which lie
  // on the same circle (their own edges count only along their length).
  const double s = first_contact(c, 4, window);
  if (s <= window && above(s) > 0.0) consider(best, t + s, EventKind::wall, kind, 0);
}

// A ball in flight meets wall w (the trajectory moved to the contact):
// the contact normal from the face, the nose's edge or the post's top,
// and the impulse of a fixed contact with the ball's wall restitution and
// the cushion's friction.
void Engine::collide_airborne_wall(std::int32_t i, std::int32_t w) {
  const auto ui = static_cast<std::size_t>(i);
  Trajectory& A = traj_[ui];
  const Wall& wall = scenario_.table.walls[static_cast<std::size_t>(w)];
  const double r = radius_[ui];
  const double e = r + A.z0 - rail_height(i);
  Vec2 across;  // horizontal, from the wall to the centre
  double d = 0.0;
  if (wall.kind == WallKind::segment) {
    across = wall.normal;
    d = dot(wall.normal, A.p0 - wall.a);
  } else {
    // The post's top is met from the point on its axis at the nose's
    // height (predict_wall_airborne), so the normal comes from there.
    const Vec2 q = A.p0 - wall.a;
    d = norm(q);
    across = d > 0.0 ? q / d : Vec2{1.0, 0.0};
  }
  Vec3 n{across.x, across.y, 0.0};
  if (e > 0.0) {
    const double len = std::sqrt(d * d + e * e);
    if (len > 0.0) n = {across.x * (d / len), across.y * (d / len), e / len};
  }
  const double vc = scenario_.physics.collapse_speed;
  const Vec3 v3 = lift(A.v0, A.vz0);
  const double closing = -dot3(v3, n);
  const double restitution = closing < vc ? 1.0 : scenario_.balls[ui].wall_restitution;
  const Motion3 out =
      fixed_contact_impact({v3, A.w0}, n, r, restitution, scenario_.table.cushion.friction);
  set_motion3(i, flat(out.velocity), out.velocity.z, out.spin);
  // Resting on a nose, gravity presses the ball into it: it leaves at
  // collapse_speed (the pressed rule), else it would bounce on it forever
  // in shrinking hops.
  {
    const Vec3 now = lift(A.v0, A.state == MotionState::airborne ? A.vz0 : 0.0);
    const double away = dot3(now, n);
    if (n.z > 0.0 && away < vc) {
      const Vec3 v = now + n * (vc - away);
      set_motion3(i, flat(v), v.z, A.w0);
    }
  }
  // Leave the contact in the predictor's arithmetic (as on the cloth).
  double extra = 4.0 * std::numeric_limits<double>::epsilon() * std::max(norm(A.v0), vc);
  for (int k = 0; k < kPartingSteps; ++k, extra *= 2.0) {
    const double vz = A.state == MotionState::airborne ? A.vz0 : 0.0;
    if (d * dot(across, A.v0) + std::max(e, 0.0) * vz > 0.0) break;
    set_motion3(i, A.v0 + across * extra, vz, A.w0);
  }
}

// Two balls meet and one (or both) is in flight: the impact along the
// line of centres in three dimensions (airborne.cpp), then each ball's
// new motion from its height (a ball on the cloth pushed down bounces off
// the slate; one pushed up takes off).
void Engine::collide_airborne_balls(std::int32_t i, std::int32_t j) {
  const auto ui = static_cast<std::size_t>(i);
  const auto uj = static_cast<std::size_t>(j);
  Trajectory& A = traj_[ui];
  Trajectory& B = traj_[uj];
  const auto height = [](const Trajectory& tr) {
    return tr.state == MotionState::airborne ? tr.z0 : 0.0;
  };
  const auto rise = [](const Trajectory& tr) {
    return tr.state == MotionState::airborne ? tr.vz0 : 0.0;
  };
  const double ra = radius_[ui];
  const double rb = radius_[uj];
  const Vec3 ca = lift(A.p0, ra + height(A));
  const Vec3 cb = lift(B.p0, rb + height(B));
  const Motion3 ma{lift(A.v0, rise(A)), A.w0};
  const Motion3 mb{lift(B.v0, rise(B)), B.w0};
  const Vec3 dc = cb - ca;
  const double len = std::sqrt(dot3(dc, dc));
  const double closing = len > 0.0 ? dot3(ma.velocity - mb.velocity, dc) / len : 0.0;
  const PhysicsParams& ph = scenario_.physics;
  const double e = closing < ph.collapse_speed ? 1.0 : pair_restitution(i, j);
  const FrictionCurve& curve = ph.ball_ball_friction_curve;
  const BallFriction friction = ph.ball_ball_friction_fit
                                    ? BallFriction{curve.a, curve.b, curve.c}
                                    : BallFriction{ph.ball_ball_friction, 0.0, 0.0};
  // A ball on the cloth pushed down is pressed between the other ball
  // and the slate: the impacts are taken in turn (the pair's, then the
  // slate's on the ball pushed into it) until the pair parts. Each round
  // loses energy (e_s < 1), so the rounds shrink geometrically.
  Motion3 a = ma;
  Motion3 b = mb;
  const Vec3 up{0.0, 0.0, 1.0};
  const auto slate = [&](Motion3& m, const Trajectory& tr, double r) {
    if (tr.state != MotionState::airborne && m.velocity.z < 0.0) {
      m = fixed_contact_impact(m, up, r, ph.slate_restitution, ph.sliding_friction);
    }
  };
  for (int round = 0; round < kPressRounds; ++round) {
    const double e_round = round + 1 < kPressRounds ? e : 0.0;
    const Impact3 r = ball_ball_impact_3d(ca, a, scenario_.balls[ui].mass, ra, cb, b,
                                          scenario_.balls[uj].mass, rb, e_round, friction);
    a = r.a;
    b = r.b;
    slate(a, A, ra);
    slate(b, B, rb);
    if (!(dot3(a.velocity - b.velocity, dc) > 0.0)) break;  // parting
  }
  // What the slate left pushed down (after the last round) it takes up.
  if (A.state != MotionState::airborne && a.velocity.z < 0.0) a.velocity.z = 0.0;
  if (B.state != MotionState::airborne && b.velocity.z < 0.0) b.velocity.z = 0.0;
  set_motion3(i, flat(a.velocity), a.velocity.z, a.spin);
  set_motion3(j, flat(b.velocity), b.velocity.z, b.spin);
  // A pair that leaves slower than collapse_speed while gravity (or the
  // cloth's friction) presses it together, as a ball resting on another
  // does, leaves at collapse_speed (the pressed-pair rule of the cloth,
  // docs/physics-core.md): else it would meet again at once, forever. The
  // extra impulse acts along the line of centres; a ball on the cloth
  // takes only its level part (the slate holds it), and then the parting
  // nudges of a few ulps make the pair part in the predictor's arithmetic.
  const Vec2 dp = B.p0 - A.p0;
  const double dz = (rb + height(B)) - (ra + height(A));
  const double dist = std::sqrt(norm2(dp) + dz * dz);
  if (!(dist > 0.0)) return;
  const Vec3 n3{dp.x / dist, dp.y / dist, dz / dist};
  const bool a_flies = A.state == MotionState::airborne;
  const bool b_flies = B.state == MotionState::airborne;
  const double ma_inv = 1.0 / scenario_.balls[ui].mass;
  const double mb_inv = 1.0 / scenario_.balls[uj].mass;
  const double level2 = n3.x * n3.x + n3.y * n3.y;
  // Relative normal velocity change per unit impulse.
  const double per_impulse =
      (a_flies ? ma_inv : ma_inv * level2) + (b_flies ? mb_inv : mb_inv * level2);
  const auto separation = [&] { return dot3(lift(B.v0, rise(B)) - lift(A.v0, rise(A)), n3); };
  const auto push = [&](double impulse) {
    const Vec3 pa = n3 * (-impulse * ma_inv);
    const Vec3 pb = n3 * (impulse * mb_inv);
    set_motion3(i, A.v0 + flat(pa), rise(A) + (a_flies ? pa.z : 0.0), A.w0);
    set_motion3(j, B.v0 + flat(pb), rise(B) + (b_flies ? pb.z : 0.0), B.w0);
  };
  const Vec3 acc_a{A.acc.x, A.acc.y, a_flies ? -A.gravity : 0.0};
  const Vec3 acc_b{B.acc.x, B.acc.y, b_flies ? -B.gravity : 0.0};
  const double out = separation();
  if (per_impulse > 0.0 && out < ph.collapse_speed && dot3(acc_b - acc_a, n3) < 0.0) {
    push((ph.collapse_speed - out) / per_impulse);
  }
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max({norm(A.v0), norm(B.v0), ph.collapse_speed});
  for (int k = 0; k < kPartingSteps && per_impulse > 0.0; ++k, extra *= 2.0) {
    if (dot(dp, B.v0 - A.v0) + dz * (rise(B) - rise(A)) > 0.0) break;
    push(extra / per_impulse);
  }
}

}  // namespace breakshot::detail
