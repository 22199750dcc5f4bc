// What the plots of breakshot.plot draw:
//   _core.simulate_traced  a run's result text and its dense frames (lab.hpp),
//                          with energy and momentum from kinetic_energy and
//                          momentum, as `breakshot simulate --plot` uses them
//   _core.layout           a scenario's table and balls at t = 0
//   _core.pool_table       a pool table's outline and pockets
//   _core.game_table       the table a game is played on, with ball radius
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bind.hpp"
#include "breakshot/game.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"

namespace breakshot::python {

namespace {

using Array = py::array_t<double>;

Array array(std::vector<py::ssize_t> shape) { return Array(std::move(shape)); }

std::string model_text(Model m) {
  switch (m) {
    case Model::ideal: return "ideal";
    case Model::friction: return "friction";
    case Model::pool: return "pool";
  }
  return "?";
}


/// The fixed part of a scenario that plots need: ids, radii, masses,
/// model and table.
void describe(py::dict& d, const Scenario& s) {
  const auto n = static_cast<py::ssize_t>(s.balls.size());
  py::list ids;
  Array radii = array({n});
  Array masses = array({n});
  auto r = radii.mutable_unchecked<1>();
  auto m = masses.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const BallSpec& b = s.balls[static_cast<std::size_t>(i)];
    ids.append(b.id);
    r(i) = b.radius;
    m(i) = b.mass;
  }
  d["ids"] = ids;
  d["radii"] = radii;
  d["masses"] = masses;
  d["model"] = model_text(s.physics.model);
  d["table"] = table_dict(s.table);
}

py::dict frames_dict(const Scenario& s, const std::vector<Sample>& frames) {
  const auto m = static_cast<py::ssize_t>(frames.size());
  const auto n = static_cast<py::ssize_t>(s.balls.size());
  Array times = array({m});
  Array pos = array({m, n, 2});
  Array vel = array({m, n, 2});
  Array spin = array({m, n, 3});
  Array energy = array({m, n});
  Array mom = array({m, n, 2});
  auto t = times.mutable_unchecked<1>();
  auto p = pos.mutable_unchecked<3>();
  auto v = vel.mutable_unchecked<3>();
  auto w = spin.mutable_unchecked<3>();
  auto e = energy.mutable_unchecked<2>();
  auto q = mom.mutable_unchecked<3>();
  for (py::ssize_t k = 0; k < m; ++k) {
    const Sample& f = frames[static_cast<std::size_t>(k)];
    t(k) = f.time;
    for (py::ssize_t i = 0; i < n; ++i) {
      // A frame shorter than the scenario (a correct trace has none)
      // reads as a ball at rest at the origin, as the SVG plots read it.
      const auto iu = static_cast<std::size_t>(i);
      const BallState b = iu < f.balls.size() ? f.balls[iu] : BallState{};
      p(k, i, 0) = b.position.x;
      p(k, i, 1) = b.position.y;
      v(k, i, 0) = b.velocity.x;
      v(k, i, 1) = b.velocity.y;
      w(k, i, 0) = b.spin.x;
      w(k, i, 1) = b.spin.y;
      w(k, i, 2) = b.spin.z;
      e(k, i) = kinetic_energy(s.balls[iu], b);
      const Vec2 mv = momentum(s.balls[iu], b);
      q(k, i, 0) = mv.x;
      q(k, i, 1) = mv.y;
    }
  }
  // Totals summed over the balls in scenario order, as the SVG plots sum.
  Array energy_total = array({m});
  Array momentum_total = array({m, 2});
  auto et = energy_total.mutable_unchecked<1>();
  auto qt = momentum_total.mutable_unchecked<2>();
  for (py::ssize_t k = 0; k < m; ++k) {
    double te = 0.0;
    double tx = 0.0;
    double ty = 0.0;
    for (py::ssize_t i = 0; i < n; ++i) {
      te += e(k, i);
      tx += q(k, i, 0);
      ty += q(k, i, 1);
    }
    et(k) = te;
    qt(k, 0) = tx;
    qt(k, 1) = ty;
  }
  py::dict d;
  d["energy_total"] = energy_total;
  d["momentum_total"] = momentum_total;
  d["times"] = times;
  d["positions"] = pos;
  d["velocities"] = vel;
  d["spins"] = spin;
  d["energy"] = energy;
  d["momentum"] = mom;
  describe(d, s);
  return d;
}

}  // namespace

py::dict table_dict(const Table& t) {
  py::dict d;
  d["shape"] = std::string(to_string(t.shape));
  Array outline = array({static_cast<py::ssize_t>(t.outline.size()), 2});
  auto o = outline.mutable_unchecked<2>();
  for (std::size_t k = 0; k < t.outline.size(); ++k) {
    o(static_cast<py::ssize_t>(k), 0) = t.outline[k].x;
    o(static_cast<py::ssize_t>(k), 1) = t.outline[k].y;
  }
  d["outline"] = outline;
  py::list pockets;
  for (const Pocket& p : t.pockets) {
    pockets.append(py::make_tuple(p.name, p.centre.x, p.centre.y, p.radius));
  }
  d["pockets"] = pockets;
  d["min"] = py::make_tuple(t.min.x, t.min.y);
  d["max"] = py::make_tuple(t.max.x, t.max.y);
  d["length"] = t.length;
  d["width"] = t.width;
  d["head_spot"] = py::make_tuple(t.head_spot.x, t.head_spot.y);
  d["foot_spot"] = py::make_tuple(t.foot_spot.x, t.foot_spot.y);
  if (t.shape == TableShape::snooker) {
    // Its markings (snooker.hpp's SnookerMarks): baulk line, D, spots.
    const SnookerMarks k = snooker_marks();
    const auto xy = [](Vec2 v) { return py::make_tuple(v.x, v.y); };
    py::dict marks;
    marks["baulk_line"] = k.baulk_x;
    marks["d_centre"] = xy(k.d_centre);
    marks["d_radius"] = k.d_radius;
    marks["spots"] =
        py::make_tuple(xy(k.yellow), xy(k.green), xy(k.brown), xy(k.blue), xy(k.pink), xy(k.black));
    d["snooker"] = marks;
  }
  return d;
}

void bind_plot(py::module_& m) {
  m.def(
      "simulate_traced",
      [](py::object scenario, std::size_t points, std::size_t max_frames) {
        const Scenario s = scenario_arg(scenario);
        TracedRun run;
        std::string text;
        {
          py::gil_scoped_release release;
          run = simulate_traced(s, points, max_frames);
          text = write_result(s, run.result);
        }
        py::dict d = frames_dict(s, run.frames);
        d["text"] = text;
        return d;
      },
      py::arg("scenario"), py::arg("points") = 2000, py::arg("max_frames") = 200000,
      "One run of a scenario: its result text (as simulate_text) and its "
      "frames (lab.hpp trace) as arrays, with energy and momentum per ball.");

  m.def(
      "layout",
      [](py::object scenario) {
        const Scenario s = scenario_arg(scenario);
        py::dict d;
        describe(d, s);
        const auto n = static_cast<py::ssize_t>(s.start.size());
        Array pos = array({n, 2});
        auto p = pos.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < n; ++i) {
          p(i, 0) = s.start[static_cast<std::size_t>(i)].position.x;
          p(i, 1) = s.start[static_cast<std::size_t>(i)].position.y;
        }
        d["positions"] = pos;
        return d;
      },
      py::arg("scenario"), "A scenario's table and balls (ids, radii, positions at t = 0).");

  m.def(
      "pool_table", [](const std::string& size) { return table_dict(make_pool_table(size)); },
      py::arg("size") = "9ft", "A pool table's outline and pockets (name, x, y, radius).");

  m.def(
      "game_table",
      [](const std::string& game, const std::string& size) {
        const Rules rules(game_config(game, size, -1, std::nullopt));
        py::dict d = table_dict(rules.table());
        d["ball_radius"] = rules.config().ball_radius;
        return d;
      },
      py::arg("game"), py::arg("size"),
      "The table `game` is played on at `size` (pool_table's form; snooker's with its"
      " markings) and its ball radius.");

}

}  // namespace breakshot::python
