// The position a pot map is asked about (bind.hpp's pot_position_arg),
// from python/breakshot/_position.py's normal form of a game position:
// a game's own state read whole from its records' JSON form, or balls
// placed on the game's start state.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bind.hpp"
#include "breakshot/game.hpp"
#include "breakshot/table.hpp"
#include "io/game_json.hpp"
#include "io/json_read.hpp"

namespace breakshot::python {

namespace {

using Positions = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Flags = py::array_t<bool, py::array::c_style | py::array::forcecast>;

/// How far a ball of a game's own state may lie into a cushion or
/// another ball (m): rounding in the engine's rest positions, never a
/// ball put in the wrong place.
constexpr double kStateSlack = 1e-6;

std::optional<std::string> optional_text(const py::dict& d, const char* key) {
  if (!d.contains(key) || d[key].is_none()) return std::nullopt;
  return py::cast<std::string>(d[key]);
}

/// Every object ball on the table lies on the playing surface clear of
/// the cushions and of every other ball, to within `slack`.
void check_balls(const Rules& rules, const GameState& s, double slack) {
  const double R = rules.config().ball_radius;
  for (std::size_t b = 1; b < s.on_table.size(); ++b) {
    if (!s.on_table[b]) continue;
    const Vec2 q = s.position[b];
    if (!std::isfinite(q.x) || !std::isfinite(q.y) ||
        wall_clearance(rules.table(), q, R) < -slack) {
      throw std::invalid_argument("ball " + std::to_string(b) +
                                  " does not lie on the playing surface clear of the cushions");
    }
    for (std::size_t c = 1; c < b; ++c) {
      if (s.on_table[c] && norm(s.position[c] - q) < 2.0 * R - slack) {
        throw std::invalid_argument("balls " + std::to_string(c) + " and " + std::to_string(b) +
                                    " overlap");
      }
    }
  }
}

/// A game's own state from its records' JSON text.
GameState read_state(const Rules& rules, const std::string& text) {
  json_io::json doc;
  if (auto problem = json_io::parse_strict(text, doc)) {
    throw std::invalid_argument("state: " + problem->error.reason);
  }
  json_io::GameReader reader;
  reader.game_context = rules.config().game;
  GameState s;
  if (!reader.state(doc, "state", s)) {
    throw std::invalid_argument(reader.error->path + ": " + reader.error->reason);
  }
  const auto n = static_cast<std::size_t>(rules.ball_count());
  if (s.game != rules.config().game) {
    throw std::invalid_argument("state: a " + std::string(to_string(s.game)) + " state, not " +
                                std::string(to_string(rules.config().game)) + "'s");
  }
  if (s.position.size() != n || s.on_table.size() != n) {
    throw std::invalid_argument("state: " + std::to_string(s.position.size()) +
                                " ball positions; " + std::string(to_string(s.game)) + " has " +
                                std::to_string(n) + " balls");
  }
  check_balls(rules, s, kStateSlack);
  return s;
}

/// The balls of a dict position on the game's start state, in phase
/// shot: `player` to shoot, no ball in hand, after the break (one shot
/// and one inning played, no push-out due); 8-ball's groups as given;
/// snooker's score as given, on a red (a colour, nominated, with
/// `colour_on`; the lowest colour once no red is left).
GameState place_balls(const Rules& rules, const py::dict& d) {
  const GameType game = rules.config().game;
  const std::string name(to_string(game));
  const int n = rules.ball_count();
  const auto positions = py::cast<Positions>(d["positions"]);
  const auto on_table = py::cast<Flags>(d["on_table"]);
  if (positions.ndim() != 2 || positions.shape(0) != n || positions.shape(1) != 2) {
    throw std::invalid_argument("positions must have the shape (" + std::to_string(n) +
                                ", 2) for " + name);
  }
  if (on_table.ndim() != 1 || on_table.shape(0) != n) {
    throw std::invalid_argument("on_table must have the shape (" + std::to_string(n) + ",) for " +
                                name);
  }
  const int player = d.contains("player") ? py::cast<int>(d["player"]) : 0;
  if (player != 0 && player != 1) throw std::invalid_argument("player must be 0 or 1");
  GameState s = rules.start(0, player);
  auto p = positions.unchecked<2>();
  auto on = on_table.unchecked<1>();
  for (int b = 0; b < n; ++b) {
    s.position[static_cast<std::size_t>(b)] = {p(b, 0), p(b, 1)};
    s.on_table[static_cast<std::size_t>(b)] = on(b) ? 1 : 0;
  }
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.kitchen_shot = false;
  s.player = player;
  s.breaker = player;
  s.shots = 1;
  s.innings = 1;
  s.push_out_allowed = false;
  s.after_push_out = false;

  const auto groups = d.contains("groups") && !d["groups"].is_none()
                          ? py::cast<std::vector<std::string>>(d["groups"])
                          : std::vector<std::string>{};
  if (!groups.empty()) {
    if (game != GameType::eight_ball) {
      throw std::invalid_argument("groups are 8-ball's; " + name + " has none");
    }
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

  const bool has_score = d.contains("score") && !d["score"].is_none();
  const bool has_colour_on = d.contains("colour_on") && !d["colour_on"].is_none();
  if (game != GameType::snooker) {
    if (has_score || has_colour_on) {
      throw std::invalid_argument(std::string(has_score ? "score" : "colour_on") +
                                  " is snooker's; " + name + " has none");
    }
  } else {
    SnookerState& k = *s.snooker;
    if (has_score) {
      const auto score = py::cast<std::vector<int>>(d["score"]);
      if (score.size() != 2 || score[0] < 0 || score[1] < 0) {
        throw std::invalid_argument("score must be two points >= 0 (players 0 and 1)");
      }
      k.score = {score[0], score[1]};
    }
    k.colour_on = has_colour_on && py::cast<bool>(d["colour_on"]);
    k.break_points = 0;
    k.free_ball = false;
    k.respotted_black = false;
    k.misses = 0;
  }
  check_balls(rules, s, 0.0);
  return s;
}

}  // namespace

GamePosition pot_position_arg(const py::dict& d) {
  const auto game = py::cast<std::string>(d["game"]);
  const auto table = py::cast<std::string>(d["table_size"]);
  Rules rules(game_config(game, table, 0, optional_text(d, "physics")));
  if (rules.table().pockets.empty()) {
    throw std::invalid_argument("pot maps need a table with pockets; " + game + " has none");
  }
  const std::optional<std::string> state = optional_text(d, "state");
  GameState s = state ? read_state(rules, *state) : place_balls(rules, d);
  return GamePosition{std::move(rules), std::move(s)};
}

}  // namespace breakshot::python
