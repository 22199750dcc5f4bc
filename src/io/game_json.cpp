// The JSON of the game's types (game_json.hpp).

#include "io/game_json.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cstddef>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace breakshot::json_io {

namespace {

// Every value of each enum, for the messages that list them.
constexpr GameType kGameTypes[] = {GameType::eight_ball, GameType::nine_ball, GameType::snooker,
                                   GameType::three_cushion, GameType::ten_ball};
constexpr Phase kPhases[] = {Phase::break_shot,           Phase::shot,
                             Phase::push_out_choice,      Phase::illegal_break_choice,
                             Phase::eight_on_break_choice, Phase::game_over,
                             Phase::foul_choice};
constexpr BallInHand kBallInHand[] = {BallInHand::none, BallInHand::kitchen,
                                      BallInHand::anywhere, BallInHand::d};
constexpr Group kGroups[] = {Group::none, Group::solids, Group::stripes};
constexpr Choice kChoices[] = {Choice::shoot,
                               Choice::pass_back,
                               Choice::accept_table,
                               Choice::rerack_and_break,
                               Choice::rerack_opponent_breaks,
                               Choice::respot_eight,
                               Choice::play_on,
                               Choice::offender_again,
                               Choice::replace_balls,
                               Choice::concede};
constexpr Foul kFouls[] = {Foul::scratch,           Foul::no_contact,     Foul::wrong_ball_first,
                           Foul::no_rail,           Foul::illegal_break,  Foul::behind_head_string,
                           Foul::ball_off_table,    Foul::in_off,         Foul::wrong_ball_potted,
                           Foul::free_ball_snooker, Foul::wrong_cue_ball, Foul::push_through};

/// The highest ball number of a game (a bound for the numbers a record names).
int last_ball(GameType g) {
  return g == GameType::snooker ? 21 : g == GameType::three_cushion ? 2 : 15;
}

/// The game named by the "game" member of `v`, if it names one.
std::optional<GameType> game_of(const nlohmann::json& v) {
  if (!v.is_object()) return std::nullopt;
  const auto it = v.find("game");
  if (it == v.end() || !it->is_string()) return std::nullopt;
  return parse_game_type(it->get_ref<const std::string&>());
}

ojson positions_json(const std::vector<Vec2>& position);
ojson flags_json(const std::vector<std::uint8_t>& on_table);
}  // namespace

// ---------------------------------------------------------------------------
// Encoding

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
  const auto& [game, table_size, ball_radius, ball_mass, max_shots, physics, carom] = c;
  // The physics is not part of this object (physics_json): the config
  // keeps the form version 1 records and the web facade give it.
  (void)physics;
  ojson j = ojson::object();
  j["game"] = to_string(game);
  j["table_size"] = table_size;
  j["ball_radius"] = ball_radius;
  j["ball_mass"] = ball_mass;
  j["max_shots"] = max_shots;
  // Three-cushion's options, only in three-cushion: the other games'
  // configs keep their bytes.
  if (game == GameType::three_cushion) {
    ojson k = ojson::object();
    k["target"] = carom.target;
    k["innings_limit"] = carom.innings_limit;
    k["equalizing_inning"] = carom.equalizing_inning;
    j["carom"] = std::move(k);
  }
  return j;
}

ojson friction_curve_json(const FrictionCurve& k) {
  ojson j = ojson::object();
  j["a"] = k.a;
  j["b"] = k.b;
  j["c"] = k.c;
  return j;
}

ojson physics_json(const GamePhysics& p) {
  ojson j = ojson::object();
  j["cushion_model"] = cushion_model_name(p.cushion_model);
  j["ball_ball_model"] = to_string(p.ball_ball_model);
  j["ball_ball_friction"] = p.ball_ball_friction_fit ? friction_curve_json(p.ball_ball_friction_curve)
                                                     : ojson(p.ball_ball_friction);
  // Written only when on, so that records of games on the cloth keep
  // their bytes; absent reads as false.
  if (p.airborne) j["airborne"] = true;
  // Written only when it is not breakshot 0.1's, so that records of the
  // physics before it was recorded keep their bytes; absent reads as
  // kLegacySpinningFriction.
  if (p.spinning_friction != kLegacySpinningFriction) {
    j["spinning_friction"] = p.spinning_friction;
  }
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

namespace {

ojson positions_json(const std::vector<Vec2>& position) {
  ojson pos = ojson::array();
  for (const Vec2& p : position) pos.push_back(vec2_json(p));
  return pos;
}

ojson flags_json(const std::vector<std::uint8_t>& on_table) {
  ojson on = ojson::array();
  for (const std::uint8_t b : on_table) on.push_back(static_cast<int>(b));
  return on;
}

ojson snooker_state_json(const SnookerState& k) {
  const auto& [score, break_points, colour_on, free_ball, respotted_black, misses,
               replace_position, replace_on_table, replace_colour_on, replace_free_ball] = k;
  ojson j = ojson::object();
  j["score"] = ojson::array({score[0], score[1]});
  j["break"] = break_points;
  j["colour_on"] = colour_on;
  j["free_ball"] = free_ball;
  j["respotted_black"] = respotted_black;
  j["misses"] = misses;
  // The table a miss's replace_balls restores: null unless a miss was
  // just called.
  if (replace_position.empty()) {
    j["replace"] = nullptr;
  } else {
    ojson r = ojson::object();
    r["position"] = positions_json(replace_position);
    r["on_table"] = flags_json(replace_on_table);
    r["colour_on"] = replace_colour_on;
    r["free_ball"] = replace_free_ball;
    j["replace"] = std::move(r);
  }
  return j;
}

}  // namespace

ojson state_json(const GameState& s) {
  // Structured bindings name every member: when GameState gains or loses
  // one, this stops compiling instead of writing records that miss it.
  const auto& [game, position, on_table, phase, player, breaker, ball_in_hand, kitchen_shot, group,
               fouls_in_a_row, push_out_allowed, after_push_out, scratch_on_break, winner, result,
               shots, innings, rack_seed, racks, snooker, carom] = s;
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
  j["position"] = positions_json(position);
  j["on_table"] = flags_json(on_table);
  // Snooker's part, only in snooker: the other games' states keep their bytes.
  if (snooker) j["snooker"] = snooker_state_json(*snooker);
  // Three-cushion's part, only in three-cushion.
  if (carom) {
    const auto& [score, run, carom_innings, equalizing] = *carom;
    ojson k = ojson::object();
    k["score"] = ojson::array({score[0], score[1]});
    k["run"] = run;
    k["innings"] = ojson::array({carom_innings[0], carom_innings[1]});
    k["equalizing"] = equalizing;
    j["carom"] = std::move(k);
  }
  return j;
}

ojson ruling_json(const Ruling& r) {
  const auto& [fouls, legal_break, turn_continues, assigned, spotted, winner, text, call_made,
               snooker, carom] = r;
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
  if (snooker) {
    // Snooker's part, only in snooker rulings.
    const auto& [points, penalty, miss, free_ball, nominated] = *snooker;
    ojson k = ojson::object();
    k["points"] = points;
    k["penalty"] = penalty;
    k["miss"] = miss;
    k["free_ball"] = free_ball;
    k["nominated"] = nominated;
    j["snooker"] = std::move(k);
  }
  if (carom) {
    // Three-cushion's part, only in three-cushion shot rulings.
    const auto& [point, cue_ball, hit, cushions, kiss] = *carom;
    ojson k = ojson::object();
    k["point"] = point;
    k["cue_ball"] = cue_ball;
    k["hit"] = hit;
    k["cushions"] = cushions;
    k["kiss"] = kiss;
    j["carom"] = std::move(k);
  }
  return j;
}

ojson action_json(const Action& a) {
  ojson j = ojson::object();
  if (const auto* place = std::get_if<PlaceCueBall>(&a)) {
    j["type"] = "place_cue_ball";
    j["position"] = vec2_json(place->position);
  } else if (const auto* shoot = std::get_if<Shoot>(&a)) {
    const auto& [strike, call, safety, push_out, nominate, cue_ball] = *shoot;
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
    if (nominate) j["nominate"] = *nominate;  // snooker only
    if (cue_ball) j["cue_ball"] = *cue_ball;  // three-cushion only
  } else {
    j["type"] = "decide";
    j["choice"] = to_string(std::get<Decide>(a).choice);
  }
  return j;
}

ojson legal_actions_json(const LegalActions& la, GameType game) {
  const auto ints = [](const std::vector<int>& v) {
    ojson a = ojson::array();
    for (const int i : v) a.push_back(i);
    return a;
  };
  ojson j = ojson::object();
  j["place"] = to_string(la.place);
  j["must_place"] = la.must_place;
  j["shoot"] = la.shoot;
  j["push_out"] = la.push_out;
  j["call"] = la.call;
  j["targets"] = ints(la.targets);
  ojson choices = ojson::array();
  for (const Choice c : la.choices) choices.push_back(to_string(c));
  j["choices"] = choices;
  // Snooker's nomination, only in snooker: the other games' replies keep
  // their bytes.
  if (game == GameType::snooker) {
    j["nominate"] = ints(la.nominate);
    j["must_nominate"] = la.must_nominate;
  }
  return j;
}

ojson facts_json(const ShotFacts& f) {
  ojson j = ojson::object();
  j["first_hit"] = f.first_hit;
  j["pocketed"] = f.pocketed;
  j["pocket_of"] = f.pocket_of;
  j["miscue"] = f.miscue;
  j["cushion_after_contact"] = f.cushion_after_contact;
  j["object_balls_to_cushion"] = f.object_balls_to_cushion;
  return j;
}

ojson game_event_json(const Table& table, const Event& e) {
  const auto wall_name = [&table](int wall) -> ojson {
    if (wall >= 0 && static_cast<std::size_t>(wall) < table.walls.size()) {
      return table.walls[static_cast<std::size_t>(wall)].name;
    }
    return nullptr;
  };
  ojson j = ojson::object();
  j["time"] = e.time;
  j["type"] = to_string(e.type);
  ojson balls = ojson::array();
  balls.push_back(e.ball);
  if (e.type == EventType::ball_ball) balls.push_back(e.other);
  j["balls"] = balls;
  switch (e.type) {
    case EventType::ball_cushion:
      j["cushion"] = wall_name(e.wall);
      break;
    case EventType::ball_pocket:
      j["pocket"] = e.pocket;
      if (e.pocket >= 0 && static_cast<std::size_t>(e.pocket) < table.pockets.size()) {
        j["pocket_name"] = table.pockets[static_cast<std::size_t>(e.pocket)].name;
      } else {
        j["pocket_name"] = nullptr;
      }
      break;
    case EventType::ball_off_table:
      if (e.wall >= 0 && static_cast<std::size_t>(e.wall) < table.walls.size()) {
        j["cushion"] = wall_name(e.wall);
      }
      break;
    case EventType::ball_slate:
    case EventType::state_change:
      j["from"] = to_string(e.from);
      j["to"] = to_string(e.to);
      break;
    case EventType::cue_strike:
    case EventType::ball_ball:
      break;
  }
  return j;
}

ojson snooker_figures_json(const GameState& s) {
  ojson j = ojson::object();
  j["balls_on"] = snooker_balls_on(s);
  j["points_remaining"] = snooker_points_remaining(s);
  j["snookers_required"] = ojson::array({snookers_required(s, 0), snookers_required(s, 1)});
  return j;
}

ojson carom_figures_json(const Rules& rules, const GameState& state, const GameRecord& record) {
  std::array<int, 2> highest{0, 0};
  for (const CaromInning& inning : carom_innings(record)) {
    int& h = highest[static_cast<std::size_t>(inning.player)];
    h = std::max(h, inning.points);
  }
  ojson j = ojson::object();
  j["cue_ball"] = rules.cue_ball(state);
  ojson average = ojson::array();
  for (std::size_t p = 0; p < 2; ++p) {
    const int innings = state.carom ? state.carom->innings[p] : 0;
    const int score = state.carom ? state.carom->score[p] : 0;
    average.push_back(innings > 0 ? static_cast<double>(score) / static_cast<double>(innings)
                                  : 0.0);
  }
  j["general_average"] = average;
  j["highest_run"] = ojson::array({highest[0], highest[1]});
  return j;
}


// ---------------------------------------------------------------------------
// Decoding

bool GameReader::config(const json& v, const std::string& path, GameConfig& c) {
  // Three-cushion's configs have a "carom" object, the other games' none.
  const bool carom = game_of(v) == GameType::three_cushion;
  if (carom ? !exact_object(
                  v, path, {"game", "table_size", "ball_radius", "ball_mass", "max_shots", "carom"})
            : !exact_object(v, path,
                            {"game", "table_size", "ball_radius", "ball_mass", "max_shots"})) {
    return false;
  }
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  if (!game_type(v["game"], at("game"), c.game)) return false;
  game_context = c.game;
  if (!(table_size(v["table_size"], at("table_size"), c.table_size) &&
        number(v["ball_radius"], at("ball_radius"), c.ball_radius) &&
        positive(c.ball_radius, at("ball_radius")) &&
        number(v["ball_mass"], at("ball_mass"), c.ball_mass) &&
        positive(c.ball_mass, at("ball_mass")) &&
        integer(v["max_shots"], at("max_shots"), 0, INT_MAX, c.max_shots))) {
    return false;
  }
  c.carom = CaromRules{};
  if (!carom) return true;
  const json& k = v["carom"];
  const std::string kp = at("carom");
  return exact_object(k, kp, {"target", "innings_limit", "equalizing_inning"}) &&
         integer(k["target"], member_path(kp, "target"), 1, INT_MAX, c.carom.target) &&
         integer(k["innings_limit"], member_path(kp, "innings_limit"), 0, INT_MAX,
                 c.carom.innings_limit) &&
         boolean(k["equalizing_inning"], member_path(kp, "equalizing_inning"),
                 c.carom.equalizing_inning);
}

bool GameReader::physics(const json& v, const std::string& path, GamePhysics& p) {
  // "airborne" and "spinning_friction" are optional: written only when
  // they differ from breakshot 0.1's physics, and messages about a
  // physics without them keep their list of keys.
  std::vector<std::string_view> keys{"cushion_model", "ball_ball_model", "ball_ball_friction"};
  const bool has_airborne = v.is_object() && v.contains("airborne");
  const bool has_spin = v.is_object() && v.contains("spinning_friction");
  if (has_airborne) keys.emplace_back("airborne");
  if (has_spin) keys.emplace_back("spinning_friction");
  if (!exact_object(v, path, keys)) return false;
  p.airborne = false;
  if (has_airborne) {
    if (!v["airborne"].is_boolean()) return fail(member_path(path, "airborne"), "expected true or false");
    p.airborne = v["airborne"].get<bool>();
  }
  p.spinning_friction = kLegacySpinningFriction;
  if (has_spin) {
    const std::string sp = member_path(path, "spinning_friction");
    if (!number(v["spinning_friction"], sp, p.spinning_friction)) return false;
    if (!(p.spinning_friction > 0.0)) {
      return fail(sp, "must be > 0 (a ball's spin would never stop)");
    }
  }
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  std::string name;
  if (!text(v["cushion_model"], at("cushion_model"), name)) return false;
  if (!parse_cushion_model(name, p.cushion_model)) {
    return fail(at("cushion_model"), unknown("cushion model", name, cushion_model_names()));
  }
  if (!text_of(v["ball_ball_model"], at("ball_ball_model"), "ball-ball model",
               {"friction", "mathavan_2014"}, name)) {
    return false;
  }
  parse_ball_ball_model(name, p.ball_ball_model);
  const json& f = v["ball_ball_friction"];
  const std::string fpath = at("ball_ball_friction");
  if (f.is_object()) {
    if (!exact_object(f, fpath, {"a", "b", "c"})) return false;
    FrictionCurve& k = p.ball_ball_friction_curve;
    if (!number(f["a"], member_path(fpath, "a"), k.a) ||
        !number(f["b"], member_path(fpath, "b"), k.b) ||
        !number(f["c"], member_path(fpath, "c"), k.c)) {
      return false;
    }
    if (auto bad = check_friction_curve(k)) {
      return fail(member_path(fpath, std::string(1, bad->member)), std::move(bad->reason));
    }
    p.ball_ball_friction_fit = true;
    p.ball_ball_friction = 0.0;
    return true;
  }
  if (!f.is_number()) return fail(fpath, expected("a number or an object {\"a\", \"b\", \"c\"}", f));
  if (!number(f, fpath, p.ball_ball_friction) || !non_negative(p.ball_ball_friction, fpath)) {
    return false;
  }
  p.ball_ball_friction_fit = false;
  p.ball_ball_friction_curve = FrictionCurve{};
  return true;
}

bool GameReader::noise(const json& v, const std::string& path, NoiseModel& n) {
  if (!exact_object(v, path, {"phi", "theta", "speed", "a", "b"})) return false;
  const auto component = [&](std::string_view key, double& out) {
    const std::string at = member_path(path, key);
    return number(v[std::string(key)], at, out) && non_negative(out, at);
  };
  return component("phi", n.phi) && component("theta", n.theta) &&
         component("speed", n.speed) && component("a", n.a) && component("b", n.b);
}

bool GameReader::strike(const json& v, const std::string& path, CueStrike& s) {
  if (!exact_object(v, path, {"speed", "phi", "theta", "a", "b"})) return false;
  return number(v["speed"], member_path(path, "speed"), s.speed) &&
         number(v["phi"], member_path(path, "phi"), s.phi) &&
         number(v["theta"], member_path(path, "theta"), s.theta) &&
         number(v["a"], member_path(path, "a"), s.a) &&
         number(v["b"], member_path(path, "b"), s.b);
}

bool GameReader::state(const json& v, const std::string& path, GameState& s) {
  // Snooker's states have a "snooker" object, three-cushion's a "carom"
  // one, the other games' neither.
  const std::optional<GameType> g = game_of(v);
  const bool snooker = g == GameType::snooker;
  const bool carom = g == GameType::three_cushion;
  std::vector<std::string_view> keys{"game",
                                     "phase",
                                     "player",
                                     "breaker",
                                     "ball_in_hand",
                                     "kitchen_shot",
                                     "group",
                                     "fouls_in_a_row",
                                     "push_out_allowed",
                                     "after_push_out",
                                     "scratch_on_break",
                                     "winner",
                                     "result",
                                     "shots",
                                     "innings",
                                     "rack_seed",
                                     "racks",
                                     "position",
                                     "on_table"};
  if (snooker) keys.push_back("snooker");
  if (carom) keys.push_back("carom");
  if (!exact_object(v, path, keys)) return false;
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  if (!game_type(v["game"], at("game"), s.game) ||
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
  s.snooker.reset();
  if (snooker) {
    SnookerState k;
    if (!snooker_state(v["snooker"], at("snooker"), k)) return false;
    s.snooker = std::move(k);
  }
  s.carom.reset();
  if (carom) {
    const json& k = v["carom"];
    const std::string kp = at("carom");
    CaromState cs;
    if (!exact_object(k, kp, {"score", "run", "innings", "equalizing"})) return false;
    const json& score = k["score"];
    const json& inn = k["innings"];
    if (!array(score, member_path(kp, "score"), 2) || !array(inn, member_path(kp, "innings"), 2)) {
      return false;
    }
    for (std::size_t i = 0; i < 2; ++i) {
      if (!integer(score[i], index_path(member_path(kp, "score"), i), 0, INT_MAX, cs.score[i]) ||
          !integer(inn[i], index_path(member_path(kp, "innings"), i), 0, INT_MAX, cs.innings[i])) {
        return false;
      }
    }
    if (!integer(k["run"], member_path(kp, "run"), 0, INT_MAX, cs.run) ||
        !boolean(k["equalizing"], member_path(kp, "equalizing"), cs.equalizing)) {
      return false;
    }
    s.carom = cs;
  }
  return true;
}

bool GameReader::positions(const json& v, const std::string& path, std::vector<Vec2>& out) {
  if (!array(v, path)) return false;
  out.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!vec2(v[i], index_path(path, i), out[i])) return false;
  }
  return true;
}

bool GameReader::flags(const json& v, const std::string& path, std::size_t n,
                       std::vector<std::uint8_t>& out) {
  if (!array(v, path)) return false;
  if (v.size() != n) {
    return fail(path, "has " + std::to_string(v.size()) + " entries but position has " +
                          std::to_string(n) + " (one per ball)");
  }
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    int flag = 0;
    if (!integer(v[i], index_path(path, i), 0, 1, flag)) return false;
    out[i] = static_cast<std::uint8_t>(flag);
  }
  return true;
}

bool GameReader::snooker_state(const json& v, const std::string& path, SnookerState& k) {
  if (!exact_object(v, path,
                    {"score", "break", "colour_on", "free_ball", "respotted_black", "misses",
                     "replace"})) {
    return false;
  }
  const auto at = [&](std::string_view key) { return member_path(path, key); };
  const json& score = v["score"];
  if (!array(score, at("score"), 2)) return false;
  for (std::size_t i = 0; i < 2; ++i) {
    if (!integer(score[i], index_path(at("score"), i), 0, INT_MAX, k.score[i])) return false;
  }
  if (!integer(v["break"], at("break"), 0, INT_MAX, k.break_points) ||
      !boolean(v["colour_on"], at("colour_on"), k.colour_on) ||
      !boolean(v["free_ball"], at("free_ball"), k.free_ball) ||
      !boolean(v["respotted_black"], at("respotted_black"), k.respotted_black) ||
      !integer(v["misses"], at("misses"), 0, 3, k.misses)) {
    return false;
  }
  const json& r = v["replace"];
  if (r.is_null()) return true;
  const std::string rp = at("replace");
  if (!exact_object(r, rp, {"position", "on_table", "colour_on", "free_ball"})) return false;
  if (!positions(r["position"], member_path(rp, "position"), k.replace_position)) return false;
  if (k.replace_position.empty()) return fail(member_path(rp, "position"), "expected the balls' positions, not []");
  return flags(r["on_table"], member_path(rp, "on_table"), k.replace_position.size(),
               k.replace_on_table) &&
         boolean(r["colour_on"], member_path(rp, "colour_on"), k.replace_colour_on) &&
         boolean(r["free_ball"], member_path(rp, "free_ball"), k.replace_free_ball);
}

bool GameReader::ruling(const json& v, const std::string& path, Ruling& r) {
  // A snooker shot's ruling has a "snooker" object; a decision's and the
  // other games' have none.
  const bool snooker = v.is_object() && find(v, "snooker") != nullptr;
  if (snooker && game_context && *game_context != GameType::snooker) {
    return fail(member_path(path, "snooker"), "only snooker rulings have this field");
  }
  const bool carom = v.is_object() && find(v, "carom") != nullptr;
  if (carom && game_context && *game_context != GameType::three_cushion) {
    return fail(member_path(path, "carom"), "only three-cushion rulings have this field");
  }
  std::vector<std::string_view> keys{"fouls",   "legal_break", "turn_continues", "assigned",
                                     "spotted", "winner",      "text",           "call_made"};
  if (snooker) keys.push_back("snooker");
  if (carom) keys.push_back("carom");
  if (!exact_object(v, path, keys)) return false;
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
    if (!integer(spotted[i], index_path(at("spotted"), i), 0,
                 last_ball(game_context.value_or(GameType::eight_ball)), r.spotted[i])) {
      return false;
    }
  }
  if (!integer(v["winner"], at("winner"), -1, 1, r.winner) ||
      !text(v["text"], at("text"), r.text) ||
      !boolean(v["call_made"], at("call_made"), r.call_made)) {
    return false;
  }
  r.snooker.reset();
  r.carom.reset();
  if (carom) {
    const json& k = v["carom"];
    const std::string kp = at("carom");
    CaromRuling cr;
    if (!exact_object(k, kp, {"point", "cue_ball", "hit", "cushions", "kiss"}) ||
        !boolean(k["point"], member_path(kp, "point"), cr.point) ||
        !integer(k["cue_ball"], member_path(kp, "cue_ball"), 0, 2, cr.cue_ball) ||
        !integer(k["cushions"], member_path(kp, "cushions"), 0, INT_MAX, cr.cushions) ||
        !boolean(k["kiss"], member_path(kp, "kiss"), cr.kiss)) {
      return false;
    }
    const json& hit = k["hit"];
    if (!array(hit, member_path(kp, "hit"))) return false;
    if (hit.size() > 2) return fail(member_path(kp, "hit"), "at most two object balls");
    cr.hit.resize(hit.size());
    for (std::size_t i = 0; i < hit.size(); ++i) {
      if (!integer(hit[i], index_path(member_path(kp, "hit"), i), 0, 2, cr.hit[i])) return false;
    }
    r.carom = std::move(cr);
  }
  if (!snooker) return true;
  const json& k = v["snooker"];
  const std::string kp = at("snooker");
  SnookerRuling sr;
  if (!exact_object(k, kp, {"points", "penalty", "miss", "free_ball", "nominated"}) ||
      !integer(k["points"], member_path(kp, "points"), 0, INT_MAX, sr.points) ||
      !integer(k["penalty"], member_path(kp, "penalty"), 0, INT_MAX, sr.penalty) ||
      !boolean(k["miss"], member_path(kp, "miss"), sr.miss) ||
      !boolean(k["free_ball"], member_path(kp, "free_ball"), sr.free_ball) ||
      !integer(k["nominated"], member_path(kp, "nominated"), -1, 21, sr.nominated)) {
    return false;
  }
  r.snooker = sr;
  return true;
}

bool GameReader::action(const json& v, const std::string& path, Action& a) {
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
    const bool nominates = find(v, "nominate") != nullptr;
    const bool names_cue = find(v, "cue_ball") != nullptr;
    std::vector<std::string_view> keys{"type", "strike", "call", "safety", "push_out"};
    if (nominates) keys.push_back("nominate");
    if (names_cue) keys.push_back("cue_ball");
    if (!exact_object(v, path, keys) ||
        !strike(v["strike"], member_path(path, "strike"), shoot.strike)) {
      return false;
    }
    if (names_cue) {
      int ball = 0;
      if (!integer(v["cue_ball"], member_path(path, "cue_ball"), 0, 2, ball)) return false;
      shoot.cue_ball = ball;
    }
    if (nominates) {
      int ball = 0;
      if (!integer(v["nominate"], member_path(path, "nominate"), 1, 21, ball)) return false;
      shoot.nominate = ball;
    }
    const json& call = v["call"];
    const std::string call_path = member_path(path, "call");
    if (!call.is_null()) {
      Call c;
      if (!exact_object(call, call_path, {"ball", "pocket"}) ||
          !integer(call["ball"], member_path(call_path, "ball"), -1, 21, c.ball) ||
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
        !choice(v["choice"], member_path(path, "choice"), decide.choice)) {
      return false;
    }
    a = decide;
    return true;
  }
  return fail(type_path, unknown("action type", t, one_of({"place_cue_ball", "shoot", "decide"})));
}

bool GameReader::game_type(const json& v, const std::string& path, GameType& out) {
  return name(v, path, "game", parse_game_type, kGameTypes, out);
}

bool GameReader::table_size(const json& v, const std::string& path, std::string& out) {
  // Snooker's table is the 12 ft one, three-cushion's the 10 ft carom
  // table; the pool games' are the others.
  if (game_context == GameType::snooker) return text_of(v, path, "table size", {"12ft"}, out);
  if (game_context == GameType::three_cushion) {
    return text_of(v, path, "table size", {"10ft"}, out);
  }
  return text_of(v, path, "table size", {"7ft", "8ft", "9ft"}, out);
}

bool GameReader::choice(const json& v, const std::string& path, Choice& out) {
  return name(v, path, "choice", parse_choice, kChoices, out);
}

}  // namespace breakshot::json_io
