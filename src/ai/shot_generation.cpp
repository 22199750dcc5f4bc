// Shot generation (include/breakshot/ai.hpp): the candidate shots the AI
// player chooses from.
//
// Every pot is planned geometrically first and then played on the engine.
// The geometry (ghost ball, cushion bounce points; shot_lines.cpp) only
// gives a starting aim and rejects what cannot work (blocked paths, cuts
// thinner than 80 degrees, bounces into a jaw). The aim is then corrected
// on noiseless simulations of the real shot (aim_refinement.cpp): the
// ball meant to drop is followed from the contact that sets it moving
// until its run ends, and the signed distance by which it passes the
// pocket's aim point is driven to zero by secant steps on phi. Throw,
// spin-induced curve, squirt-free spin variants and the cushion's real
// rebound are all inside that simulation, so nothing of them is assumed
// away. The slope the secant measures (metres of miss per degree of phi)
// is also the shot's sensitivity to aim error, which gives the prior: the
// chance that the tournament noise leaves the miss within the pocket's
// room.
//
// The aim is refined once per shot line (least speed, centre ball); each
// speed and spin variant then starts from that aim and the line's slope
// and needs a Newton step or two, because throw depends on speed and spin
// (pot_candidates.cpp). A candidate is kept only if the noiseless play,
// run to rest and ruled by the game's rules (judge.hpp), pockets the
// target in the intended pocket with the intended first contact and no
// foul (and, in 8-ball, without the 8 unless it is the target). The run
// used for the last aim correction is simply continued to rest, so
// verification costs no extra simulation.
//
// Jump shots (only with physics.airborne, and only where the level asks
// for them) are direct pots whose cue ball path is blocked by balls near
// it: the flight's closed form (jump_lines.cpp) gives, for each elevation
// tried, the range of cue speeds that lift the cue ball over the blockers
// and bring it down before the ghost ball, and the engine aims and checks
// them like any other pot.
//
// Safeties (safeties.cpp) are strikes at legal balls (full to thin, soft
// to medium) and, when needed, one-rail kicks, all played out; a legal
// hit with no foul and no scratch is kept and ranked by how little the
// opponent is left.
//
// Nothing here is random and every loop runs in a fixed order, so the
// same state always gives the same candidates in the same order.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/pool.hpp"
#include "shot_generator.hpp"

namespace breakshot {

std::string_view to_string(ShotKind k) {
  switch (k) {
    case ShotKind::direct:
      return "direct";
    case ShotKind::bank:
      return "bank";
    case ShotKind::kick:
      return "kick";
    case ShotKind::combination:
      return "combination";
    case ShotKind::safety:
      return "safety";
    case ShotKind::break_shot:
      return "break_shot";
    case ShotKind::jump:
      return "jump";
  }
  return "unknown";
}

namespace ai_detail::shot_gen {

Generator::Generator(const Rules& rules, const GameState& state, const ShotGenOptions& options)
    : rules_(rules),
      state_(state),
      opt_(options),
      table_(rules.table()),
      R_(rules.config().ball_radius),
      m_(rules.config().ball_mass),
      policy_(game_policy(state.game)),
      colour_on_(state.snooker && state.snooker->colour_on) {
  layout_.pos = state.position;
  layout_.on = state.on_table;
  la_ = rules.legal_actions(state);
  // The balls on as the rules name them (snooker: a free ball, any ball
  // nominated as the ball on after a foul, is not planned; the pool
  // games: the legal first balls).
  const std::vector<int> planned = rules.balls_on(state);
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

std::vector<CandidateShot> Generator::run() {
  std::vector<CandidateShot> out;
  // Snooker's break-off is a shot like any other (at the reds, from
  // the D); the pool games' break has its own search (break_shot.cpp).
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

}  // namespace ai_detail::shot_gen

std::vector<CandidateShot> generate_shots(const Rules& rules, const GameState& state,
                                          const ShotGenOptions& options) {
  return ai_detail::shot_gen::Generator(rules, state, options).run();
}

}  // namespace breakshot
