// The AI player (docs/ai.md): shot generation with aim refined on the
// engine, Monte Carlo evaluation under the player's own execution noise,
// the value of the table left, and lookahead, in the manner of the
// computational pool tournament winners (PickPocket, CueCard).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"

namespace breakshot {

enum class ShotKind : std::uint8_t {
  direct,       ///< the cue ball hits `target`, which goes into `pocket`
  bank,         ///< `target` goes into `pocket` off one cushion
  kick,         ///< the cue ball reaches `target` off one cushion first
  combination,  ///< the cue ball hits `first`, which drives `target` into `pocket`
  safety,       ///< no pot intended: a legal hit that leaves the opponent badly
  break_shot,   ///< the opening break
  jump,         ///< the cue ball flies over the balls in its way; `target` into `pocket`
};
std::string_view to_string(ShotKind k);

/// One shot the player could play, as it would be played without noise.
struct CandidateShot {
  ShotKind kind = ShotKind::direct;
  Shoot shot;       ///< strike, and the call (8-ball) or safety flag
  int first = -1;   ///< the object ball the cue ball is aimed to hit first
  int target = -1;  ///< the ball meant to be pocketed (-1 for a safety)
  int pocket = -1;  ///< the pocket meant (-1 for a safety)
  /// A cheap a-priori estimate in [0, 1] of how likely the shot succeeds
  /// (from the geometry), used to rank candidates before any sampling.
  double prior = 0.0;
  /// Pots: the geometric estimate in [0, 1] of the shooter's best next pot
  /// on the table the noiseless play leaves (1 when that pot wins the
  /// game), so that candidates can be ranked by position before any
  /// sampling. -1 for shots that end the turn (safeties).
  double leave = -1.0;
};

struct ShotGenOptions {
  bool banks = true;
  bool kicks = true;
  bool combinations = true;
  bool safeties = true;
  /// Jump shots over the balls that block a direct pot, tried only when
  /// the game's physics lets balls leave the cloth
  /// (GamePhysics::airborne); off, nothing changes.
  bool jumps = false;
  /// Cue elevations (degrees) tried for jump shots.
  std::vector<double> jump_thetas{25.0, 35.0, 45.0, 55.0};
  /// Cue speeds tried per aim line, as multiples of the least speed that
  /// carries the target to the pocket (e.g. {1.0, 1.6, 2.4}).
  std::vector<double> speed_factors{1.0, 1.6, 2.4};
  /// Vertical tip offsets tried (fractions of R: negative draw, positive
  /// follow).
  std::vector<double> spins{-0.4, 0.0, 0.4};
  /// Side (horizontal) tip offsets tried, as fractions of R, each with a
  /// centre-height tip at every speed factor (none by default).
  std::vector<double> sides{};
  /// Safeties: the cut angles (degrees off a full hit, the line of centres
  /// turned both ways), cue speeds (m/s) and tip heights (fractions of R)
  /// tried on every legal ball that can be hit directly.
  std::vector<double> safety_turns{0.0, 25.0, 50.0};
  std::vector<double> safety_speeds{1.2, 2.2, 3.4};
  std::vector<double> safety_spins{0.0};
  /// Secant iterations that correct the aim on noiseless simulations.
  int refine_iterations = 4;
  /// At most this many candidates are returned, best priors first.
  int max_candidates = 120;
  /// Aim noise (degrees) with which the leave of each pot is rated
  /// (CandidateShot::leave): the player's own.
  double leave_sigma_deg = 0.125;
  /// Pots of this ball only (its number; -1: any ball) and into this
  /// pocket only (an index into Table::pockets; -1: any pocket). Pot maps
  /// (pot_map.hpp) set both, with safeties off.
  int only_ball = -1;
  int only_pocket = -1;
};

/// Candidate shots for the player to act in `state` (phase shot, cue ball
/// on the table). Pots (direct, bank, combination; kicks at a ball that
/// can then be pocketed) have their aim refined on noiseless simulations
/// of the engine, so throw, squirt and cushion physics are accounted for;
/// a pot is kept only if its noiseless play pockets the target in the
/// pocket with no foul. Blocked paths are rejected, except that with
/// `options.jumps` and airborne physics a direct pot blocked by balls
/// near the cue ball is tried as jump shots (elevated strokes whose
/// flight clears them). Safeties and kicks
/// that merely make a legal hit are added when `options.safeties`. Every
/// candidate passes Rules::check. Deterministic.
std::vector<CandidateShot> generate_shots(const Rules& rules, const GameState& state,
                                          const ShotGenOptions& options);

/// A level of play: the noise the player shoots with and the search it
/// does.
struct AiLevel {
  std::string name;
  NoiseModel noise;         ///< the noise this player's shots are played with
  ShotGenOptions generation;
  /// Snooker's shot generation where set (else `generation`): its colours
  /// sit a metre from pockets that take a ball only within about 0.15 m
  /// of the line, so finer speed and spin variants pay more there.
  std::optional<ShotGenOptions> snooker_generation;
  int candidates = 12;      ///< candidates evaluated by sampling (best priors first)
  int samples = 16;         ///< noisy simulations per evaluated candidate
  /// Value the table left by the opponent's or the player's next shot
  /// (a second ply), for the best `lookahead_candidates` candidates.
  bool lookahead = false;
  int lookahead_candidates = 3;
  /// Tables each of those candidates' samples left that are read a shot
  /// deeper (0: 8 with 48 samples or more, else 4).
  int lookahead_states = 0;
  /// The same two for 9-ball (0: as above). The rotation fixes the next
  /// ball, so the position for it decides more than in 8-ball, where some
  /// ball of the group is usually on.
  int lookahead_candidates_nine = 0;
  int lookahead_states_nine = 0;
  /// Sample each shortlisted pot also with its aim moved to the middle of
  /// the range of aims that pot it when played without noise (shot
  /// generation aims at a point in the pocket, which may sit near one
  /// edge of that range once jaws, throw and the cushions are counted).
  /// Both aims are sampled: the move also turns the cue ball's path, so
  /// the first may leave the better position.
  bool centre_aim = false;
  /// Budget per decision in simulations (0: no limit but the above); the
  /// decision is deterministic for a given seed and this budget.
  std::int64_t simulation_budget = 0;
  /// Budget per decision in seconds (0: none). A time budget makes the
  /// decision depend on the machine's speed; matches for figures use
  /// simulation budgets.
  double time_budget = 0.0;
  /// Worker threads (0: all cores).
  int threads = 0;
};

/// `beginner`, `amateur`, `club`, `expert`, `champion` (docs/ai.md).
/// Throws std::invalid_argument naming the known levels otherwise.
AiLevel ai_level(std::string_view name);
std::vector<std::string> ai_level_names();

/// How deep a level's lookahead reads in a game: how many candidates, and
/// how many of the tables each one's samples left.
struct LookaheadDepth {
  int candidates = 0;
  int states = 0;
};
/// `level`'s depth in `game`: in 9-ball its 9-ball fields where set (> 0),
/// otherwise the 8-ball ones; states unset (0) is 8 with 48 samples or
/// more, else 4.
LookaheadDepth lookahead_depth(const AiLevel& level, GameType game);

/// The AI player of `level`. Its noise() is level.noise.
std::unique_ptr<Player> make_ai_player(const AiLevel& level);

}  // namespace breakshot
