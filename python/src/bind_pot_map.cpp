// Pot maps (pot_map.hpp) for breakshot.pot_chance and breakshot.pot_map:
//   _core.pot_table    the table of a position (its pockets, for names and grids)
//   _core.pot_chance   one cue-ball position
//   _core.pot_map      a grid of them
//   _core.level_names  the computer players' levels
// A position is the dict of python/breakshot/_position.py's
// game_position (pot_position_arg, game_position.cpp).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bind.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/pot_map.hpp"

namespace breakshot::python {

namespace {

using Array = py::array_t<double>;

Array array(std::vector<py::ssize_t> shape) { return Array(std::move(shape)); }

PotMapOptions options(int samples, int candidates, std::uint64_t seed, int threads) {
  PotMapOptions o;
  o.samples = samples;
  o.candidates = candidates;
  o.seed = seed;
  o.threads = threads;
  return o;
}
}  // namespace

void bind_pot_map(py::module_& m) {
  m.def("level_names", &ai_level_names, "The computer players' levels, weakest first.");

  m.def(
      "pot_table",
      [](const py::dict& position) {
        const GamePosition pos = pot_position_arg(position);
        py::dict d;
        d["table"] = table_dict(pos.rules.table());
        d["ball_radius"] = pos.rules.config().ball_radius;
        return d;
      },
      py::arg("position"),
      "The table (table_dict) and ball radius of a position, checked as pot maps check it.");

  m.def(
      "pot_chance",
      [](const py::dict& position, double x, double y, int ball, int pocket,
         const std::string& level, int samples, int candidates, std::uint64_t seed, int threads) {
        const GamePosition pos = pot_position_arg(position);
        const AiLevel lv = ai_level(level);
        PotChance c;
        {
          py::gil_scoped_release release;
          c = pot_chance(pos.rules, pos.state, {x, y}, ball, pocket, lv,
                         options(samples, candidates, seed, threads));
        }
        py::dict d;
        d["placeable"] = c.placeable;
        d["unplaceable"] = c.unplaceable;
        d["probability"] = c.probability;
        d["shots"] = c.shots;
        d["aim"] = py::make_tuple(c.aim.phi, c.aim.theta, c.aim.speed, c.aim.a, c.aim.b);
        d["kind"] = std::string(to_string(c.kind));
        d["plays"] = c.plays;
        d["simulations"] = c.simulations;
        return d;
      },
      py::arg("position"), py::arg("x"), py::arg("y"), py::arg("ball"), py::arg("pocket"),
      py::arg("level"), py::arg("samples"), py::arg("candidates"), py::arg("seed"),
      py::arg("threads"),
      "pot_chance (pot_map.hpp) as a dict, also where the cue ball cannot be placed"
      " (placeable False, unplaceable the reason); use breakshot.pot_chance.");

  m.def(
      "pot_map",
      [](const py::dict& position, int ball, int pocket, const std::string& level,
         const std::vector<double>& xs, const std::vector<double>& ys, int samples, int candidates,
         std::uint64_t seed, int threads) {
        const GamePosition pos = pot_position_arg(position);
        const AiLevel lv = ai_level(level);
        PotMap map;
        {
          py::gil_scoped_release release;
          map = pot_map(pos.rules, pos.state, ball, pocket, lv, xs, ys,
                        options(samples, candidates, seed, threads));
        }
        const auto nx = static_cast<py::ssize_t>(xs.size());
        const auto ny = static_cast<py::ssize_t>(ys.size());
        Array prob = array({ny, nx});
        Array aims = array({ny, nx, 5});
        py::array_t<bool> valid({ny, nx});
        py::array_t<std::int32_t> shots({ny, nx});
        py::array_t<std::int32_t> plays({ny, nx});
        py::list kinds;
        auto pr = prob.mutable_unchecked<2>();
        auto am = aims.mutable_unchecked<3>();
        auto va = valid.mutable_unchecked<2>();
        auto sh = shots.mutable_unchecked<2>();
        auto pl = plays.mutable_unchecked<2>();
        std::int64_t simulations = 0;
        for (py::ssize_t j = 0; j < ny; ++j) {
          py::list row;
          for (py::ssize_t i = 0; i < nx; ++i) {
            const PotChance& c = map.cells[static_cast<std::size_t>(j * nx + i)];
            pr(j, i) = c.probability;
            const bool aimed = c.placeable && c.shots > 0;
            const std::array<double, 5> a = {c.aim.phi, c.aim.theta, c.aim.speed, c.aim.a, c.aim.b};
            for (py::ssize_t k = 0; k < 5; ++k)
              am(j, i, k) = aimed ? a[static_cast<std::size_t>(k)] : 0.0;
            va(j, i) = c.placeable;
            sh(j, i) = c.shots;
            pl(j, i) = c.plays;
            row.append(aimed ? py::object(py::str(std::string(to_string(c.kind)))) : py::none());
            simulations += c.simulations;
          }
          kinds.append(row);
        }
        py::dict d;
        d["probability"] = prob;
        d["aims"] = aims;
        d["valid"] = valid;
        d["shots"] = shots;
        d["plays"] = plays;
        d["kinds"] = kinds;
        d["simulations"] = simulations;
        d["table"] = table_dict(pos.rules.table());
        d["ball_radius"] = pos.rules.config().ball_radius;
        return d;
      },
      py::arg("position"), py::arg("ball"), py::arg("pocket"), py::arg("level"), py::arg("xs"),
      py::arg("ys"), py::arg("samples"), py::arg("candidates"), py::arg("seed"), py::arg("threads"),
      "pot_map (pot_map.hpp): plain arrays, 0 where a cell has no value (valid, shots say"
      " where); use breakshot.pot_map.");
}

}  // namespace breakshot::python
