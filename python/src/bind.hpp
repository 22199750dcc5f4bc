// The pieces of the Python extension breakshot._core: each bind_*.cpp adds
// one concept to the module, and module.cpp calls them in order.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

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

void bind_errors(py::module_& m);
void bind_scenario(py::module_& m);
void bind_simulation(py::module_& m);
void bind_shots(py::module_& m);
void bind_game(py::module_& m);
void bind_plot(py::module_& m);
void bind_pot_map(py::module_& m);

}  // namespace breakshot::python
