// Match summaries as JSON, and game records written to a folder.
#pragma once

#include <string>

#include "breakshot/match.hpp"

namespace breakshot {

/// The summary as JSON text (indented, keys in a fixed order, a trailing
/// newline): the same summary gives the same bytes.
std::string match_summary_json(const MatchSummary& summary);

/// A sink that writes game g's record (write_record) to
/// DIR/game-NNNN.json, NNNN = g + 1 with at least four digits. The folder
/// is created at once if missing; std::runtime_error naming the path when
/// it cannot be created or a record cannot be written.
RecordSink record_files(const std::string& dir);

}  // namespace breakshot
