// The baseline player (include/breakshot/players.hpp): ghost-ball aim at
// every legal ball and pocket, the easiest unblocked shot.
//
// A pot is planned in two legs. The object ball's leg runs from the ball
// to where its centre enters the pocket's capture circle (Table::pockets),
// aimed at the pocket centre or a little to either side of it, whichever
// leaves the most room between the path and the jaws. The cue ball's leg
// runs to the ghost ball, the place where it touches the object ball with
// the line of centres along the object ball's leg. A leg is open when it
// stays 2R (plus a hair) clear of every other ball and R clear of every
// cushion and jaw (a ball already closer than that, say frozen on a rail,
// may keep its distance but not come closer).
//
// The ghost-ball aim ignores throw: ball-ball friction turns the object
// ball a degree or more toward the cue ball's direction on a cut, and the
// spin the impact gives it curves its path until it rolls. The planner
// estimates the cue ball's speed and roll at the contact (a centre hit
// slides, then rolls: the pool model's defaults, docs/physics.md), runs
// the engine's own impact law, ball_ball_impact(), to see where the
// object ball goes, and turns the line of centres by the difference, a
// few times over. The same impact gives the cue ball's departure, from
// which the planner rejects shots whose cue ball would run into a pocket.
// The speed is the least (from 1.5 m/s cue speed) that brings the object
// ball to the pocket with some pace left.
//
// Difficulty: an aim error e of the cue moves the object ball about
// d1 d2 e / (2R cos cut) sideways at the pocket (d1: cue ball to ghost,
// d2: object ball to pocket), and the shot goes in while that is less
// than the room left at the jaws, so the score is d1 d2 / (cos cut room),
// lower being easier.
//
// With no pot on, the player plays a safety: a hit on a legal ball along
// an open path, the fullest on the nearest first, then one-rail kicks.
// Geometry cannot see kisses, caroms or a rail's real rebound angle, so
// these candidates are played out on the engine (Rules::shot_scenario)
// and the first that hits a legal ball first without a foul is taken.
// Pots are not played out: the baseline aims, it does not search.
//
// Ball in hand: the cue ball goes behind the easiest object ball on the
// line of one of its open legs (straight in or a slight cut, a few
// distances back), or failing that to the best point of a 5 cm grid.
//
// Snooker: the same planner over the balls on (a free ball is not
// taken). After a red it pots the easiest colour and nominates it; with
// no pot on, it plays a safety or a one-rail kick at one ball on at a time
// (nominating it when the ball on is a colour), tried out on the engine.
// With the cue ball in hand it places it in the D as for a pot. After a
// foul it plays on; it concedes the frame when it needs snookers.
//
// Three-cushion: one-ball-first system shots from the mirror
// construction, refined on the engine (baseline_carom.cpp).
//
// Everything is deterministic: no randomness is used at all, so the seed
// is ignored.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "baseline_carom.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/player.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "geometry.hpp"
#include "judge.hpp"
#include "physics/detmath.hpp"
#include "policy.hpp"

namespace breakshot {

namespace {

using ai::kBallBallRestitution;
using ai::kDeg;
using ai::kGravity;
using ai::kInf;
using ai::kPi;
using ai::kRollingFriction;
using ai::kSlidingFriction;

// Cosines of the largest cut angles, correctly rounded (literals, so that
// no maths library is involved).
constexpr double kMaxCutCos = 0.17364817766693041;  // 80 degrees: thinner cuts are not tried
constexpr double kCos60 = 0.50000000000000011;      // 60 degrees
constexpr double kBallMargin = 0.001;    // m beyond 2R between a path and a ball
constexpr double kWallMargin = 0.001;    // m beyond R between a path and a cushion or jaw
constexpr double kMinSpeed = 1.5;        // m/s cue speed of pots
constexpr double kSafetySpeed = 2.0;     // m/s least cue speed of safeties
constexpr double kMaxSpeed = 5.0;        // m/s cue speed of pots and safeties
constexpr double kSpeedStep = 0.1;
constexpr int kSpeeds = 36;           // kMinSpeed, kMinSpeed + kSpeedStep, ... kMaxSpeed
constexpr double kArrival = 0.4;      // m/s the object ball should still have at the pocket
constexpr double kBreakSpeed = 7.75;  // m/s cue speed of the break
constexpr int kThrowIterations = 4;
constexpr double kGridStep = 0.05;  // m, the placement grid's spacing

Vec2 unit(Vec2 v) { return v / norm(v); }

Vec2 rotate(Vec2 v, double angle) {
  double s = 0.0;
  double c = 0.0;
  dm::sincos(angle, s, c);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// Signed angle from a to b (radians, counter-clockwise positive).
double angle_between(Vec2 a, Vec2 b) { return dm::atan2(cross(a, b), dot(a, b)); }

using ai::segments_distance;
using ai::wall_distance;

/// Speed and rolling speed (R omega about the horizontal axis across the
/// path; equal to the speed once rolling) of a ball after travelling d
/// along a straight line from speed v0 and rolling speed w0 <= v0:
/// sliding friction brings the two together, then rolling resistance
/// slows it. nullopt if it stops first.
struct Motion {
  double v = 0.0;
  double w = 0.0;
};

std::optional<Motion> travel(double v0, double w0, double d) {
  const double slide = kSlidingFriction * kGravity;
  const double slip = v0 - w0;
  if (slip > 0.0) {
    const double t_slide = 2.0 * slip / (7.0 * slide);
    const double d_slide = v0 * t_slide - 0.5 * slide * t_slide * t_slide;
    if (d <= d_slide) {
      const double t = (v0 - std::sqrt(std::max(v0 * v0 - 2.0 * slide * d, 0.0))) / slide;
      return Motion{v0 - slide * t, w0 + 2.5 * slide * t};
    }
    d -= d_slide;
    v0 = (5.0 * v0 + 2.0 * w0) / 7.0;
  }
  const double v2 = v0 * v0 - 2.0 * kRollingFriction * kGravity * d;
  if (v2 <= 0.0) return std::nullopt;
  const double v = std::sqrt(v2);
  return Motion{v, v};
}

/// The velocity a ball rolling with spin w has: R (w_y, -w_x).
Vec2 rolling_velocity(Vec3 w, double R) { return {R * w.y, -R * w.x}; }

/// The spin of a ball rolling with velocity v.
Vec3 rolling_spin(Vec2 v, double R) { return {-v.y / R, v.x / R, 0.0}; }

/// Where the object ball's leg may end: a pocket entered along a path.
struct Leg {
  Vec2 direction;       ///< unit, of the object ball
  double length = 0.0;  ///< to the capture circle
  double room = 0.0;    ///< m the path could move sideways before meeting a jaw
};

/// One planned shot: a pot of `ball` into `pocket`, or a safety
/// (pocket -1) that hits `ball` first.
struct Plan {
  int ball = -1;
  int pocket = -1;
  double phi = 0.0;  ///< degrees
  double speed = 0.0;
  double score = kInf;
};

class Planner {
 public:
  Planner(const Rules& rules, const GameState& state)
      : rules_(rules),
        state_(state),
        table_(rules.table()),
        R_(rules.config().ball_radius),
        m_(rules.config().ball_mass) {
    CueStrike unit_strike;
    unit_strike.speed = 1.0;
    launch_ = strike(unit_strike, m_, R_, CueParams{}).velocity.x;
  }

  /// Legal targets the cue ball may be aimed at: with the cue ball placed
  /// in the kitchen, only balls beyond the head string.
  std::vector<int> aimable(const std::vector<int>& targets, bool kitchen) const {
    std::vector<int> out;
    for (int t : targets) {
      if (t <= 0 || t >= static_cast<int>(state_.on_table.size()) || !on(t)) continue;
      if (kitchen && pos(t).x <= rules_.head_string()) continue;
      out.push_back(t);
    }
    return out;
  }

  /// The best object ball leg of `ball` into each pocket (nullopt where
  /// none is open). Independent of the cue ball.
  std::vector<std::optional<Leg>> legs(int ball) const {
    std::vector<std::optional<Leg>> out;
    for (std::size_t k = 0; k < table_.pockets.size(); ++k) out.push_back(leg(ball, k));
    return out;
  }

  /// The easiest pot from cue position `cue`, over `targets` and their
  /// legs (targets[i] goes with legs[i]).
  std::optional<Plan> best_pot(Vec2 cue, const std::vector<int>& targets,
                               const std::vector<std::vector<std::optional<Leg>>>& all_legs) const {
    std::optional<Plan> best;
    for (std::size_t i = 0; i < targets.size(); ++i) {
      for (std::size_t k = 0; k < all_legs[i].size(); ++k) {
        if (!all_legs[i][k]) continue;
        const std::optional<Plan> p = pot(cue, targets[i], static_cast<int>(k), *all_legs[i][k]);
        if (p && (!best || p->score < best->score)) best = p;
      }
    }
    return best;
  }

  /// Shots that hit one of `targets` first and drive a ball to a
  /// cushion: the cue ball to a ghost at a few angles around each target
  /// along an open path, the fullest hit on the nearest ball first.
  std::vector<Plan> safeties(Vec2 cue, const std::vector<int>& targets) const {
    std::vector<Plan> out;
    constexpr std::array<double, 9> kTurns{0.0, 15.0, -15.0, 30.0, -30.0, 45.0, -45.0, 60.0, -60.0};
    for (int t : targets) {
      const Vec2 b = pos(t);
      if (norm(b - cue) < 1e-9) continue;
      const Vec2 straight = unit(b - cue);
      for (double turn : kTurns) {
        const Vec2 n = rotate(straight, turn * kDeg);  // line of centres at contact
        const Vec2 ghost = b - n * (2.0 * R_);
        const double d1 = norm(ghost - cue);
        if (d1 < 1e-9) continue;
        const Vec2 u = (ghost - cue) / d1;
        const double cos_cut = dot(u, n);
        if (cos_cut < kMaxCutCos) continue;
        if (!ghost_fits(ghost) || !open(cue, ghost, t, true)) continue;
        // Enough speed for the object ball to reach a cushion.
        const double to_rail = distance_to_rail(b, n);
        double speed = kMaxSpeed;
        std::optional<Contact> c;
        for (int i = 0; i < kSpeeds; ++i) {
          const double v = kSafetySpeed + i * kSpeedStep;
          if (v > kMaxSpeed) break;
          c = contact(cue, ghost, b, v);
          if (c && travel(norm(c->object_velocity), 0.0, to_rail)) {
            speed = v;
            break;
          }
          c.reset();
        }
        if (!c) c = contact(cue, ghost, b, speed);
        double score = (d1 + 0.2) / cos_cut * (1.0 + std::abs(turn) / 30.0);
        if (c && scratch_risk(ghost, *c)) score *= 100.0;
        // The 8 must not drop on a safety (8-ball: a loss); other balls
        // had better not either (the turn ends anyway).
        if (heads_into_pocket(b, n, to_rail)) score *= t == 8 ? 1e4 : 10.0;
        out.push_back(Plan{t, -1, dm::atan2(u.y, u.x) / kDeg, speed, score});
      }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Plan& x, const Plan& y) { return x.score < y.score; });
    return out;
  }

  /// A cue ball path that goes once off a rail into a ghost position
  /// around one of `targets`: the aim at the ghost's mirror image in the
  /// rail (the real rebound differs, so callers try it out). Easiest
  /// first.
  std::vector<Plan> kicks(Vec2 cue, const std::vector<int>& targets) const {
    std::vector<Plan> out;
    const double lo_x = R_;
    const double hi_x = table_.length - R_;
    const double lo_y = R_;
    const double hi_y = table_.width - R_;
    for (int t : targets) {
      const Vec2 b = pos(t);
      for (int k = 0; k < 8; ++k) {
        const Vec2 n = rotate(Vec2{1.0, 0.0}, k * 45.0 * kDeg);
        const Vec2 ghost = b - n * (2.0 * R_);
        if (!ghost_fits(ghost)) continue;
        const std::array<Vec2, 4> images{
            Vec2{2.0 * lo_x - ghost.x, ghost.y}, Vec2{2.0 * hi_x - ghost.x, ghost.y},
            Vec2{ghost.x, 2.0 * lo_y - ghost.y}, Vec2{ghost.x, 2.0 * hi_y - ghost.y}};
        for (std::size_t r = 0; r < images.size(); ++r) {
          const Vec2 to = images[r] - cue;
          const double s = r < 2 ? ((r == 0 ? lo_x : hi_x) - cue.x) / to.x
                                 : ((r == 2 ? lo_y : hi_y) - cue.y) / to.y;
          if (!(s > 0.0 && s < 1.0)) continue;
          const Vec2 bounce = cue + to * s;
          bool near_pocket = false;
          for (const Pocket& pk : table_.pockets) {
            near_pocket = near_pocket || norm(pk.centre - bounce) < pk.radius + 4.0 * R_;
          }
          if (near_pocket) continue;
          const double leg2 = norm(ghost - bounce);
          if (leg2 < 1e-9) continue;
          const double cos_cut = dot((ghost - bounce) / leg2, n);
          if (cos_cut < kCos60) continue;
          if (!open(cue, bounce, -1, false) || !open(bounce, ghost, t, false)) continue;
          const double length = norm(bounce - cue) + leg2;
          Plan p;
          p.ball = t;
          p.phi = dm::atan2(to.y, to.x) / kDeg;
          p.speed = std::clamp(2.0 + 0.8 * length, 2.5, kMaxSpeed);
          p.score = length / cos_cut;
          out.push_back(p);
        }
      }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Plan& x, const Plan& y) { return x.score < y.score; });
    return out;
  }

  bool ghost_fits(Vec2 g) const { return disk_fits(table_, g, R_); }

  /// True if a ball moving along the segment a-b keeps 2R (plus the
  /// margin) from every object ball but `skip` (a ball it starts beside
  /// and moves away from is no obstacle); with `walls`, also R from every
  /// cushion piece, except that a path starting or ending closer may keep
  /// that distance.
  bool open(Vec2 a, Vec2 b, int skip, bool walls) const {
    for (std::size_t n = 1; n < state_.on_table.size(); ++n) {
      if (!state_.on_table[n] || static_cast<int>(n) == skip) continue;
      const Vec2 p = state_.position[n];
      if (dot(p - a, b - a) <= 0.0) continue;
      if (segment_distance(p, a, b) < 2.0 * R_ + kBallMargin) return false;
    }
    if (!walls) return true;
    // Walls further than R + kWallMargin pass (geometry.hpp, PathReach).
    const ai::PathReach reach(a, b, R_ + kWallMargin);
    for (const Wall& w : table_.walls) {
      if (reach.beyond(w)) continue;
      const double need =
          std::min({R_ + kWallMargin, wall_distance(w, a, a), wall_distance(w, b, b)});
      if (wall_distance(w, a, b) < need - 1e-12) return false;
    }
    return true;
  }

  double R() const { return R_; }
  Vec2 pos(int b) const { return state_.position[static_cast<std::size_t>(b)]; }
  bool on(int b) const { return state_.on_table[static_cast<std::size_t>(b)] != 0; }

 private:
  /// The cue ball and the object ball just after the contact.
  struct Contact {
    Vec2 cue_velocity;
    Vec3 cue_spin;
    Vec2 object_velocity;
    Vec3 object_spin;
  };

  /// The contact of a centre-ball strike at cue speed `speed` from `cue`
  /// that reaches the ghost position `ghost` and hits the ball at `b`.
  std::optional<Contact> contact(Vec2 cue, Vec2 ghost, Vec2 b, double speed) const {
    const double d1 = norm(ghost - cue);
    const Vec2 u = (ghost - cue) / d1;
    const std::optional<Motion> at = travel(launch_ * speed, 0.0, d1);
    if (!at) return std::nullopt;
    const BallImpact imp =
        ball_ball_impact(ghost, u * at->v, rolling_spin(u * at->w, R_), m_, R_, b, Vec2{}, Vec3{},
                         m_, R_, kBallBallRestitution, BallFriction{});
    return Contact{imp.v1, imp.w1, imp.v2, imp.w2};
  }

  /// True if a ball running from p along unit d for `run` passes over a
  /// pocket's capture circle (give or take half a ball).
  bool heads_into_pocket(Vec2 p, Vec2 d, double run) const {
    const Vec2 end = p + d * (run + R_);
    for (const Pocket& pk : table_.pockets) {
      if (segment_distance(pk.centre, p, end) < pk.radius + 0.5 * R_) return true;
    }
    return false;
  }

  /// Free run of a ball centre from p along unit d before it touches a
  /// rail (the cushion noses; pockets ignored).
  double distance_to_rail(Vec2 p, Vec2 d) const {
    double t = kInf;
    if (d.x > 0.0) t = std::min(t, (table_.length - R_ - p.x) / d.x);
    if (d.x < 0.0) t = std::min(t, (R_ - p.x) / d.x);
    if (d.y > 0.0) t = std::min(t, (table_.width - R_ - p.y) / d.y);
    if (d.y < 0.0) t = std::min(t, (R_ - p.y) / d.y);
    return std::max(t, 0.0);
  }

  /// The open leg of `ball` into pocket k with the most room, if any.
  std::optional<Leg> leg(int ball, std::size_t k) const {
    const Pocket& pocket = table_.pockets[k];
    const Vec2 b = pos(ball);
    if (norm(pocket.centre - b) <= pocket.radius) return std::nullopt;
    const Vec2 across = perp(unit(pocket.centre - b));
    std::optional<Leg> best;
    for (double off : {0.0, 0.4, -0.4}) {
      const Vec2 aim = pocket.centre + across * (off * pocket.radius);
      const Vec2 d = unit(aim - b);
      // First point where b + s d meets the capture circle.
      const Vec2 f = b - pocket.centre;
      const double half_b = dot(f, d);
      const double disc = half_b * half_b - (norm2(f) - pocket.radius * pocket.radius);
      if (disc <= 0.0) continue;
      const double s = -half_b - std::sqrt(disc);
      if (s <= 0.0) continue;
      const Vec2 end = b + d * s;
      if (!open(b, end, ball, false)) continue;
      double room = kInf;
      bool blocked = false;
      for (const Wall& w : table_.walls) {
        const double dist = wall_distance(w, b, end);
        const double need = std::min(R_ + kWallMargin, wall_distance(w, b, b));
        if (dist < need - 1e-12) {
          blocked = true;
          break;
        }
        room = std::min(room, dist - R_);
      }
      if (blocked) continue;
      if (!best || room > best->room) best = Leg{d, s, room};
    }
    return best;
  }

  /// The shot that pots `ball` along `lg` into pocket k from `cue`.
  std::optional<Plan> pot(Vec2 cue, int ball, int k, const Leg& lg) const {
    const Vec2 b = pos(ball);
    const Vec2 d = lg.direction;
    const double d2 = lg.length;
    Vec2 n = d;  // line of centres at contact, turned against the throw below
    double speed = 0.0;
    std::optional<Contact> c;
    Vec2 ghost;
    for (int it = 0; it <= kThrowIterations; ++it) {
      ghost = b - n * (2.0 * R_);
      const double d1 = norm(ghost - cue);
      if (d1 < 1e-9) return std::nullopt;
      const Vec2 u = (ghost - cue) / d1;
      const double cos_cut = dot(u, n);
      if (cos_cut < kMaxCutCos) return std::nullopt;
      if (it == 0) {
        // The slowest speed (on the grid) that gets the object ball to
        // the pocket with some pace left.
        speed = -1.0;
        for (int i = 0; i < kSpeeds; ++i) {
          const double v = kMinSpeed + i * kSpeedStep;
          const std::optional<Contact> cv = contact(cue, ghost, b, v);
          if (!cv) continue;
          const double vo = norm(cv->object_velocity);
          const double wo = dot(rolling_velocity(cv->object_spin, R_), cv->object_velocity) / vo;
          const std::optional<Motion> end = travel(vo, std::min(wo, vo), d2);
          if (end && end->v >= kArrival) {
            speed = v;
            break;
          }
        }
        if (speed < 0.0) return std::nullopt;
      }
      c = contact(cue, ghost, b, speed);
      if (!c) return std::nullopt;
      if (it == kThrowIterations) break;
      // Turn the line of centres so that the thrown object ball runs
      // along d.
      const double thrown = angle_between(n, object_path_end(*c, d2));
      n = rotate(d, -thrown);
    }
    const double d1 = norm(ghost - cue);
    const Vec2 u = (ghost - cue) / d1;
    const double cos_cut = dot(u, n);
    if (cos_cut < kMaxCutCos) return std::nullopt;
    if (!ghost_fits(ghost) || !open(cue, ghost, ball, true)) return std::nullopt;
    if (scratch_risk(ghost, *c)) return std::nullopt;
    const double room = std::max(lg.room, 0.002);
    Plan p;
    p.ball = ball;
    p.pocket = k;
    p.phi = dm::atan2(u.y, u.x) / kDeg;
    p.speed = speed;
    p.score = (d1 + 0.05) * (d2 + 0.05) / (cos_cut * room);
    return p;
  }

  /// Where the object ball is, relative to where it was hit, once it has
  /// gone about `dist`: the impact leaves it sliding with a little spin
  /// across its path, so it curves until it rolls, then runs straight.
  Vec2 object_path_end(const Contact& c, double dist) const {
    const Vec2 v = c.object_velocity;
    const Vec2 w = rolling_velocity(c.object_spin, R_);
    const Vec2 slip = v - w;
    const double slip_speed = norm(slip);
    if (slip_speed < 1e-9) return unit(v) * dist;
    const double slide = kSlidingFriction * kGravity;
    const double t_slide = 2.0 * slip_speed / (7.0 * slide);
    const Vec2 curve = v * t_slide - slip / slip_speed * (0.5 * slide * t_slide * t_slide);
    const double curve_length = norm(curve);
    const Vec2 rolling = (v * 5.0 + w * 2.0) / 7.0;
    if (curve_length >= dist || norm(rolling) < 1e-9) return curve;
    return curve + unit(rolling) * (dist - curve_length);
  }

  /// True if the cue ball, leaving the contact at `ghost`, looks like
  /// running into a pocket: its sliding curve and then its roll, up to
  /// the first cushion, pass within a pocket's capture radius (plus half
  /// a ball, the estimate being rough) of the pocket centre.
  bool scratch_risk(Vec2 ghost, const Contact& c) const {
    const Vec2 v = c.cue_velocity;
    const Vec2 w = rolling_velocity(c.cue_spin, R_);
    const Vec2 slip = v - w;
    const double slide = kSlidingFriction * kGravity;
    std::vector<Vec2> path{ghost};
    const double slip_speed = norm(slip);
    if (slip_speed > 1e-9) {
      const double t_slide = 2.0 * slip_speed / (7.0 * slide);
      const Vec2 a = slip / slip_speed * (-slide);
      for (int i = 1; i <= 4; ++i) {
        const double t = t_slide * i / 4.0;
        path.push_back(ghost + v * t + a * (0.5 * t * t));
      }
    }
    const Vec2 rolling = (v * 5.0 + w * 2.0) / 7.0;
    const double roll = norm2(rolling) / (2.0 * kRollingFriction * kGravity);
    if (roll > 1e-9) path.push_back(path.back() + unit(rolling) * roll);
    for (std::size_t i = 1; i < path.size(); ++i) {
      Vec2 a = path[i - 1];
      Vec2 b = path[i];
      const bool leaves = clip(a, b);
      for (const Pocket& pk : table_.pockets) {
        if (segment_distance(pk.centre, a, b) < pk.radius + 0.5 * R_) return true;
      }
      if (leaves) break;
    }
    return false;
  }

  /// Cuts the segment a-b where it leaves the playing surface [0, L] x
  /// [0, W] (beyond, the ball would be off a cushion or in a pocket).
  /// Returns true if it was cut.
  bool clip(Vec2 a, Vec2& b) const {
    double t = 1.0;
    const Vec2 d = b - a;
    if (b.x < 0.0 && d.x < 0.0) t = std::min(t, -a.x / d.x);
    if (b.x > table_.length && d.x > 0.0) t = std::min(t, (table_.length - a.x) / d.x);
    if (b.y < 0.0 && d.y < 0.0) t = std::min(t, -a.y / d.y);
    if (b.y > table_.width && d.y > 0.0) t = std::min(t, (table_.width - a.y) / d.y);
    t = std::max(t, 0.0);
    b = a + d * t;
    return t < 1.0;
  }

  const Rules& rules_;
  const GameState& state_;
  const Table& table_;
  double R_;
  double m_;
  double launch_ = 1.0;  // cue ball speed per unit of cue speed, centre hit
};

Shoot make_shoot(double phi, double speed) {
  Shoot s;
  s.strike.speed = speed;
  s.strike.phi = phi;
  return s;
}

class BaselinePlayer final : public Player {
 public:
  std::string name() const override { return "baseline"; }

  Action decide(const Rules& rules, const GameState& state, std::uint64_t /*seed*/) override {
    const LegalActions la = rules.legal_actions(state);
    const ai_detail::GamePolicy& policy = ai_detail::game_policy(state.game);
    if (policy.search == ai_detail::GamePolicy::Search::snooker) return snooker(rules, state, la);
    if (policy.search == ai_detail::GamePolicy::Search::carom) {
      return ai::three_cushion_shot(rules, state);
    }
    if (!la.choices.empty()) return Decide{choose(rules, state, la)};
    if (state.phase == Phase::break_shot) return break_action(rules, state, la);
    if (la.place != BallInHand::none) {
      if (const std::optional<Vec2> p = placement(rules, state, la)) return PlaceCueBall{*p};
    }
    return shot(rules, state, la);
  }

 private:
  /// Targets (beyond the head string when shooting from the kitchen) and
  /// their object ball legs.
  struct Options {
    std::vector<int> targets;
    std::vector<std::vector<std::optional<Leg>>> legs;
  };

  static Options options(const Planner& planner, const std::vector<int>& targets, bool kitchen) {
    Options o;
    o.targets = planner.aimable(targets, kitchen);
    for (int t : o.targets) o.legs.push_back(planner.legs(t));
    return o;
  }

  static Choice choose(const Rules& rules, const GameState& state, const LegalActions& la) {
    const auto offered = [&](Choice c) {
      return std::find(la.choices.begin(), la.choices.end(), c) != la.choices.end();
    };
    if (state.phase == Phase::push_out_choice && offered(Choice::shoot) &&
        offered(Choice::pass_back)) {
      // Take the table only with a pot on from where the balls lie.
      GameState as_shooter = state;
      as_shooter.phase = Phase::shot;
      as_shooter.ball_in_hand = BallInHand::none;
      const Planner planner(rules, as_shooter);
      const Options o = options(planner, rules.legal_actions(as_shooter).targets, false);
      const bool makeable =
          as_shooter.on_table[0] && planner.best_pot(planner.pos(0), o.targets, o.legs);
      return makeable ? Choice::shoot : Choice::pass_back;
    }
    for (Choice c : {Choice::accept_table, Choice::respot_eight, Choice::shoot}) {
      if (offered(c)) return c;
    }
    return la.choices.front();
  }

  static Action break_action(const Rules& rules, const GameState& state, const LegalActions& la) {
    const Planner planner(rules, state);
    if (la.must_place) {
      if (!rules.check_placement(state, rules.table().head_spot)) {
        return PlaceCueBall{rules.table().head_spot};
      }
      if (const std::optional<Vec2> p = scan(rules, state, planner, {}, {})) {
        return PlaceCueBall{*p};
      }
    }
    // Straight at the apex: the 1 in 9-ball, the object ball nearest the
    // head (the lowest x) in 8-ball.
    int apex = -1;
    if (ai_detail::game_policy(state.game).rotation && !la.targets.empty()) {
      apex = la.targets.front();
    } else {
      for (std::size_t b = 1; b < state.on_table.size(); ++b) {
        if (state.on_table[b] && (apex < 0 || state.position[b].x < planner.pos(apex).x)) {
          apex = static_cast<int>(b);
        }
      }
    }
    const Vec2 cue = planner.pos(0);
    const Vec2 to = apex > 0 ? planner.pos(apex) - cue : Vec2{1.0, 0.0};
    return make_shoot(dm::atan2(to.y, to.x) / kDeg, kBreakSpeed);
  }

  /// Where to put the cue ball, or nullopt to play it from where it lies.
  static std::optional<Vec2> placement(const Rules& rules, const GameState& state,
                                       const LegalActions& la) {
    const Planner planner(rules, state);
    const bool kitchen = la.place == BallInHand::kitchen;
    const Options o = options(planner, la.targets, kitchen);

    std::optional<Plan> here;
    if (!la.must_place) here = planner.best_pot(planner.pos(0), o.targets, o.legs);

    // Candidates: behind each object ball on its leg's line, straight in
    // or at a small cut, near or farther back.
    std::optional<Vec2> best_place;
    double best_score = kInf;
    const double R = planner.R();
    for (std::size_t i = 0; i < o.targets.size(); ++i) {
      const Vec2 b = planner.pos(o.targets[i]);
      for (const std::optional<Leg>& lg : o.legs[i]) {
        if (!lg) continue;
        const Vec2 ghost = b - lg->direction * (2.0 * R);
        for (double angle : {0.0, 12.0, -12.0, 25.0, -25.0}) {
          const Vec2 back = rotate(lg->direction, angle * kDeg);
          for (double dist : {0.08, 0.15, 0.25, 0.4, 0.6}) {
            const Vec2 p = ghost - back * dist;
            if (rules.check_placement(state, p)) continue;
            const std::optional<Plan> plan = planner.best_pot(p, o.targets, o.legs);
            if (plan && plan->score < best_score) {
              best_score = plan->score;
              best_place = p;
            }
          }
        }
      }
    }
    if (!best_place) {
      best_place = scan(rules, state, planner, o.targets, o.legs);
      if (best_place) {
        const std::optional<Plan> plan = planner.best_pot(*best_place, o.targets, o.legs);
        best_score = plan ? plan->score : kInf;
      }
    }
    if (la.must_place) {
      if (best_place) return best_place;
      return rules.table().head_spot;  // nothing legal found: check() will say why
    }
    // The cue ball is on the table: move it only for an easier pot, or
    // when there is no pot from where it lies but there is one elsewhere.
    if (best_place && best_score < kInf && (!here || best_score < 0.9 * here->score)) {
      return best_place;
    }
    return std::nullopt;
  }

  /// The legal placement on a grid with the easiest pot; without any pot,
  /// the legal grid point with the best safety; nullopt if no grid point
  /// is legal.
  static std::optional<Vec2> scan(const Rules& rules, const GameState& state,
                                  const Planner& planner, const std::vector<int>& targets,
                                  const std::vector<std::vector<std::optional<Leg>>>& legs) {
    const Table& t = rules.table();
    const double R = planner.R();
    std::optional<Vec2> best_pot_at;
    double best_pot = kInf;
    std::optional<Vec2> best_safe_at;
    double best_safe = kInf;
    std::optional<Vec2> any;
    const int nx = static_cast<int>((t.length - 2.0 * R) / kGridStep);
    const int ny = static_cast<int>((t.width - 2.0 * R) / kGridStep);
    for (int i = 0; i <= nx; ++i) {
      for (int j = 0; j <= ny; ++j) {
        const Vec2 p{R + 0.001 + i * kGridStep, R + 0.001 + j * kGridStep};
        if (rules.check_placement(state, p)) continue;
        if (!any) any = p;
        if (const std::optional<Plan> plan = planner.best_pot(p, targets, legs)) {
          if (plan->score < best_pot) {
            best_pot = plan->score;
            best_pot_at = p;
          }
        } else if (!best_pot_at) {
          const std::vector<Plan> safe = planner.safeties(p, targets);
          if (!safe.empty() && safe.front().score < best_safe) {
            best_safe = safe.front().score;
            best_safe_at = p;
          }
        }
      }
    }
    if (best_pot_at) return best_pot_at;
    if (best_safe_at) return best_safe_at;
    return any;
  }

  /// The first of the safeties (at most a dozen tried) that the engine
  /// plays without a foul: the planner cannot see caroms and kisses.
  static std::optional<Shoot> first_legal(const Rules& rules, const GameState& state,
                                          const std::vector<Plan>& plans,
                                          const std::vector<int>& targets) {
    constexpr std::size_t kMaxTrials = 12;
    for (std::size_t i = 0; i < plans.size() && i < kMaxTrials; ++i) {
      const Shoot s = make_shoot(plans[i].phi, plans[i].speed);
      if (plays_legally(rules, state, s, targets)) return s;
    }
    return std::nullopt;
  }

  /// A one-rail kick at a legal ball when every direct way is blocked.
  /// The mirror aim ignores how the cushion changes the angle, so each
  /// candidate (and small turns of it) is played out on the engine, and
  /// the first whose cue ball touches a legal ball first without
  /// scratching is taken.
  static std::optional<Shoot> kick(const Rules& rules, const GameState& state,
                                   const Planner& planner, Vec2 cue,
                                   const std::vector<int>& targets) {
    constexpr int kMaxTrials = 48;
    int trials = 0;
    for (const Plan& p : planner.kicks(cue, targets)) {
      for (double turn : {0.0, 1.0, -1.0, 2.0, -2.0, 4.0, -4.0}) {
        if (trials++ >= kMaxTrials) return std::nullopt;
        const Shoot s = make_shoot(p.phi + turn, p.speed);
        if (plays_legally(rules, state, s, targets)) return s;
      }
    }
    return std::nullopt;
  }

  /// True if `shot`, played without noise, first meets one of `targets`
  /// and the game's rules find no foul in it and do not end the game
  /// against the shooter: the judge's ruling (judge.hpp), the one a real
  /// shot gets, not a copy of the rules.
  static bool plays_legally(const Rules& rules, const GameState& state, const Shoot& shot,
                            const std::vector<int>& targets) {
    if (rules.check(state, Action{shot})) return false;
    std::vector<int> numbers;
    Simulation sim(rules.shot_scenario(state, shot.strike, &numbers));
    const ai_detail::Judged j = ai_detail::judge(rules, state, shot, sim, numbers);
    return j.legal && std::find(targets.begin(), targets.end(), j.first_hit) != targets.end();
  }

  /// Snooker: concede when snookers are needed, play on after a foul,
  /// place the cue ball for a pot, then pot or play safe.
  static Action snooker(const Rules& rules, const GameState& state, const LegalActions& la) {
    const auto offered = [&](Choice c) {
      return std::find(la.choices.begin(), la.choices.end(), c) != la.choices.end();
    };
    if (offered(Choice::concede) && snookers_required(state, state.player) > 0) {
      return Decide{Choice::concede};
    }
    if (state.phase == Phase::foul_choice) {
      return Decide{offered(Choice::play_on) ? Choice::play_on : la.choices.front()};
    }
    if (la.place != BallInHand::none && state.phase != Phase::break_shot) {
      if (const std::optional<Vec2> p = placement(rules, state, la)) return PlaceCueBall{*p};
    }
    return snooker_shot(rules, state, la);
  }

  static Action snooker_shot(const Rules& rules, const GameState& state, const LegalActions& la) {
    const Planner planner(rules, state);
    const std::vector<int> on = rules.balls_on(state);  // a free ball is not taken
    const Options o = options(planner, on, false);
    const Vec2 cue = planner.pos(0);
    const auto nominate = [&](Shoot s, int ball) {
      if (la.must_nominate) s.nominate = ball;
      return s;
    };
    if (const std::optional<Plan> p = planner.best_pot(cue, o.targets, o.legs)) {
      Shoot s = nominate(make_shoot(p->phi, p->speed), p->ball);
      s.call = Call{p->ball, p->pocket};  // information: a pot attempt (docs/rules.md)
      return s;
    }
    // No pot: a safety, then a kick, at one ball on at a time, nearest
    // first (so that a colour's nomination is the ball the trial hit).
    std::vector<int> targets = o.targets;
    std::stable_sort(targets.begin(), targets.end(), [&](int x, int y) {
      return norm(planner.pos(x) - cue) < norm(planner.pos(y) - cue);
    });
    constexpr std::size_t kMaxTargets = 4;
    for (std::size_t i = 0; i < targets.size() && i < kMaxTargets; ++i) {
      const std::vector<int> one{targets[i]};
      const std::vector<Plan> safe = planner.safeties(cue, one);
      if (const std::optional<Shoot> tried = first_legal(rules, state, safe, one)) {
        return nominate(*tried, targets[i]);
      }
    }
    for (std::size_t i = 0; i < targets.size() && i < kMaxTargets; ++i) {
      const std::vector<int> one{targets[i]};
      if (const std::optional<Shoot> k = kick(rules, state, planner, cue, one)) {
        return nominate(*k, targets[i]);
      }
    }
    if (!targets.empty()) {
      // Every way is blocked: straight at the nearest ball on anyway.
      const Vec2 to = planner.pos(targets.front()) - cue;
      return nominate(make_shoot(dm::atan2(to.y, to.x) / kDeg, 3.0), targets.front());
    }
    Shoot s = make_shoot(0.0, 3.0);
    if (la.must_nominate && !la.nominate.empty()) s.nominate = la.nominate.front();
    return s;
  }

  static Action shot(const Rules& rules, const GameState& state, const LegalActions& la) {
    const Planner planner(rules, state);
    const bool kitchen = state.kitchen_shot;
    const Options o = options(planner, la.targets, kitchen);
    const Vec2 cue = planner.pos(0);
    if (const std::optional<Plan> p = planner.best_pot(cue, o.targets, o.legs)) {
      Shoot s = make_shoot(p->phi, p->speed);
      if (la.call) s.call = Call{p->ball, p->pocket};
      return s;
    }
    // Nothing to pot: a safety that hits a legal ball first and sends a
    // ball to a cushion.
    std::vector<int> targets = o.targets;
    if (targets.empty()) targets = planner.aimable(la.targets, false);
    std::stable_sort(targets.begin(), targets.end(), [&](int x, int y) {
      return norm(planner.pos(x) - cue) < norm(planner.pos(y) - cue);
    });
    Shoot s;
    const std::vector<Plan> safe = planner.safeties(cue, targets);
    if (const std::optional<Shoot> tried = first_legal(rules, state, safe, targets)) {
      s = *tried;
    } else if (const std::optional<Shoot> k = kick(rules, state, planner, cue, targets)) {
      s = *k;
    } else if (!safe.empty()) {
      s = make_shoot(safe.front().phi, safe.front().speed);
    } else if (!targets.empty()) {
      // Every way is blocked: straight at the nearest legal ball anyway.
      const Vec2 to = planner.pos(targets.front()) - cue;
      s = make_shoot(dm::atan2(to.y, to.x) / kDeg, 3.0);
    } else {
      s = make_shoot(0.0, 3.0);
    }
    s.safety = la.call;  // 8-ball: a declared safety (never with a call)
    if (rules.check(state, s)) s.safety = false;
    return s;
  }
};

}  // namespace

std::unique_ptr<Player> make_baseline_player() { return std::make_unique<BaselinePlayer>(); }

}  // namespace breakshot
