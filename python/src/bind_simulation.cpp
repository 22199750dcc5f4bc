// breakshot.Simulation: the C++ Simulation (a copyable value) stepped from
// Python, its state as numpy arrays and its events as the result file's
// dicts.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>

#include "bind.hpp"
#include "breakshot/simulation.hpp"

namespace breakshot::python {

namespace {

/// The motion states by code: states() gives the codes, STATE_NAMES[code]
/// the name that the result file writes.
constexpr MotionState kStates[] = {MotionState::stationary, MotionState::moving,
                                   MotionState::sliding,    MotionState::rolling,
                                   MotionState::spinning,   MotionState::pocketed};

/// A Simulation and whether a thread is advancing it with the GIL
/// released: every other call on it is refused meanwhile (the flag is read
/// and written with the GIL held).
struct PySimulation {
  Simulation sim;
  bool busy = false;

  explicit PySimulation(const Scenario& s) : sim(s) {}
  PySimulation(const PySimulation& other) : sim(other.checked()) {}
  PySimulation(PySimulation&&) = default;
  PySimulation& operator=(const PySimulation&) = delete;
  PySimulation& operator=(PySimulation&&) = delete;

  const Simulation& checked() const {
    if (busy) {
      throw std::runtime_error(
          "this Simulation is being advanced in another thread; wait for it to return");
    }
    return sim;
  }
  Simulation& checked() {
    std::as_const(*this).checked();
    return sim;
  }
};

/// Sets `busy` while the GIL is released.
class Advancing {
 public:
  explicit Advancing(PySimulation& s) : s_(s) {
    s_.checked();
    s_.busy = true;
  }
  ~Advancing() { s_.busy = false; }
  Advancing(const Advancing&) = delete;
  Advancing& operator=(const Advancing&) = delete;

 private:
  PySimulation& s_;
};

const char* stop_name(StopReason r) {
  return r == StopReason::reached ? "reached" : "event_limit";
}

py::object ball_id(const Scenario& s, std::int32_t i) {
  if (i >= 0 && static_cast<std::size_t>(i) < s.balls.size()) {
    return py::str(s.balls[static_cast<std::size_t>(i)].id);
  }
  return py::none();
}

/// An event as the result file writes it (io/result_json.cpp,
/// write_event): time, type, balls by id, and cushion, pocket or from/to.
py::dict event_dict(const Scenario& s, const Event& e) {
  py::dict d;
  d["time"] = e.time;
  d["type"] = std::string(to_string(e.type));
  py::list balls;
  balls.append(ball_id(s, e.ball));
  if (e.type == EventType::ball_ball) balls.append(ball_id(s, e.other));
  d["balls"] = balls;
  switch (e.type) {
    case EventType::ball_cushion:
      d["cushion"] = e.wall >= 0 && static_cast<std::size_t>(e.wall) < s.table.walls.size()
                         ? py::object(py::str(s.table.walls[static_cast<std::size_t>(e.wall)].name))
                         : py::object(py::none());
      break;
    case EventType::ball_pocket:
      d["pocket"] =
          e.pocket >= 0 && static_cast<std::size_t>(e.pocket) < s.table.pockets.size()
              ? py::object(py::str(s.table.pockets[static_cast<std::size_t>(e.pocket)].name))
              : py::object(py::none());
      break;
    case EventType::ball_off_table:
      if (e.wall >= 0 && static_cast<std::size_t>(e.wall) < s.table.walls.size()) {
        d["cushion"] = std::string(s.table.walls[static_cast<std::size_t>(e.wall)].name);
      }
      break;
    case EventType::ball_slate:
    case EventType::state_change:
      d["from"] = std::string(to_string(e.from));
      d["to"] = std::string(to_string(e.to));
      break;
    case EventType::cue_strike:
    case EventType::ball_ball:
      break;
  }
  return d;
}

/// Ball i from an int index (negative counts from the end) or a str id.
std::size_t ball_index(const Simulation& sim, py::handle which) {
  const auto& balls = sim.scenario().balls;
  if (py::isinstance<py::str>(which)) {
    const auto id = which.cast<std::string>();
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].id == id) return i;
    }
    throw py::key_error("ball: no ball has the id '" + id + "'");
  }
  if (!py::isinstance<py::int_>(which) || py::isinstance<py::bool_>(which)) {
    throw py::type_error("ball: expected an index (int) or an id (str)");
  }
  const auto n = static_cast<long long>(balls.size());
  long long i = which.cast<long long>();
  if (i < 0) i += n;
  if (i < 0 || i >= n) {
    throw py::index_error("ball: index " + std::to_string(which.cast<long long>()) +
                          " out of range for " + std::to_string(n) + " balls");
  }
  return static_cast<std::size_t>(i);
}

/// A time argument: a finite number no earlier than the clock.
double time_arg(const Simulation& sim, py::handle t) {
  if (py::isinstance<py::str>(t) || py::isinstance<py::bytes>(t)) {
    throw py::type_error("t: expected a number of seconds, not a string");
  }
  double v = 0.0;
  try {
    v = py::float_(py::reinterpret_borrow<py::object>(t)).cast<double>();
  } catch (const py::error_already_set&) {
    throw py::type_error("t: expected a number of seconds, not " +
                         std::string(py::str(py::type::of(t).attr("__name__"))));
  }
  if (!std::isfinite(v)) {
    throw py::value_error("t: must be a finite time in seconds, not " +
                          std::string(py::str(py::float_(v))));
  }
  if (v < sim.time()) {
    std::ostringstream out;
    out.precision(17);
    out << "t: " << v << " is before the simulation's time " << sim.time()
        << " (a simulation only goes forward; restore a copy to go back)";
    throw py::value_error(out.str());
  }
  return v;
}

py::array_t<double> vec2s(const Simulation& sim, Vec2 BallState::*field) {
  const std::size_t n = sim.ball_count();
  py::array_t<double> out({static_cast<py::ssize_t>(n), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 v = sim.ball(i).*field;
    a(static_cast<py::ssize_t>(i), 0) = v.x;
    a(static_cast<py::ssize_t>(i), 1) = v.y;
  }
  return out;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::list names;
  for (MotionState s : kStates) names.append(std::string(to_string(s)));
  py::tuple state_names(names);

  py::class_<PySimulation>(m, "Simulation", R"doc(A simulation stepped from Python.

Simulation(scenario) starts the scenario (a dict, JSON text, a path or a
breakshot.Scenario; raises ScenarioError when it is invalid) at time 0,
with its cue strike applied. It ignores the scenario's `until` and
`samples`: the caller advances it with advance_to(t) or advance_to_rest().
Advancing in steps gives exactly the same events as one run.

The state is read as numpy arrays in scenario order (ball_ids):
positions() (n, 2), velocities() (n, 2), spins() (n, 3) and states() (n,)
motion-state codes (names in Simulation.STATE_NAMES). copy.copy(sim),
copy.deepcopy(sim) and sim.copy() save the whole state; sim.restore(saved)
puts it back. The GIL is released while advancing; one Simulation must not
be used from two threads at once (a call during an advance raises
RuntimeError).)doc")
      .def(py::init([](py::object scenario) { return PySimulation(scenario_arg(scenario)); }),
           py::arg("scenario"))
      .def_property_readonly_static(
          "STATE_NAMES", [state_names](py::object) { return state_names; },
          "The motion states by code: STATE_NAMES[code] is the name the result file "
          "writes ('stationary', 'moving', 'sliding', 'rolling', 'spinning', 'pocketed').")
      .def(
          "advance_to",
          [](PySimulation& self, py::object t) {
            const double v = time_arg(self.checked(), t);
            StopReason r;
            {
              Advancing guard(self);
              py::gil_scoped_release release;
              r = self.sim.advance_to(v);
            }
            return std::string(stop_name(r));
          },
          py::arg("t"),
          R"doc(Process every event up to time t (seconds) in order and move the clock to t.

t must be finite and not before `time` (ValueError otherwise). Returns
'reached', or 'event_limit' when the scenario's max_events stopped it
first (the clock then stays at the last event).)doc")
      .def(
          "advance_to_rest",
          [](PySimulation& self) {
            StopReason r;
            {
              Advancing guard(self);
              py::gil_scoped_release release;
              r = self.sim.advance_to_rest();
            }
            return std::string(stop_name(r));
          },
          R"doc(Advance until every ball is at rest or pocketed.

Returns 'reached', or 'event_limit' when the scenario's max_events stopped
it (a run that never comes to rest, such as moving balls in the ideal
model, ends there). The clock is left at the last event.)doc")
      .def_property_readonly(
          "time", [](const PySimulation& self) { return self.checked().time(); },
          "The current clock, in seconds.")
      .def_property_readonly(
          "event_count",
          [](const PySimulation& self) { return self.checked().event_count(); },
          "How many events have happened so far.")
      .def_property_readonly(
          "at_rest", [](const PySimulation& self) { return self.checked().at_rest(); },
          "True when no ball moves.")
      .def_property_readonly(
          "next_event_time",
          [](PySimulation& self) { return self.checked().next_event_time(); },
          "The time of the next event, math.inf when none is coming.")
      .def_property_readonly(
          "ball_ids",
          [](const PySimulation& self) {
            py::list ids;
            for (const BallSpec& b : self.checked().scenario().balls) ids.append(b.id);
            return ids;
          },
          "The balls' ids in scenario order (the rows of every array).")
      .def_property_readonly(
          "scenario", [](const PySimulation& self) { return self.checked().scenario(); },
          "The breakshot.Scenario simulated (a copy).")
      .def_property_readonly(
          "events",
          [](const PySimulation& self) {
            const Simulation& sim = self.checked();
            py::list out;
            for (const Event& e : sim.events()) out.append(event_dict(sim.scenario(), e));
            return out;
          },
          "Every event so far, in order, as the result file's dicts (time, type, balls "
          "by id, and cushion, pocket or from/to): for a run to rest, equal to "
          "breakshot.simulate(scenario).events.")
      .def(
          "events_since",
          [](const PySimulation& self, std::size_t start) {
            const Simulation& sim = self.checked();
            py::list out;
            const auto& ev = sim.events();
            for (std::size_t k = start; k < ev.size(); ++k) {
              out.append(event_dict(sim.scenario(), ev[k]));
            }
            return out;
          },
          py::arg("start"),
          "The events from index `start` on (events[start:] without building the "
          "earlier ones): pass the event_count of the previous frame.")
      .def(
          "positions",
          [](const PySimulation& self) { return vec2s(self.checked(), &BallState::position); },
          "Ball centres at the current time: a float64 array (n, 2), metres.")
      .def(
          "velocities",
          [](const PySimulation& self) { return vec2s(self.checked(), &BallState::velocity); },
          "Ball velocities at the current time: a float64 array (n, 2), m/s.")
      .def(
          "spins",
          [](const PySimulation& self) {
            const Simulation& sim = self.checked();
            const std::size_t n = sim.ball_count();
            py::array_t<double> out({static_cast<py::ssize_t>(n), py::ssize_t{3}});
            auto a = out.mutable_unchecked<2>();
            for (std::size_t i = 0; i < n; ++i) {
              const Vec3 w = sim.ball(i).spin;
              const auto r = static_cast<py::ssize_t>(i);
              a(r, 0) = w.x;
              a(r, 1) = w.y;
              a(r, 2) = w.z;
            }
            return out;
          },
          "Ball spins at the current time: a float64 array (n, 3), rad/s (zero outside "
          "the pool model).")
      .def(
          "states",
          [](const PySimulation& self) {
            const Simulation& sim = self.checked();
            const std::size_t n = sim.ball_count();
            py::array_t<std::int8_t> out(static_cast<py::ssize_t>(n));
            auto a = out.mutable_unchecked<1>();
            for (std::size_t i = 0; i < n; ++i) {
              a(static_cast<py::ssize_t>(i)) = static_cast<std::int8_t>(sim.ball(i).state);
            }
            return out;
          },
          "Motion-state codes at the current time: an int8 array (n,); "
          "Simulation.STATE_NAMES[code] is the name (0 stationary, 1 moving, 2 sliding, "
          "3 rolling, 4 spinning, 5 pocketed).")
      .def(
          "ball",
          [](const PySimulation& self, py::object which) {
            const Simulation& sim = self.checked();
            const std::size_t i = ball_index(sim, which);
            const BallState b = sim.ball(i);
            py::dict d;
            d["id"] = sim.scenario().balls[i].id;
            d["position"] = py::make_tuple(b.position.x, b.position.y);
            d["velocity"] = py::make_tuple(b.velocity.x, b.velocity.y);
            d["spin"] = py::make_tuple(b.spin.x, b.spin.y, b.spin.z);
            d["state"] = std::string(to_string(b.state));
            return d;
          },
          py::arg("which"),
          R"doc(One ball's state at the current time, as a dict.

`which` is an index in scenario order (negative counts from the end) or a
ball id. Returns {'id', 'position': (x, y), 'velocity': (vx, vy), 'spin':
(wx, wy, wz), 'state': name}. IndexError or KeyError for no such ball.)doc")
      .def(
          "copy", [](const PySimulation& self) { return PySimulation(self); },
          "A copy of the whole state (the same as copy.copy): advance either, the other "
          "stays as it was.")
      .def("__copy__", [](const PySimulation& self) { return PySimulation(self); })
      .def("__deepcopy__",
           [](const PySimulation& self, py::object) { return PySimulation(self); },
           py::arg("memo"))
      .def(
          "restore",
          [](PySimulation& self, const PySimulation& saved) {
            self.checked();
            if (&saved != &self) self.sim = saved.checked();
          },
          py::arg("saved"),
          R"doc(Put back the state of `saved` (a Simulation, e.g. a copy taken earlier).

After restore(saved) this simulation is equal to saved in every respect
(clock, balls, events, and the scenario, as the C++ copy assignment does);
saved itself is unchanged and can be restored again.)doc")
      .def("__repr__", [](const PySimulation& self) {
        if (self.busy) return std::string("<breakshot.Simulation (advancing)>");
        const Simulation& sim = self.sim;
        std::ostringstream out;
        out.precision(6);
        out << "<breakshot.Simulation t=" << sim.time() << " balls=" << sim.ball_count()
            << " events=" << sim.event_count() << (sim.at_rest() ? " at_rest" : " moving")
            << '>';
        return out.str();
      });
}

}  // namespace breakshot::python
