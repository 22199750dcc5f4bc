// The AI's strategy that belongs to one game, in one registry
// (policy.cpp): the only place in src/ai that tells the games apart. The
// rules (what is legal, what a shot is ruled, who plays next, the balls
// on) come from the game's ruleset through Rules; what a game's players
// do with them, and which search decides, comes from its GamePolicy. A new
// game gets an entry here, naming the strategy it shares.
// Internal: not installed.
#pragma once

#include "breakshot/game.hpp"

namespace breakshot::ai_detail {

struct GamePolicy {
  /// Which search decides: the pool games' (shot generation, samples,
  /// lookahead), snooker's (the same with a frame's scoring around it) or
  /// three-cushion's (carom_ai.cpp, the baseline's baseline_carom.cpp).
  enum class Search { pool, snooker, carom };
  Search search = Search::pool;
  /// A table is worth the shooter's chance of the frame from the score
  /// and the balls left (snooker_position_value) rather than the next
  /// pot's promise; no miss charge (the frame chance already prices a
  /// miss); a pot ranks by its points.
  bool frame_scoring = false;
  /// A declared safety is also sampled unannounced (8-ball: a first ball
  /// that drops then keeps the turn).
  bool unannounced_safeties = false;
  /// A rotation game (the lowest ball first): the break aims at that
  /// ball, a safety or kick whose samples mostly pot one ball in one
  /// pocket is called for it, and the lookahead reads the rotation's
  /// deeper settings (AiLevel::lookahead_candidates_nine, ..._states_nine)
  /// and the break its faster speeds.
  bool rotation = false;
  /// Which balls a combination off the first ball may pot.
  enum class Combinations { own_group, any_ball, reds_only };
  Combinations combinations = Combinations::any_ball;
  /// The break is a shot like any other (snooker's break-off), not the
  /// pool games' own break search.
  bool break_is_a_shot = false;
  /// Jump shots may be tried (a foul in snooker).
  bool jumps = true;
  /// The level's snooker shot generation (AiLevel::snooker_generation)
  /// where it has one.
  bool snooker_generation = false;
};

/// The policy of `game`.
const GamePolicy& game_policy(GameType game);

}  // namespace breakshot::ai_detail
