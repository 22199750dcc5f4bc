// breakshot._core: the C++ engine, games and AI for Python. The package
// python/breakshot wraps it; docs/python.md documents every name.
#include <string>

#include "bind.hpp"
#include "breakshot/version.hpp"

PYBIND11_MODULE(_core, m) {
  namespace bp = breakshot::python;
  m.doc() = "breakshot's C++ core (use the breakshot package, not this module)";
  m.attr("version") = std::string(breakshot::kVersion);
  bp::bind_errors(m);
  bp::bind_scenario(m);
  bp::bind_simulation(m);
  bp::bind_shots(m);
  bp::bind_game(m);
  bp::bind_plot(m);
  bp::bind_pot_map(m);
}
