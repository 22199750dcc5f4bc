// The scenario reader on a JSON tree already parsed: read_scenario
// (scenario_io.hpp) is this after parse_strict. For callers that build a
// scenario's document themselves (the C API, capi/). Internal: not
// installed.
#pragma once

#include <variant>

#include "breakshot/scenario.hpp"
#include "io/json_read.hpp"

namespace breakshot::json_io {

/// Reads and validates the scenario `doc` exactly as read_scenario reads
/// its text once parsed; never throws for bad input.
std::variant<Scenario, ScenarioError> read_scenario_tree(const json& doc);

}  // namespace breakshot::json_io
