// Game records as files: writing, reading and replaying them. The file
// format is described at the top of src/io/record_json.cpp.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "breakshot/game.hpp"
#include "breakshot/record.hpp"

namespace breakshot {

/// The record as JSON text (pretty, a trailing newline). Keys come in a
/// fixed order and doubles in a form that reads back exactly, so the same
/// record gives the same bytes. Seeds are decimal strings: JSON readers
/// in other languages often hold numbers in doubles, which lose 64-bit
/// integers. Throws std::invalid_argument for a non-finite number (JSON
/// has none), naming its path.
std::string write_record(const GameRecord& record);

/// A problem with a record file: the JSON path ("actions[3].after.phase")
/// and what is wrong there.
struct RecordError {
  std::string path;
  std::string reason;
};

/// Reads a record written by write_record. Strict: unknown or repeated
/// keys, missing fields, wrong types, unknown names and values out of
/// range are errors naming their path. Never throws for bad input. Only
/// the form is checked here; whether the game is right is replay()'s
/// question.
std::variant<GameRecord, RecordError> read_record(std::string_view json_text);

/// What replay() found.
struct ReplayReport {
  bool identical = false;
  /// Actions replayed and found identical (all of them when identical).
  std::size_t actions_identical = 0;
  /// Index of the first action that differs; nullopt when everything is
  /// identical or when the game differs before its first action (the
  /// config or the start).
  std::optional<std::size_t> action;
  /// Path of the first difference in the record's JSON
  /// ("actions[7].after.position[3][0]", "start.on_table[5]"), or of the
  /// record part that could not be replayed.
  std::string where;
  std::string recorded;  ///< the recorded value there, as JSON text
  std::string replayed;  ///< the replayed value (or why the action could not be played)
  /// The replayed state after the last identical action (the start if none).
  GameState final_state;
  /// One line for people: "identical", or what differs and where.
  std::string message;
};

/// Plays the record again: rebuilds the rules from the config, checks the
/// start against Rules::start, re-derives every executed strike from the
/// intended one and the acting seat's noise (shots recorded without an
/// intended strike are taken as they are), checks who acts, applies every
/// action and compares each ruling and state with the recorded ones. Stops
/// at the first difference. Never throws for a bad record: an action the rules refuse
/// or a config they cannot build is reported as a difference.
ReplayReport replay(const GameRecord& record);

}  // namespace breakshot
