// Games, computer players and matches for Python: _core.GameCore (a
// GameSession), _core.PlayerCore (a Player made by name) and
// _core.match_json, and the pieces of a match spread over many machines
// (match_chunk, add_match_summaries, record_file_name, determinism_hash).
// Actions, states, rulings, legal actions, facts, events, figures and the
// table cross the boundary as the JSON text of src/io/game_json.hpp and
// table_json.hpp, the one encoding the records and the web facade use, so
// a Python dict and a record's action or the facade's table are the same
// thing; the Python classes (python/breakshot/game.py) build on these.
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bind.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/players.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/session.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/carom.hpp"
#include "breakshot/snooker.hpp"
#include "io/game_json.hpp"
#include "io/json_read.hpp"
#include "io/table_json.hpp"

namespace breakshot::python {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

void check_table(GameType game, const std::string& table) {
  if (game == GameType::snooker) {
    if (table != "12ft") {
      throw std::invalid_argument("table: unknown table size '" + table + "' (snooker: 12ft)");
    }
  } else if (game == GameType::three_cushion) {
    if (table != "10ft") {
      throw std::invalid_argument("table: unknown table size '" + table +
                                  "' (three_cushion: 10ft)");
    }
  } else if (table != "7ft" && table != "8ft" && table != "9ft") {
    throw std::invalid_argument("table: unknown table size '" + table + "' (7ft, 8ft or 9ft)");
  }
}

GameType game_arg(const std::string& name) {
  if (auto g = parse_game_type(name)) return *g;
  throw std::invalid_argument("game: unknown game '" + name + "' (known games: " +
                              join(game_type_names()) + ")");
}

GamePhysics physics_arg(const std::optional<std::string>& text) {
  GamePhysics p;
  if (!text) return p;
  json_io::json doc;
  if (auto problem = json_io::parse_strict(*text, doc)) {
    throw std::invalid_argument("physics: " + problem->error.reason);
  }
  if (!doc.is_object()) throw std::invalid_argument("physics: expected an object");
  const json_io::json defaults = json_io::json::parse(json_io::physics_json(p).dump());
  for (const auto& [key, value] : defaults.items()) {
    if (!doc.contains(key)) doc[key] = value;
  }
  json_io::GameReader reader;
  if (!reader.physics(doc, "physics", p)) {
    throw std::invalid_argument(reader.error->path + ": " + reader.error->reason);
  }
  return p;
}

GameConfig game_config(const std::string& game, const std::string& table, int max_shots,
                       const std::optional<std::string>& physics) {
  const GameType g = game_arg(game);
  // Snooker: the 12 ft table and snooker balls; three-cushion: the carom
  // table and balls.
  GameConfig c = g == GameType::snooker         ? snooker_config()
                 : g == GameType::three_cushion ? three_cushion_config()
                                                : GameConfig{};
  c.physics = physics_arg(physics);
  c.game = g;
  check_table(g, table);
  c.table_size = table;
  // -1: the rules' default; 0: no limit.
  if (max_shots < -1) {
    throw std::invalid_argument("max_shots: must be 0 (no limit) or more, not " +
                                std::to_string(max_shots));
  }
  if (max_shots >= 0) c.max_shots = max_shots;
  return c;
}

namespace {

using json_io::ojson;

NoiseModel noise_arg(const std::string& spec, const std::string& what) {
  try {
    return parse_noise(spec);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(what + ": " + e.what());
  }
}

/// An action from its JSON text (the records' form); std::invalid_argument
/// naming the path ("action.strike.speed") otherwise.
Action parse_action(const std::string& text) {
  json_io::json doc;
  if (auto problem = json_io::parse_strict(text, doc)) {
    throw std::invalid_argument("action: " + problem->error.reason);
  }
  json_io::GameReader reader;
  Action a;
  if (!reader.action(doc, "action", a)) {
    throw std::invalid_argument(reader.error->path + ": " + reader.error->reason);
  }
  return a;
}

/// A game in progress: one GameSession.
class GameCore {
 public:
  GameCore(const std::string& game, const std::string& table, std::uint64_t seed, int breaker,
           const std::array<std::string, 2>& names, const std::array<std::string, 2>& noise,
           int max_shots, const std::optional<std::string>& physics)
      : session_(game_config(game, table, max_shots, physics), seats(names, noise), seed,
                 breaker) {}

  explicit GameCore(GameSession session) : session_(std::move(session)) {}

  /// A game from a record's text: read, checked by replay(), then played
  /// again action by action as recorded.
  static GameCore from_record(const std::string& text) {
    auto parsed = read_record(text);
    if (const auto* err = std::get_if<RecordError>(&parsed)) {
      throw std::invalid_argument("invalid record: " + err->path + ": " + err->reason);
    }
    const GameRecord& record = std::get<GameRecord>(parsed);
    const ReplayReport report = replay(record);
    if (!report.identical) {
      throw std::invalid_argument("the record does not replay: " + report.message);
    }
    GameSession session(record.config, Seats{record.players, record.noise}, record.seed,
                        record.start.rack_seed, record.start.breaker);
    for (const RecordedAction& ra : record.actions) {
      session.play_executed(ra.action, ra.intended, ra.noise_seed);
    }
    return GameCore(std::move(session));
  }

  const GameSession& session() const { return session_; }

  std::string state_json(std::size_t i) const {
    if (i > session_.actions()) {
      throw std::invalid_argument("state_before: action " + std::to_string(i) + " of " +
                                  std::to_string(session_.actions()));
    }
    return json_io::state_json(session_.state_before(i)).dump();
  }

  std::vector<int> targets() const {
    if (session_.over()) return {};
    return session_.rules().targets(session_.state());
  }

  /// What the player to act may do (json_io::legal_actions_json; nothing
  /// once the game is over), as JSON text.
  std::string legal_json() const {
    const GameState& st = session_.state();
    return json_io::legal_actions_json(session_.rules().legal_actions(st), st.game).dump();
  }

  /// Snooker: what the table leaves before action i
  /// (json_io::snooker_figures_json); three-cushion: the figures of the
  /// score panel before action i (json_io::carom_figures_json); as JSON
  /// text, or None in the other games.
  std::optional<std::string> figures_json(std::size_t i) const {
    if (i > session_.actions()) {
      throw std::invalid_argument("state_before: action " + std::to_string(i) + " of " +
                                  std::to_string(session_.actions()));
    }
    const GameState& s = session_.state_before(i);
    if (s.snooker) return json_io::snooker_figures_json(s).dump();
    if (s.carom) {
      if (i == session_.actions()) {
        return json_io::carom_figures_json(session_.rules(), s, session_.record()).dump();
      }
      GameRecord before = session_.record();
      before.actions.resize(i);
      return json_io::carom_figures_json(session_.rules(), s, before).dump();
    }
    return std::nullopt;
  }

  std::optional<std::string> check(const std::string& action_text) const {
    return session_.check(parse_action(action_text));
  }

  std::optional<std::string> check_placement(double x, double y) const {
    if (session_.over()) return std::string("the game is over");
    return session_.rules().check_placement(session_.state(), Vec2{x, y});
  }

  /// Plays an action for the seat to act (noise applied to a shot) and
  /// returns the outcome as JSON text.
  std::string apply(const std::string& action_text) {
    const Action action = parse_action(action_text);
    if (session_.over()) throw std::invalid_argument("the game is over");
    const std::size_t i = session_.actions();
    // The GIL stays held: a shot takes well under a millisecond, and the
    // session must not change under another Python thread.
    const Outcome out = session_.play(action);
    const RecordedAction& ra = session_.record().actions.back();
    ojson j = ojson::object();
    j["index"] = i;
    j["player"] = ra.player;
    j["executed"] = json_io::action_json(ra.action);
    j["intended"] = ra.intended ? json_io::strike_json(*ra.intended) : ojson(nullptr);
    j["noise_seed"] = json_io::seed_json(ra.noise_seed);
    j["ruling"] = json_io::ruling_json(out.ruling);
    j["facts"] = json_io::facts_json(out.facts);
    ojson events = ojson::array();
    for (const Event& e : out.events) {
      events.push_back(json_io::game_event_json(session_.rules().table(), e));
    }
    j["events"] = events;
    j["state"] = json_io::state_json(out.state);
    return j.dump();
  }

  void take_back_to(std::size_t n) { session_.take_back_to(n); }

  std::string record_text() const { return write_record(session_.record()); }

  /// The table and its markings (json_io::game_table_json) as JSON text.
  std::string table_json() const { return json_io::game_table_json(session_.rules()).dump(); }

  std::string config_json() const { return json_io::config_json(session_.rules().config()).dump(); }
  std::string physics_json() const {
    return json_io::physics_json(session_.rules().config().physics).dump();
  }

  std::vector<std::string> names() const {
    return {session_.record().players[0], session_.record().players[1]};
  }
  std::vector<std::string> noise() const {
    return {to_string(session_.record().noise[0]), to_string(session_.record().noise[1])};
  }

 private:
  static Seats seats(const std::array<std::string, 2>& names,
                     const std::array<std::string, 2>& noise) {
    Seats s;
    s.names = names;
    s.noise = {noise_arg(noise[0], "noise (seat 0)"), noise_arg(noise[1], "noise (seat 1)")};
    return s;
  }

  GameSession session_;
};

/// A computer player by name, with the AI's thread count settable.
class PlayerCore {
 public:
  PlayerCore(const std::string& name, int threads) : name_(name), threads_(threads) {
    if (threads < 0) {
      throw std::invalid_argument("threads: must be 0 (every core) or more, not " +
                                  std::to_string(threads));
    }
    const std::vector<std::string> levels = ai_level_names();
    if (std::find(levels.begin(), levels.end(), name) != levels.end()) {
      AiLevel level = ai_level(name);
      if (threads > 0) level.threads = threads;
      threads_ = level.threads;
      player_ = make_ai_player(level);
    } else {
      player_ = make_player(name);  // throws, naming the known players
      threads_ = 1;
    }
  }

  std::string name() const { return player_->name(); }
  int threads() const { return threads_; }
  std::optional<std::string> noise() const {
    if (auto n = player_->noise()) return to_string(*n);
    return std::nullopt;
  }

  /// The player's action for the game's state now, with decision seed
  /// `seed`, as JSON text. The GIL is released while it thinks.
  std::string decide(const GameCore& game, std::uint64_t seed) {
    const GameSession& s = game.session();
    if (s.over()) throw std::invalid_argument("decide: the game is over");
    // Copies: the game may change in another Python thread meanwhile.
    const Rules rules = s.rules();
    const GameState state = s.state();
    Action a;
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);
      a = player_->decide(rules, state, seed);
    }
    return json_io::action_json(a).dump();
  }

  Player& player() { return *player_; }

 private:
  std::string name_;
  int threads_ = 0;
  std::unique_ptr<Player> player_;
  std::mutex mutex_;
};

MatchOptions match_options(const std::string& game, const std::array<std::string, 2>& players,
                           int games, std::uint64_t seed, const std::string& noise,
                           const std::string& table, int first_game,
                           const std::optional<std::string>& physics) {
  MatchOptions opt;
  opt.physics = physics_arg(physics);
  opt.game = game_arg(game);
  opt.players = players;
  if (games < 1) {
    throw std::invalid_argument("games: expected a whole number of games >= 1, not " +
                                std::to_string(games));
  }
  opt.games = games;
  if (first_game < 0) {
    throw std::invalid_argument("first_game: expected a whole number >= 0, not " +
                                std::to_string(first_game));
  }
  if (first_game > std::numeric_limits<int>::max() - games) {
    throw std::invalid_argument("first_game: first_game + games must be at most " +
                                std::to_string(std::numeric_limits<int>::max()) + ", not " +
                                std::to_string(first_game) + " + " + std::to_string(games));
  }
  opt.first_game = first_game;
  opt.seed = seed;
  opt.noise = noise_arg(noise, "noise");
  check_table(opt.game, table);
  opt.table_size = table;
  for (const std::string& name : players) {
    if (auto why = check_player(name, opt.game)) throw std::invalid_argument("players: " + *why);
  }
  return opt;
}

std::string match_json(const std::string& game, const std::array<std::string, 2>& players,
                       int games, std::uint64_t seed, const std::string& noise,
                       const std::string& table, const std::optional<std::string>& records,
                       int threads, int first_game, const std::optional<std::string>& physics,
                       int jobs) {
  MatchOptions opt = match_options(game, players, games, seed, noise, table, first_game, physics);
  if (jobs < 0) {
    throw std::invalid_argument("jobs: expected a whole number >= 0 (0: one per core), not " +
                                std::to_string(jobs));
  }
  opt.jobs = jobs;
  if (threads < 0) {
    throw std::invalid_argument("threads: must be 0 (every core) or more, not " +
                                std::to_string(threads));
  }
  std::string text;
  if (match_threads(jobs, games) > 1) {
    // Games at once, each thread with its own players (`breakshot match
    // --jobs`); the same summary as one game at a time.
    py::gil_scoped_release release;
    const RecordSink sink = records ? record_files(*records) : RecordSink{};
    if (threads == 0) {
      text = match_summary_json(play_match(opt, sink));
    } else {
      const PlayerFactory make = [&opt, threads](int seat) {
        return make_player(opt.players[static_cast<std::size_t>(seat)], threads);
      };
      text = match_summary_json(play_match(opt, make, sink));
    }
    return text;
  }
  PlayerCore p0(players[0], threads);
  PlayerCore p1(players[1], threads);
  {
    py::gil_scoped_release release;
    const RecordSink sink = records ? record_files(*records) : RecordSink{};
    text = match_summary_json(play_match(opt, p0.player(), p1.player(), sink));
  }
  return text;
}

/// Games first_game .. first_game + games - 1 of a match: the summary
/// text and, if asked, each game's record text by index. A failing game
/// raises RuntimeError "game G (seed S): ..." (MatchGameError).
std::pair<std::string, std::vector<std::pair<int, std::string>>> match_chunk(
    const std::string& game, const std::array<std::string, 2>& players, std::uint64_t seed,
    const std::string& noise, const std::string& table, int first_game, int games, int threads,
    bool records, const std::optional<std::string>& physics) {
  MatchOptions opt = match_options(game, players, games, seed, noise, table, first_game, physics);
  opt.name_failing_game = true;
  PlayerCore p0(players[0], threads);
  PlayerCore p1(players[1], threads);
  std::vector<std::pair<int, std::string>> texts;
  std::string summary;
  {
    py::gil_scoped_release release;
    RecordSink sink;
    if (records) {
      sink = [&texts](int g, const GameRecord& r) { texts.emplace_back(g, write_record(r)); };
    }
    summary = match_summary_json(play_match(opt, p0.player(), p1.player(), sink));
  }
  return {std::move(summary), std::move(texts)};
}

std::string add_match_summaries(const std::vector<std::string>& texts) {
  if (texts.empty()) throw std::invalid_argument("summaries: no summaries to add");
  MatchSummary sum;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const std::string at = "summaries[" + std::to_string(i) + "]: ";
    MatchSummary part;
    try {
      part = read_match_summary(texts[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(at + e.what());
    }
    if (i == 0) {
      sum = std::move(part);
      continue;
    }
    try {
      add_summary(sum, part);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(at + "cannot be added to the summaries before it: " + e.what());
    }
  }
  return match_summary_json(sum);
}

std::string record_file_name_arg(int game) {
  if (game < 0) {
    throw std::invalid_argument("game: expected a game index >= 0, not " + std::to_string(game));
  }
  return record_file_name(game);
}

/// 64-bit FNV-1a.
std::uint64_t fnv1a(std::uint64_t h, const std::string& bytes) {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

/// A digest of what this build computes: the result file of a fixed 8-ball
/// break (the physics) and the summary of a 2-game 9-ball match between
/// the baseline and the beginner level with tournament noise (the rules,
/// the noise, the AI). Two builds with the same digest play these the same
/// to the bit; a build that differs gives another digest (almost surely).
std::string determinism_hash() {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  {
    py::gil_scoped_release release;
    const Scenario scenario = make_break_scenario("eight_ball", "9ft", 1, 7.0);
    h = fnv1a(h, write_result(scenario, simulate(scenario)));
    MatchOptions opt;
    opt.game = GameType::nine_ball;
    opt.players = {"baseline", "beginner"};
    opt.games = 2;
    opt.seed = 1;
    opt.noise = parse_noise("tournament");
    PlayerCore p0("baseline", 1);
    PlayerCore p1("beginner", 1);
    h = fnv1a(h, match_summary_json(play_match(opt, p0.player(), p1.player())));
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace

void bind_game(py::module_& m) {
  m.def("game_names", &game_type_names, "The games the library plays (GameType names).");
  m.def("player_names", static_cast<std::vector<std::string> (*)()>(&player_names),
        "The computer players: 'baseline', then the AI levels.");
  m.def(
      "check_player",
      [](const std::string& name, const std::string& game) {
        return check_player(name, game_arg(game));
      },
      py::arg("name"), py::arg("game"),
      "Why the player `name` (NAME or NAME@NOISE) cannot play `game`, or None.");
  m.def("mix_seed", &mix_seed, py::arg("a"), py::arg("b"),
        "SplitMix64 seed mixing (noise.hpp): game g of a match has seed mix_seed(seed, g).");
  m.def("player_seed", &GameSeeds::player, py::arg("game_seed"), py::arg("action"),
        "GameSeeds::player: the decision seed of action i of a game.");

  py::class_<GameCore>(m, "GameCore", "A game in progress (a C++ GameSession); see breakshot.Game.")
      .def(py::init<const std::string&, const std::string&, std::uint64_t, int,
                    const std::array<std::string, 2>&, const std::array<std::string, 2>&, int,
                    const std::optional<std::string>&>(),
           py::arg("game"), py::arg("table"), py::arg("seed"), py::arg("breaker"),
           py::arg("names"), py::arg("noise"), py::arg("max_shots"),
           py::arg("physics") = py::none())
      .def_static("from_record", &GameCore::from_record, py::arg("text"))
      .def("state_json", &GameCore::state_json, py::arg("i"))
      .def("targets", &GameCore::targets)
      .def("figures_json", &GameCore::figures_json, py::arg("i"))
      .def("legal_json", &GameCore::legal_json)
      .def("check", &GameCore::check, py::arg("action"))
      .def("check_placement", &GameCore::check_placement, py::arg("x"), py::arg("y"))
      .def("apply", &GameCore::apply, py::arg("action"))
      .def("take_back_to", &GameCore::take_back_to, py::arg("n"))
      .def("record_text", &GameCore::record_text)
      .def("table_json", &GameCore::table_json)
      .def("config_json", &GameCore::config_json)
      .def("physics_json", &GameCore::physics_json)
      .def("names", &GameCore::names)
      .def("noise", &GameCore::noise)
      .def_property_readonly("actions", [](const GameCore& g) { return g.session().actions(); })
      .def_property_readonly("over", [](const GameCore& g) { return g.session().over(); })
      .def_property_readonly("seed", [](const GameCore& g) { return g.session().record().seed; })
      .def_property_readonly("next_player_seed",
                             [](const GameCore& g) { return g.session().next_player_seed(); })
      .def_property_readonly("next_noise_seed",
                             [](const GameCore& g) { return g.session().next_noise_seed(); })
      .def("__copy__", [](const GameCore& g) { return GameCore(g); });

  py::class_<PlayerCore>(m, "PlayerCore", "A computer player (C++); see breakshot.Player.")
      .def(py::init<const std::string&, int>(), py::arg("name"), py::arg("threads"))
      .def_property_readonly("name", &PlayerCore::name)
      .def_property_readonly("threads", &PlayerCore::threads)
      .def_property_readonly("noise", &PlayerCore::noise)
      .def("decide", &PlayerCore::decide, py::arg("game"), py::arg("seed"));

  m.def("match_json", &match_json, py::arg("game"), py::arg("players"), py::arg("games"),
        py::arg("seed"), py::arg("noise"), py::arg("table"), py::arg("records"),
        py::arg("threads"), py::arg("first_game") = 0, py::arg("physics") = py::none(),
        py::arg("jobs") = 1,
        "The summary text `breakshot match` prints for the same arguments (physics: JSON text"
        " of the game's physics, or None for the defaults; jobs: games at once, 0 one per"
        " core).");
  m.def("match_chunk", &match_chunk, py::arg("game"), py::arg("players"), py::arg("seed"),
        py::arg("noise"), py::arg("table"), py::arg("first_game"), py::arg("games"),
        py::arg("threads"), py::arg("records"), py::arg("physics") = py::none(),
        "Games first_game .. first_game + games - 1 of a match (`breakshot match --first-game`):"
        " (summary text, [(g, record text), ...] if records else []). A failing game raises"
        " RuntimeError 'game G (seed S): ...'.");
  m.def("add_match_summaries", &add_match_summaries, py::arg("texts"),
        "The summary text of the summaries (texts) added together (`breakshot match-sum`).");
  m.def("record_file_name", &record_file_name_arg, py::arg("g"),
        "The name of game g's record file ('game-0001.json' for game 0).");
  m.def("determinism_hash", &determinism_hash,
        "A 16-hex-digit digest of a fixed break's result and a fixed 2-game match's summary:"
        " builds that compute differently give different digests.");
}

}  // namespace breakshot::python
