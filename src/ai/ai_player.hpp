// The AI levels' player (internal; make_ai_player, include/breakshot/ai.hpp;
// the method: ai_player.cpp). Its searches are files of their own:
//
//   ai_player.cpp     the player: which search a decision goes to
//   levels.cpp        the five levels (AiLevel) and their lookahead depth
//   decision.cpp      choosing among actions: a shot or a push-out, the
//                     incoming player's choices, snooker's foul choices
//                     and concession
//   sampling.cpp      the best shot: candidates sampled under the level's
//                     noise with common random numbers, in two rounds
//   shortlist.cpp     which candidates are sampled, by their promise
//   lookahead.cpp     the best candidates' tables read a shot deeper
//   ball_in_hand.cpp  where to place the cue ball
//   break_shot.cpp    the pool games' break and snooker's break-off place
//
// Shot generation (shot_generator.hpp), the values of tables and sampled
// shots (evaluate.hpp) and three-cushion's search (carom_ai.hpp) are the
// player's other parts. Internal: not installed.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "budget.hpp"
#include "evaluate.hpp"
#include "geometry.hpp"
#include "physics/detmath.hpp"
#include "policy.hpp"

namespace breakshot::ai_detail {

inline constexpr double kNoValue = -std::numeric_limits<double>::infinity();

// Stream tags keep the seeds of the different searches apart (ASCII of
// their names; arbitrary constants).
inline constexpr std::uint64_t kSampleStream = 0x73616d706c65ULL;    // "sample"
inline constexpr std::uint64_t kLookStream = 0x6c6f6f6bULL;          // "look"
inline constexpr std::uint64_t kBreakStream = 0x627265616bULL;       // "break"
inline constexpr std::uint64_t kPushStream = 0x70757368ULL;          // "push"
inline constexpr std::uint64_t kPlaceStream = 0x706c616365ULL;       // "place"
inline constexpr std::uint64_t kBreakOffStream = 0x626f6666ULL;      // "boff"
inline constexpr std::uint64_t kChoiceStream = 0x63686f696365ULL;    // "choice"

/// A shot chosen with what it is estimated to be worth to the shooter.
struct Evaluated {
  Shoot shot;
  double value = kNoValue;
};

inline Shoot make_shoot(double phi, double speed, double b = 0.0) {
  Shoot s;
  s.strike.phi = phi;
  s.strike.speed = speed;
  s.strike.b = b;
  return s;
}

/// Direction from `from` to `to`, degrees counter-clockwise from +x.
inline double aim_deg(Vec2 from, Vec2 to) {
  return dm::atan2(to.y - from.y, to.x - from.x) / ai::kDeg;
}

/// What a pot's noiseless play promises, for ranking candidates before
/// they are sampled (shortlist.cpp).
double promise(const CandidateShot& c);

class AiPlayer final : public Player {
 public:
  explicit AiPlayer(AiLevel level);

  std::string name() const override { return level_.name; }
  std::optional<NoiseModel> noise() const override { return level_.noise; }

  Action decide(const Rules& rules, const GameState& state, std::uint64_t seed) override;

 private:
  bool searches() const { return level_.samples > 0 && level_.candidates > 0; }
  /// The shot generation for `game` (snooker's own where the level has one).
  const ShotGenOptions& generation(GameType game) const {
    return game_policy(game).snooker_generation && level_.snooker_generation
               ? *level_.snooker_generation
               : level_.generation;
  }

  // Decisions (decision.cpp)

  Action snooker_action(const Rules& rules, const GameState& state, const LegalActions& la,
                        std::uint64_t seed, Budget& budget) const;
  Action shot_action(const Rules& rules, const GameState& state, const LegalActions& la,
                     std::uint64_t seed, Budget& budget) const;
  Evaluated best_push(const Rules& rules, const GameState& state, std::uint64_t seed,
                      Budget& budget) const;
  Choice choose(const Rules& rules, const GameState& state, const LegalActions& la,
                std::uint64_t seed, Budget& budget) const;

  // The best shot (sampling.cpp, shortlist.cpp, lookahead.cpp)

  Evaluated best_shot(const Rules& rules, const GameState& state, std::uint64_t seed, double scale,
                      Budget& budget) const;
  static std::vector<CandidateShot> shortlist(std::vector<CandidateShot> cands, std::size_t n);
  void lookahead(const Rules& rules, const GameState& state, std::uint64_t seed,
                 const std::vector<std::size_t>& top,
                 const std::vector<std::vector<GameState>>& left, const std::vector<int>& count,
                 std::vector<double>& value, Budget& budget) const;

  // Cue ball in hand (ball_in_hand.cpp)

  Action placement_or_shot(const Rules& rules, const GameState& state, const LegalActions& la,
                           std::uint64_t seed, Budget& budget) const;
  static std::vector<Vec2> placements(const Rules& rules, const GameState& state,
                                      const LegalActions& la);

  // The break (break_shot.cpp)

  Action break_off(const Rules& rules, const GameState& state, const LegalActions& la,
                   std::uint64_t seed, Budget& budget) const;
  Action break_action(const Rules& rules, const GameState& state, const LegalActions& la,
                      Budget& budget) const;

  AiLevel level_;
  double sigma_;
};

}  // namespace breakshot::ai_detail
