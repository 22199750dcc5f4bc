// Events: what happened, when, to whom.
#pragma once

#include <cstdint>
#include <string_view>

#include "breakshot/ball.hpp"

namespace breakshot {

enum class EventType : std::uint8_t {
  cue_strike,
  ball_ball,
  ball_cushion,
  ball_pocket,
  state_change,
  ball_slate,      ///< an airborne ball lands on the slate (`from`, `to`)
  ball_off_table,  ///< a ball leaves the table (over wall `wall`, or -1)
};

std::string_view to_string(EventType t);

/// One event. Balls are indices into the scenario's ball list; `wall`
/// indexes Table::walls.
struct Event {
  double time = 0.0;
  EventType type = EventType::ball_ball;
  std::int32_t ball = -1;   ///< first ball (the lower index for ball_ball)
  std::int32_t other = -1;  ///< second ball of a ball_ball event
  std::int32_t wall = -1;   ///< wall of a ball_cushion event
  std::int32_t pocket = -1; ///< pocket of a ball_pocket event
  MotionState from = MotionState::stationary;  ///< state_change, ball_slate
  MotionState to = MotionState::stationary;    ///< state_change, ball_slate

  bool operator==(const Event&) const = default;
};

}  // namespace breakshot
