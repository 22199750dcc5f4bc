// Game records (include/breakshot/record.hpp): writing, reading and
// replaying them.
//
// The file, version 2 (3 with an ending):
//
//   {
//     "format": "breakshot-game-record",
//     "version": 2,
//     "engine": {"version": "0.1.0"},
//     "config": {"game", "table_size", "ball_radius", "ball_mass", "max_shots",
//                three-cushion only: "carom": {"target", "innings_limit",
//                "equalizing_inning"}},
//     "physics": {"cushion_model", "ball_ball_model",
//                 "ball_ball_friction": {"a", "b", "c"} | number,
//                 "airborne": true, "spinning_friction": number},
//     "players": [NAME, NAME],
//     "seed": "DECIMAL",
//     "noise": [NOISE, NOISE],
//     "start": STATE,
//     "actions": [
//       {"player", "action", "intended", "noise_seed", "ruling", "after": STATE},
//       ...one action per line
//     ],
//     version 3 only: "ending": ENDING
//   }
//
//   "engine" is the library version that played the game (version.hpp)
//   and "physics" the game's physics choices (GameConfig::physics, by the
//   scenario names of table.cushion_model, physics.ball_ball_model and
//   physics.ball_ball_friction; "airborne" only when on, "spinning_friction"
//   only when it is not breakshot 0.1's 0.044, which a record without it
//   was played with). Version 1 records have neither: they were
//   all written by breakshot 0.1.0 and are read as played with
//   kLegacyGamePhysics, on which they replay. A physics name or field this
//   build does not know is refused with the record's version and engine in
//   the message; so is a record version above this build's. A record
//   that reads but does not replay (replay()) is reported with its
//   version and engine too, and "another engine" when that is not this
//   build.
//
//   A record with an ending (GameRecord::ending: a game online play ended
//   by a forfeit, which the rules did not end) is version 3, and version 3
//   requires it; every other record is written as version 2, its bytes
//   unchanged. Versions 1 and 2 have no ending.
//
//   ENDING  {"kind": "forfeit" | "abandoned", "player", "winner", "text"}:
//           a forfeit names the seat that left for good ("player", 0 or 1)
//           and the other ("winner"); an abandoned game (both left) has
//           player and winner -1; "text" says it in words
//   NOISE   {"phi", "theta", "speed", "a", "b"}: the noise model of a seat's
//           shots (seat order, as "players"), in noise.hpp's units
//   STATE   {"game", "phase", "player", "breaker", "ball_in_hand", "kitchen_shot", "group": [2],
//            "fouls_in_a_row": [2], "push_out_allowed", "after_push_out",
//            "scratch_on_break", "winner", "result", "shots", "innings",
//            "rack_seed": "DECIMAL", "racks", "position": [[x, y] by ball number],
//            "on_table": [0 or 1 by ball number],
//            snooker only: "snooker": {"score": [2], "break", "colour_on", "free_ball",
//            "respotted_black", "misses", "replace": null | {"position", "on_table",
//            "colour_on", "free_ball"}},
//            three-cushion only: "carom": {"score": [2], "run", "innings": [2],
//            "equalizing"}}
//   action  {"type": "place_cue_ball", "position": [x, y]}
//           {"type": "shoot", "strike": STRIKE, "call": null | {"ball", "pocket"},
//            "safety", "push_out", snooker only, when the shot nominates: "nominate",
//            three-cushion only, when the shot names its ball: "cue_ball"}
//           {"type": "decide", "choice"}
//   STRIKE  {"speed", "phi", "theta", "a", "b"}; "intended" is a STRIKE or null
//   ruling  {"fouls": [names], "legal_break", "turn_continues", "assigned",
//            "spotted": [ball numbers], "winner", "text", "call_made",
//            a snooker shot's only: "snooker": {"points", "penalty", "miss",
//            "free_ball", "nominated"},
//            a three-cushion shot's only: "carom": {"point", "cue_ball", "hit": [balls],
//            "cushions", "kiss"}}
//
// The config and the NOISE, STATE, action, STRIKE and ruling objects are
// the one JSON of those types (io/game_json.hpp), which the web facade
// uses too. Every field is always written (null for an empty optional)
// and always required on reading, so a record cannot lose a field without
// notice; snooker's fields exist in snooker records only and
// three-cushion's in three-cushion records only, so the other games'
// records keep their bytes.
// Enum values are the names of game.hpp's to_string. Seeds are decimal
// strings (64-bit integers do not survive readers that keep numbers in
// doubles). Doubles are printed by nlohmann::json in a form that reads
// back to the same bits, so write(read(write(r))) == write(r) byte for
// byte.
//
// The reader is io/json_read.hpp's, as the scenario reader's: the first
// problem stops the read and is reported with its JSON path; unknown and
// repeated keys are errors, because a record that reads "almost" right
// would replay as a different game.
//
// replay() lives here too: it names what differs by its path in this
// format, found by comparing the JSON of the recorded and the replayed
// values. It compares rulings and states, not their words (a ruling's
// "text", a state's "result"): those read better from one version to the
// next, and records written before still replay.

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <exception>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/record_io.hpp"
#include "breakshot/session.hpp"
#include "breakshot/version.hpp"
#include "io/game_json.hpp"
#include "io/json_read.hpp"

namespace breakshot {

namespace {

using json_io::action_json;
using json_io::config_json;
using json_io::index_path;
using json_io::json;
using json_io::kDocumentPath;
using json_io::member_path;
using json_io::noise_json;
using json_io::physics_json;
using json_io::ojson;
using json_io::ruling_json;
using json_io::seed_json;
using json_io::state_json;
using json_io::strike_json;

// ---------------------------------------------------------------------------
// Writing

ojson recorded_action_json(const RecordedAction& ra) {
  ojson j = ojson::object();
  j["player"] = ra.player;
  j["action"] = action_json(ra.action);
  j["intended"] = ra.intended ? strike_json(*ra.intended) : ojson(nullptr);
  j["noise_seed"] = seed_json(ra.noise_seed);
  j["ruling"] = ruling_json(ra.ruling);
  j["after"] = state_json(ra.after);
  return j;
}

ojson record_ending_json(const GameEnding& e) {
  ojson j = ojson::object();
  j["kind"] = std::string(to_string(e.kind));
  j["player"] = e.player;
  j["winner"] = e.winner;
  j["text"] = e.text;
  return j;
}

/// Path of the first infinity or NaN in `j`: JSON has no such numbers
/// (nlohmann would write null, which reads back as a type error).
std::optional<std::string> non_finite(const ojson& j, const std::string& path) {
  if (j.is_number_float()) {
    if (std::isfinite(j.get<double>())) return std::nullopt;
    return path.empty() ? std::string(kDocumentPath) : path;
  }
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      if (auto p = non_finite(value, member_path(path, key))) return p;
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      if (auto p = non_finite(j[i], index_path(path, i))) return p;
    }
  }
  return std::nullopt;
}

std::string dump_compact(const ojson& j) {
  try {
    return j.dump();
  } catch (const ojson::type_error&) {
    // The only type error dump() raises: a string that is not UTF-8.
    throw std::invalid_argument("record: a name or text is not valid UTF-8");
  }
}

// ---------------------------------------------------------------------------
// Reading

struct EndingProblem {
  std::string_view field;
  std::string reason;
};

/// What is wrong with an ending whose fields each have a valid value, if
/// anything: the seats and the winner must agree with its kind.
std::optional<EndingProblem> ending_problem(const GameEnding& e) {
  if (e.kind == GameEnding::Kind::forfeit) {
    if (e.player != 0 && e.player != 1) {
      return EndingProblem{
          "player", "a forfeit names the seat that left (0 or 1), not " + std::to_string(e.player)};
    }
    if (e.winner != 1 - e.player) {
      return EndingProblem{"winner", "the winner of a forfeit is the other seat (" +
                                         std::to_string(1 - e.player) + "), not " +
                                         std::to_string(e.winner)};
    }
  } else {
    if (e.player != -1) return EndingProblem{"player", "an abandoned game names no seat (-1)"};
    if (e.winner != -1) return EndingProblem{"winner", "an abandoned game has no winner (-1)"};
  }
  if (e.text.empty()) return EndingProblem{"text", "expected the ending in words, not \"\""};
  return std::nullopt;
}

/// The library version that wrote every version 1 record.
constexpr std::string_view kVersion1Engine = "0.1.0";

/// The numbers of a version "MAJOR.MINOR.PATCH..." (digits and dots
/// only); empty if it is not of that form.
std::vector<long long> version_numbers(std::string_view v) {
  std::vector<long long> out;
  long long n = 0;
  bool digits = false;
  for (const char ch : v) {
    if (ch >= '0' && ch <= '9') {
      if (n > (LLONG_MAX - 9) / 10) return {};
      n = n * 10 + (ch - '0');
      digits = true;
    } else if (ch == '.' && digits) {
      out.push_back(n);
      n = 0;
      digits = false;
    } else {
      return {};
    }
  }
  if (!digits) return {};
  out.push_back(n);
  return out;
}

/// Whether `engine` is a version after this build's kVersion.
bool newer_engine(std::string_view engine) {
  const std::vector<long long> a = version_numbers(engine);
  const std::vector<long long> b = version_numbers(kVersion);
  return !a.empty() && !b.empty() && a > b;
}

/// Builds a GameRecord from a parsed document. Every function returns
/// false after recording the first problem in `error`.
class RecordReader : public json_io::GameReader {
 public:
  bool read(const json& doc, GameRecord& r);

 private:
  bool recorded_action(const json& v, const std::string& path, RecordedAction& ra);
  bool ending(const json& v, const std::string& path, GameEnding& e);
};

bool RecordReader::read(const json& doc, GameRecord& r) {
  if (!require_object(doc, "")) return false;
  const json* format = nullptr;
  const json* version_field = nullptr;
  if (!required(doc, "", "format", format)) return false;
  if (!format->is_string() || format->get<std::string>() != GameRecord::kFormat) {
    return fail("format", "expected \"" + std::string(GameRecord::kFormat) + "\", not " +
                              format->dump());
  }
  if (!required(doc, "", "version", version_field)) return false;
  int version = 0;
  if (!integer(*version_field, "version", INT_MIN, INT_MAX, version)) return false;
  if (version < 1 || version > GameRecord::kVersion) {
    std::string maker;
    if (const json* e = find(doc, "engine"); e != nullptr && e->is_object()) {
      if (const json* v = find(*e, "version"); v != nullptr && v->is_string()) {
        const std::string engine = v->get<std::string>();
        maker = " (made by breakshot " + engine + (newer_engine(engine) ? ", a newer version" : "") +
                ")";
      }
    }
    return fail("version", "this breakshot (" + std::string(kVersion) +
                               ") reads records of versions 1 to " +
                               std::to_string(GameRecord::kVersion) + ", not version " +
                               std::to_string(version) + maker);
  }
  if (version == 1) {
    // Before the engine and the physics were recorded: every version 1
    // record was written by breakshot 0.1.0 and played with the physics
    // of that time, by its names kLegacyGamePhysics.
    if (!exact_object(doc, "",
                      {"format", "version", "config", "players", "seed", "noise", "start",
                       "actions"})) {
      return false;
    }
    r.engine = std::string(kVersion1Engine);
    r.version = 1;
    if (!config(doc["config"], "config", r.config)) return false;
    r.config.physics = kLegacyGamePhysics;
  } else {
    if (version == 2 && !exact_object(doc, "",
                                      {"format", "version", "engine", "config", "physics",
                                       "players", "seed", "noise", "start", "actions"})) {
      return false;
    }
    if (version == 3 && !exact_object(doc, "",
                                      {"format", "version", "engine", "config", "physics",
                                       "players", "seed", "noise", "start", "actions", "ending"})) {
      return false;
    }
    const json& engine = doc["engine"];
    if (!exact_object(engine, "engine", {"version"}) ||
        !text(engine["version"], "engine.version", r.engine)) {
      return false;
    }
    if (r.engine.empty()) return fail("engine.version", "expected a library version, not \"\"");
    r.version = version;
    if (!config(doc["config"], "config", r.config)) return false;
    if (!physics(doc["physics"], "physics", r.config.physics)) {
      // A name or a field this build does not have: say who made the
      // record, so that the reader knows which breakshot replays it.
      error->reason += "; this breakshot (" + std::string(kVersion) +
                       ") cannot replay this version " + std::to_string(version) +
                       " record made by breakshot " + r.engine +
                       (newer_engine(r.engine) ? ", a newer version" : "");
      return false;
    }
  }
  const json& players = doc["players"];
  if (!array(players, "players", 2)) return false;
  for (std::size_t i = 0; i < 2; ++i) {
    if (!text(players[i], index_path("players", i), r.players[i])) return false;
  }
  if (!seed(doc["seed"], "seed", r.seed)) return false;
  const json& noise_models = doc["noise"];
  if (!array(noise_models, "noise", 2)) return false;
  for (std::size_t i = 0; i < 2; ++i) {
    if (!noise(noise_models[i], index_path("noise", i), r.noise[i])) return false;
  }
  if (!state(doc["start"], "start", r.start)) return false;
  const json& actions = doc["actions"];
  if (!array(actions, "actions")) return false;
  r.actions.resize(actions.size());
  for (std::size_t i = 0; i < actions.size(); ++i) {
    if (!recorded_action(actions[i], index_path("actions", i), r.actions[i])) return false;
  }
  if (version >= 3) {
    GameEnding e;
    if (!ending(doc["ending"], "ending", e)) return false;
    r.ending = std::move(e);
  }
  return true;
}

bool RecordReader::ending(const json& v, const std::string& path, GameEnding& e) {
  if (!exact_object(v, path, {"kind", "player", "winner", "text"})) return false;
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  std::string kind;
  if (!text(v["kind"], at("kind"), kind)) return false;
  const std::optional<GameEnding::Kind> k = parse_ending_kind(kind);
  if (!k) return fail(at("kind"), "expected \"forfeit\" or \"abandoned\", not \"" + kind + "\"");
  e.kind = *k;
  if (!integer(v["player"], at("player"), -1, 1, e.player) ||
      !integer(v["winner"], at("winner"), -1, 1, e.winner) ||
      !text(v["text"], at("text"), e.text)) {
    return false;
  }
  if (auto bad = ending_problem(e)) return fail(at(bad->field), bad->reason);
  return true;
}

bool RecordReader::recorded_action(const json& v, const std::string& path, RecordedAction& ra) {
  if (!exact_object(v, path, {"player", "action", "intended", "noise_seed", "ruling", "after"})) {
    return false;
  }
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  if (!integer(v["player"], at("player"), 0, 1, ra.player) ||
      !action(v["action"], at("action"), ra.action)) {
    return false;
  }
  const json& intended = v["intended"];
  if (!intended.is_null()) {
    // Only a shot has a strike to perturb; an intended strike anywhere
    // else means the record was put together wrongly.
    if (!std::holds_alternative<Shoot>(ra.action)) {
      return fail(at("intended"), "only a shot has an intended strike (null here)");
    }
    CueStrike s;
    if (!strike(intended, at("intended"), s)) return false;
    ra.intended = s;
  }
  return seed(v["noise_seed"], at("noise_seed"), ra.noise_seed) &&
         ruling(v["ruling"], at("ruling"), ra.ruling) && state(v["after"], at("after"), ra.after);
}

// ---------------------------------------------------------------------------
// Replay: naming the first difference

std::string shorten(std::string s) {
  constexpr std::size_t kMax = 300;
  if (s.size() > kMax) {
    s.resize(kMax);
    s += "...";
  }
  return s;
}

struct Difference {
  std::string path;
  std::string recorded;
  std::string replayed;
};

/// The first place where two documents of the same shape differ, in
/// document order.
std::optional<Difference> first_difference(const ojson& recorded, const ojson& replayed,
                                           const std::string& path) {
  if (recorded.is_object() && replayed.is_object()) {
    for (const auto& [key, value] : recorded.items()) {
      const auto it = replayed.find(key);
      if (it == replayed.end()) {
        return Difference{member_path(path, key), shorten(value.dump()), "(absent)"};
      }
      if (auto d = first_difference(value, *it, member_path(path, key))) return d;
    }
    return std::nullopt;
  }
  if (recorded.is_array() && replayed.is_array()) {
    const std::size_t n = std::min(recorded.size(), replayed.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (auto d = first_difference(recorded[i], replayed[i], index_path(path, i))) return d;
    }
    if (recorded.size() == replayed.size()) return std::nullopt;
    return Difference{path, shorten(recorded.dump()), shorten(replayed.dump())};
  }
  // Doubles are compared by their text: the text is exact, and it tells
  // -0 from +0 where == does not.
  const std::string a = recorded.dump();
  const std::string b = replayed.dump();
  if (a == b) return std::nullopt;
  return Difference{path, shorten(a), shorten(b)};
}

/// The difference between the recorded and the replayed value, which
/// are known to differ. Their JSON may still be the same text (a value
/// JSON cannot show, which the writer would have refused): then the
/// path of the whole value is named.
Difference difference(const ojson& recorded, const ojson& replayed, const std::string& path) {
  if (auto d = first_difference(recorded, replayed, path)) return *d;
  return Difference{path, shorten(recorded.dump()), "(differs in a way JSON does not show)"};
}

/// A ruling and a state as replay compares them: without their words
/// (Ruling::text, GameState::result), which may be put better from one
/// version to the next; records written before keep replaying.
Ruling without_words(Ruling r) {
  r.text.clear();
  return r;
}
GameState without_words(GameState s) {
  s.result.clear();
  return s;
}

std::string_view action_name(const Action& a) {
  if (std::holds_alternative<PlaceCueBall>(a)) return "place_cue_ball";
  if (std::holds_alternative<Shoot>(a)) return "shoot";
  return "decide";
}

/// Who made a record, for a replay that differs: its format version and
/// engine, and when the engine is not this build, that it is another
/// engine (whose physics may differ under the same names): a record that
/// does not replay never ends in a plain "differs".
std::string record_maker(const GameRecord& record) {
  std::string s = " (a version " + std::to_string(record.version) + " record made by breakshot " +
                  record.engine;
  if (record.engine != kVersion) {
    s += "; this is breakshot " + std::string(kVersion) +
         ", another engine, whose physics may differ under the same names";
  }
  return s + ")";
}

void report_difference(ReplayReport& rep, Difference d, std::string context,
                       const GameRecord& record) {
  rep.identical = false;
  rep.where = std::move(d.path);
  rep.recorded = std::move(d.recorded);
  rep.replayed = std::move(d.replayed);
  rep.message = std::move(context) + ": " + rep.where + ": recorded " + rep.recorded +
                ", replayed " + rep.replayed + record_maker(record);
}

}  // namespace

std::string write_record(const GameRecord& record) {
  // The parts are built as JSON trees and dumped compact, each action on
  // a line of its own: a game is a few hundred actions, and one per line
  // keeps the file readable and greppable without the four lines per
  // ball position that a fully indented dump would take.
  struct Part {
    std::string_view key;
    ojson value;
  };
  const Part head[] = {
      {"format", GameRecord::kFormat},
      {"version", record.ending ? GameRecord::kVersion : GameRecord::kVersionWithoutEnding},
      {"engine", ojson::object({{"version", record.engine}})},
      {"config", config_json(record.config)},
      {"physics", physics_json(record.config.physics)},
      {"players", ojson::array({record.players[0], record.players[1]})},
      {"seed", seed_json(record.seed)},
      {"noise", ojson::array({noise_json(record.noise[0]), noise_json(record.noise[1])})},
      {"start", state_json(record.start)},
  };
  std::string out = "{\n";
  for (const Part& p : head) {
    if (auto bad = non_finite(p.value, std::string(p.key))) {
      throw std::invalid_argument("record: " + *bad + " is not a finite number");
    }
    out += "  ";
    out += dump_compact(p.key);
    out += ": ";
    out += dump_compact(p.value);
    out += ",\n";
  }
  out += "  \"actions\": [";
  for (std::size_t i = 0; i < record.actions.size(); ++i) {
    const ojson a = recorded_action_json(record.actions[i]);
    if (auto bad = non_finite(a, index_path("actions", i))) {
      throw std::invalid_argument("record: " + *bad + " is not a finite number");
    }
    out += i == 0 ? "\n    " : ",\n    ";
    out += dump_compact(a);
  }
  out += record.actions.empty() ? "]" : "\n  ]";
  if (record.ending) {
    const GameEnding& e = *record.ending;
    if (auto bad = ending_problem(e)) {
      throw std::invalid_argument("record: ending." + std::string(bad->field) + ": " + bad->reason);
    }
    out += ",\n  \"ending\": ";
    out += dump_compact(record_ending_json(e));
  }
  out += "\n}\n";
  return out;
}

std::variant<GameRecord, RecordError> read_record(std::string_view json_text) {
  try {
    json doc;
    if (auto problem = json_io::parse_strict(json_text, doc)) {
      return RecordError{std::move(problem->error.path), std::move(problem->error.reason)};
    }
    GameRecord record;
    RecordReader reader;
    if (!reader.read(doc, record)) return RecordError{reader.error->path, reader.error->reason};
    return record;
  } catch (const std::bad_alloc&) {
    return RecordError{kDocumentPath, "out of memory while reading the record"};
  } catch (const std::exception& e) {
    // Not expected: every check reports instead of throwing. Kept so that
    // a bug here is a message, never a crash.
    return RecordError{kDocumentPath, std::string("internal error: ") + e.what()};
  }
}

ReplayReport replay(const GameRecord& record) {
  ReplayReport rep;
  rep.final_state = record.start;
  std::optional<GameSession> session;
  try {
    (void)Rules(record.config);
  } catch (const std::exception& e) {
    rep.where = "config";
    rep.recorded = shorten(config_json(record.config).dump());
    rep.replayed = e.what();
    rep.message = std::string("the rules cannot be built from the config: ") + e.what() +
                  record_maker(record);
    return rep;
  }
  try {
    session.emplace(record.config, Seats{record.players, record.noise}, record.seed,
                    record.start.rack_seed, record.start.breaker);
  } catch (const std::exception& e) {
    rep.where = "start";
    rep.recorded = shorten(state_json(record.start).dump());
    rep.replayed = e.what();
    rep.message = std::string("the start cannot be set up: ") + e.what() + record_maker(record);
    return rep;
  }
  if (!identical(session->state(), record.start)) {
    report_difference(rep,
                      difference(state_json(record.start), state_json(session->state()), "start"),
                      "the start differs from Rules::start", record);
    rep.final_state = session->state();
    return rep;
  }
  rep.final_state = session->state();

  for (std::size_t i = 0; i < record.actions.size(); ++i) {
    const RecordedAction& ra = record.actions[i];
    const GameState& state = session->state();
    const std::string path = index_path("actions", i);
    const std::string context = "action " + std::to_string(i) + " (player " +
                                std::to_string(ra.player) + ", " +
                                std::string(action_name(ra.action)) + ") differs";
    rep.action = i;
    if (ra.player != state.player) {
      report_difference(
          rep,
          {member_path(path, "player"), std::to_string(ra.player), std::to_string(state.player)},
          context, record);
      return rep;
    }
    if (const auto* shoot = std::get_if<Shoot>(&ra.action); shoot != nullptr && ra.intended) {
      CueStrike executed;
      try {
        executed = session->executed(*ra.intended, ra.player, ra.noise_seed);
      } catch (const std::exception& e) {
        report_difference(rep,
                          {member_path(path, "intended"), shorten(strike_json(*ra.intended).dump()),
                           std::string("(noise cannot be applied: ") + e.what() + ")"},
                          context, record);
        return rep;
      }
      if (!identical(executed, shoot->strike)) {
        report_difference(rep,
                          difference(strike_json(shoot->strike), strike_json(executed),
                                     member_path(member_path(path, "action"), "strike")),
                          context +
                              ": the executed strike is not the intended one with the "
                              "recorded noise of its seat (noise[" +
                              std::to_string(ra.player) + "])",
                          record);
        return rep;
      }
    } else if (shoot == nullptr && ra.intended) {
      report_difference(rep,
                        {member_path(path, "intended"), shorten(strike_json(*ra.intended).dump()),
                         "null (not a shot)"},
                        context, record);
      return rep;
    }

    Outcome out;
    try {
      out = session->play_executed(ra.action, ra.intended, ra.noise_seed);
    } catch (const std::invalid_argument& e) {
      report_difference(rep,
                        {member_path(path, "action"), shorten(action_json(ra.action).dump()),
                         std::string("(not allowed: ") + e.what() + ")"},
                        context, record);
      return rep;
    } catch (const std::exception& e) {
      // Allowed, but the rules could not play it (a shot that never came
      // to rest, say): the recorded game cannot have gone this way.
      report_difference(rep,
                        {member_path(path, "action"), shorten(action_json(ra.action).dump()),
                         std::string("(cannot be played: ") + e.what() + ")"},
                        context, record);
      return rep;
    }
    const Ruling ruled = without_words(out.ruling);
    const Ruling recorded_ruling = without_words(ra.ruling);
    if (!(ruled == recorded_ruling)) {
      report_difference(rep, difference(ruling_json(recorded_ruling), ruling_json(ruled),
                                        member_path(path, "ruling")),
                        context, record);
      return rep;
    }
    const GameState after = without_words(out.state);
    const GameState recorded_after = without_words(ra.after);
    if (!identical(after, recorded_after)) {
      report_difference(rep, difference(state_json(recorded_after), state_json(after),
                                        member_path(path, "after")),
                        context, record);
      return rep;
    }
    rep.final_state = session->state();
    rep.actions_identical = i + 1;
  }
  if (record.ending && rep.final_state.phase == Phase::game_over) {
    // A forfeit ends a game the rules had not ended.
    rep.action.reset();
    report_difference(rep,
                      {"ending", shorten(record_ending_json(*record.ending).dump()),
                       "(the rules ended the game first: " + rep.final_state.result + ")"},
                      "the ending differs", record);
    return rep;
  }
  rep.action.reset();
  rep.identical = true;
  rep.message = "identical";
  return rep;
}

}  // namespace breakshot
