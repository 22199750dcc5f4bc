// Safeties (shot_generator.hpp): strikes at every legal ball, full to
// thin, soft to medium, and where those fail one-rail kicks, all played
// out; a hit the rules find no foul in is kept and ranked by how little
// the opponent is left.
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "shot_generator.hpp"

namespace breakshot::ai_detail::shot_gen {

/// Balls the opponent may hit first on the table a shot leaves, as the
/// rules say (Rules::targets with the opponent to play).
std::vector<int> Generator::opponent_targets(const GameState& next) const {
  GameState opp = next;
  opp.player = 1 - state_.player;
  return rules_.targets(opp);
}

/// The opponent's easiest direct pot on the table a shot left, as a
/// geometric prior in [0, 1] (0: no pot, or no ball even visible;
/// cheap: no simulation).
double Generator::opponent_chance(const Judged& j) const {
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

void Generator::add_safety(const CueStrike& s, int first, bool kick,
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

void Generator::add_safeties(std::vector<CandidateShot>& out) const {
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

}  // namespace breakshot::ai_detail::shot_gen
