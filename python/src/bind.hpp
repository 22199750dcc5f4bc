// The pieces of the Python extension breakshot._core: each bind_*.cpp adds
// one concept to the module, and module.cpp calls them in order.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "breakshot/game.hpp"
#include "breakshot/scenario.hpp"

namespace breakshot::python {

namespace py = pybind11;

/// Thrown for a scenario that read_scenario or validate refuses; becomes
/// breakshot.ScenarioError (python/breakshot/errors.py).
struct ScenarioRefused {
  ScenarioError error;
};

/// A scenario from what a Python caller passes: a breakshot.Scenario, a
/// dict, JSON text or a path (str or os.PathLike). Throws ScenarioRefused
/// for an invalid one.
Scenario scenario_arg(py::handle obj);

/// The scenario's JSON text from a dict, JSON text or a path
/// (breakshot._input.scenario_text).
std::string scenario_text(py::handle obj);

/// A table's outline and pockets as the plots and pot maps pass them
/// (bind_plot.cpp).
py::dict table_dict(const Table& t);

// Games by name (bind_game.cpp). Each throws std::invalid_argument (a
// ValueError) naming the argument.

/// Refuses a table size `game` is not played on: "7ft", "8ft" or "9ft";
/// snooker "12ft"; three-cushion "10ft".
void check_table(GameType game, const std::string& table);
/// A game from its name (GameType's), naming the known ones otherwise.
GameType game_arg(const std::string& name);
/// A game's physics from JSON text (None: the defaults): an object with
/// any of GamePhysics's fields as a record writes them; the fields left
/// out keep their defaults. "physics.FIELD: ..." otherwise.
GamePhysics physics_arg(const std::optional<std::string>& text);
/// The config of `game` on `table` (snooker's and three-cushion's own
/// balls and tables) with `physics`; max_shots -1 keeps the rules'
/// default, 0 is no limit.
GameConfig game_config(const std::string& game, const std::string& table, int max_shots,
                       const std::optional<std::string>& physics);

/// A game position from Python (python/breakshot/_position.py's normal
/// form, game_position.cpp): the rules of its game and the state.
struct GamePosition {
  Rules rules;
  GameState state;
};

/// The position a pot map is asked about, from the dict that
/// _position.game_position returns: "game", "table_size", "physics"
/// (JSON text or None) and either "state" (the records' JSON form of a
/// state, as text: the state as it is) or the balls ("positions" (n, 2),
/// "on_table" (n,)) with "player", "groups" (8-ball) and, in snooker,
/// "score" and "colour_on", set on the game's start state in phase shot.
/// The game must be played on a table with pockets. The stalemate limit
/// (max_shots) is not applied: a pot map asks about one shot.
GamePosition pot_position_arg(const py::dict& position);

void bind_errors(py::module_& m);
void bind_scenario(py::module_& m);
void bind_simulation(py::module_& m);
void bind_shots(py::module_& m);
void bind_game(py::module_& m);
void bind_plot(py::module_& m);
void bind_pot_map(py::module_& m);

}  // namespace breakshot::python
