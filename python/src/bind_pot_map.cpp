// Pot maps (pot_map.hpp) for breakshot.pot_chance and breakshot.pot_map:
//   _core.pot_chance   one cue-ball position
//   _core.pot_map      a grid of them
//   _core.level_names  the computer players' levels
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
#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/pot_map.hpp"
#include "breakshot/table.hpp"

namespace breakshot::python {

namespace {

using Array = py::array_t<double>;

Array array(std::vector<py::ssize_t> shape) { return Array(std::move(shape)); }

/// A game position from what breakshot/pot_map.py passes: the game, the
/// table size, positions (n, 2) and on-table flags by ball number, the
/// shooter and the 8-ball groups. Phase shot, no ball in hand.
struct Position {
  Rules rules;
  GameState state;
};

Position position(const std::string& game, const std::string& table_size,
                  const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
                  const py::array_t<bool, py::array::c_style | py::array::forcecast>& on_table,
                  int player, const std::vector<std::string>& groups) {
  const std::optional<GameType> g = parse_game_type(game);
  if (!g) {
    throw std::invalid_argument("unknown game \"" + game + "\" (known: eight_ball, nine_ball)");
  }
  GameConfig config;
  config.game = *g;
  config.table_size = table_size;
  Position out{Rules(config), GameState{}};
  const int n = out.rules.ball_count();
  if (positions.ndim() != 2 || positions.shape(0) != n || positions.shape(1) != 2) {
    throw std::invalid_argument("positions must have the shape (" + std::to_string(n) + ", 2)");
  }
  if (on_table.ndim() != 1 || on_table.shape(0) != n) {
    throw std::invalid_argument("on_table must have the shape (" + std::to_string(n) + ",)");
  }
  if (player != 0 && player != 1) throw std::invalid_argument("player must be 0 or 1");
  GameState s = out.rules.start(0, player);
  auto p = positions.unchecked<2>();
  auto on = on_table.unchecked<1>();
  for (int b = 0; b < n; ++b) {
    s.position[static_cast<std::size_t>(b)] = {p(b, 0), p(b, 1)};
    s.on_table[static_cast<std::size_t>(b)] = on(b) ? 1 : 0;
  }
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.player = player;
  s.breaker = player;
  s.shots = 1;
  s.innings = 1;
  if (!groups.empty()) {
    if (groups.size() != 2) throw std::invalid_argument("groups must name two groups");
    for (std::size_t k = 0; k < 2; ++k) {
      const std::optional<Group> gr = parse_group(groups[k]);
      if (!gr) {
        throw std::invalid_argument("unknown group \"" + groups[k] +
                                    "\" (known: none, solids, stripes)");
      }
      s.group[k] = *gr;
    }
  }
  for (int b = 1; b < n; ++b) {
    if (!s.on_table[static_cast<std::size_t>(b)]) continue;
    const Vec2 q = s.position[static_cast<std::size_t>(b)];
    if (!std::isfinite(q.x) || !std::isfinite(q.y) ||
        wall_clearance(out.rules.table(), q, config.ball_radius) < 0.0) {
      throw std::invalid_argument("ball " + std::to_string(b) +
                                  " does not lie on the playing surface clear of the cushions");
    }
    for (int c = 1; c < b; ++c) {
      if (s.on_table[static_cast<std::size_t>(c)] &&
          norm(s.position[static_cast<std::size_t>(c)] - q) < 2.0 * config.ball_radius) {
        throw std::invalid_argument("balls " + std::to_string(c) + " and " + std::to_string(b) +
                                    " overlap");
      }
    }
  }
  out.state = std::move(s);
  return out;
}

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
      "pot_chance",
      [](const std::string& game, const std::string& table_size,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
         const py::array_t<bool, py::array::c_style | py::array::forcecast>& on_table, int player,
         const std::vector<std::string>& groups, double x, double y, int ball, int pocket,
         const std::string& level, int samples, int candidates, std::uint64_t seed, int threads) {
        const Position pos = position(game, table_size, positions, on_table, player, groups);
        const AiLevel lv = ai_level(level);
        PotChance c;
        {
          py::gil_scoped_release release;
          c = pot_chance(pos.rules, pos.state, {x, y}, ball, pocket, lv,
                         options(samples, candidates, seed, threads));
        }
        py::dict d;
        d["placeable"] = c.placeable;
        d["probability"] = c.probability;
        d["shots"] = c.shots;
        d["aim"] = py::make_tuple(c.aim.phi, c.aim.theta, c.aim.speed, c.aim.a, c.aim.b);
        d["kind"] = std::string(to_string(c.kind));
        d["plays"] = c.plays;
        d["simulations"] = c.simulations;
        return d;
      },
      py::arg("game"), py::arg("table_size"), py::arg("positions"), py::arg("on_table"),
      py::arg("player"), py::arg("groups"), py::arg("x"), py::arg("y"), py::arg("ball"),
      py::arg("pocket"), py::arg("level"), py::arg("samples"), py::arg("candidates"),
      py::arg("seed"), py::arg("threads"), "pot_chance (pot_map.hpp); use breakshot.pot_chance.");

  m.def(
      "pot_map",
      [](const std::string& game, const std::string& table_size,
         const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
         const py::array_t<bool, py::array::c_style | py::array::forcecast>& on_table, int player,
         const std::vector<std::string>& groups, int ball, int pocket, const std::string& level,
         const std::vector<double>& xs, const std::vector<double>& ys, int samples, int candidates,
         std::uint64_t seed, int threads) {
        const Position pos = position(game, table_size, positions, on_table, player, groups);
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
        constexpr double nan = std::numeric_limits<double>::quiet_NaN();
        for (py::ssize_t j = 0; j < ny; ++j) {
          py::list row;
          for (py::ssize_t i = 0; i < nx; ++i) {
            const PotChance& c = map.cells[static_cast<std::size_t>(j * nx + i)];
            pr(j, i) = c.probability;
            const bool aimed = c.placeable && c.shots > 0;
            const std::array<double, 5> a = {c.aim.phi, c.aim.theta, c.aim.speed, c.aim.a, c.aim.b};
            for (py::ssize_t k = 0; k < 5; ++k)
              am(j, i, k) = aimed ? a[static_cast<std::size_t>(k)] : nan;
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
      py::arg("game"), py::arg("table_size"), py::arg("positions"), py::arg("on_table"),
      py::arg("player"), py::arg("groups"), py::arg("ball"), py::arg("pocket"), py::arg("level"),
      py::arg("xs"), py::arg("ys"), py::arg("samples"), py::arg("candidates"), py::arg("seed"),
      py::arg("threads"), "pot_map (pot_map.hpp); use breakshot.pot_map.");
}

}  // namespace breakshot::python
