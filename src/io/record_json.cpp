// Game records (include/breakshot/record.hpp): writing, reading and
// replaying them.
//
// The file, version 1:
//
//   {
//     "format": "breakshot-game-record",
//     "version": 1,
//     "config": {"game", "table_size", "ball_radius", "ball_mass", "max_shots"},
//     "players": [NAME, NAME],
//     "seed": "DECIMAL",
//     "noise": [NOISE, NOISE],
//     "start": STATE,
//     "actions": [
//       {"player", "action", "intended", "noise_seed", "ruling", "after": STATE},
//       ...one action per line
//     ]
//   }
//
//   NOISE   {"phi", "theta", "speed", "a", "b"}: the noise model of a seat's
//           shots (seat order, as "players"), in noise.hpp's units
//   STATE   {"game", "phase", "player", "breaker", "ball_in_hand", "kitchen_shot", "group": [2],
//            "fouls_in_a_row": [2], "push_out_allowed", "after_push_out",
//            "scratch_on_break", "winner", "result", "shots", "innings",
//            "rack_seed": "DECIMAL", "racks", "position": [[x, y] by ball number],
//            "on_table": [0 or 1 by ball number]}
//   action  {"type": "place_cue_ball", "position": [x, y]}
//           {"type": "shoot", "strike": STRIKE, "call": null | {"ball", "pocket"},
//            "safety", "push_out"}
//           {"type": "decide", "choice"}
//   STRIKE  {"speed", "phi", "theta", "a", "b"}; "intended" is a STRIKE or null
//   ruling  {"fouls": [names], "legal_break", "turn_continues", "assigned",
//            "spotted": [ball numbers], "winner", "text", "call_made"}
//
// Every field is always written (null for an empty optional) and always
// required on reading, so a record cannot lose a field without notice.
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
// values.

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

#include "breakshot/record.hpp"
#include "io/json_read.hpp"

namespace breakshot {

namespace {

using json_io::expected;
using json_io::index_path;
using json_io::json;
using json_io::kDocumentPath;
using json_io::member_path;
// Written documents keep their keys in the order they are added.
using ojson = nlohmann::ordered_json;

// Every value of each enum, for the messages that list them.
constexpr GameType kGameTypes[] = {GameType::eight_ball, GameType::nine_ball};
constexpr Phase kPhases[] = {Phase::break_shot,           Phase::shot,
                             Phase::push_out_choice,      Phase::illegal_break_choice,
                             Phase::eight_on_break_choice, Phase::game_over};
constexpr BallInHand kBallInHand[] = {BallInHand::none, BallInHand::kitchen,
                                      BallInHand::anywhere};
constexpr Group kGroups[] = {Group::none, Group::solids, Group::stripes};
constexpr Choice kChoices[] = {Choice::shoot,
                               Choice::pass_back,
                               Choice::accept_table,
                               Choice::rerack_and_break,
                               Choice::rerack_opponent_breaks,
                               Choice::respot_eight};
constexpr Foul kFouls[] = {Foul::scratch,      Foul::no_contact,    Foul::wrong_ball_first,
                           Foul::no_rail,      Foul::illegal_break, Foul::behind_head_string};

// ---------------------------------------------------------------------------
// Writing

ojson seed_json(std::uint64_t s) { return std::to_string(s); }

ojson vec2_json(Vec2 v) { return ojson::array({v.x, v.y}); }

ojson strike_json(const CueStrike& s) {
  const auto& [speed, phi, theta, a, b] = s;
  ojson j = ojson::object();
  j["speed"] = speed;
  j["phi"] = phi;
  j["theta"] = theta;
  j["a"] = a;
  j["b"] = b;
  return j;
}

ojson config_json(const GameConfig& c) {
  const auto& [game, table_size, ball_radius, ball_mass, max_shots] = c;
  ojson j = ojson::object();
  j["game"] = to_string(game);
  j["table_size"] = table_size;
  j["ball_radius"] = ball_radius;
  j["ball_mass"] = ball_mass;
  j["max_shots"] = max_shots;
  return j;
}

ojson noise_json(const NoiseModel& n) {
  const auto& [phi, theta, speed, a, b] = n;
  ojson j = ojson::object();
  j["phi"] = phi;
  j["theta"] = theta;
  j["speed"] = speed;
  j["a"] = a;
  j["b"] = b;
  return j;
}

ojson state_json(const GameState& s) {
  // Structured bindings name every member: when GameState gains or loses
  // one, this stops compiling instead of writing records that miss it.
  const auto& [game, position, on_table, phase, player, breaker, ball_in_hand, kitchen_shot,
               group, fouls_in_a_row, push_out_allowed, after_push_out, scratch_on_break,
               winner, result, shots, innings, rack_seed, racks] = s;
  ojson j = ojson::object();
  j["game"] = to_string(game);
  j["phase"] = to_string(phase);
  j["player"] = player;
  j["breaker"] = breaker;
  j["ball_in_hand"] = to_string(ball_in_hand);
  j["kitchen_shot"] = kitchen_shot;
  j["group"] = ojson::array({to_string(group[0]), to_string(group[1])});
  j["fouls_in_a_row"] = ojson::array({fouls_in_a_row[0], fouls_in_a_row[1]});
  j["push_out_allowed"] = push_out_allowed;
  j["after_push_out"] = after_push_out;
  j["scratch_on_break"] = scratch_on_break;
  j["winner"] = winner;
  j["result"] = result;
  j["shots"] = shots;
  j["innings"] = innings;
  j["rack_seed"] = seed_json(rack_seed);
  j["racks"] = racks;
  ojson pos = ojson::array();
  for (const Vec2& p : position) pos.push_back(vec2_json(p));
  j["position"] = std::move(pos);
  ojson on = ojson::array();
  for (const std::uint8_t b : on_table) on.push_back(static_cast<int>(b));
  j["on_table"] = std::move(on);
  return j;
}

ojson ruling_json(const Ruling& r) {
  const auto& [fouls, legal_break, turn_continues, assigned, spotted, winner, text, call_made] = r;
  ojson j = ojson::object();
  ojson names = ojson::array();
  for (const Foul f : fouls) names.push_back(to_string(f));
  j["fouls"] = std::move(names);
  j["legal_break"] = legal_break;
  j["turn_continues"] = turn_continues;
  j["assigned"] = to_string(assigned);
  j["spotted"] = spotted;
  j["winner"] = winner;
  j["text"] = text;
  j["call_made"] = call_made;
  return j;
}

ojson action_json(const Action& a) {
  ojson j = ojson::object();
  if (const auto* place = std::get_if<PlaceCueBall>(&a)) {
    j["type"] = "place_cue_ball";
    j["position"] = vec2_json(place->position);
  } else if (const auto* shoot = std::get_if<Shoot>(&a)) {
    const auto& [strike, call, safety, push_out] = *shoot;
    j["type"] = "shoot";
    j["strike"] = strike_json(strike);
    if (call) {
      const auto& [ball, pocket] = *call;
      j["call"] = ojson::object();
      j["call"]["ball"] = ball;
      j["call"]["pocket"] = pocket;
    } else {
      j["call"] = nullptr;
    }
    j["safety"] = safety;
    j["push_out"] = push_out;
  } else {
    j["type"] = "decide";
    j["choice"] = to_string(std::get<Decide>(a).choice);
  }
  return j;
}

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

/// Builds a GameRecord from a parsed document. Every function returns
/// false after recording the first problem in `error`.
class RecordReader : public json_io::Reader {
 public:
  bool read(const json& doc, GameRecord& r);

 private:
  bool non_negative(const json& v, const std::string& path, double& out) {
    return number(v, path, out) && Reader::non_negative(out, path);
  }

  bool positive(const json& v, const std::string& path, double& out) {
    return number(v, path, out) && Reader::positive(out, path);
  }

  bool config(const json& v, const std::string& path, GameConfig& c);
  bool noise(const json& v, const std::string& path, NoiseModel& n);
  bool strike(const json& v, const std::string& path, CueStrike& s);
  bool state(const json& v, const std::string& path, GameState& s);
  bool ruling(const json& v, const std::string& path, Ruling& r);
  bool action(const json& v, const std::string& path, Action& a);
  bool recorded_action(const json& v, const std::string& path, RecordedAction& ra);
};

bool RecordReader::read(const json& doc, GameRecord& r) {
  if (!exact_object(doc, "",
              {"format", "version", "config", "players", "seed", "noise", "start", "actions"})) {
    return false;
  }
  const json& format = doc["format"];
  if (!format.is_string() || format.get<std::string>() != GameRecord::kFormat) {
    return fail("format", "expected \"" + std::string(GameRecord::kFormat) + "\", not " +
                              format.dump());
  }
  int version = 0;
  if (!integer(doc["version"], "version", INT_MIN, INT_MAX, version)) return false;
  if (version != GameRecord::kVersion) {
    return fail("version", "this breakshot reads version " +
                               std::to_string(GameRecord::kVersion) + " records, not version " +
                               std::to_string(version));
  }
  if (!config(doc["config"], "config", r.config)) return false;
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
  return true;
}

bool RecordReader::config(const json& v, const std::string& path, GameConfig& c) {
  if (!exact_object(v, path, {"game", "table_size", "ball_radius", "ball_mass", "max_shots"})) {
    return false;
  }
  if (!name(v["game"], member_path(path, "game"), "game", parse_game_type, kGameTypes, c.game)) return false;
  const std::string size_path = member_path(path, "table_size");
  if (!text_of(v["table_size"], size_path, "table size", {"7ft", "8ft", "9ft"}, c.table_size)) {
    return false;
  }
  return positive(v["ball_radius"], member_path(path, "ball_radius"), c.ball_radius) &&
         positive(v["ball_mass"], member_path(path, "ball_mass"), c.ball_mass) &&
         integer(v["max_shots"], member_path(path, "max_shots"), 0, INT_MAX, c.max_shots);
}

bool RecordReader::noise(const json& v, const std::string& path, NoiseModel& n) {
  if (!exact_object(v, path, {"phi", "theta", "speed", "a", "b"})) return false;
  return non_negative(v["phi"], member_path(path, "phi"), n.phi) &&
         non_negative(v["theta"], member_path(path, "theta"), n.theta) &&
         non_negative(v["speed"], member_path(path, "speed"), n.speed) &&
         non_negative(v["a"], member_path(path, "a"), n.a) &&
         non_negative(v["b"], member_path(path, "b"), n.b);
}

bool RecordReader::strike(const json& v, const std::string& path, CueStrike& s) {
  if (!exact_object(v, path, {"speed", "phi", "theta", "a", "b"})) return false;
  return number(v["speed"], member_path(path, "speed"), s.speed) &&
         number(v["phi"], member_path(path, "phi"), s.phi) &&
         number(v["theta"], member_path(path, "theta"), s.theta) &&
         number(v["a"], member_path(path, "a"), s.a) &&
         number(v["b"], member_path(path, "b"), s.b);
}

bool RecordReader::state(const json& v, const std::string& path, GameState& s) {
  if (!exact_object(v, path,
              {"game", "phase", "player", "breaker", "ball_in_hand", "kitchen_shot", "group",
               "fouls_in_a_row",
               "push_out_allowed", "after_push_out", "scratch_on_break", "winner", "result",
               "shots", "innings", "rack_seed", "racks", "position", "on_table"})) {
    return false;
  }
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  if (!name(v["game"], at("game"), "game", parse_game_type, kGameTypes, s.game) ||
      !name(v["phase"], at("phase"), "phase", parse_phase, kPhases, s.phase) ||
      !integer(v["player"], at("player"), 0, 1, s.player) ||
      !integer(v["breaker"], at("breaker"), 0, 1, s.breaker) ||
      !name(v["ball_in_hand"], at("ball_in_hand"), "ball_in_hand", parse_ball_in_hand,
            kBallInHand, s.ball_in_hand) ||
      !boolean(v["kitchen_shot"], at("kitchen_shot"), s.kitchen_shot)) {
    return false;
  }
  const json& group = v["group"];
  const json& fouls = v["fouls_in_a_row"];
  if (!array(group, at("group"), 2) || !array(fouls, at("fouls_in_a_row"), 2)) return false;
  for (std::size_t i = 0; i < 2; ++i) {
    if (!name(group[i], index_path(at("group"), i), "group", parse_group, kGroups, s.group[i]) ||
        !integer(fouls[i], index_path(at("fouls_in_a_row"), i), 0, INT_MAX,
                 s.fouls_in_a_row[i])) {
      return false;
    }
  }
  if (!boolean(v["push_out_allowed"], at("push_out_allowed"), s.push_out_allowed) ||
      !boolean(v["after_push_out"], at("after_push_out"), s.after_push_out) ||
      !boolean(v["scratch_on_break"], at("scratch_on_break"), s.scratch_on_break) ||
      !integer(v["winner"], at("winner"), -1, 1, s.winner) ||
      !text(v["result"], at("result"), s.result) ||
      !integer(v["shots"], at("shots"), 0, INT_MAX, s.shots) ||
      !integer(v["innings"], at("innings"), 0, INT_MAX, s.innings) ||
      !seed(v["rack_seed"], at("rack_seed"), s.rack_seed) ||
      !integer(v["racks"], at("racks"), 0, INT_MAX, s.racks)) {
    return false;
  }
  const json& position = v["position"];
  if (!array(position, at("position"))) return false;
  s.position.resize(position.size());
  for (std::size_t i = 0; i < position.size(); ++i) {
    if (!vec2(position[i], index_path(at("position"), i), s.position[i])) return false;
  }
  const json& on_table = v["on_table"];
  if (!array(on_table, at("on_table"))) return false;
  if (on_table.size() != position.size()) {
    return fail(at("on_table"), "has " + std::to_string(on_table.size()) +
                                    " entries but position has " +
                                    std::to_string(position.size()) + " (one per ball)");
  }
  s.on_table.resize(on_table.size());
  for (std::size_t i = 0; i < on_table.size(); ++i) {
    int flag = 0;
    if (!integer(on_table[i], index_path(at("on_table"), i), 0, 1, flag)) return false;
    s.on_table[i] = static_cast<std::uint8_t>(flag);
  }
  return true;
}

bool RecordReader::ruling(const json& v, const std::string& path, Ruling& r) {
  if (!exact_object(v, path,
              {"fouls", "legal_break", "turn_continues", "assigned", "spotted", "winner",
               "text", "call_made"})) {
    return false;
  }
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  const json& fouls = v["fouls"];
  if (!array(fouls, at("fouls"))) return false;
  r.fouls.resize(fouls.size());
  for (std::size_t i = 0; i < fouls.size(); ++i) {
    if (!name(fouls[i], index_path(at("fouls"), i), "foul", parse_foul, kFouls, r.fouls[i])) {
      return false;
    }
  }
  if (!boolean(v["legal_break"], at("legal_break"), r.legal_break) ||
      !boolean(v["turn_continues"], at("turn_continues"), r.turn_continues) ||
      !name(v["assigned"], at("assigned"), "group", parse_group, kGroups, r.assigned)) {
    return false;
  }
  const json& spotted = v["spotted"];
  if (!array(spotted, at("spotted"))) return false;
  r.spotted.resize(spotted.size());
  for (std::size_t i = 0; i < spotted.size(); ++i) {
    if (!integer(spotted[i], index_path(at("spotted"), i), 0, 15, r.spotted[i])) return false;
  }
  return integer(v["winner"], at("winner"), -1, 1, r.winner) &&
         text(v["text"], at("text"), r.text) &&
         boolean(v["call_made"], at("call_made"), r.call_made);
}

bool RecordReader::action(const json& v, const std::string& path, Action& a) {
  if (!require_object(v, path)) return false;
  const json* type = find(v, "type");
  const std::string type_path = member_path(path, "type");
  if (type == nullptr) return fail(type_path, "missing required field");
  if (!type->is_string()) return fail(type_path, expected("a string", *type));
  const std::string& t = type->get_ref<const std::string&>();
  if (t == "place_cue_ball") {
    PlaceCueBall place;
    if (!exact_object(v, path, {"type", "position"}) ||
        !vec2(v["position"], member_path(path, "position"), place.position)) {
      return false;
    }
    a = place;
    return true;
  }
  if (t == "shoot") {
    Shoot shoot;
    if (!exact_object(v, path, {"type", "strike", "call", "safety", "push_out"}) ||
        !strike(v["strike"], member_path(path, "strike"), shoot.strike)) {
      return false;
    }
    const json& call = v["call"];
    const std::string call_path = member_path(path, "call");
    if (!call.is_null()) {
      Call c;
      if (!exact_object(call, call_path, {"ball", "pocket"}) ||
          !integer(call["ball"], member_path(call_path, "ball"), -1, 15, c.ball) ||
          !integer(call["pocket"], member_path(call_path, "pocket"), -1, 5, c.pocket)) {
        return false;
      }
      shoot.call = c;
    }
    if (!boolean(v["safety"], member_path(path, "safety"), shoot.safety) ||
        !boolean(v["push_out"], member_path(path, "push_out"), shoot.push_out)) {
      return false;
    }
    a = shoot;
    return true;
  }
  if (t == "decide") {
    Decide decide;
    if (!exact_object(v, path, {"type", "choice"}) ||
        !name(v["choice"], member_path(path, "choice"), "choice", parse_choice, kChoices,
               decide.choice)) {
      return false;
    }
    a = decide;
    return true;
  }
  return fail(type_path,
              "unknown action type \"" + t + "\" (place_cue_ball, shoot or decide)");
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

std::string_view action_name(const Action& a) {
  if (std::holds_alternative<PlaceCueBall>(a)) return "place_cue_ball";
  if (std::holds_alternative<Shoot>(a)) return "shoot";
  return "decide";
}

void report_difference(ReplayReport& rep, Difference d, std::string context) {
  rep.identical = false;
  rep.where = std::move(d.path);
  rep.recorded = std::move(d.recorded);
  rep.replayed = std::move(d.replayed);
  rep.message = std::move(context) + ": " + rep.where + ": recorded " + rep.recorded +
                ", replayed " + rep.replayed;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

}  // namespace

bool identical(const CueStrike& a, const CueStrike& b) {
  return same_bits(a.speed, b.speed) && same_bits(a.phi, b.phi) && same_bits(a.theta, b.theta) &&
         same_bits(a.a, b.a) && same_bits(a.b, b.b);
}

bool identical(const Action& a, const Action& b) {
  if (a.index() != b.index()) return false;
  if (const auto* pa = std::get_if<PlaceCueBall>(&a)) {
    const auto& pb = std::get<PlaceCueBall>(b);
    return same_bits(pa->position.x, pb.position.x) && same_bits(pa->position.y, pb.position.y);
  }
  if (const auto* sa = std::get_if<Shoot>(&a)) {
    const auto& sb = std::get<Shoot>(b);
    return identical(sa->strike, sb.strike) && sa->call == sb.call && sa->safety == sb.safety &&
           sa->push_out == sb.push_out;
  }
  return std::get<Decide>(a) == std::get<Decide>(b);
}

namespace {

bool identical_state(const GameState& a, const GameState& b) {
  if (!(a == b)) return false;
  for (std::size_t i = 0; i < a.position.size(); ++i) {
    if (!same_bits(a.position[i].x, b.position[i].x) ||
        !same_bits(a.position[i].y, b.position[i].y)) {
      return false;
    }
  }
  return true;
}

bool identical_config(const GameConfig& a, const GameConfig& b) {
  // GameConfig has no operator==; its JSON names every member, exactly.
  return config_json(a).dump() == config_json(b).dump();
}

bool identical_noise(const NoiseModel& a, const NoiseModel& b) {
  return same_bits(a.phi, b.phi) && same_bits(a.theta, b.theta) && same_bits(a.speed, b.speed) &&
         same_bits(a.a, b.a) && same_bits(a.b, b.b);
}

}  // namespace

bool RecordedAction::operator==(const RecordedAction& o) const {
  const bool intended_same =
      intended.has_value() == o.intended.has_value() && (!intended || identical(*intended, *o.intended));
  return player == o.player && identical(action, o.action) && intended_same &&
         noise_seed == o.noise_seed && ruling == o.ruling && identical_state(after, o.after);
}

bool GameRecord::operator==(const GameRecord& o) const {
  return identical_config(config, o.config) && players == o.players && seed == o.seed &&
         identical_noise(noise[0], o.noise[0]) && identical_noise(noise[1], o.noise[1]) &&
         identical_state(start, o.start) && actions == o.actions;
}

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
      {"version", GameRecord::kVersion},
      {"config", config_json(record.config)},
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
  out += record.actions.empty() ? "]\n}\n" : "\n  ]\n}\n";
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
  std::optional<Rules> rules;
  try {
    rules.emplace(record.config);
  } catch (const std::exception& e) {
    rep.where = "config";
    rep.recorded = shorten(config_json(record.config).dump());
    rep.replayed = e.what();
    rep.message = std::string("the rules cannot be built from the config: ") + e.what();
    return rep;
  }

  GameState state;
  try {
    state = rules->start(record.start.rack_seed, record.start.breaker);
  } catch (const std::exception& e) {
    rep.where = "start";
    rep.recorded = shorten(state_json(record.start).dump());
    rep.replayed = e.what();
    rep.message = std::string("the start cannot be set up: ") + e.what();
    return rep;
  }
  if (!identical_state(state, record.start)) {
    report_difference(rep, difference(state_json(record.start), state_json(state), "start"),
                      "the start differs from Rules::start");
    rep.final_state = state;
    return rep;
  }
  rep.final_state = state;

  const double radius = record.config.ball_radius;
  for (std::size_t i = 0; i < record.actions.size(); ++i) {
    const RecordedAction& ra = record.actions[i];
    const std::string path = index_path("actions", i);
    const std::string context = "action " + std::to_string(i) + " (player " +
                                std::to_string(ra.player) + ", " +
                                std::string(action_name(ra.action)) + ") differs";
    rep.action = i;
    if (ra.player != state.player) {
      report_difference(rep, {member_path(path, "player"), std::to_string(ra.player),
                              std::to_string(state.player)},
                        context);
      return rep;
    }
    if (const auto* shoot = std::get_if<Shoot>(&ra.action); shoot != nullptr && ra.intended) {
      CueStrike executed;
      try {
        executed = perturb(*ra.intended, record.noise[static_cast<std::size_t>(ra.player)], radius,
                           ra.noise_seed);
      } catch (const std::exception& e) {
        report_difference(rep, {member_path(path, "intended"),
                                shorten(strike_json(*ra.intended).dump()),
                                std::string("(noise cannot be applied: ") + e.what() + ")"},
                          context);
        return rep;
      }
      if (!identical(executed, shoot->strike)) {
        report_difference(rep,
                          difference(strike_json(shoot->strike), strike_json(executed),
                                     member_path(member_path(path, "action"), "strike")),
                          context + ": the executed strike is not the intended one with the "
                                    "recorded noise of its seat (noise[" +
                              std::to_string(ra.player) + "])");
        return rep;
      }
    } else if (shoot == nullptr && ra.intended) {
      report_difference(rep, {member_path(path, "intended"),
                              shorten(strike_json(*ra.intended).dump()), "null (not a shot)"},
                        context);
      return rep;
    }

    Outcome out;
    try {
      out = rules->apply(state, ra.action);
    } catch (const std::invalid_argument& e) {
      report_difference(rep, {member_path(path, "action"), shorten(action_json(ra.action).dump()),
                              std::string("(not allowed: ") + e.what() + ")"},
                        context);
      return rep;
    } catch (const std::exception& e) {
      // Allowed, but the rules could not play it (a shot that never came
      // to rest, say): the recorded game cannot have gone this way.
      report_difference(rep, {member_path(path, "action"), shorten(action_json(ra.action).dump()),
                              std::string("(cannot be played: ") + e.what() + ")"},
                        context);
      return rep;
    }
    if (!(out.ruling == ra.ruling)) {
      report_difference(rep, difference(ruling_json(ra.ruling), ruling_json(out.ruling),
                                        member_path(path, "ruling")),
                        context);
      return rep;
    }
    if (!identical_state(out.state, ra.after)) {
      report_difference(rep, difference(state_json(ra.after), state_json(out.state),
                                        member_path(path, "after")),
                        context);
      return rep;
    }
    state = std::move(out.state);
    rep.final_state = state;
    rep.actions_identical = i + 1;
  }
  rep.action.reset();
  rep.identical = true;
  rep.message = "identical";
  return rep;
}

}  // namespace breakshot
