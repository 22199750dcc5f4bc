// Names of enumerations as they appear in scenario and result files.
#include "breakshot/ball.hpp"
#include "breakshot/event.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/table.hpp"

namespace breakshot {

std::string_view to_string(Model m) {
  switch (m) {
    case Model::ideal: return "ideal";
    case Model::friction: return "friction";
    case Model::pool: return "pool";
  }
  return "?";
}

std::string_view to_string(BallBallModel m) {
  switch (m) {
    case BallBallModel::friction: return "friction";
    case BallBallModel::mathavan_2014: return "mathavan_2014";
  }
  return "?";
}

bool parse_ball_ball_model(std::string_view name, BallBallModel& out) {
  for (BallBallModel m : {BallBallModel::friction, BallBallModel::mathavan_2014}) {
    if (name == to_string(m)) {
      out = m;
      return true;
    }
  }
  return false;
}

std::string_view to_string(TableShape shape) {
  switch (shape) {
    case TableShape::rectangle: return "rectangle";
    case TableShape::polygon: return "polygon";
    case TableShape::pool: return "pool";
    case TableShape::snooker: return "snooker";
    case TableShape::carom: return "carom";
  }
  return "?";
}

bool parse_table_shape(std::string_view name, TableShape& out) {
  for (TableShape shape : {TableShape::rectangle, TableShape::polygon, TableShape::pool,
                           TableShape::snooker, TableShape::carom}) {
    if (name == to_string(shape)) {
      out = shape;
      return true;
    }
  }
  return false;
}

std::string_view to_string(MotionState s) {
  switch (s) {
    case MotionState::stationary: return "stationary";
    case MotionState::moving: return "moving";
    case MotionState::sliding: return "sliding";
    case MotionState::rolling: return "rolling";
    case MotionState::spinning: return "spinning";
    case MotionState::pocketed: return "pocketed";
    case MotionState::airborne: return "airborne";
    case MotionState::off_table: return "off_table";
  }
  return "?";
}

std::string_view to_string(EventType t) {
  switch (t) {
    case EventType::cue_strike: return "cue_strike";
    case EventType::ball_ball: return "ball_ball";
    case EventType::ball_cushion: return "ball_cushion";
    case EventType::ball_pocket: return "ball_pocket";
    case EventType::state_change: return "state_change";
    case EventType::ball_slate: return "ball_slate";
    case EventType::ball_off_table: return "ball_off_table";
  }
  return "?";
}

}  // namespace breakshot
