// validate(): what every scenario must satisfy before it is simulated,
// whether it was read from a file or built in code. The scenario reader
// checks types and ranges field by field as it reads; this is where the
// geometry is checked (balls inside the table, clear of the walls and of
// each other), and it repeats the range checks for scenarios built in
// code, with the same paths the reader would give.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "breakshot/scenario.hpp"

namespace breakshot {
namespace {

/// How far two balls, or a ball and a wall, may overlap and still count
/// as touching. Balls placed in contact by hand (a Newton's cradle, a
/// rack) are a distance r1 + r2 apart only up to the rounding of their
/// coordinates; refusing those would refuse the scenarios that test
/// contact the most. A nanometre is far below any physical tolerance and
/// far above the rounding of metre-sized coordinates.
constexpr double kTouchTolerance = 1e-9;

std::string ball_path(std::size_t i, const char* field) {
  return "balls[" + std::to_string(i) + "]." + field;
}

std::string num(double x) {
  // Enough digits to tell apart the values in a message, no more.
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool in_unit_interval(double x) { return x >= 0.0 && x <= 1.0; }
bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }
bool non_negative_finite(double x) { return std::isfinite(x) && x >= 0.0; }

}  // namespace

std::optional<FrictionCurveProblem> check_friction_curve(const FrictionCurve& k) {
  for (const auto& [member, value] : {std::pair{'a', k.a}, {'b', k.b}, {'c', k.c}}) {
    if (!std::isfinite(value)) return FrictionCurveProblem{member, "must be finite"};
  }
  if (!(k.c >= 0.0)) {
    return FrictionCurveProblem{
        'c', "must be >= 0, not " + num(k.c) +
                 " (with c < 0, mu = a + b exp(-c v) grows without bound with the slip speed)"};
  }
  if (!in_unit_interval(k.a)) {
    return FrictionCurveProblem{
        'a', "a (mu at high slip speeds) must be in [0, 1], not " + num(k.a)};
  }
  if (!in_unit_interval(k.a + k.b)) {
    return FrictionCurveProblem{
        'b', "a + b (mu at zero slip) must be in [0, 1], not " + num(k.a + k.b)};
  }
  return std::nullopt;
}

namespace {

std::optional<ScenarioError> check_physics(const PhysicsParams& p) {
  if (!(std::isfinite(p.ball_ball_restitution) && in_unit_interval(p.ball_ball_restitution))) {
    return ScenarioError{"physics.ball_ball_restitution", "restitution must be in [0, 1]"};
  }
  const std::pair<const char*, double> non_negative[] = {
      {"physics.ball_ball_friction", p.ball_ball_friction},
      {"physics.gravity", p.gravity},
      {"physics.deceleration", p.deceleration},
      {"physics.sliding_friction", p.sliding_friction},
      {"physics.rolling_friction", p.rolling_friction},
      {"physics.spinning_friction", p.spinning_friction},
  };
  for (const auto& [path, value] : non_negative) {
    if (!non_negative_finite(value)) {
      return ScenarioError{path, "must be finite and >= 0, not " + num(value)};
    }
  }
  if (p.ball_ball_model != BallBallModel::friction && p.model != Model::pool) {
    return ScenarioError{"physics.ball_ball_model",
                         "\"" + std::string(to_string(p.ball_ball_model)) +
                             "\" needs the pool model"};
  }
  if (p.ball_ball_friction_fit) {
    if (auto bad = check_friction_curve(p.ball_ball_friction_curve)) {
      return ScenarioError{std::string("physics.ball_ball_friction.") + bad->member,
                           std::move(bad->reason)};
    }
  }
  if (!positive_finite(p.collapse_speed)) {
    return ScenarioError{"physics.collapse_speed",
                         "must be finite and positive, not " + num(p.collapse_speed)};
  }
  return std::nullopt;
}

std::optional<ScenarioError> check_ball(const Scenario& s, std::size_t i) {
  const BallSpec& b = s.balls[i];
  const BallState& st = s.start[i];
  if (b.id.empty()) return ScenarioError{ball_path(i, "id"), "must not be empty"};
  if (!finite(st.position)) return ScenarioError{ball_path(i, "position"), "must be finite"};
  if (!finite(st.velocity)) return ScenarioError{ball_path(i, "velocity"), "must be finite"};
  if (!finite(st.spin)) return ScenarioError{ball_path(i, "spin"), "must be finite"};
  if (st.spin != Vec3{} && s.physics.model != Model::pool) {
    return ScenarioError{ball_path(i, "spin"), "spin needs the pool model"};
  }
  if (!positive_finite(b.radius)) {
    return ScenarioError{ball_path(i, "radius"), "must be finite and positive, not " + num(b.radius)};
  }
  if (!positive_finite(b.mass)) {
    return ScenarioError{ball_path(i, "mass"), "must be finite and positive, not " + num(b.mass)};
  }
  if (!in_unit_interval(b.wall_restitution)) {
    return ScenarioError{ball_path(i, "wall_restitution"),
                         "restitution must be in [0, 1], not " + num(b.wall_restitution)};
  }
  return std::nullopt;
}

/// The cushion parameters (pool model; the defaults pass on any table).
std::optional<ScenarioError> check_cushion(const Scenario& s) {
  const CushionParams& c = s.table.cushion;
  if (!is_cushion_model(c.model)) {
    return ScenarioError{"table.cushion_model", "unknown cushion model"};
  }
  if (!(std::isfinite(c.height) && c.height >= 0.0)) {
    return ScenarioError{"table.cushion_height",
                         "must be finite and positive (metres), not " + num(c.height)};
  }
  if (c.height > 0.0 && s.physics.model == Model::pool) {
    // The nose must meet every ball above its centre and below its top.
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
      const double r = s.balls[i].radius;
      if (!(c.height > r && c.height < 2.0 * r)) {
        return ScenarioError{"table.cushion_height",
                             "must lie above the centre and below the top of every ball (between " +
                                 num(r) + " and " + num(2.0 * r) + " m for ball '" +
                                 s.balls[i].id + "'), not " + num(c.height)};
      }
    }
  }

  if (!(c.nose_height > 0.5 && c.nose_height < 1.0)) {
    return ScenarioError{"table.nose_height",
                         "must be between 0.5 and 1 (a fraction of the ball's diameter, above "
                         "its centre), not " + num(c.nose_height)};
  }
  if (!non_negative_finite(c.friction)) {
    return ScenarioError{"table.cushion_friction", "must be finite and >= 0, not " +
                                                       num(c.friction)};
  }
  if (!(c.compliance_ratio >= kMinComplianceRatio && c.compliance_ratio <= kMaxComplianceRatio)) {
    return ScenarioError{"table.cushion_compliance_ratio",
                         "must be between 0.01 and 100, not " + num(c.compliance_ratio)};
  }
  if (!in_unit_interval(c.restitution)) {
    return ScenarioError{"table.cushion_restitution",
                         "restitution must be in [0, 1], not " + num(c.restitution)};
  }
  return std::nullopt;
}

/// The cue strike (pool model), with the paths of the file's "cue".
std::optional<ScenarioError> check_cue(const Scenario& s) {
  if (!s.cue) return std::nullopt;
  const CueSpec& cue = *s.cue;
  if (s.physics.model != Model::pool) {
    return ScenarioError{"cue", "a cue strike needs the pool model"};
  }
  if (cue.ball < 0 || static_cast<std::size_t>(cue.ball) >= s.balls.size()) {
    return ScenarioError{"cue.ball", "ball index out of range"};
  }
  const BallState& b = s.start[static_cast<std::size_t>(cue.ball)];
  if (b.velocity != Vec2{} || b.spin != Vec3{}) {
    return ScenarioError{"cue.ball", "ball '" + s.balls[static_cast<std::size_t>(cue.ball)].id +
                                         "' has a velocity or spin; the ball a cue strikes "
                                         "must be at rest"};
  }
  const CueStrike& k = cue.strike;
  if (!positive_finite(k.speed)) {
    return ScenarioError{"cue.speed", "must be finite and positive, not " + num(k.speed)};
  }
  if (!std::isfinite(k.phi)) return ScenarioError{"cue.phi", "must be finite"};
  if (!(k.theta >= 0.0 && k.theta < 90.0)) {
    return ScenarioError{"cue.theta",
                         "the cue elevation must be in [0, 90) degrees, not " + num(k.theta)};
  }
  if (!std::isfinite(k.a)) return ScenarioError{"cue.a", "must be finite"};
  if (!std::isfinite(k.b)) return ScenarioError{"cue.b", "must be finite"};
  if (!positive_finite(cue.params.mass)) {
    return ScenarioError{"cue.cue_mass",
                         "must be finite and positive, not " + num(cue.params.mass)};
  }
  if (!in_unit_interval(cue.params.tip_restitution)) {
    return ScenarioError{"cue.tip_restitution", "restitution must be in [0, 1], not " +
                                                    num(cue.params.tip_restitution)};
  }
  return std::nullopt;
}

/// Signed distance from p to an arc wall (table.hpp): the circle of
/// `radius` about `a`, hit from outside, only where the direction from
/// `a` lies counter-clockwise from the unit vector `b` (start) to the
/// unit vector `normal` (end). Where the direction is within that range
/// the nearest point is on the circle, and a centre inside the circle
/// gives a negative distance (the ball is in the jaw); elsewhere the
/// nearest point is an end of the arc.
double arc_distance(Vec2 p, const Wall& w) {
  const Vec2 d = p - w.a;
  const double dist = norm(d);
  // Counter-clockwise of the start and clockwise of the end, for a range
  // of at most half a turn; a wider range is the whole circle less the
  // range from its end to its start.
  const bool after_start = cross(w.b, d) >= 0.0;
  const bool before_end = cross(d, w.normal) >= 0.0;
  const bool wide = cross(w.b, w.normal) < 0.0;
  const bool within = wide ? (after_start || before_end) : (after_start && before_end);
  if (within) return dist - w.radius;
  return std::min(norm(p - (w.a + w.b * w.radius)), norm(p - (w.a + w.normal * w.radius)));
}

/// Distance from p to one wall piece, for naming the nearest.
double wall_distance(Vec2 p, const Wall& w) {
  switch (w.kind) {
    case WallKind::segment: return segment_distance(p, w.a, w.b);
    case WallKind::corner: return norm(p - w.a);
    case WallKind::arc: return std::max(0.0, arc_distance(p, w));
  }
  return norm(p - w.a);
}

/// wall_clearance() with the round pieces of a pool table's jaws too:
/// table.cpp's measures the straight walls only (a reflex corner is the
/// end of two of them, so for rectangles and polygons that is every
/// wall). For a centre inside the table; tables without arcs get exactly
/// wall_clearance().
double clearance_of(const Table& table, Vec2 p, double r) {
  double c = wall_clearance(table, p, r);
  for (const Wall& w : table.walls) {
    if (w.kind == WallKind::arc) c = std::min(c, arc_distance(p, w) - r);
  }
  return c;
}

/// The wall nearest to p, to name it in a message. The clearance says
/// whether a ball crosses a wall; this only says which.
const Wall* nearest_wall(const Table& table, Vec2 p) {
  const Wall* best = nullptr;
  double best_d = std::numeric_limits<double>::infinity();
  for (const Wall& w : table.walls) {
    const double d = wall_distance(p, w);
    if (d < best_d) {
      best_d = d;
      best = &w;
    }
  }
  return best;
}

std::optional<ScenarioError> check_against_table(const Scenario& s, std::size_t i) {
  const Vec2 p = s.start[i].position;
  const double r = s.balls[i].radius;
  // A ball that starts in a pocket has fallen in before the run begins.
  // Checked first: such a centre usually lies outside the outline too,
  // and "inside pocket" says more than "outside the table".
  for (const Pocket& pocket : s.table.pockets) {
    if (norm(p - pocket.centre) <= pocket.radius) {
      return ScenarioError{ball_path(i, "position"),
                           "ball '" + s.balls[i].id + "' at (" + num(p.x) + ", " + num(p.y) +
                               ") is inside pocket '" + pocket.name + "'"};
    }
  }
  if (!contains(s.table, p)) {
    return ScenarioError{ball_path(i, "position"), "ball '" + s.balls[i].id + "' at (" +
                                                       num(p.x) + ", " + num(p.y) +
                                                       ") lies outside the table"};
  }
  const double clearance = clearance_of(s.table, p, r);
  if (clearance < -kTouchTolerance) {
    std::string reason = "ball '" + s.balls[i].id + "' overlaps ";
    const Wall* w = nearest_wall(s.table, p);
    reason += w != nullptr ? "the wall '" + w->name + "'" : "a wall";
    reason += " by " + num(-clearance) + " m";
    return ScenarioError{ball_path(i, "position"), reason};
  }
  return std::nullopt;
}

/// The overlapping pair that a check of every pair in scenario order
/// (for j = 1.., for i < j) would report first: smallest j, then
/// smallest i. Found without looking at every pair: balls are sorted by
/// the lower edge of their extent along the axis where they spread most,
/// and each ball is compared only with those whose extent along that axis
/// starts before its own ends. Only balls that overlap along the axis are
/// compared, O(N log N) plus the number of such pairs.
std::optional<std::pair<std::size_t, std::size_t>> first_overlap(const Scenario& s) {
  const std::size_t n = s.balls.size();
  if (n < 2) return std::nullopt;
  double lo_x = std::numeric_limits<double>::infinity();
  double hi_x = -lo_x;
  double lo_y = lo_x;
  double hi_y = -lo_x;
  for (const BallState& b : s.start) {
    lo_x = std::min(lo_x, b.position.x);
    hi_x = std::max(hi_x, b.position.x);
    lo_y = std::min(lo_y, b.position.y);
    hi_y = std::max(hi_y, b.position.y);
  }
  const bool along_x = hi_x - lo_x >= hi_y - lo_y;
  auto coord = [&](std::size_t i) {
    return along_x ? s.start[i].position.x : s.start[i].position.y;
  };

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<double> lower(n);
  for (std::size_t i = 0; i < n; ++i) lower[i] = coord(i) - s.balls[i].radius;
  // Ties broken by index so that the sweep is the same on every run.
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return lower[a] < lower[b] || (lower[a] == lower[b] && a < b);
  });

  std::optional<std::pair<std::size_t, std::size_t>> best;  // (j, i), i < j
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = order[k];
    const double upper = coord(a) + s.balls[a].radius + kTouchTolerance;
    for (std::size_t m = k + 1; m < n && lower[order[m]] < upper; ++m) {
      const std::size_t b = order[m];
      const double reach = s.balls[a].radius + s.balls[b].radius - kTouchTolerance;
      if (norm(s.start[a].position - s.start[b].position) < reach) {
        const std::pair<std::size_t, std::size_t> pair{std::max(a, b), std::min(a, b)};
        if (!best || pair < *best) best = pair;
      }
    }
  }
  return best;
}

/// The pool model's balls slow by friction forces mu m g: with gravity
/// or the sliding or rolling friction at 0, a ball that moves never
/// stops (a sliding ball never rolls, a rolling ball never stops), and
/// with the spinning friction at 0 a ball spinning about the vertical
/// never stops spinning. A cue strike moves its ball, and spins it about
/// the vertical when it has side english (a != 0). Spin about the
/// vertical that cushions or other balls give later is not foreseen here:
/// such a run ends at max_events.
std::optional<ScenarioError> check_pool_run_ends(const std::string& how, const Scenario& s) {
  const PhysicsParams& ph = s.physics;
  const auto stops = [&](double amount, double mu) {
    return mu * ph.gravity > 0.0 && std::isfinite(amount / (mu * ph.gravity));
  };
  const auto refuse = [&](const std::string& why) {
    return ScenarioError{"until", how + ": " + why + "; give {\"time\": T}"};
  };
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const BallState& b = s.start[i];
    const double r = s.balls[i].radius;
    const bool struck = s.cue && static_cast<std::size_t>(s.cue->ball) == i;
    // A bound on the speed of the ball and of its contact point with the
    // cloth; a struck ball leaves at less than twice the cue's speed.
    double speed = norm(b.velocity) + r * norm(Vec2{b.spin.x, b.spin.y});
    if (struck) speed = std::max(speed, 2.0 * s.cue->strike.speed);
    double spin_z = std::fabs(b.spin.z);
    const bool english = struck && s.cue->strike.a != 0.0;
    const std::string who = struck ? "the cue strikes ball '" + s.balls[i].id + "'"
                                   : "ball '" + s.balls[i].id + "' moves";
    if (speed > 0.0) {
      if (ph.gravity == 0.0) return refuse("physics.gravity is 0 (no friction acts) and " + who);
      if (ph.sliding_friction == 0.0) {
        return refuse(
            "physics.sliding_friction is 0, so a sliding ball never starts rolling, "
            "and " +
            who);
      }
      if (ph.rolling_friction == 0.0) {
        return refuse("physics.rolling_friction is 0, so a rolling ball never stops, and " + who);
      }
      if (!stops(speed, ph.sliding_friction) || !stops(speed, ph.rolling_friction)) {
        return refuse("the frictions are too small for the ball to stop after " + who);
      }
    }
    if (spin_z > 0.0 || english) {
      const std::string spinner = spin_z > 0.0
                                      ? "ball '" + s.balls[i].id + "' spins about the vertical"
                                      : "the cue strike's side english (cue.a) spins ball '" +
                                            s.balls[i].id + "' about the vertical";
      if (ph.gravity == 0.0)
        return refuse("physics.gravity is 0 (no friction acts) and " + spinner);
      if (ph.spinning_friction == 0.0) {
        return refuse("physics.spinning_friction is 0 and " + spinner);
      }
      // The spin decays at 5 mu_sp g / (2 R).
      if (english) spin_z = std::max(spin_z, 2.0 * s.cue->strike.speed / r);
      if (!stops(spin_z * r, ph.spinning_friction)) {
        return refuse("physics.spinning_friction is too small for the spin of ball '" +
                      s.balls[i].id + "' ever to stop");
      }
    }
  }
  return std::nullopt;
}

}  // namespace

// "rest" must come: in the ideal model, the friction model without
// deceleration, or the pool model without one of its frictions, a moving
// ball never stops and the run would only end at max_events, long after
// the user wanted an answer. The scenario reader reports the same
// problem, adding that "rest" is the default when the file gives no
// "until".
std::optional<ScenarioError> check_run_ends(const Scenario& s) {
  if (!s.until.rest) return std::nullopt;
  const std::string how = "\"rest\" never comes";
  if (s.physics.model == Model::pool) return check_pool_run_ends(how, s);
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const double speed = norm(s.start[i].velocity);
    if (speed == 0.0) continue;
    const std::string who = "ball '" + s.balls[i].id + "' moves";
    if (s.physics.model == Model::ideal) {
      return ScenarioError{"until", how + ": nothing slows a ball in the ideal model and " + who +
                                        "; give {\"time\": T}"};
    }
    if (s.physics.model == Model::friction) {
      if (s.physics.deceleration == 0.0) {
        return ScenarioError{"until", how + ": physics.deceleration is 0 and " + who +
                                          "; give {\"time\": T} or a positive deceleration"};
      }
      if (!std::isfinite(speed / s.physics.deceleration)) {
        return ScenarioError{"until", how + ": physics.deceleration is too small for " + who +
                                          " ever to stop; give {\"time\": T}"};
      }
    }
  }
  return std::nullopt;
}

std::optional<ScenarioError> validate(const Scenario& s) {
  if (s.start.size() != s.balls.size()) {
    return ScenarioError{"balls", "the scenario has " + std::to_string(s.balls.size()) +
                                      " balls but " + std::to_string(s.start.size()) +
                                      " start states"};
  }
  if (s.balls.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    return ScenarioError{"balls", "too many balls"};
  }
  if (auto e = check_physics(s.physics)) return e;

  std::unordered_map<std::string, std::size_t> index_of;
  index_of.reserve(s.balls.size());
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    if (auto e = check_ball(s, i)) return e;
    if (const auto [it, inserted] = index_of.emplace(s.balls[i].id, i); !inserted) {
      return ScenarioError{ball_path(i, "id"), "duplicate id '" + s.balls[i].id +
                                                   "' (also balls[" +
                                                   std::to_string(it->second) + "])"};
    }
  }

  std::vector<std::uint64_t> pair_keys;
  pair_keys.reserve(s.pair_restitution.size());
  const auto n = static_cast<std::int64_t>(s.balls.size());
  for (std::size_t k = 0; k < s.pair_restitution.size(); ++k) {
    const PairRestitution& pr = s.pair_restitution[k];
    const std::string path = "pair_restitution[" + std::to_string(k) + "]";
    if (pr.a < 0 || pr.b < 0 || pr.a >= n || pr.b >= n) {
      return ScenarioError{path + ".balls", "ball index out of range"};
    }
    if (pr.a == pr.b) return ScenarioError{path + ".balls", "the two balls must differ"};
    if (!in_unit_interval(pr.restitution)) {
      return ScenarioError{path + ".restitution",
                           "restitution must be in [0, 1], not " + num(pr.restitution)};
    }
    const auto lo = static_cast<std::uint64_t>(std::min(pr.a, pr.b));
    const auto hi = static_cast<std::uint64_t>(std::max(pr.a, pr.b));
    pair_keys.push_back(lo * static_cast<std::uint64_t>(n) + hi);
  }
  std::sort(pair_keys.begin(), pair_keys.end());
  if (std::adjacent_find(pair_keys.begin(), pair_keys.end()) != pair_keys.end()) {
    return ScenarioError{"pair_restitution", "a pair of balls is listed twice"};
  }

  if (!s.until.rest && !positive_finite(s.until.time)) {
    return ScenarioError{"until.time", "must be finite and positive, not " + num(s.until.time)};
  }
  if (s.sample_dt && !positive_finite(*s.sample_dt)) {
    return ScenarioError{"samples.dt", "must be finite and positive, not " + num(*s.sample_dt)};
  }
  if (s.max_events == 0) return ScenarioError{"max_events", "must be a positive integer"};
  if (auto e = check_cue(s)) return e;
  if (auto e = check_run_ends(s)) return e;
  if (auto e = check_cushion(s)) return e;

  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    if (auto e = check_against_table(s, i)) return e;
  }
  if (const auto pair = first_overlap(s)) {
    const auto [j, i] = *pair;
    return ScenarioError{ball_path(j, "position"),
                         "ball '" + s.balls[j].id + "' overlaps ball '" + s.balls[i].id +
                             "' (balls[" + std::to_string(i) + "])"};
  }
  return std::nullopt;
}

}  // namespace breakshot
