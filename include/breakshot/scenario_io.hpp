// Reading scenario files and writing result files (the contract in
// docs/contract.md).
#pragma once

#include <string>
#include <string_view>
#include <variant>

#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"

namespace breakshot {

/// Parses and validates a scenario from JSON text. On failure returns a
/// ScenarioError naming the JSON path and the reason; never throws for
/// bad input.
std::variant<Scenario, ScenarioError> read_scenario(std::string_view json_text);

/// The result file as JSON text (a trailing newline included). The same
/// scenario and result give the same bytes on every run.
std::string write_result(const Scenario& scenario, const RunResult& result);

}  // namespace breakshot
