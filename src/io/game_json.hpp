// The JSON of the game's types: one encoding of each, used by game
// records (record_json.cpp), the web facade (web/api), the C API (capi/)
// and the Python binding (python/src). The table and its markings are in
// table_json.hpp. Internal: not installed.
//
//   GameConfig  {"game", "table_size", "ball_radius", "ball_mass", "max_shots",
//                three-cushion only: "carom": {"target", "innings_limit",
//                "equalizing_inning"}}
//               (its physics is an object of its own, GamePhysics)
//   GamePhysics {"cushion_model", "ball_ball_model",
//                "ball_ball_friction": {"a", "b", "c"} | number,
//                "airborne": true (only when on),
//                "spinning_friction" (only when not 0.044; absent: 0.044)}
//   NoiseModel  {"phi", "theta", "speed", "a", "b"} (noise.hpp's units)
//   CueStrike   {"speed", "phi", "theta", "a", "b"}
//   GameState   {"game", "phase", "player", "breaker", "ball_in_hand", "kitchen_shot",
//                "group": [2], "fouls_in_a_row": [2], "push_out_allowed",
//                "after_push_out", "scratch_on_break", "winner", "result", "shots",
//                "innings", "rack_seed": "DECIMAL", "racks",
//                "position": [[x, y] by ball number], "on_table": [0 or 1 by ball number],
//                snooker only: "snooker": SNOOKER,
//                three-cushion only: "carom": {"score": [2], "run", "innings": [2],
//                "equalizing"}}
//   SNOOKER     {"score": [2], "break", "colour_on", "free_ball", "respotted_black",
//                "misses", "replace": null | {"position", "on_table", "colour_on",
//                "free_ball"}}
//   Ruling      {"fouls": [names], "legal_break", "turn_continues", "assigned",
//                "spotted": [ball numbers], "winner", "text", "call_made",
//                a snooker shot's only: "snooker": {"points", "penalty", "miss",
//                "free_ball", "nominated"},
//                a three-cushion shot's only: "carom": {"point", "cue_ball",
//                "hit": [balls], "cushions", "kiss"}}
//   Action      {"type": "place_cue_ball", "position": [x, y]}
//               {"type": "shoot", "strike": CueStrike, "call": null | {"ball", "pocket"},
//                "safety", "push_out", snooker only and when given: "nominate",
//                three-cushion only and when given: "cue_ball"}
//               {"type": "decide", "choice"}
//
// Every field is always written (null for an empty optional) and always
// required on reading, but snooker's and three-cushion's, which the other
// games never have (so that their records keep their bytes): "snooker" in
// a snooker state and "carom" in a three-cushion state and config are
// required, in a shot's ruling written, "nominate" and "cue_ball" written
// when the shot gives them. Enum values are the names of game.hpp's
// to_string. Seeds are decimal strings (64-bit integers do not survive
// readers that keep numbers in doubles). The encoders give
// nlohmann::ordered_json trees, which keep their keys in the order
// above; doubles are dumped in a form that reads back to the same bits.
// Game records are this JSON, so it cannot change without a new record
// version.

#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/record.hpp"
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
/// What the player to act may do (Rules::legal_actions): {"place",
/// "must_place", "shoot", "push_out", "call", "targets", "choices"}, in
/// snooker also "nominate" and "must_nominate". Not part of records: the
/// facade's game state and the C API's legal actions.
ojson legal_actions_json(const LegalActions& la, GameType game);
/// What the rules read from a shot's events (ShotFacts): {"first_hit",
/// "pocketed", "pocket_of", "miscue", "cushion_after_contact",
/// "object_balls_to_cushion"}. Not part of records.
ojson facts_json(const ShotFacts& f);
/// An event of a game shot as a result file writes it (time, type, balls,
/// then cushion, pocket or from/to), but its balls are ball numbers (0 the
/// cue ball) and a pocket is its index in `table` (the index a call
/// names) with its "pocket_name". Not part of records.
ojson game_event_json(const Table& table, const Event& e);
/// Snooker: what the table leaves (game.hpp): {"balls_on",
/// "points_remaining", "snookers_required": [2]}. Not part of records.
ojson snooker_figures_json(const GameState& s);
/// Three-cushion: {"cue_ball": the ball the player to act strikes,
/// "general_average": [2] (points per inning begun), "highest_run": [2]},
/// for `state` after the actions of `record` (record.hpp's carom_innings,
/// the inning in progress included). Not part of records.
ojson carom_figures_json(const Rules& rules, const GameState& state, const GameRecord& record);

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

  /// A game name: "eight_ball", "nine_ball", "ten_ball", "snooker" or "three_cushion".
  bool game_type(const json& v, const std::string& path, GameType& out);
  /// A table size: "7ft", "8ft" or "9ft"; "12ft" when game_context is
  /// snooker, "10ft" when it is three_cushion.
  bool table_size(const json& v, const std::string& path, std::string& out);
  /// A choice name (Decide).
  bool choice(const json& v, const std::string& path, Choice& out);

  /// The game of the document being read, once config() has read it:
  /// bounds the ball numbers of rulings and admits snooker's fields.
  std::optional<GameType> game_context;

 private:
  bool snooker_state(const json& v, const std::string& path, SnookerState& k);
  bool positions(const json& v, const std::string& path, std::vector<Vec2>& out);
  bool flags(const json& v, const std::string& path, std::size_t n,
             std::vector<std::uint8_t>& out);
};

}  // namespace breakshot::json_io
