// The games' AI policies (policy.hpp): one entry a game.
#include "policy.hpp"

#include <stdexcept>

namespace breakshot::ai_detail {

namespace {

constexpr GamePolicy eight_ball() {
  GamePolicy p;
  p.unannounced_safeties = true;
  p.combinations = GamePolicy::Combinations::own_group;
  return p;
}

constexpr GamePolicy nine_ball() {
  GamePolicy p;
  p.rotation = true;
  p.combinations = GamePolicy::Combinations::any_ball;
  return p;
}

constexpr GamePolicy snooker() {
  GamePolicy p;
  p.search = GamePolicy::Search::snooker;
  p.frame_scoring = true;
  p.combinations = GamePolicy::Combinations::reds_only;
  p.break_is_a_shot = true;
  p.jumps = false;
  p.snooker_generation = true;
  return p;
}

constexpr GamePolicy three_cushion() {
  GamePolicy p;
  p.search = GamePolicy::Search::carom;
  return p;
}

}  // namespace

const GamePolicy& game_policy(GameType game) {
  static constexpr GamePolicy kEight = eight_ball();
  static constexpr GamePolicy kNine = nine_ball();
  static constexpr GamePolicy kSnooker = snooker();
  static constexpr GamePolicy kCarom = three_cushion();
  // 10-ball plays 9-ball's rotation strategy (its calls and its choice
  // after a ball pocketed wrongly come from its rules).
  switch (game) {
    case GameType::eight_ball:
      return kEight;
    case GameType::nine_ball:
      return kNine;
    case GameType::snooker:
      return kSnooker;
    case GameType::three_cushion:
      return kCarom;
    case GameType::ten_ball:
      return kNine;
  }
  throw std::invalid_argument("game_policy: not a game");
}

}  // namespace breakshot::ai_detail
