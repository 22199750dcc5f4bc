// The JSON of the game's types: one encoding of each, used by game
// records (record_json.cpp) and by the web facade (web/api).
// Internal: not installed.
//
//   GameConfig  {"game", "table_size", "ball_radius", "ball_mass", "max_shots"}
//               (its physics is an object of its own, GamePhysics)
//   GamePhysics {"cushion_model", "ball_ball_model",
//                "ball_ball_friction": {"a", "b", "c"} | number}
//   NoiseModel  {"phi", "theta", "speed", "a", "b"} (noise.hpp's units)
//   CueStrike   {"speed", "phi", "theta", "a", "b"}
//   GameState   {"game", "phase", "player", "breaker", "ball_in_hand", "kitchen_shot",
//                "group": [2], "fouls_in_a_row": [2], "push_out_allowed",
//                "after_push_out", "scratch_on_break", "winner", "result", "shots",
//                "innings", "rack_seed": "DECIMAL", "racks",
//                "position": [[x, y] by ball number], "on_table": [0 or 1 by ball number]}
//   Ruling      {"fouls": [names], "legal_break", "turn_continues", "assigned",
//                "spotted": [ball numbers], "winner", "text", "call_made"}
//   Action      {"type": "place_cue_ball", "position": [x, y]}
//               {"type": "shoot", "strike": CueStrike, "call": null | {"ball", "pocket"},
//                "safety", "push_out"}
//               {"type": "decide", "choice"}
//
// Every field is always written (null for an empty optional) and always
// required on reading. Enum values are the names of game.hpp's
// to_string. Seeds are decimal strings (64-bit integers do not survive
// readers that keep numbers in doubles). The encoders give
// nlohmann::ordered_json trees, which keep their keys in the order
// above; doubles are dumped in a form that reads back to the same bits.
// Game records are this JSON, so it cannot change without a new record
// version.

#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "io/json_read.hpp"

namespace breakshot::json_io {

using ojson = nlohmann::ordered_json;

// ---------------------------------------------------------------------------
// Encoding

ojson seed_json(std::uint64_t s);
ojson vec2_json(Vec2 v);
ojson config_json(const GameConfig& c);
ojson physics_json(const GamePhysics& p);
ojson noise_json(const NoiseModel& n);
ojson strike_json(const CueStrike& s);
ojson state_json(const GameState& s);
ojson ruling_json(const Ruling& r);
ojson action_json(const Action& a);

// ---------------------------------------------------------------------------
// Decoding

class GameReader : public Reader {
 public:
  bool config(const json& v, const std::string& path, GameConfig& c);
  /// Names and values this build has; a curve is checked by
  /// check_friction_curve.
  bool physics(const json& v, const std::string& path, GamePhysics& p);
  bool noise(const json& v, const std::string& path, NoiseModel& n);
  bool strike(const json& v, const std::string& path, CueStrike& s);
  bool state(const json& v, const std::string& path, GameState& s);
  bool ruling(const json& v, const std::string& path, Ruling& r);
  bool action(const json& v, const std::string& path, Action& a);

  /// A game name: "eight_ball" or "nine_ball".
  bool game_type(const json& v, const std::string& path, GameType& out);
  /// A pool table size: "7ft", "8ft" or "9ft".
  bool table_size(const json& v, const std::string& path, std::string& out);
  /// A choice name (Decide).
  bool choice(const json& v, const std::string& path, Choice& out);
};

}  // namespace breakshot::json_io
