// Pots played and kept (shot_generator.hpp): each line's aim refined at
// its least speed, then its speed and spin variants from that aim, each
// noiseless play continued to rest and judged (judge.hpp). A candidate is
// kept only if the ruling finds no foul, the game not lost, the intended
// first contact and the target in the intended pocket; the state the
// ruling leaves gives its leave, so verification and the leave cost no
// extra simulation.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "breakshot/pool.hpp"
#include "evaluate.hpp"
#include "shot_generator.hpp"

namespace breakshot::ai_detail::shot_gen {

/// The candidate shot of a strike: the call (8-ball needs it; 9-ball
/// and snooker take it as information), the nomination snooker needs
/// after a red (the ball `target`), the declaration of a safety. The
/// call is dropped where the rules refuse it (add_pot did so too).
Shoot Generator::shot_of(const CueStrike& strike, int target, int pocket, bool safety) const {
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

/// The line's pot made as the rules see it: no foul, the game not
/// lost, the line's first ball hit and its target in its pocket.
bool Generator::pot_made(const Judged& j, const Line& l) {
  return j.legal && j.first_hit == l.first && pocket_of(j, l.target) == l.pocket;
}

/// A jump line: each of its speeds at its elevation, centre ball, the
/// aim refined on the engine; kept when the noiseless play pots.
void Generator::play_jump(const Line& l, std::vector<CandidateShot>& out) const {
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
void Generator::add_pot(const Line& l, const Judged& j, const Shoot& shot, double prior,
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

void Generator::play_line(const Line& l, std::vector<CandidateShot>& out) const {
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
double Generator::leave(const Judged& j) const {
  if (j.wins) return 1.0;
  if (j.next.phase == Phase::game_over || j.next.player != state_.player) return 0.0;
  if (policy_.frame_scoring) {
    // What the next pot is worth, not only its chance: p (value +
    // carry) as the estimate ranks pots, scaled so that a sure black
    // is 1. A black at 0.8 then outranks a yellow at 0.85.
    int ball = -1;
    const double p = ai_detail::best_pot_estimate_from(rules_, j.next, j.next.position[0], false,
                                                       opt_.leave_sigma_deg, &ball);
    return ball > 0 ? p * (rules_.ball_value(ball) + ai_detail::kSnookerCarry) /
                          (7.0 + ai_detail::kSnookerCarry)
                    : 0.0;
  }
  return ai_detail::best_pot_estimate(rules_, j.next, opt_.leave_sigma_deg);
}

}  // namespace breakshot::ai_detail::shot_gen
