// Shot lines from geometry (shot_generator.hpp): direct pots, banks off
// one rail, kicks off one rail and combinations, each with its starting
// aim, the least cue speed that carries the target to its pocket, its
// room at the pocket and a prior from geometry alone. Paths must stay
// clear of balls and cushions; refinement on the engine corrects the aim.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "shot_generator.hpp"

namespace breakshot::ai_detail::shot_gen {

namespace {

using ai::kBallBallRestitution;
using ai::kGravity;
using ai::kRollingFriction;
using ai::kSlidingFriction;
constexpr double kRailRetention = 0.7;  // speed kept through a cushion, roughly
constexpr double kMinCueSpeed = 0.8;    // m/s
// Effective phi noise (degrees) for priors: tournament phi noise 0.125
// plus about as much again from tip-offset squirt and speed-dependent throw.
constexpr double kSigmaAim = 0.17;

double standard_normal_within(double x) { return dm::erf(x / std::sqrt(2.0)); }

}  // namespace

/// Lateral miss at the pocket per degree of cue aim (m/deg) of a cut
/// over cue leg d1 and object leg d2: the contact point moves d1 dphi
/// across, which turns the object ball by that over 2R cos(cut).
double Generator::slope_estimate(double d1, double d2, double cos_cut) const {
  return (d1 + 2.0 * R_) * d2 / (2.0 * R_ * std::max(cos_cut, 0.1)) * kDeg;
}

double Generator::prior_from(double room, double slope) {
  if (!(std::abs(slope) > 0.0)) return 0.0;
  const double tolerance = room / std::abs(slope);  // degrees of phi
  return standard_normal_within(tolerance / kSigmaAim);
}

/// Ball centre lines of the four rails: x = R, x = L - R, y = R, y = W - R.
double Generator::rail_line(int rail) const {
  switch (rail) {
    case 0: return R_;
    case 1: return table_.length - R_;
    case 2: return R_;
    default: return table_.width - R_;
  }
}

Vec2 Generator::mirror(Vec2 p, int rail) const {
  const double c = rail_line(rail);
  return rail < 2 ? Vec2{2.0 * c - p.x, p.y} : Vec2{p.x, 2.0 * c - p.y};
}

/// Where a ball going from a to p off the rail should meet it, if on a
/// straight cushion away from the pockets. Not the mirror point: the
/// cushion keeps less of the normal speed than of the speed along it, so
/// the ball leaves flatter, tan(out) = tan(in) / kRebound (the engine's
/// cushion law gives 0.73-0.9 just after the impact, and the spin left
/// bends the path a little further); refinement does the rest.
std::optional<Vec2> Generator::bounce(Vec2 a, Vec2 p, int rail) const {
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

/// Speed a ball needs at the start of a straight leg of length d to have
/// `end` left: rolling resistance, plus the loss of a struck or hit ball
/// sliding into its roll (it keeps 5/7 of its speed once it rolls, and
/// gets there after 12 v^2 / (49 mu_s g)).
double Generator::start_speed(double end, double d) {
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
double Generator::transfer(double cos_cut) { return 0.5 * (1.0 + kBallBallRestitution) * cos_cut; }

double Generator::cue_speed_for(double ball_speed) const {
  return std::max(kMinCueSpeed, ball_speed / launch_);
}

std::optional<Line> Generator::direct_line(int t, int pocket) const {
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

std::optional<Line> Generator::bank_line(int t, int pocket, int rail) const {
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

std::optional<Line> Generator::kick_line(int t, int pocket, int rail) const {
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

/// Balls a combination off first ball f may pocket: 9-ball, any other
/// ball (a legal hit on the lowest makes any pot count); 8-ball, another
/// legal target (so the call is a ball of the shooter's group; the 8 is a
/// target only when it alone is, and then it is the first ball).
std::vector<int> Generator::combination_targets(int f) const {
  std::vector<int> out;
  using Combinations = ai_detail::GamePolicy::Combinations;
  if (policy_.combinations == Combinations::own_group) {
    for (int t : targets_) {
      if (t != f) out.push_back(t);
    }
    return out;
  }
  if (policy_.combinations == Combinations::reds_only) {
    // Snooker: a red off a red. A colour must be both hit first and
    // potted (the nominated ball), so colours have no combinations.
    if (colour_on_) return out;
    for (int t : targets_) {
      if (t != f && rules_.ball_value(t) == 1) out.push_back(t);
    }
    return out;
  }
  for (std::size_t n = 1; n < state_.on_table.size(); ++n) {
    if (state_.on_table[n] && static_cast<int>(n) != f) out.push_back(static_cast<int>(n));
  }
  return out;
}

std::optional<Line> Generator::combination_line(int f, int t, int pocket) const {
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

}  // namespace breakshot::ai_detail::shot_gen
