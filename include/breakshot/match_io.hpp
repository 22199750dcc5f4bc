// Match summaries as JSON, and game records written to a folder.
#pragma once

#include <string>
#include <string_view>

#include "breakshot/match.hpp"

namespace breakshot {

/// The summary as JSON text (indented, keys in a fixed order, a trailing
/// newline): the same summary gives the same bytes. The games it covers
/// are written only when they are not games 0 .. games_played - 1 (so a
/// match from game 0 reads as it always has): "first_game": N before
/// "games_played" for one range from N, or "game_ranges": [{"first_game":
/// N, "games": K}, ...] for several (a sum of chunks with a gap). The
/// physics ("physics": {"cushion_model", "ball_ball_model",
/// "ball_ball_friction"}, as in a game record) is written after
/// "table_size" only when it is not the default GamePhysics{}.
std::string match_summary_json(const MatchSummary& summary);

/// Reads a summary written by match_summary_json, so that
/// match_summary_json(read_match_summary(text)) == text. Strict: unknown,
/// repeated or missing keys, wrong types, unknown names and values out
/// of range are errors, as are rates that are not derived from the
/// counts, a games_played other than the wins plus the draws, game ranges
/// that do not add up to games_played, and decision times (a --timing
/// summary keeps only their quantiles, which cannot be added). Throws
/// std::invalid_argument "PATH: REASON" ("players[1].innings: expected an
/// integer, not a string").
MatchSummary read_match_summary(std::string_view json_text);

/// The name of game g's record file: "game-NNNN.json", NNNN = g + 1 with
/// at least four digits ("game-0001.json" for game 0).
std::string record_file_name(int game);

/// A sink that writes game g's record (write_record) to
/// DIR/record_file_name(g). The folder
/// is created at once if missing; std::runtime_error naming the path when
/// it cannot be created or a record cannot be written.
RecordSink record_files(const std::string& dir);

}  // namespace breakshot
