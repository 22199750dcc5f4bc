// The result file's pieces that are written elsewhere too (result_json.cpp).
// Internal: not installed.

#pragma once

#include "breakshot/event.hpp"
#include "breakshot/scenario.hpp"
#include "io/json_write.hpp"

namespace breakshot::json_io {

/// An event as the result file writes it (the contract): {"time", "type",
/// "balls": [ids], and "cushion", "pocket" or "from" and "to" by type},
/// balls by id, cushions and pockets by name (null for an index the
/// scenario does not have). The one encoding of an Event: the web
/// facade's playback events are the same text.
void write_event(JsonWriter& w, const Scenario& s, const Event& e);

}  // namespace breakshot::json_io
