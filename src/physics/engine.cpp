// The event loop: predict each ball's earliest event, pop the earliest of
// all, re-check it, advance only the balls involved, resolve, re-predict.
// docs/architecture.md follows one scenario through this file.
#include "physics/engine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "breakshot/pool.hpp"
#include "breakshot/roots.hpp"

namespace breakshot::detail {

namespace {

// With ball_clusters, the working memory of cluster impacts is reserved at
// set-up for up to this many balls (any pool game); larger scenes grow it
// when a cluster first needs it.
constexpr std::size_t kClusterReserveBalls = 64;

// A wall contact counts if the foot of the ball's centre on the wall's
// line lies on the segment, with this much slack (as a fraction of the
// segment's length) so that a ball arriving exactly at the junction of
// two walls is caught by one of them.
constexpr double kSegmentSlack = 1e-9;

}  // namespace

// ---------------------------------------------------------------------------
// Set-up

Engine::Engine(const Scenario& scenario) : scenario_(scenario) {
  const std::size_t n = scenario_.balls.size();
  traj_.resize(n);
  radius_.resize(n);
  for (std::size_t i = 0; i < n; ++i) radius_[i] = scenario_.balls[i].radius;
  ideal_ = scenario_.physics.model == Model::ideal;
  // Corner walls exist exactly where a polygon has a reflex vertex.
  convex_ = std::none_of(scenario_.table.walls.begin(), scenario_.table.walls.end(),
                         [](const Wall& w) { return w.kind != WallKind::segment; });
  counter_.assign(n, 0);
  // Room for the events of a typical shot, so that simulating one
  // allocates nothing after set-up (a break has about 100 events).
  events_.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(scenario_.max_events, 64 + 16 * n)));
  if (scenario_.physics.ball_clusters && n <= kClusterReserveBalls) {
    // A cluster holds at most every ball; each impact on one adds an
    // event per pair that touched (about three per ball in a rack), and
    // the events of a spread rack come on top.
    events_.reserve(events_.capacity() + 4 * n);
    const std::size_t pairs = n * (n - 1) / 2;
    cluster_group_.reserve(n);
    cluster_place_.reserve(n);
    cluster_place_index_.reserve(n);
    cluster_bodies_.reserve(n);
    cluster_scratch_.position.reserve(n);
    cluster_scratch_.velocity.reserve(n);
    cluster_scratch_.pairs.reserve(pairs);
    cluster_out_.velocity.reserve(n);
    cluster_out_.touched.reserve(pairs);
  }
  event_.resize(n);
  queue_.reset(n);
  for (std::size_t i = 0; i < n; ++i) {
    Trajectory& tr = traj_[i];
    tr.t0 = 0.0;
    tr.p0 = scenario_.start[i].position;
    tr.w0 = scenario_.start[i].spin;
    tr.state = MotionState::stationary;
    tr.t_end = kInf;
    set_motion(static_cast<std::int32_t>(i), scenario_.start[i].velocity, scenario_.start[i].spin);
  }

  // Boxes around the walls, to skip the ones a ball's path never nears.
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

  // Pair restitutions, sorted for binary search at collision time.
  std::vector<std::pair<std::uint64_t, double>> pairs;
  for (const PairRestitution& p : scenario_.pair_restitution) {
    const auto a = static_cast<std::uint64_t>(std::min(p.a, p.b));
    const auto b = static_cast<std::uint64_t>(std::max(p.a, p.b));
    pairs.emplace_back(a * n + b, p.restitution);
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [k, e] : pairs) {
    pair_keys_.push_back(k);
    pair_values_.push_back(e);
  }

  if (n >= kCellThreshold) {
    // With many balls, the grid of cells.
    double max_r = 0.0;
    for (const BallSpec& b : scenario_.balls) max_r = std::max(max_r, b.radius);
    if (grid_.build(scenario_.table.min, scenario_.table.max, n, max_r)) {
      for (std::size_t i = 0; i < n; ++i) {
        const auto bi = static_cast<std::int32_t>(i);
        grid_.link(bi, grid_.index(traj_[i].p0));
      }
      // Cluster impacts gather the balls within kClusterGap of a member:
      // their cells are at most this many away, one more for a ball on a
      // cell's edge whose crossing falls at the impact's time.
      cluster_reach_ =
          static_cast<std::int32_t>(std::ceil((2.0 * max_r + kClusterGap) / grid_.cell_size())) + 1;
    }
  }

  // The cue strike: the shot's first event, at t = 0. A miscue is
  // reported (cue_result) and not played.
  if (scenario_.cue && scenario_.cue->ball >= 0 &&
      static_cast<std::size_t>(scenario_.cue->ball) < n) {
    const CueSpec& cue = *scenario_.cue;
    const auto ub = static_cast<std::size_t>(cue.ball);
    cue_result_ = strike(cue.strike, scenario_.balls[ub].mass, radius_[ub], cue.params);
    if (!cue_result_->miscue) {
      set_motion(cue.ball, cue_result_->velocity, cue_result_->spin);
      Event ev;
      ev.time = 0.0;
      ev.type = EventType::cue_strike;
      ev.ball = cue.ball;
      events_.push_back(ev);
      ++event_count_;
      ++counter_[ub];
    }
  }

  for (std::size_t i = 0; i < n; ++i) predict(static_cast<std::int32_t>(i));
  queue_.build();
}

// ---------------------------------------------------------------------------
// The state of the balls

std::vector<BallState> Engine::balls() const {
  std::vector<BallState> out;
  out.reserve(traj_.size());
  for (std::size_t i = 0; i < traj_.size(); ++i) out.push_back(ball(i));
  return out;
}

// ---------------------------------------------------------------------------
// Prediction

namespace {

// Among a ball's candidate events at the same time the order is fixed by
// kind (ball, wall, stop, cell) and then by index, so the choice never
// depends on the order in which candidates were examined (cells list
// balls in arbitrary order).
template <class P, class K>
void consider(P& best, double t, K kind, std::int32_t other, std::uint64_t counter) {
  if (best.kind == K::none || t < best.time ||
      (t == best.time && (kind < best.kind || (kind == best.kind && other < best.other)))) {
    best = {t, kind, other, counter};
  }
}

// The part of a window worth searching: a contact later than the best
// candidate so far can never be taken, so the search stops a little past
// it (the slack covers the rounding of t + tau; anything found beyond the
// best loses in `consider`).
template <class P>
double within_best(const P& best, double t, double window) {
  const double left = best.time - t;
  return std::min(window, left + left * 1e-12 + best.time * 1e-15);
}

}  // namespace

Engine::Kinematics Engine::kinematics(std::int32_t i) const {
  const Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const double t = origin_;
  Kinematics k;
  k.p = position_at(A, t);
  k.v = velocity_at(A, t);
  k.a = t < A.t_end ? A.acc : Vec2{};
  k.t_end = A.t_end;
  k.radius = scenario_.balls[static_cast<std::size_t>(i)].radius;
  k.still = !translating(A.state);
  k.box_lo = A.box_lo;
  k.box_hi = A.box_hi;
  return k;
}

// Inlined into the neighbour loops: it is most of the cost of an event.
[[gnu::always_inline]] inline void Engine::predict_ball_pair(const Kinematics& ki,
                                                                  std::int32_t j,
                                                                  Prediction& best) const {
  const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  if (ideal_) {
    // No ball ever accelerates: the quadratic case, written out because
    // this loop is most of the cost of an event.
    const double t = origin_;
    const double dt = t - B.t0;
    const Vec2 dp = B.p0 + B.v0 * dt - ki.p;
    const Vec2 dv = B.v0 - ki.v;
    const double b = dot(dp, dv);
    if (b >= 0.0) return;  // not approaching
    const double sigma = ki.radius + radius_[static_cast<std::size_t>(j)];
    const double c = norm2(dp) - sigma * sigma;
    // The root c / (-b + sqrt(b^2 - a c)) is at least c / (-2 b): skip
    // the square root when even that is later than the best so far.
    if (c > 0.0 && c > (best.time - t) * (-2.0 * b)) return;
    // first_contact_quadratic, inlined.
    double tau = 0.0;
    if (c > 0.0) {
      const double disc = b * b - norm2(dv) * c;
      if (disc < 0.0) return;
      tau = c / (-b + std::sqrt(disc));
    }
    consider(best, t + tau, EventKind::ball, j, counter_[static_cast<std::size_t>(j)]);
    return;
  }
  predict_accelerating_pair(ki, j, best);
}

void Engine::predict_accelerating_pair(const Kinematics& ki, std::int32_t j,
                                           Prediction& best) const {
  const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  if (B.state == MotionState::pocketed) return;
  const bool b_still = !translating(B.state);
  if (ki.still && b_still) return;
  const double sigma = ki.radius + radius_[static_cast<std::size_t>(j)];
  if (B.box_lo.x - ki.box_hi.x > sigma || ki.box_lo.x - B.box_hi.x > sigma ||
      B.box_lo.y - ki.box_hi.y > sigma || ki.box_lo.y - B.box_hi.y > sigma) {
    return;  // their paths never come within reach
  }
  const double t = origin_;
  // B's kinematics at t, inline (this is the innermost loop).
  const double dt = std::min(t, B.t_end) - B.t0;
  const Vec2 pb = B.p0 + B.v0 * dt + B.acc * (0.5 * dt * dt);
  const bool b_moves = t < B.t_end;
  const Vec2 dp = pb - ki.p;
  const Vec2 dv = (b_moves ? B.v0 + B.acc * dt : Vec2{}) - ki.v;
  const Vec2 da = (b_moves ? B.acc : Vec2{}) - ki.a;
  const double dist2 = norm2(dp);
  double tau = kInf;
  if (da.x == 0.0 && da.y == 0.0) {
    const double b = dot(dp, dv);
    if (b >= 0.0) return;  // moving apart or not at all: never closer
    tau = first_contact_quadratic(dist2 - sigma * sigma, b, norm2(dv));
    if (!(tau <= std::min(ki.t_end, B.t_end) - t)) return;
  } else {
    const double window =
        within_best(best, t, std::max(0.0, std::min(ki.t_end, B.t_end) - t));
    // Cheap rejection: the gap can close by at most |dv| w + |da| w^2 / 2.
    const double gap = std::sqrt(dist2) - sigma;
    const double w = window;
    if (gap > 0.0 && w < kInf && norm(dv) * w + 0.5 * norm(da) * w * w < gap) return;
    // |dp + dv s + da s^2 / 2|^2 - sigma^2 as a quartic in s.
    const double c[5] = {dist2 - sigma * sigma, 2.0 * dot(dp, dv), norm2(dv) + dot(dp, da),
                         dot(dv, da), 0.25 * norm2(da)};
    tau = first_contact(c, 4, window);
    if (!(tau < kInf)) return;
  }
  consider(best, t + tau, EventKind::ball, j, counter_[static_cast<std::size_t>(j)]);
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
      predict_wall(ki, w, within_best(best, t, std::max(0.0, ki.t_end - t)), best);
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

// A ball falls into a pocket when its centre comes within the pocket's
// radius of the pocket's centre (docs/physics.md, "Pockets").
void Engine::predict_pockets(const Kinematics& ki, Prediction& best) const {
  if (ki.still) return;
  const double t = origin_;
  const double window = within_best(best, t, std::max(0.0, ki.t_end - t));
  const auto& pockets = scenario_.table.pockets;
  for (std::size_t k = 0; k < pockets.size(); ++k) {
    const Vec2 centre = pockets[k].centre;
    const double pr = pockets[k].radius;
    if (centre.x - pr > ki.box_hi.x || ki.box_lo.x > centre.x + pr ||
        centre.y - pr > ki.box_hi.y || ki.box_lo.y > centre.y + pr) {
      continue;
    }
    const Vec2 d = ki.p - centre;
    const double rr = pockets[k].radius * pockets[k].radius;
    double tau = kInf;
    if (ki.a.x == 0.0 && ki.a.y == 0.0) {
      const double b = dot(d, ki.v);
      if (b >= 0.0) continue;
      tau = first_contact_quadratic(norm2(d) - rr, b, norm2(ki.v));
    } else {
      const double c[5] = {norm2(d) - rr, 2.0 * dot(d, ki.v), norm2(ki.v) + dot(d, ki.a),
                           dot(ki.v, ki.a), 0.25 * norm2(ki.a)};
      tau = first_contact(c, 4, window);
    }
    if (tau <= window) consider(best, t + tau, EventKind::pocket, static_cast<std::int32_t>(k), 0);
  }
}

void Engine::predict_cell(std::int32_t i, Prediction& best) const {
  const Trajectory& A = traj_[static_cast<std::size_t>(i)];
  if (!translating(A.state)) return;
  const double t = origin_;
  const double window = std::max(0.0, A.t_end - t);
  const Vec2 p = position_at(A, t);
  const Vec2 v = velocity_at(A, t);
  const Vec2 a = t < A.t_end ? A.acc : Vec2{};
  const std::int32_t cell = grid_.cell_of(i);
  const std::int32_t cx = cell % grid_.nx();
  const std::int32_t cy = cell / grid_.nx();
  const double size = grid_.cell_size();
  const double lo[2] = {grid_.origin().x + size * cx, grid_.origin().y + size * cy};
  const double pos[2] = {p.x, p.y};
  const double vel[2] = {v.x, v.y};
  const double acc[2] = {a.x, a.y};
  const std::int32_t idx[2] = {cx, cy};
  const std::int32_t count[2] = {grid_.nx(), grid_.ny()};
  // Direction codes: 0 = +x, 1 = -x, 2 = +y, 3 = -y. Leaving a cell is a
  // "contact" of the ball's centre with the cell's edge, found with the
  // same root finder as the collisions.
  for (int axis = 0; axis < 2; ++axis) {
    if (acc[axis] == 0.0) {
      // Straight motion along this axis (always so in the ideal model):
      // the crossing time is a division.
      if (vel[axis] > 0.0 && idx[axis] + 1 < count[axis]) {
        const double tau = std::max(0.0, (lo[axis] + size - pos[axis]) / vel[axis]);
        if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis, 0);
      } else if (vel[axis] < 0.0 && idx[axis] > 0) {
        const double tau = std::max(0.0, (lo[axis] - pos[axis]) / vel[axis]);
        if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis + 1, 0);
      }
      continue;
    }
    if (idx[axis] + 1 < count[axis]) {
      const double c[3] = {lo[axis] + size - pos[axis], -vel[axis], -0.5 * acc[axis]};
      const double tau = first_contact(c, 2, window);
      if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis, 0);
    }
    if (idx[axis] > 0) {
      const double c[3] = {pos[axis] - lo[axis], vel[axis], 0.5 * acc[axis]};
      const double tau = first_contact(c, 2, window);
      if (tau <= window) consider(best, t + tau, EventKind::cell, 2 * axis + 1, 0);
    }
  }
}

void Engine::predict_cells(std::int32_t i, const Kinematics& ki, std::int32_t x0,
                               std::int32_t x1, std::int32_t y0, std::int32_t y1,
                               Prediction& best) const {
  x0 = std::max(0, x0);
  y0 = std::max(0, y0);
  x1 = std::min(grid_.nx() - 1, x1);
  y1 = std::min(grid_.ny() - 1, y1);
  for (std::int32_t y = y0; y <= y1; ++y) {
    for (std::int32_t x = x0; x <= x1; ++x) {
      for (std::int32_t j = grid_.first(y * grid_.nx() + x); j >= 0; j = grid_.next(j)) {
        if (j != i) predict_ball_pair(ki, j, best);
      }
    }
  }
}

void Engine::predict(std::int32_t i) {
  const auto ui = static_cast<std::size_t>(i);
  Prediction best{kInf, EventKind::none, -1, 0};
  if (traj_[ui].state == MotionState::pocketed) {
    event_[ui] = best;
    queue_.set(i, best);
    return;
  }
  const Kinematics ki = kinematics(i);

  // breaks ties by kind and index), but each search stops at the best
  // candidate so far, so the cheap ones go first.
  const Trajectory& tr = traj_[ui];
  if (!resting(tr.state) && tr.t_end < kInf) {
    consider(best, tr.t_end, EventKind::stop, -1, 0);
  }
  if (grid_.used()) {
    const std::int32_t cell = grid_.cell_of(i);
    const std::int32_t cx = cell % grid_.nx();
    const std::int32_t cy = cell / grid_.nx();
    predict_cells(i, ki, cx - 1, cx + 1, cy - 1, cy + 1, best);
  } else {
    const auto n = static_cast<std::int32_t>(traj_.size());
    for (std::int32_t j = 0; j < n; ++j) {
      if (j != i) predict_ball_pair(ki, j, best);
    }
  }
  predict_walls(ki, best);
  if (!scenario_.table.pockets.empty()) predict_pockets(ki, best);
  event_[ui] = best;
  finish_prediction(i);
}

void Engine::finish_prediction(std::int32_t i) {
  const auto ui = static_cast<std::size_t>(i);
  Prediction best = event_[ui];
  if (grid_.used()) predict_cell(i, best);
  queue_.set(i, best);
}

// ---------------------------------------------------------------------------
// Collisions

double Engine::pair_restitution(std::int32_t i, std::int32_t j) const {
  if (pair_keys_.empty()) return scenario_.physics.ball_ball_restitution;
  const auto n = static_cast<std::uint64_t>(traj_.size());
  const auto a = static_cast<std::uint64_t>(std::min(i, j));
  const auto b = static_cast<std::uint64_t>(std::max(i, j));
  const auto it = std::lower_bound(pair_keys_.begin(), pair_keys_.end(), a * n + b);
  if (it != pair_keys_.end() && *it == a * n + b) {
    return pair_values_[static_cast<std::size_t>(it - pair_keys_.begin())];
  }
  return scenario_.physics.ball_ball_restitution;
}

// The separating normal speed after an impact with closing speed
// `closing`. Inelastic collapse (Luding & McNamara 1998; McNamara &
// Falcon 2005 use a restitution that tends to 1 at low impact speed): an
// impact slower than collapse_speed is elastic, so a cluster cannot make
// infinitely many ever-softer collisions in finite time. It never adds
// energy: the result is at most `closing`.
double Engine::outgoing_speed(double closing, double restitution) const {
  if (closing <= 0.0) return 0.0;
  if (closing < scenario_.physics.collapse_speed) return closing;
  return restitution * closing;
}

// True if a contact left at normal speed `out` with normal acceleration
// `acc_n` (negative: back into contact) closes again before `window`
// ends, at a speed too low for the collapse rule to end the sequence.
// With the friction model's deceleration a ball never turns back, so a
// single ball leaving a wall is never pressed; two balls whose
// decelerations differ can be.
bool Engine::pressed(double out, double acc_n, double window) const {
  if (out >= scenario_.physics.collapse_speed || !(acc_n < 0.0)) return false;
  return 2.0 * out < -acc_n * window;
}

// The pool model's impacts: friction between the balls (throw, spin
// transfer) and the cushion model, with the same collapse and parting
// rules as the simpler models.
void Engine::collide_pool_balls(std::int32_t i, std::int32_t j) {
  const auto ui = static_cast<std::size_t>(i);
  const auto uj = static_cast<std::size_t>(j);
  Trajectory& A = traj_[ui];
  Trajectory& B = traj_[uj];
  const double ma = scenario_.balls[ui].mass;
  const double mb = scenario_.balls[uj].mass;
  Vec2 n = B.p0 - A.p0;
  const double len = norm(n);
  n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  const double closing = dot(A.v0 - B.v0, n);
  const double vc = scenario_.physics.collapse_speed;
  const double e = closing < vc ? 1.0 : pair_restitution(i, j);
  const PhysicsParams& ph = scenario_.physics;
  const BallFriction friction = ph.ball_ball_friction_fit
                                    ? BallFriction{}
                                    : BallFriction{ph.ball_ball_friction, 0.0, 0.0};
  const BallImpact r = ball_ball_impact(A.p0, A.v0, A.w0, ma, radius_[ui], B.p0, B.v0, B.w0, mb,
                                        radius_[uj], e, friction);
  set_motion(i, r.v1, r.w1);
  set_motion(j, r.v2, r.w2);
  const double reduced = ma * mb / (ma + mb);
  auto push = [&](double dv) {  // extra normal impulse reduced * dv
    const double impulse = reduced * dv;
    set_motion(i, A.v0 - n * (impulse / ma), A.w0);
    set_motion(j, B.v0 + n * (impulse / mb), B.w0);
  };
  const double out = dot(B.v0 - A.v0, n);
  // A pool ball's phase can end within a nanosecond (a tiny slip), while
  // the push goes on in the next phase: any inward push counts here.
  if (pressed(out, dot(B.acc - A.acc, n), kInf)) push(vc - out);
  const Vec2 dp = B.p0 - A.p0;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max({norm(A.v0), norm(B.v0), vc});
  for (int k = 0; k < 64 && dot(dp, B.v0 - A.v0) < 0.0; ++k, extra *= 2.0) push(extra);
}

// An impact of i on j (both moved to t) when more balls lie within
// kClusterGap of them, or of each other, in a chain: the whole cluster is
// resolved at once (cluster_impact.hpp). Returns false, doing nothing,
// for a lone pair or a contact slower than collapse_speed; else applies
// the new velocities (spins unchanged; the pairwise impact on top when
// i and j still close), records a ball_ball event for
// (i, j) and then one for every other pair that exchanged an impulse, and
// predicts again for every ball of the cluster.
bool Engine::collide_cluster(std::int32_t i, std::int32_t j, double t) {
  const Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  const Vec2 d = B.p0 - A.p0;
  const double len = norm(d);
  if (!(len > 0.0) || dot(A.v0 - B.v0, d) / len < scenario_.physics.collapse_speed) return false;
  std::vector<std::int32_t>& group = cluster_group_;
  group.clear();
  group.push_back(i);
  group.push_back(j);
  const auto n = static_cast<std::int32_t>(traj_.size());
  // Ball k joins when its place at t is within kClusterGap of group
  // member g's. Members are taken in order and, for each, the candidates
  // in increasing index, so the group (and so the result) is the same
  // whether every ball is a candidate or only those of the cells nearby.
  const auto join = [&](std::size_t ug, Vec2 pg, std::int32_t k, Vec2 pk) {
    const auto uk = static_cast<std::size_t>(k);
    if (norm(pk - pg) - radius_[uk] - radius_[ug] < kClusterGap &&
        std::find(group.begin(), group.end(), k) == group.end()) {
      move_to(traj_[uk], t);
      group.push_back(k);
    }
  };
  if (grid_.used()) {
    // Only the balls of the cells within reach: a large scene pays for
    // the balls near the impact, not for all of them.
    std::vector<std::int32_t>& near = cluster_place_index_;
    for (std::size_t g = 0; g < group.size(); ++g) {
      const auto ug = static_cast<std::size_t>(group[g]);
      const Vec2 pg = traj_[ug].p0;
      const std::int32_t cx = grid_.cell_of(group[g]) % grid_.nx();
      const std::int32_t cy = grid_.cell_of(group[g]) / grid_.nx();
      near.clear();
      for (std::int32_t y = std::max(0, cy - cluster_reach_);
           y <= std::min(grid_.ny() - 1, cy + cluster_reach_); ++y) {
        for (std::int32_t x = std::max(0, cx - cluster_reach_);
             x <= std::min(grid_.nx() - 1, cx + cluster_reach_); ++x) {
          for (std::int32_t k = grid_.first(y * grid_.nx() + x); k >= 0; k = grid_.next(k)) {
            if (traj_[static_cast<std::size_t>(k)].state != MotionState::pocketed) {
              near.push_back(k);
            }
          }
        }
      }
      std::sort(near.begin(), near.end());
      for (std::int32_t k : near) {
        join(ug, pg, k, position_at(traj_[static_cast<std::size_t>(k)], t));
      }
    }
  } else {
    // Every ball's place at t, once (pocketed balls are never gathered).
    std::vector<Vec2>& at = cluster_place_;
    at.clear();
    for (std::int32_t k = 0; k < n; ++k) {
      const Trajectory& tk = traj_[static_cast<std::size_t>(k)];
      at.push_back(tk.state == MotionState::pocketed ? Vec2{} : position_at(tk, t));
    }
    for (std::size_t g = 0; g < group.size(); ++g) {
      const auto ug = static_cast<std::size_t>(group[g]);
      const Vec2 pg = traj_[ug].p0;
      for (std::int32_t k = 0; k < n; ++k) {
        if (traj_[static_cast<std::size_t>(k)].state == MotionState::pocketed) continue;
        join(ug, pg, k, at[static_cast<std::size_t>(k)]);
      }
    }
  }
  if (group.size() < 3) return false;
  std::vector<ClusterBody>& bodies = cluster_bodies_;
  bodies.clear();
  for (std::int32_t k : group) {
    const auto uk = static_cast<std::size_t>(k);
    bodies.push_back({traj_[uk].p0, traj_[uk].v0, radius_[uk], scenario_.balls[uk].mass});
  }
  struct Restitution final : ClusterRestitution {
    const Engine* sim;
    const std::vector<std::int32_t>* ids;
    Restitution(const Engine* s, const std::vector<std::int32_t>* g) : sim(s), ids(g) {}
    double at(int a, int b) const override {
      return sim->pair_restitution((*ids)[static_cast<std::size_t>(a)], (*ids)[static_cast<std::size_t>(b)]);
    }
  };
  const Restitution restitution(this, &group);
  ClusterOutcome& r = cluster_out_;
  cluster_impact(bodies, restitution, cluster_scratch_, r);
  for (std::size_t g = 0; g < group.size(); ++g) {
    const std::int32_t k = group[g];
    if (scenario_.physics.model == Model::pool) {
      set_motion(k, r.velocity[g], traj_[static_cast<std::size_t>(k)].w0);
    } else {
      set_velocity(k, r.velocity[g]);
    }
    ++counter_[static_cast<std::size_t>(k)];
  }
  // A grazing contact (closing far slower than the balls slide past each
  // other) can leave the cluster's contacts with next to no impulse while
  // the pair, frozen where it touched, still closes: the pairwise impact
  // then settles that pair, so the same contact never comes up again.
  if (dot(traj_[static_cast<std::size_t>(j)].v0 - traj_[static_cast<std::size_t>(i)].v0, d) < 0.0) {
    collide_balls(i, j);
  }
  Event ev;
  ev.time = t;
  ev.type = EventType::ball_ball;
  ev.ball = std::min(i, j);
  ev.other = std::max(i, j);
  events_.push_back(ev);
  ++event_count_;
  for (const auto& [a, b] : r.touched) {
    const std::int32_t x = group[static_cast<std::size_t>(a)];
    const std::int32_t y = group[static_cast<std::size_t>(b)];
    if (std::min(x, y) == ev.ball && std::max(x, y) == ev.other) continue;
    Event e2 = ev;
    e2.ball = std::min(x, y);
    e2.other = std::max(x, y);
    events_.push_back(e2);
    ++event_count_;
  }
  for (std::int32_t k : group) {
    predict(k);
    queue_.fix(k);
  }
  return true;
}

void Engine::collide_pool_wall(std::int32_t i, std::int32_t w) {
  const auto ui = static_cast<std::size_t>(i);
  Trajectory& A = traj_[ui];
  const Wall& wall = scenario_.table.walls[static_cast<std::size_t>(w)];
  Vec2 n = wall.normal;
  if (wall.kind != WallKind::segment) {
    n = A.p0 - wall.a;
    const double len = norm(n);
    n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  }
  const double closing = -dot(A.v0, n);
  const double vc = scenario_.physics.collapse_speed;
  CushionParams cp = scenario_.table.cushion;
  cp.restitution = closing < vc ? 1.0 : scenario_.balls[ui].wall_restitution;
  const CushionImpact r = cushion_impact(A.v0, A.w0, n, scenario_.balls[ui].mass, radius_[ui], cp);
  set_motion(i, r.velocity, r.spin);
  const double out = dot(A.v0, n);
  if (pressed(out, dot(A.acc, n), A.t_end - A.t0)) set_motion(i, A.v0 + n * (vc - out), A.w0);
  const Vec2 away = wall.kind == WallKind::segment ? wall.normal : A.p0 - wall.a;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() * std::max(norm(A.v0), vc);
  for (int k = 0; k < 64 && dot(away, A.v0) < 0.0; ++k, extra *= 2.0) {
    set_motion(i, A.v0 + n * extra, A.w0);
  }
}

void Engine::collide_balls(std::int32_t i, std::int32_t j) {
  if (scenario_.physics.model == Model::pool) {
    collide_pool_balls(i, j);
    return;
  }
  Trajectory& A = traj_[static_cast<std::size_t>(i)];
  Trajectory& B = traj_[static_cast<std::size_t>(j)];
  const double ma = scenario_.balls[static_cast<std::size_t>(i)].mass;
  const double mb = scenario_.balls[static_cast<std::size_t>(j)].mass;
  Vec2 n = B.p0 - A.p0;
  const double len = norm(n);
  n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  const Vec2 va = A.v0;
  const Vec2 vb = B.v0;
  const double closing = dot(va - vb, n);
  const double reduced = ma * mb / (ma + mb);
  double out = outgoing_speed(closing, pair_restitution(i, j));
  double impulse = std::max(0.0, reduced * (closing + out));
  set_velocity(i, va - n * (impulse / ma));
  set_velocity(j, vb + n * (impulse / mb));
  // A pair that leaves (nearly) together while friction pushes the two
  // into each other would meet again at once, forever. Such a pair leaves
  // at collapse_speed: the only case where an impact may add energy, at
  // most reduced * collapse_speed^2 / 2 (docs/physics-core.md).
  if (pressed(out, dot(B.acc - A.acc, n), std::min(A.t_end, B.t_end) - A.t0)) {
    out = scenario_.physics.collapse_speed;
    impulse = std::max(0.0, reduced * (closing + out));
    set_velocity(i, va - n * (impulse / ma));
    set_velocity(j, vb + n * (impulse / mb));
  }
  // Round-off can leave a pair that should part (or move on together)
  // approaching by a hair in the very arithmetic the predictor uses; it
  // would then collide again at once, forever. Add the least impulse that
  // makes them part in floating point: the energy it adds is of the order
  // of the round-off itself.
  const Vec2 dp = B.p0 - A.p0;
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max({norm(va), norm(vb), scenario_.physics.collapse_speed});
  for (int k = 0; k < 64 && dot(dp, B.v0 - A.v0) < 0.0; ++k, extra *= 2.0) {
    impulse += reduced * extra;
    set_velocity(i, va - n * (impulse / ma));
    set_velocity(j, vb + n * (impulse / mb));
  }
}

void Engine::collide_wall(std::int32_t i, std::int32_t w) {
  if (scenario_.physics.model == Model::pool) {
    collide_pool_wall(i, w);
    return;
  }
  Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const Wall& wall = scenario_.table.walls[static_cast<std::size_t>(w)];
  Vec2 n = wall.normal;
  if (wall.kind != WallKind::segment) {
    n = A.p0 - wall.a;
    const double len = norm(n);
    n = len > 0.0 ? n / len : Vec2{1.0, 0.0};
  }
  const Vec2 v = A.v0;
  const double closing = -dot(v, n);
  const double e = scenario_.balls[static_cast<std::size_t>(i)].wall_restitution;
  const double out = outgoing_speed(closing, e);
  double dv = std::max(0.0, closing + out);
  set_velocity(i, v + n * dv);
  // A ball that keeps being pressed into the wall leaves at
  // collapse_speed, as a pressed pair of balls does.
  if (pressed(out, dot(A.acc, n), A.t_end - A.t0)) {
    dv = std::max(0.0, closing + scenario_.physics.collapse_speed);
    set_velocity(i, v + n * dv);
  }
  // As for two balls: leave the wall in the predictor's own arithmetic.
  double extra = 4.0 * std::numeric_limits<double>::epsilon() *
                 std::max(norm(v), scenario_.physics.collapse_speed);
  const Vec2 away = wall.kind != WallKind::segment ? A.p0 - wall.a : wall.normal;
  for (int k = 0; k < 64 && dot(away, A.v0) < 0.0; ++k, extra *= 2.0) {
    dv += extra;
    set_velocity(i, v + n * dv);
  }
}

// ---------------------------------------------------------------------------
// The loop

bool Engine::step(double limit) {
  if (queue_.empty()) return false;
  const std::int32_t i = queue_.top();
  const Prediction p = queue_.next(i);
  if (p.kind == EventKind::none || p.time > limit) return false;
  const auto ui = static_cast<std::size_t>(i);

  if (p.kind == EventKind::ball && counter_[static_cast<std::size_t>(p.other)] != p.other_counter) {
    // The partner had an event since this was predicted: predict again.
    origin_ = std::max(origin_, p.time);
    predict(i);
    queue_.fix(i);
    return true;
  }
  if (p.kind == EventKind::cell) {
    // Crossing into a neighbouring cell changes no motion, so no one
    // else's prediction is affected; only this ball looks around again.
    origin_ = std::max(origin_, p.time);
    const std::int32_t cell = grid_.cell_of(i);
    const std::int32_t cx = cell % grid_.nx() + kStepX[p.other];
    const std::int32_t cy = cell / grid_.nx() + kStepY[p.other];
    grid_.unlink(i);
    grid_.link(i, cy * grid_.nx() + cx);
    // Only the row or column of cells that just came into the
    // neighbourhood holds new partners; the best event found before still
    // stands (if its partner has moved on since, it is found stale when it
    // comes up, as any other).
    const Kinematics ki = kinematics(i);
    Prediction best = event_[ui];
    const std::int32_t fx = cx + kStepX[p.other];
    const std::int32_t fy = cy + kStepY[p.other];
    if (kStepX[p.other] != 0) {
      predict_cells(i, ki, fx, fx, cy - 1, cy + 1, best);
    } else {
      predict_cells(i, ki, cx - 1, cx + 1, fy, fy, best);
    }
    event_[ui] = best;
    finish_prediction(i);
    queue_.fix(i);
    return true;
  }
  if (event_count_ >= scenario_.max_events) {
    limit_hit_ = true;
    return false;
  }

  const double t = std::max(origin_, p.time);
  origin_ = t;
  now_ = std::max(now_, t);
  Event ev;
  ev.time = t;
  ev.ball = i;
  switch (p.kind) {
    case EventKind::ball: {
      const std::int32_t j = p.other;
      move_to(traj_[ui], t);
      move_to(traj_[static_cast<std::size_t>(j)], t);
      if (scenario_.physics.ball_clusters && collide_cluster(i, j, t)) return true;
      collide_balls(i, j);
      ++counter_[ui];
      ++counter_[static_cast<std::size_t>(j)];
      ev.type = EventType::ball_ball;
      ev.ball = std::min(i, j);
      ev.other = std::max(i, j);
      events_.push_back(ev);
      ++event_count_;
      predict(i);
      queue_.fix(i);
      predict(j);
      queue_.fix(j);
      return true;
    }
    case EventKind::wall:
      move_to(traj_[ui], t);
      collide_wall(i, p.other);
      ev.type = EventType::ball_cushion;
      ev.wall = p.other;
      break;
    case EventKind::stop:
      ev.type = EventType::state_change;
      ev.from = end_phase(i, t);
      ev.to = traj_[ui].state;
      break;
    case EventKind::pocket: {
      Trajectory& tr = traj_[ui];
      move_to(tr, t);
      set_motion(i, {}, {});  // at rest (counted as such) ...
      tr.state = MotionState::pocketed;  // ... and out of play
      update_box(tr);
      if (grid_.used()) grid_.unlink(i);
      ev.type = EventType::ball_pocket;
      ev.pocket = p.other;
      break;
    }
    default:
      return false;
  }
  ++counter_[ui];
  events_.push_back(ev);
  ++event_count_;
  predict(i);
  queue_.fix(i);
  return true;
}

StopReason Engine::advance_to(double t) {
  if (!(t >= now_)) return StopReason::reached;  // the clock never goes back
  limit_hit_ = false;
  while (step(t)) {
  }
  if (limit_hit_) return StopReason::event_limit;
  now_ = t;
  return StopReason::reached;
}

StopReason Engine::advance_to_rest() {
  limit_hit_ = false;
  while (moving_ > 0 && step(kInf)) {
  }
  return limit_hit_ ? StopReason::event_limit : StopReason::reached;
}

double Engine::next_event_time() {
  // Resolve stale predictions and cell crossings at the top so that the
  // answer is the time of a real event. Doing that early changes nothing:
  // they are handled in the same order whenever they are handled.
  for (;;) {
    if (queue_.empty()) return kInf;
    const std::int32_t i = queue_.top();
    const Prediction& p = queue_.next(i);
    if (p.kind == EventKind::none) return kInf;
    const bool stale =
        p.kind == EventKind::ball && counter_[static_cast<std::size_t>(p.other)] != p.other_counter;
    if (!stale && p.kind != EventKind::cell) return p.time;
    step(p.time);
  }
}

}  // namespace breakshot::detail
