// Shot generation (include/breakshot/ai.hpp): the candidate shots the AI
// player chooses from.
//
// Every pot is planned geometrically first and then played on the engine.
// The geometry (ghost ball, cushion bounce points) only gives a
// starting aim and rejects what cannot work (blocked paths, cuts thinner
// than 80 degrees, bounces into a jaw). The aim is then corrected on
// noiseless simulations of the real shot: the ball meant to drop is
// followed from the contact that sets it moving until its run ends (a
// pocket, a ball, a cushion beyond the one it is meant to bank off, or a
// stop), and the signed distance by which the straight continuation of its
// last motion passes the pocket's aim point is driven to zero by secant
// steps on phi. Throw, spin-induced curve, squirt-free spin variants and
// the cushion's real rebound are all inside that simulation, so nothing of
// them is assumed away. The slope the secant measures (metres of miss per
// degree of phi) is also the shot's sensitivity to aim error, which gives
// the prior: the chance that the tournament noise leaves the miss within
// the pocket's room.
//
// The aim is refined once per shot line (least speed, centre ball); each
// speed and spin variant then starts from that aim and the line's slope
// and needs a Newton step or two, because throw depends on speed and spin.
// A candidate is kept only if the noiseless play, run to rest, pockets the
// target in the intended pocket with the intended first contact and no
// foul (and, in 8-ball, without the 8 unless it is the target). The run
// used for the last aim correction is simply continued to rest, so
// verification costs no extra simulation.
//
// Jump shots (only with physics.airborne, and only where the level asks
// for them) are direct pots whose cue ball path is blocked by balls near
// it: the flight's closed form (jump_lines) gives, for each elevation
// tried, the range of cue speeds that lift the cue ball over the blockers
// and bring it down before the ghost ball, and the engine aims and checks
// them like any other pot.
//
// Safeties are strikes at legal balls (full to thin, soft to medium) and,
// when needed, one-rail kicks, all played out; a legal hit with no foul
// and no scratch is kept and ranked by how little the opponent is left.
//
// Nothing here is random and every loop runs in a fixed order, so the
// same state always gives the same candidates in the same order.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/airborne.hpp"
#include "breakshot/detmath.hpp"
#include "breakshot/game.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "evaluate.hpp"
#include "geometry.hpp"
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
constexpr double kRailRetention = 0.7;  // speed kept through a cushion, roughly

// The largest cut angles, as their cosines correctly rounded (literals, so
// that no maths library is involved): 80 degrees for direct cuts (thinner
// ones are hopeless), 70 for banks, kicks and combinations, 60 for each
// contact of a combination.
constexpr double kMaxCutCos = 0.17364817766693041;
constexpr double kMaxBankCutCos = 0.34202014332566882;
constexpr double kMaxComboCutCos = 0.50000000000000011;
constexpr double kArrival = 0.5;              // m/s the target keeps at the pocket
constexpr double kMinCueSpeed = 0.8;          // m/s
constexpr double kMaxPotSpeed = 9.0;          // m/s: faster least speeds are not tried
constexpr double kAcceptMiss = 0.0008;        // m: aim good enough, stop refining
constexpr double kMaxStep = 2.0;              // degrees a secant step may turn the aim
// Jump shots (physics.airborne): the cue ball's centre passes a blocker
// this much beyond 2R; blockers farther along the path than
// kMaxJumpBlocker are not jumped (a flight long enough to clear them
// would overshoot most pots); the least cue speed that clears is raised
// by kJumpSpeedMargin, about ten times the tournament speed noise (0.075
// m/s) at the 2-3 m/s that short jumps take, as a share; and a jump's
// prior is its aim prior times kJumpPrior, for what the aim slope cannot
// see (elevation and speed errors move the landing).
constexpr double kJumpClearance = 0.004;  // m
constexpr double kMaxJumpBlocker = 0.6;   // m
constexpr double kJumpSpeedMargin = 1.1;
constexpr double kJumpPrior = 0.6;
// Effective phi noise (degrees) for priors: tournament phi noise 0.125
// plus about as much again from tip-offset squirt and speed-dependent throw.
constexpr double kSigmaAim = 0.17;

Vec2 unit(Vec2 v) { return v / norm(v); }

Vec2 rotate(Vec2 v, double angle) {
  double s = 0.0;
  double c = 0.0;
  dm::sincos(angle, s, c);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

double phi_of(Vec2 v) { return dm::atan2(v.y, v.x) / kDeg; }

using ai::Approach;
using ai::Layout;
using ai::segments_distance;
using ai::wall_distance;

double standard_normal_within(double x) { return dm::erf(x / std::sqrt(2.0)); }

/// What a probe of a shot measured on the engine.
struct Probe {
  bool ok = false;       ///< the watched run happened and gives a measure
  double miss = 0.0;     ///< signed lateral miss at the aim point (m)
  bool reached = false;  ///< the watched ball got as far as the aim line
};

/// Which run of which ball a probe follows, and against what line.
struct Watch {
  int ball = -1;          ///< scenario index of the watched ball
  bool from_start = false;  ///< run starts at the strike (the cue ball)
  int pass_cushions = 0;  ///< cushion contacts the run goes through
  Vec2 aim;               ///< the run should pass through here...
  Vec2 dir;               ///< ...moving this way
};

/// One shot line before its speed and spin variants.
struct Line {
  ShotKind kind = ShotKind::direct;
  int first = -1;
  int target = -1;
  int pocket = -1;
  double phi = 0.0;                 ///< geometric aim, degrees
  double speed = 0.0;               ///< least cue speed estimate, m/s
  double room = 0.0;                ///< m of room at the pocket
  double geo_prior = 0.0;           ///< prior from geometry alone, for ordering
  double prior_scale = 1.0;         ///< what the slope cannot see (cushion, kicks)
  Watch watch;                      ///< the target's run into the pocket
  std::optional<Watch> pre;         ///< kicks: the cue ball's run off the rail first
  double theta = 0.0;               ///< jumps: the cue's elevation, degrees
  std::vector<double> jump_speeds;  ///< jumps: the cue speeds tried, m/s
};

class Generator {
 public:
  Generator(const Rules& rules, const GameState& state, const ShotGenOptions& options)
      : rules_(rules),
        state_(state),
        opt_(options),
        table_(rules.table()),
        R_(rules.config().ball_radius),
        m_(rules.config().ball_mass),
        policy_(ai_detail::game_policy(state.game)),
        colour_on_(state.snooker && state.snooker->colour_on) {
    layout_.pos = state.position;
    layout_.on = state.on_table;
    la_ = rules.legal_actions(state);
    // Snooker: the balls on; a free ball (any ball nominated as the ball
    // on after a foul) is not planned.
    const std::vector<int> planned = policy_.plan_balls_on ? snooker_balls_on(state) : la_.targets;
    for (int t : planned) {
      if (t <= 0 || t >= static_cast<int>(state.on_table.size()) || !on(t)) continue;
      // From the kitchen, a ball behind the head string is fair only once
      // the cue ball has crossed it; such shots are not planned.
      if (state.kitchen_shot && pos(t).x <= rules.head_string()) continue;
      targets_.push_back(t);
    }
    CueStrike unit_strike;
    unit_strike.speed = 1.0;
    launch_ = strike(unit_strike, m_, R_, CueParams{}).velocity.x;
    base_ = rules.shot_scenario(state, CueStrike{}, &numbers_);
    run_ = base_;
    index_.assign(state.on_table.size(), -1);
    for (std::size_t k = 0; k < numbers_.size(); ++k) {
      index_[static_cast<std::size_t>(numbers_[k])] = static_cast<int>(k);
    }
  }

  std::vector<CandidateShot> run() {
    std::vector<CandidateShot> out;
    // Snooker's break-off is a shot like any other (at the reds, from
    // the D); the pool games' break has its own search (ai_player.cpp).
    const bool shot_phase =
        state_.phase == Phase::shot ||
        (policy_.break_is_a_shot && state_.phase == Phase::break_shot);
    if (!shot_phase || !la_.shoot || !on(0) || targets_.empty()) return out;
    std::vector<Line> lines;
    // Whether each target has a direct pot into each pocket: kicks are
    // planned only where it has not.
    std::vector<std::vector<bool>> direct_ok(state_.on_table.size(),
                                             std::vector<bool>(table_.pockets.size(), false));
    for (int t : targets_) {
      for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
        if (std::optional<Line> l = direct_line(t, static_cast<int>(k))) {
          direct_ok[static_cast<std::size_t>(t)][k] = true;
          lines.push_back(*l);
        }
      }
    }
    // Jumps over the balls that block a direct pot (physics.airborne).
    // Snooker has no jump shots: the cue ball jumping over a ball is a
    // foul (docs/rules.md).
    if (opt_.jumps && base_.physics.airborne && policy_.jumps) {
      for (int t : targets_) {
        for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
          if (direct_ok[static_cast<std::size_t>(t)][k]) continue;
          for (Line& l : jump_lines(t, static_cast<int>(k))) lines.push_back(std::move(l));
        }
      }
    }
    if (opt_.banks) {
      for (int t : targets_) {
        for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
          for (int rail = 0; rail < 4; ++rail) {
            if (std::optional<Line> l = bank_line(t, static_cast<int>(k), rail)) lines.push_back(*l);
          }
        }
      }
    }
    if (opt_.kicks) {
      for (int t : targets_) {
        for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
          if (direct_ok[static_cast<std::size_t>(t)][k]) continue;
          for (int rail = 0; rail < 4; ++rail) {
            if (std::optional<Line> l = kick_line(t, static_cast<int>(k), rail)) lines.push_back(*l);
          }
        }
      }
    }
    if (opt_.combinations) {
      for (int f : targets_) {
        for (int t : combination_targets(f)) {
          for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
            if (std::optional<Line> l = combination_line(f, t, static_cast<int>(k))) {
              lines.push_back(*l);
            }
          }
        }
      }
    }
    // Pot maps ask for one ball and one pocket only.
    std::erase_if(lines, [&](const Line& l) {
      return (opt_.only_ball >= 0 && l.target != opt_.only_ball) ||
             (opt_.only_pocket >= 0 && l.pocket != opt_.only_pocket);
    });
    // Most promising lines first (stable: generation order breaks ties),
    // so that a cap on simulated lines keeps the best.
    std::stable_sort(lines.begin(), lines.end(),
                     [](const Line& a, const Line& b) { return a.geo_prior > b.geo_prior; });
    constexpr std::size_t kMaxLines = 48;
    if (lines.size() > kMaxLines) lines.resize(kMaxLines);
    for (const Line& l : lines) play_line(l, out);

    if (opt_.safeties) add_safeties(out);

    std::stable_sort(out.begin(), out.end(), [](const CandidateShot& a, const CandidateShot& b) {
      return a.prior > b.prior;
    });
    const auto cap = static_cast<std::size_t>(std::max(opt_.max_candidates, 0));
    if (out.size() > cap) out.resize(cap);
    return out;
  }

 private:
  // -------------------------------------------------------------------------
  // Geometry

  Vec2 pos(int b) const { return state_.position[static_cast<std::size_t>(b)]; }
  bool on(int b) const { return state_.on_table[static_cast<std::size_t>(b)] != 0; }

  bool balls_clear(const Layout& lay, Vec2 a, Vec2 b, int skip1, int skip2 = -1) const {
    return ai::balls_clear(lay, R_, a, b, skip1, skip2);
  }
  bool walls_clear(Vec2 a, Vec2 b) const { return ai::walls_clear(table_, R_, a, b); }

  bool fits(Vec2 p) const { return wall_clearance(table_, p, R_) >= 0.0; }

  std::optional<Approach> approach(const Layout& lay, Vec2 from, int pocket, int skip1,
                                   int skip2 = -1, bool at_rest = true) const {
    return ai::pocket_approach(table_, R_, lay, from, pocket, skip1, skip2, at_rest);
  }

  /// Lateral miss at the pocket per degree of cue aim (m/deg) of a cut
  /// over cue leg d1 and object leg d2: the contact point moves d1 dphi
  /// across, which turns the object ball by that over 2R cos(cut).
  double slope_estimate(double d1, double d2, double cos_cut) const {
    return (d1 + 2.0 * R_) * d2 / (2.0 * R_ * std::max(cos_cut, 0.1)) * kDeg;
  }

  static double prior_from(double room, double slope) {
    if (!(std::abs(slope) > 0.0)) return 0.0;
    const double tolerance = room / std::abs(slope);  // degrees of phi
    return standard_normal_within(tolerance / kSigmaAim);
  }

  /// Ball centre lines of the four rails: x = R, x = L - R, y = R, y = W - R.
  double rail_line(int rail) const {
    switch (rail) {
      case 0: return R_;
      case 1: return table_.length - R_;
      case 2: return R_;
      default: return table_.width - R_;
    }
  }
  Vec2 mirror(Vec2 p, int rail) const {
    const double c = rail_line(rail);
    return rail < 2 ? Vec2{2.0 * c - p.x, p.y} : Vec2{p.x, 2.0 * c - p.y};
  }
  /// Where a ball going from a to p off the rail should meet it, if on a
  /// straight cushion away from the pockets. Not the mirror point: the
  /// cushion keeps less of the normal speed than of the speed along it, so
  /// the ball leaves flatter, tan(out) = tan(in) / kRebound (the engine's
  /// cushion law gives 0.73-0.9 just after the impact, and the spin left
  /// bends the path a little further); refinement does the rest.
  std::optional<Vec2> bounce(Vec2 a, Vec2 p, int rail) const {
    constexpr double kRebound = 0.8;
    const double c = rail_line(rail);
    const bool vertical = rail < 2;  // the rail line is x = c
    const double inward = (rail == 0 || rail == 2) ? 1.0 : -1.0;
    const double h1 = ((vertical ? a.x : a.y) - c) * inward;
    const double h2 = ((vertical ? p.x : p.y) - c) * inward;
    if (h1 <= 0.0 || h2 <= R_) return std::nullopt;
    const double a_along = vertical ? a.y : a.x;
    const double p_along = vertical ? p.y : p.x;
    const double t = (p_along - a_along) / (h1 + h2 / kRebound);
    const double along = a_along + h1 * t;
    const Vec2 hit = vertical ? Vec2{c, along} : Vec2{along, c};
    const double extent = vertical ? table_.width : table_.length;
    if (along < 0.0 || along > extent) return std::nullopt;
    for (const Pocket& pk : table_.pockets) {
      if (norm(pk.centre - hit) < pk.radius + 2.5 * R_) return std::nullopt;
    }
    return hit;
  }

  // -------------------------------------------------------------------------
  // Speed estimates

  /// Speed a ball needs at the start of a straight leg of length d to have
  /// `end` left: rolling resistance, plus the loss of a struck or hit ball
  /// sliding into its roll (it keeps 5/7 of its speed once it rolls, and
  /// gets there after 12 v^2 / (49 mu_s g)).
  static double start_speed(double end, double d) {
    const double rolled = std::sqrt(end * end + 2.0 * kRollingFriction * kGravity * d);
    double v = rolled;
    for (int i = 0; i < 3; ++i) {
      const double slide = 12.0 * v * v / (49.0 * kSlidingFriction * kGravity);
      const double lost = 2.0 / 7.0 * std::min(1.0, d / std::max(slide, 1e-9));
      v = rolled / (1.0 - lost);
    }
    return v;
  }

  /// Speed a ball hit at cut angle `cos_cut` leaves with per unit speed of
  /// the ball hitting it (equal masses).
  static double transfer(double cos_cut) { return 0.5 * (1.0 + kBallBallRestitution) * cos_cut; }

  double cue_speed_for(double ball_speed) const {
    return std::max(kMinCueSpeed, ball_speed / launch_);
  }

  // -------------------------------------------------------------------------
  // Shot lines

  std::optional<Line> direct_line(int t, int pocket) const {
    const std::optional<Approach> ap = approach(layout_, pos(t), pocket, t);
    if (!ap) return std::nullopt;
    const Vec2 b = pos(t);
    const Vec2 ghost = b - ap->dir * (2.0 * R_);
    const Vec2 cue = pos(0);
    const double d1 = norm(ghost - cue);
    if (d1 < 1e-6 || !fits(ghost)) return std::nullopt;
    const Vec2 u = (ghost - cue) / d1;
    const double cos_cut = dot(u, ap->dir);
    if (cos_cut < kMaxCutCos) return std::nullopt;
    if (!balls_clear(layout_, cue, ghost, t) || !walls_clear(cue, ghost)) return std::nullopt;
    Line l;
    l.kind = ShotKind::direct;
    l.first = t;
    l.target = t;
    l.pocket = pocket;
    l.phi = phi_of(u);
    const double vo = start_speed(kArrival, ap->length);
    l.speed = cue_speed_for(start_speed(vo / transfer(cos_cut), d1));
    l.room = ap->room;
    l.geo_prior = prior_from(ap->room, slope_estimate(d1, ap->length, cos_cut));
    l.watch = Watch{index_of(t), false, 0, ap->aim, ap->dir};
    if (l.speed > kMaxPotSpeed) return std::nullopt;
    return l;
  }

  std::optional<Line> bank_line(int t, int pocket, int rail) const {
    const Pocket& pk = table_.pockets[static_cast<std::size_t>(pocket)];
    const Vec2 b = pos(t);
    const std::optional<Vec2> hit = bounce(b, pk.centre, rail);
    if (!hit) return std::nullopt;
    // The second leg, from the cushion into the pocket.
    const std::optional<Approach> ap = approach(layout_, *hit, pocket, t, -1, false);
    if (!ap) return std::nullopt;
    const Vec2 d_first = unit(*hit - b);
    const double leg1 = norm(*hit - b);
    if (!balls_clear(layout_, b, *hit, t) || !walls_clear(b, *hit)) return std::nullopt;
    const Vec2 ghost = b - d_first * (2.0 * R_);
    const Vec2 cue = pos(0);
    const double d1 = norm(ghost - cue);
    if (d1 < 1e-6 || !fits(ghost)) return std::nullopt;
    const Vec2 u = (ghost - cue) / d1;
    const double cos_cut = dot(u, d_first);
    if (cos_cut < kMaxBankCutCos) return std::nullopt;
    if (!balls_clear(layout_, cue, ghost, t) || !walls_clear(cue, ghost)) return std::nullopt;
    Line l;
    l.kind = ShotKind::bank;
    l.first = t;
    l.target = t;
    l.pocket = pocket;
    l.phi = phi_of(u);
    const double at_rail = start_speed(kArrival, ap->length) / kRailRetention;
    const double vo = start_speed(at_rail, leg1);
    l.speed = cue_speed_for(start_speed(vo / transfer(cos_cut), d1));
    l.room = ap->room;
    // A bank doubles the object ball's error at the pocket roughly by the
    // mirror geometry: the unfolded leg is leg1 + leg2 long.
    l.geo_prior = 0.7 * prior_from(ap->room, slope_estimate(d1, leg1 + ap->length, cos_cut));
    l.prior_scale = 0.7;  // cushion rebound varies with speed and spin
    l.watch = Watch{index_of(t), false, 1, ap->aim, ap->dir};
    if (l.speed > kMaxPotSpeed) return std::nullopt;
    return l;
  }

  std::optional<Line> kick_line(int t, int pocket, int rail) const {
    const std::optional<Approach> ap = approach(layout_, pos(t), pocket, t);
    if (!ap) return std::nullopt;
    const Vec2 b = pos(t);
    const Vec2 ghost = b - ap->dir * (2.0 * R_);
    if (!fits(ghost)) return std::nullopt;
    const Vec2 cue = pos(0);
    const std::optional<Vec2> hit = bounce(cue, ghost, rail);
    if (!hit) return std::nullopt;
    const double leg1 = norm(*hit - cue);
    const double leg2 = norm(ghost - *hit);
    if (leg2 < 1e-6) return std::nullopt;
    const Vec2 u2 = (ghost - *hit) / leg2;
    const double cos_cut = dot(u2, ap->dir);
    if (cos_cut < kMaxBankCutCos) return std::nullopt;
    if (!balls_clear(layout_, cue, *hit, -1) || !walls_clear(cue, *hit)) return std::nullopt;
    if (!balls_clear(layout_, *hit, ghost, t) || !walls_clear(*hit, ghost)) return std::nullopt;
    Line l;
    l.kind = ShotKind::kick;
    l.first = t;
    l.target = t;
    l.pocket = pocket;
    l.phi = phi_of(*hit - cue);
    const double vo = start_speed(kArrival, ap->length);
    const double at_rail = start_speed(vo / transfer(cos_cut), leg2) / kRailRetention;
    l.speed = cue_speed_for(start_speed(at_rail, leg1));
    l.room = ap->room;
    l.geo_prior = 0.5 * prior_from(ap->room, slope_estimate(leg1 + leg2, ap->length, cos_cut));
    l.prior_scale = 0.5;
    l.watch = Watch{index_of(t), false, 0, ap->aim, ap->dir};
    l.pre = Watch{index_of(0), true, 1, ghost, u2};
    if (l.speed > kMaxPotSpeed) return std::nullopt;
    return l;
  }

  /// The flight of a cue ball struck at elevation theta (degrees) with a
  /// centre hit, per unit cue speed: its speed along the cloth and its
  /// vertical speed once the slate has thrown it back up. The strike is
  /// linear in the cue speed (cue.cpp) and so is the slate's impulse
  /// (fixed_contact_impact: restitution on the normal part, friction
  /// capped at the impulse that stops the slip), so a cue speed V gives
  /// V times both.
  struct Flight {
    double along = 0.0;  ///< m/s per m/s of cue speed
    double up = 0.0;     ///< m/s per m/s of cue speed
  };
  Flight flight(double theta) const {
    CueStrike k;
    k.speed = 1.0;
    k.theta = theta;
    const StrikeResult sr = strike(k, m_, R_, base_.cue ? base_.cue->params : CueParams{});
    const Motion3 in{{sr.velocity.x, sr.velocity.y, sr.vertical}, sr.spin};
    const Motion3 out = fixed_contact_impact(
        in, {0.0, 0.0, 1.0}, R_, base_.physics.slate_restitution, base_.physics.sliding_friction);
    return {std::sqrt(out.velocity.x * out.velocity.x + out.velocity.y * out.velocity.y),
            out.velocity.z};
  }

  /// Jump shots at t into `pocket` (physics.airborne): when the cue
  /// ball's straight path to the ghost ball is blocked by other balls,
  /// one line per elevation of opt_.jump_thetas at which some cue speed
  /// lifts it over every one of them and brings it down before the ghost
  /// ball. The flight from the slate is the closed form
  ///   z(x) = k x - g x^2 / (2 v^2),   k = vz / v,
  /// with v and vz the speeds along the cloth and up (Flight); a blocker
  /// whose centre is s along the path and l to its side is cleared when
  /// the centres stay 2R (and a margin) apart,
  ///   z(x)^2 >= (2R)^2 - l^2 - (x - s)^2,
  /// checked at points across the blocker, which bounds the cue speed
  /// from below; landing (z = 0 at x = 2 k v^2 / g) at least R short of
  /// the ghost ball bounds it from above. The speeds tried lie in that
  /// range; the engine then aims each one and keeps what pots.
  std::vector<Line> jump_lines(int t, int pocket) const {
    std::vector<Line> out;
    const std::optional<Approach> ap = approach(layout_, pos(t), pocket, t);
    if (!ap) return out;
    const Vec2 b = pos(t);
    const Vec2 ghost = b - ap->dir * (2.0 * R_);
    const Vec2 cue = pos(0);
    const double d1 = norm(ghost - cue);
    if (d1 < 1e-6 || !fits(ghost)) return out;
    const Vec2 u = (ghost - cue) / d1;
    const double cos_cut = dot(u, ap->dir);
    if (cos_cut < kMaxCutCos) return out;
    if (!walls_clear(cue, ghost) || balls_clear(layout_, cue, ghost, t)) return out;
    // The balls in the way, as balls_clear finds them: their distance
    // along the path and to its side.
    struct Blocker {
      double s = 0.0;
      double l = 0.0;
    };
    std::vector<Blocker> blockers;
    const double reach = 2.0 * R_ + kJumpClearance;
    for (std::size_t n = 1; n < layout_.on.size(); ++n) {
      if (!layout_.on[n] || static_cast<int>(n) == t) continue;
      const Vec2 p = layout_.pos[n];
      if (dot(p - cue, u) <= 0.0 && norm(p - cue) >= 2.0 * R_) continue;
      if (segments_distance(p, p, cue, ghost) >= 2.0 * R_ + ai::kBallMargin) continue;
      const double s = dot(p - cue, u);
      if (s > kMaxJumpBlocker) return out;  // too far off for a jump to clear
      blockers.push_back({s, std::abs(cross(u, p - cue))});
    }
    if (blockers.empty()) return out;
    const double g = base_.physics.gravity;
    const double vo = start_speed(kArrival, ap->length);
    const double need = start_speed(vo / transfer(cos_cut), d1);  // cue ball speed at the start
    const double geo = prior_from(ap->room, slope_estimate(d1, ap->length, cos_cut));
    for (double theta : opt_.jump_thetas) {
      const Flight f = flight(theta);
      if (!(f.along > 0.0) || !(f.up > 0.0)) continue;
      const double k = f.up / f.along;
      // Least speed along the cloth (squared) that clears every blocker.
      double v2_lo = 0.0;
      bool possible = true;
      for (const Blocker& bl : blockers) {
        const double w = std::sqrt(std::max(reach * reach - bl.l * bl.l, 0.0));
        constexpr int kPoints = 16;
        for (int i = 0; i <= kPoints && possible; ++i) {
          const double x = bl.s - w + 2.0 * w * i / kPoints;
          const double h2 = reach * reach - bl.l * bl.l - (x - bl.s) * (x - bl.s);
          if (h2 <= 0.0) continue;
          const double spare = k * x - std::sqrt(h2);
          if (!(x > 0.0) || !(spare > 0.0)) {
            possible = false;
          } else {
            v2_lo = std::max(v2_lo, g * x * x / (2.0 * spare));
          }
        }
      }
      if (!possible) continue;
      // Most speed that still lands R short of the ghost ball.
      const double v2_hi = g * (d1 - R_) / (2.0 * k);
      // Cue speeds: the least one with a margin for the speed noise, and
      // the middle of the range, each at least what the pot needs.
      const double lo = std::max(std::sqrt(v2_lo) * kJumpSpeedMargin, need) / f.along;
      const double hi = std::sqrt(std::max(v2_hi, 0.0)) / f.along;
      if (!(lo < hi) || lo > kMaxPotSpeed) continue;
      Line l;
      l.kind = ShotKind::jump;
      l.first = t;
      l.target = t;
      l.pocket = pocket;
      l.phi = phi_of(u);
      l.theta = theta;
      l.jump_speeds.push_back(lo);
      const double mid = std::min(0.5 * (lo + hi), kMaxPotSpeed);
      if (mid > 1.05 * lo) l.jump_speeds.push_back(mid);
      l.speed = lo;
      l.room = ap->room;
      l.geo_prior = kJumpPrior * geo;
      l.prior_scale = kJumpPrior;
      l.watch = Watch{index_of(t), false, 0, ap->aim, ap->dir};
      out.push_back(std::move(l));
    }
    return out;
  }

  /// Balls a combination off first ball f may pocket: 9-ball, any other
  /// ball (a legal hit on the lowest makes any pot count); 8-ball, another
  /// legal target (so the call is a ball of the shooter's group).
  std::vector<int> combination_targets(int f) const {
    std::vector<int> out;
    using Combinations = ai_detail::GamePolicy::Combinations;
    if (policy_.combinations == Combinations::own_group) {
      for (int t : targets_) {
        if (t != f && t != 8) out.push_back(t);
      }
      return out;
    }
    if (policy_.combinations == Combinations::reds_only) {
      // Snooker: a red off a red. A colour must be both hit first and
      // potted (the nominated ball), so colours have no combinations.
      if (colour_on_) return out;
      for (int t : targets_) {
        if (t != f && snooker_value(t) == 1) out.push_back(t);
      }
      return out;
    }
    for (std::size_t n = 1; n < state_.on_table.size(); ++n) {
      if (state_.on_table[n] && static_cast<int>(n) != f) out.push_back(static_cast<int>(n));
    }
    return out;
  }

  std::optional<Line> combination_line(int f, int t, int pocket) const {
    const Vec2 bt = pos(t);
    const Vec2 bf = pos(f);
    // Cheap rejections first: the carrier must be close enough to be
    // steered, and the target must lie roughly between it and the pocket.
    const double ft = norm(bt - bf);
    if (ft > 0.8) return std::nullopt;
    const Vec2 pc = table_.pockets[static_cast<std::size_t>(pocket)].centre;
    if (dot(pc - bt, bt - bf) <= 0.0) return std::nullopt;
    const std::optional<Approach> ap = approach(layout_, bt, pocket, t);
    if (!ap) return std::nullopt;
    const Vec2 ghost_t = bt - ap->dir * (2.0 * R_);  // where f must touch t
    if (!fits(ghost_t)) return std::nullopt;
    const double d_f = norm(ghost_t - bf);
    if (d_f < 1e-6) return std::nullopt;
    const Vec2 uf = (ghost_t - bf) / d_f;
    const double cos_cut2 = dot(uf, ap->dir);
    if (cos_cut2 < kMaxComboCutCos) return std::nullopt;
    if (!balls_clear(layout_, bf, ghost_t, f, t) || !walls_clear(bf, ghost_t)) return std::nullopt;
    const Vec2 ghost_f = bf - uf * (2.0 * R_);
    if (!fits(ghost_f)) return std::nullopt;
    const Vec2 cue = pos(0);
    const double d1 = norm(ghost_f - cue);
    if (d1 < 1e-6) return std::nullopt;
    const Vec2 u = (ghost_f - cue) / d1;
    const double cos_cut1 = dot(u, uf);
    if (cos_cut1 < kMaxComboCutCos) return std::nullopt;
    if (!balls_clear(layout_, cue, ghost_f, f) || !walls_clear(cue, ghost_f)) return std::nullopt;
    Line l;
    l.kind = ShotKind::combination;
    l.first = f;
    l.target = t;
    l.pocket = pocket;
    l.phi = phi_of(u);
    const double vt = start_speed(kArrival, ap->length);
    const double vf = start_speed(vt / transfer(cos_cut2), d_f);
    l.speed = cue_speed_for(start_speed(vf / transfer(cos_cut1), d1));
    l.room = ap->room;
    // Errors compound: the carrier's direction error is amplified again
    // by the second contact.
    const double s1 = slope_estimate(d1, d_f, cos_cut1);
    const double amplify = (d_f + ap->length) / (2.0 * R_ * std::max(cos_cut2, 0.1));
    l.geo_prior = 0.8 * prior_from(ap->room, s1 * std::max(amplify, 1.0) * 0.5);
    l.prior_scale = 0.8;
    l.watch = Watch{index_of(t), false, 0, ap->aim, ap->dir};
    if (l.speed > kMaxPotSpeed) return std::nullopt;
    return l;
  }

  int index_of(int number) const { return index_[static_cast<std::size_t>(number)]; }

  // -------------------------------------------------------------------------
  // Simulation

  /// A run of the shot with this strike: a spare simulation re-armed
  /// (Simulation::reset) when there is one, else a new one.
  Simulation start(double phi, double speed, double b, double a = 0.0, double theta = 0.0) const {
    CueStrike& strike = run_.cue->strike;
    strike.speed = speed;
    strike.phi = phi;
    strike.b = b;
    strike.a = a;
    strike.theta = theta;
    ++simulations_;
    if (spare_.empty()) return Simulation(run_);
    Simulation sim = std::move(spare_.back());
    spare_.pop_back();
    sim.reset(run_);
    return sim;
  }

  /// A run no longer needed, kept for start() to re-arm.
  void recycle(Simulation&& sim) const { spare_.push_back(std::move(sim)); }

  /// Steps `sim` until the watched run ends and measures it. The
  /// simulation is left where it stopped, to be continued.
  static Probe follow(Simulation& sim, const Watch& w) {
    Probe out;
    bool started = w.from_start;
    int cushions = 0;
    std::size_t seen = sim.events().size();
    while (true) {
      const double t = sim.next_event_time();
      if (!std::isfinite(t)) return out;  // at rest: the run never ended
      const Simulation::Trajectory before = sim.trajectory(static_cast<std::size_t>(w.ball));
      if (sim.advance_to(t) != StopReason::reached) return out;
      const std::vector<Event>& ev = sim.events();
      bool ended = false;
      bool stopped = false;
      for (; seen < ev.size(); ++seen) {
        const Event& e = ev[seen];
        const bool mine = e.ball == w.ball || (e.type == EventType::ball_ball && e.other == w.ball);
        if (!mine || ended) continue;
        if (e.type == EventType::state_change) {
          if (started && e.to == MotionState::stationary) ended = stopped = true;
          continue;
        }
        if (e.type == EventType::cue_strike) continue;
        if (!started) {
          if (e.type == EventType::ball_ball) started = true;
          else return out;  // moved by something else first: not this shot
          continue;
        }
        if (e.type == EventType::ball_cushion && cushions < w.pass_cushions) {
          ++cushions;
          continue;
        }
        if (cushions < w.pass_cushions) return out;  // ended before the bank
        ended = true;
      }
      if (!ended) continue;
      const double dt = t - before.t0;
      const Vec2 p = before.p0 + before.v0 * dt + before.acc * (0.5 * dt * dt);
      Vec2 v = before.v0 + before.acc * dt;
      if (norm(v) < 1e-6) v = before.v0;
      if (norm(v) < 1e-9) return out;
      const Vec2 vu = unit(v);
      const double along = dot(vu, w.dir);
      if (along < 0.05) return out;  // moving away from the aim line
      const double s = dot(w.aim - p, w.dir) / along;
      const Vec2 q = p + vu * s;
      out.ok = true;
      out.miss = cross(w.dir, q - w.aim);
      out.reached = !stopped || dot(p - w.aim, w.dir) > -0.06;
      return out;
    }
  }

  /// A shot's noiseless play ruled by the game's own rules
  /// (Rules::apply_events on the events the simulation gave): the facts
  /// the generator ranks by and the state the ruling leaves.
  struct Judged {
    /// No foul, and the game not lost (8-ball: no 8 before its time).
    bool legal = false;
    bool wins = false;  ///< the shot wins the game for the shooter
    int first_hit = -1;
    std::vector<int> pocketed;
    std::vector<int> pocket_of;
    Layout after;
    GameState next;  ///< the state the ruling leaves
  };

  /// The candidate shot of a strike: the call (8-ball needs it; 9-ball
  /// and snooker take it as information), the nomination snooker needs
  /// after a red (the ball `target`), the declaration of a safety. The
  /// call is dropped where the rules refuse it (add_pot did so too).
  Shoot shot_of(const CueStrike& strike, int target, int pocket, bool safety) const {
    Shoot shot;
    shot.strike = strike;
    if (la_.must_nominate) shot.nominate = target;
    if (safety) {
      shot.safety = la_.call;  // 8-ball: a declared safety, never called
      return shot;
    }
    shot.call = Call{target, pocket};
    if (!la_.call && rules_.check(state_, Action{shot})) shot.call.reset();
    return shot;
  }

  /// Runs `sim` to rest and rules `shot` on what it did. A shot the rules
  /// refuse, or a run that does not come to rest, is judged not legal.
  Judged judge(Simulation& sim, const Shoot& shot) const {
    Judged j;
    if (sim.advance_to_rest() != StopReason::reached || !sim.at_rest()) return j;
    if (rules_.check(state_, Action{shot})) return j;
    std::vector<Event> events = sim.events();
    for (Event& e : events) {
      if (e.ball >= 0) e.ball = numbers_[static_cast<std::size_t>(e.ball)];
      if (e.other >= 0) e.other = numbers_[static_cast<std::size_t>(e.other)];
    }
    std::vector<Vec2> rest = layout_.pos;
    for (std::size_t k = 0; k < numbers_.size(); ++k) {
      rest[static_cast<std::size_t>(numbers_[k])] = sim.ball(k).position;
    }
    const bool miscue = sim.cue_result() && sim.cue_result()->miscue;
    Outcome o = rules_.apply_events(state_, shot, std::move(events), rest, miscue);
    j.first_hit = o.facts.first_hit;
    j.pocketed = o.facts.pocketed;
    j.pocket_of = o.facts.pocket_of;
    j.after.pos = o.state.position;
    j.after.on = o.state.on_table;
    const bool over = o.state.phase == Phase::game_over;
    j.wins = over && o.state.winner == state_.player;
    j.legal = o.ruling.fouls.empty() && (!over || j.wins);
    j.next = std::move(o.state);
    return j;
  }

  static int pocket_of(const Judged& j, int ball) {
    for (std::size_t k = 0; k < j.pocketed.size(); ++k) {
      if (j.pocketed[k] == ball) return j.pocket_of[k];
    }
    return -1;
  }

  /// The line's pot made as the rules see it: no foul, the game not
  /// lost, the line's first ball hit and its target in its pocket.
  static bool pot_made(const Judged& j, const Line& l) {
    return j.legal && j.first_hit == l.first && pocket_of(j, l.target) == l.pocket;
  }

  /// The result of correcting an aim: the aim, the run at that aim
  /// (stopped where its probe ended) and the slope found.
  struct Refined {
    double phi = 0.0;
    double slope = 0.0;  ///< m of miss per degree
    Probe probe;
    std::optional<Simulation> sim;
  };

  /// Secant iterations on phi that drive watch's miss to zero, from phi0
  /// with `slope` (0: measure it first). Once the miss has been seen on
  /// both sides of zero, steps stay inside that bracket (bisecting when a
  /// secant step would leave it), and an aim that gives no measure (the
  /// run ends some other way) is backed off halfway toward the best aim.
  /// At most `iterations` + 2 simulations.
  std::optional<Refined> refine(double phi0, double speed, double b, const Watch& w, double slope,
                                int iterations, double a = 0.0, double theta = 0.0) const {
    Refined best;
    bool have = false;
    double best_abs = kInf;
    std::optional<std::pair<double, double>> prev;  // last measured (phi, miss)
    std::optional<double> below, above;             // phi with miss < 0, > 0
    double phi = phi0;
    for (int it = 0; it < iterations + 2; ++it) {
      Simulation sim = start(phi, speed, b, a, theta);
      const Probe p = follow(sim, w);
      if (!p.ok) {
        recycle(std::move(sim));
        if (!have) return std::nullopt;
        phi = 0.5 * (phi + best.phi);
        continue;
      }
      if (std::abs(p.miss) < best_abs) {
        best_abs = std::abs(p.miss);
        best.phi = phi;
        best.probe = p;
        if (best.sim) recycle(std::move(*best.sim));
        best.sim = std::move(sim);
        have = true;
      } else {
        recycle(std::move(sim));
      }
      (p.miss < 0.0 ? below : above) = phi;
      if (prev && std::abs(phi - prev->first) > 1e-12) {
        const double s = (p.miss - prev->second) / (phi - prev->first);
        // Keep the sign of a measured slope: a secant across a kink that
        // flips it would send the aim the wrong way.
        if (slope == 0.0 || s * slope > 0.0) slope = s;
      }
      prev = std::make_pair(phi, p.miss);
      if (std::abs(p.miss) < kAcceptMiss) break;
      if (slope == 0.0) {
        phi += 0.05;  // a small step gives the first slope
        continue;
      }
      double next = best.phi - std::clamp(best.probe.miss / slope, -kMaxStep, kMaxStep);
      if (below && above) {
        const double lo = std::min(*below, *above);
        const double hi = std::max(*below, *above);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      }
      phi = next;
    }
    if (!have) return std::nullopt;
    if (slope == 0.0) {
      // Right on the first try: one more run for the slope, which the
      // variants and the prior need.
      Simulation sim = start(best.phi + 0.05, speed, b, a, theta);
      const Probe p = follow(sim, w);
      if (p.ok) slope = (p.miss - best.probe.miss) / 0.05;
      recycle(std::move(sim));
    }
    best.slope = slope;
    return best;
  }

  /// A jump line: each of its speeds at its elevation, centre ball, the
  /// aim refined on the engine; kept when the noiseless play pots.
  void play_jump(const Line& l, std::vector<CandidateShot>& out) const {
    for (double speed : l.jump_speeds) {
      std::optional<Refined> r =
          refine(l.phi, speed, 0.0, l.watch, 0.0, opt_.refine_iterations + 2, 0.0, l.theta);
      if (!r || !r->sim || !r->probe.reached || r->slope == 0.0) continue;
      CueStrike strike;
      strike.speed = speed;
      strike.phi = r->phi;
      strike.theta = l.theta;
      const Shoot shot = shot_of(strike, l.target, l.pocket, false);
      const Judged j = judge(*r->sim, shot);
      if (!pot_made(j, l)) continue;
      add_pot(l, j, shot, std::clamp(l.prior_scale * prior_from(l.room, r->slope), 0.0, 1.0),
              out);
    }
  }

  /// A pot of line l that the noiseless play `j` of `shot` (shot_of: the
  /// call 8-ball needs, which in 9-ball and snooker is information, a pot
  /// attempt for the statistics that the centred aim works on) made, as a
  /// candidate.
  void add_pot(const Line& l, const Judged& j, const Shoot& shot, double prior,
               std::vector<CandidateShot>& out) const {
    CandidateShot c;
    c.kind = l.kind;
    c.first = l.first;
    c.target = l.target;
    c.pocket = l.pocket;
    c.shot = shot;
    c.prior = prior;
    c.leave = leave(j);
    out.push_back(c);
  }

  void play_line(const Line& l, std::vector<CandidateShot>& out) const {
    if (l.kind == ShotKind::jump) {
      play_jump(l, out);
      return;
    }
    double phi = l.phi;
    double speed = l.speed;
    // Kicks: first bring the cue ball off the rail onto the ghost ball.
    if (l.pre) {
      const std::optional<Refined> r =
          refine(phi, speed, 0.0, *l.pre, 0.0, opt_.refine_iterations + 4);
      if (!r) return;
      phi = r->phi;
    }
    // The line at its least speed, centre ball; too slow to arrive, try
    // faster (the estimate ignores the shape of the run).
    std::optional<Refined> base;
    for (int attempt = 0; attempt < 3; ++attempt) {
      base = refine(phi, speed, 0.0, l.watch, 0.0,
                    opt_.refine_iterations + (l.kind == ShotKind::direct ? 0 : 4));
      if (!base) return;
      if (base->probe.reached) break;
      speed *= 1.35;
      if (speed > kMaxPotSpeed) return;
    }
    if (!base || !base->probe.reached || std::abs(base->probe.miss) > 0.5 * l.room + 0.002) return;
    const double slope = base->slope;
    if (slope == 0.0) return;
    const double prior = std::clamp(l.prior_scale * prior_from(l.room, slope), 0.0, 1.0);

    // Tip offsets: every height (b) on the centre line, then each side
    // offset (a) at centre height.
    std::vector<std::pair<double, double>> tips;
    for (double b : opt_.spins) tips.emplace_back(0.0, b);
    for (double a : opt_.sides) {
      if (a != 0.0) tips.emplace_back(a, 0.0);
    }
    for (double factor : opt_.speed_factors) {
      for (const auto& [a, b] : tips) {
        // The same ball speed with spin: the tip offset takes some of the
        // cue's energy into spin.
        const double off2 = a * a + b * b;
        const double spin_comp = (1.0 + m_ / CueParams{}.mass + 2.5 * off2) /
                                 (1.0 + m_ / CueParams{}.mass);
        const double v = std::clamp(speed * factor * spin_comp, 0.1, kMaxCueSpeed);
        std::optional<Refined> r;
        if (factor == 1.0 && b == 0.0 && a == 0.0) {
          r = base;
        } else {
          r = refine(base->phi, v, b, l.watch, slope, l.kind == ShotKind::direct ? 2 : 4, a);
        }
        if (!r || !r->sim) continue;
        CueStrike strike;
        strike.speed = factor == 1.0 && b == 0.0 && a == 0.0 ? speed : v;
        strike.phi = r->phi;
        strike.b = b;
        strike.a = a;
        const Shoot shot = shot_of(strike, l.target, l.pocket, false);
        const Judged j = judge(*r->sim, shot);
        if (!pot_made(j, l)) continue;
        // A little less for the harder strokes, so that ties go to the
        // simpler one.
        add_pot(l, j, shot,
                prior * (1.0 - 0.03 * (std::abs(b) + std::abs(a))) * (factor > 2.0 ? 0.97 : 1.0),
                out);
      }
    }
  }

  /// The shooter's best next pot on the table a pot's noiseless play
  /// left (CandidateShot::leave), on the state the rules left (groups
  /// taken, a colour respotted, the ball on): 1 when the pot wins the
  /// game, 0 when the turn passed.
  double leave(const Judged& j) const {
    if (j.wins) return 1.0;
    if (j.next.phase == Phase::game_over || j.next.player != state_.player) return 0.0;
    if (policy_.frame_scoring) {
      // What the next pot is worth, not only its chance: p (value +
      // carry) as the estimate ranks pots, scaled so that a sure black
      // is 1. A black at 0.8 then outranks a yellow at 0.85.
      int ball = -1;
      const double p = ai_detail::best_pot_estimate_from(rules_, j.next, j.next.position[0], false,
                                                         opt_.leave_sigma_deg, &ball);
      return ball > 0 ? p * (snooker_value(ball) + ai_detail::kSnookerCarry) /
                            (7.0 + ai_detail::kSnookerCarry)
                      : 0.0;
    }
    return ai_detail::best_pot_estimate(rules_, j.next, opt_.leave_sigma_deg);
  }

  // -------------------------------------------------------------------------
  // Safeties

  /// Balls the opponent may hit first on the table a shot leaves, as the
  /// rules say (Rules::targets with the opponent to play).
  std::vector<int> opponent_targets(const GameState& next) const {
    GameState opp = next;
    opp.player = 1 - state_.player;
    return rules_.targets(opp);
  }

  /// The opponent's easiest direct pot on the table a shot left, as a
  /// geometric prior in [0, 1] (0: no pot, or no ball even visible;
  /// cheap: no simulation).
  double opponent_chance(const Judged& j) const {
    const Layout& lay = j.after;
    if (!lay.on[0]) return 1.0;
    const Vec2 cue = lay.pos[0];
    double best = 0.0;
    for (int t : opponent_targets(j.next)) {
      const Vec2 b = lay.pos[static_cast<std::size_t>(t)];
      for (std::size_t k = 0; k < table_.pockets.size(); ++k) {
        const std::optional<Approach> ap = approach(lay, b, static_cast<int>(k), t);
        if (!ap) continue;
        const Vec2 ghost = b - ap->dir * (2.0 * R_);
        const double d1 = norm(ghost - cue);
        if (d1 < 1e-6) continue;
        const double cos_cut = dot((ghost - cue) / d1, ap->dir);
        if (cos_cut < kMaxCutCos) continue;
        if (!balls_clear(lay, cue, ghost, t)) continue;
        best = std::max(best, prior_from(ap->room, slope_estimate(d1, ap->length, cos_cut)));
      }
    }
    return best;
  }

  void add_safety(const CueStrike& s, int first, bool kick,
                  std::vector<CandidateShot>& found) const {
    const Shoot shot = shot_of(s, first, -1, true);  // snooker: nominates the colour it hits
    Simulation sim = start(s.phi, s.speed, s.b);
    const Judged j = judge(sim, shot);
    recycle(std::move(sim));
    if (!j.legal) return;
    CandidateShot c;
    c.kind = kick ? ShotKind::kick : ShotKind::safety;
    c.first = first;
    c.shot = shot;
    // Worth to the shooter: how little the opponent is left. Scaled below
    // real pots, which the evaluator prefers when they are on.
    c.prior = 0.4 * (1.0 - opponent_chance(j));
    found.push_back(c);
  }

  void add_safeties(std::vector<CandidateShot>& out) const {
    std::vector<CandidateShot> found;
    const Vec2 cue = pos(0);
    bool any_open = false;
    std::vector<double> turns;  // each cut both ways
    for (double tu : opt_.safety_turns) {
      turns.push_back(tu);
      if (tu != 0.0) turns.push_back(-tu);
    }
    for (int t : targets_) {
      const Vec2 b = pos(t);
      if (norm(b - cue) < 1e-9) continue;
      const Vec2 straight = unit(b - cue);
      for (double turn : turns) {
        const Vec2 n = rotate(straight, turn * kDeg);  // line of centres at contact
        const Vec2 ghost = b - n * (2.0 * R_);
        const double d1 = norm(ghost - cue);
        if (d1 < 1e-9 || !fits(ghost)) continue;
        const Vec2 u = (ghost - cue) / d1;
        if (dot(u, n) < kMaxCutCos) continue;
        if (!balls_clear(layout_, cue, ghost, t) || !walls_clear(cue, ghost)) continue;
        any_open = true;
        for (double speed : opt_.safety_speeds) {
          for (double tip : opt_.safety_spins) {
            CueStrike s;
            s.speed = speed;
            s.phi = phi_of(u);
            s.b = tip;
            add_safety(s, t, false, found);
          }
        }
      }
    }
    // One-rail kicks at a full hit on each legal ball, when no ball can be
    // hit directly or nothing direct played legally: the mirror aim is
    // corrected for the real rebound on the engine, like a kick pot.
    if (opt_.kicks && (!any_open || found.empty())) {
      for (int t : targets_) {
        const Vec2 b = pos(t);
        for (int rail = 0; rail < 4; ++rail) {
          const Vec2 approx = b - unit(b - mirror(cue, rail)) * (2.0 * R_);
          const std::optional<Vec2> hit = bounce(cue, approx, rail);
          if (!hit) continue;
          const Vec2 dir = unit(b - *hit);
          const Vec2 ghost = b - dir * (2.0 * R_);
          if (!fits(ghost)) continue;
          if (!balls_clear(layout_, cue, *hit, -1) || !walls_clear(cue, *hit)) continue;
          if (!balls_clear(layout_, *hit, ghost, t) || !walls_clear(*hit, ghost)) continue;
          const double length = norm(*hit - cue) + norm(ghost - *hit);
          const double speed = std::clamp(1.5 + 1.0 * length, 2.0, 6.0);
          const Watch w{index_of(0), true, 1, ghost, dir};
          const std::optional<Refined> r =
              refine(phi_of(*hit - cue), speed, 0.0, w, 0.0, opt_.refine_iterations);
          if (!r) continue;
          CueStrike s;
          s.speed = speed;
          s.phi = r->phi;
          add_safety(s, t, true, found);
        }
      }
    }
    std::stable_sort(found.begin(), found.end(), [](const CandidateShot& a, const CandidateShot& b) {
      return a.prior > b.prior;
    });
    const std::size_t keep =
        std::max<std::size_t>(8, static_cast<std::size_t>(std::max(opt_.max_candidates, 0)) / 4);
    if (found.size() > keep) found.resize(keep);
    out.insert(out.end(), found.begin(), found.end());
  }

  const Rules& rules_;
  const GameState& state_;
  const ShotGenOptions& opt_;
  const Table& table_;
  double R_;
  double m_;
  const ai_detail::GamePolicy& policy_;  // the game's strategy (policy.hpp)
  bool colour_on_;  // snooker: a colour is on after a red
  LegalActions la_;
  std::vector<int> targets_;  // legal first balls that may be aimed at
  Layout layout_;
  double launch_ = 1.0;       // cue ball speed per unit cue speed, centre hit
  Scenario base_;             // the shot's scenario; the strike is set per run
  mutable Scenario run_;      // base_ with the strike of the last start()
  mutable std::vector<Simulation> spare_;  // runs done with, for start() to re-arm
  std::vector<int> numbers_;  // scenario index -> ball number
  std::vector<int> index_;    // ball number -> scenario index (-1: off the table)
  mutable long simulations_ = 0;
};

}  // namespace

std::vector<CandidateShot> generate_shots(const Rules& rules, const GameState& state,
                                          const ShotGenOptions& options) {
  return Generator(rules, state, options).run();
}

}  // namespace breakshot
