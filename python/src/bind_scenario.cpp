// breakshot.Scenario (a parsed, validated scenario) and breakshot.simulate.
#include <cmath>
#include <sstream>
#include <string>
#include <variant>

#include "bind.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"

namespace breakshot::python {

namespace {

const char* model_name(Model m) {
  switch (m) {
    case Model::ideal: return "ideal";
    case Model::friction: return "friction";
    case Model::pool: return "pool";
  }
  return "?";
}

Scenario parse(const std::string& text) {
  auto parsed = read_scenario(text);
  if (auto* err = std::get_if<ScenarioError>(&parsed)) throw ScenarioRefused{*err};
  // A copy, made once the reader's JSON tree is freed: the scenario's
  // pieces then lie together in memory instead of among the tree's nodes.
  // Batches over thousands of parsed scenarios read each one per shot, and
  // the compact copy makes that about 10 % faster (docs/performance.md,
  // "Python").
  return Scenario(std::get<Scenario>(parsed));
}

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const BallState& b) {
  return finite(b.position) && finite(b.velocity) && finite(b.spin);
}

/// As `breakshot simulate` does: a non-finite number in a result is an
/// engine bug, never an answer.
void check_finite(const RunResult& r) {
  bool ok = std::isfinite(r.final_time);
  for (const auto& b : r.final_balls) ok = ok && finite(b);
  for (const auto& e : r.events) ok = ok && std::isfinite(e.time);
  for (const auto& s : r.samples) {
    ok = ok && std::isfinite(s.time);
    for (const auto& b : s.balls) ok = ok && finite(b);
  }
  if (!ok) throw std::runtime_error("the simulation produced a non-finite number (an engine bug)");
}

}  // namespace

std::string scenario_text(py::handle obj) {
  return py::module_::import("breakshot._input").attr("scenario_text")(obj).cast<std::string>();
}

Scenario scenario_arg(py::handle obj) {
  if (py::isinstance<Scenario>(obj)) return obj.cast<const Scenario&>();
  return parse(scenario_text(obj));
}

void bind_scenario(py::module_& m) {
  py::class_<Scenario>(m, "Scenario", R"doc(A scenario read and checked once.

Scenario(scenario) reads a dict, JSON text or a path (str or os.PathLike)
in the scenario format of `breakshot simulate` (docs/contract.md) and
raises breakshot.ScenarioError naming the field when it is invalid. Pass it
to simulate, Simulation or shots to skip reading it again.)doc")
      .def(py::init([](py::object obj) { return scenario_arg(obj); }), py::arg("scenario"))
      .def_property_readonly(
          "ball_ids",
          [](const Scenario& s) {
            py::list ids;
            for (const BallSpec& b : s.balls) ids.append(b.id);
            return ids;
          },
          "The balls' ids in scenario order (the order of every array).")
      .def_property_readonly(
          "model", [](const Scenario& s) { return std::string(model_name(s.physics.model)); },
          "The physics model: 'ideal', 'friction' or 'pool'.")
      .def_property_readonly(
          "has_cue", [](const Scenario& s) { return s.cue.has_value(); },
          "True when the scenario strikes a ball with the cue at t = 0.")
      .def_property_readonly(
          "until_rest", [](const Scenario& s) { return s.until.rest; },
          "True when the run ends with every ball at rest, False at a time.")
      .def_property_readonly(
          "max_events", [](const Scenario& s) { return s.max_events; },
          "The event limit of a run.")
      .def("__copy__", [](const Scenario& s) { return Scenario(s); })
      .def("__deepcopy__", [](const Scenario& s, py::dict) { return Scenario(s); })
      .def("__repr__", [](const Scenario& s) {
        std::ostringstream out;
        out << "<breakshot.Scenario model=" << model_name(s.physics.model)
            << " balls=" << s.balls.size() << (s.cue ? " cue" : "")
            << (s.until.rest ? " until=rest" : "") << '>';
        return out.str();
      });

  m.def(
      "simulate_text",
      [](py::object obj) {
        Scenario s = scenario_arg(obj);
        std::string text;
        {
          py::gil_scoped_release release;
          RunResult r = simulate(s);
          check_finite(r);
          text = write_result(s, r);
        }
        return text;
      },
      py::arg("scenario"),
      "The result file's text for a scenario, exactly as `breakshot simulate` writes it.");
}

}  // namespace breakshot::python
