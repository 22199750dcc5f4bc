// Jump shots (shot_generator.hpp; only with physics.airborne, and only
// where the level asks for them): direct pots whose cue ball path is
// blocked by balls near it. The flight's closed form gives, for each
// elevation tried, the range of cue speeds that lift the cue ball over
// the blockers and bring it down before the ghost ball; the engine then
// aims and checks them like any other pot.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "breakshot/pool.hpp"
#include "physics/airborne.hpp"
#include "shot_generator.hpp"

namespace breakshot::ai_detail::shot_gen {

namespace {

using ai::segments_distance;
// The cue ball's centre passes a blocker this much beyond 2R; blockers
// farther along the path than kMaxJumpBlocker are not jumped (a flight
// long enough to clear them would overshoot most pots); the least cue
// speed that clears is raised by kJumpSpeedMargin, about ten times the
// tournament speed noise (0.075 m/s) at the 2-3 m/s that short jumps
// take, as a share; and a jump's prior is its aim prior times
// kJumpPrior, for what the aim slope cannot see (elevation and speed
// errors move the landing).
constexpr double kJumpClearance = 0.004;  // m
constexpr double kMaxJumpBlocker = 0.6;   // m
constexpr double kJumpSpeedMargin = 1.1;
constexpr double kJumpPrior = 0.6;

}  // namespace

/// The flight of a cue ball struck at elevation theta (degrees) with a
/// centre hit, per unit cue speed: its speed along the cloth and its
/// vertical speed once the slate has thrown it back up. The strike is
/// linear in the cue speed (cue.cpp) and so is the slate's impulse
/// (fixed_contact_impact: restitution on the normal part, friction
/// capped at the impulse that stops the slip), so a cue speed V gives
/// V times both.
Generator::Flight Generator::flight(double theta) const {
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
std::vector<Line> Generator::jump_lines(int t, int pocket) const {
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

}  // namespace breakshot::ai_detail::shot_gen
