// Games (BsGame): configs, actions, the AI's actions, the state and the
// table as JSON, a shot's playback, and undo. The game's types (state,
// action, strike, ruling) are in the one JSON of game records
// (src/io/game_json.hpp), both ways: what a reply shows is what the
// record holds.
//
// Games. A BsGame holds the rules and a GameRecord (record.hpp) that
// grows with every action, so bs_game_record is that record as
// write_record writes it, and `breakshot replay` accepts it. A BsGame
// plays through a GameSession (session.hpp), as play_game does, so its
// seeds are play_game's and a game between two AI seats is the game
// play_game plays with the same players (tests/test_web_api.cpp checks it). A seat is "human" (no
// noise: the strike is played as given) or an AI level name (ai.hpp): it
// shoots with the level's noise, whoever chose the shot. The AI decides
// with one thread, no time budget and a budget in simulations per
// decision (AiLevel::simulation_budget), so that a decision is the same
// on every machine and, in wasm, quick enough for a page (measured in
// docs/web.md):
//   beginner 100 (it samples nothing)   amateur 600   club 2000
//   expert 4000   champion 24000 (its 9-ball lookahead alone can take 12000,
//   and its sampling of up to 105 candidates before that 9000)
// A game's config may set "ai_budget" to override them all (tests).

#include "facade.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/player.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"
#include "breakshot/session.hpp"
#include "breakshot/snooker.hpp"
#include "io/table_json.hpp"

namespace facade {

namespace {

// ---------------------------------------------------------------------------
// Writing replies

// The one JSON of each of the game's types (src/io/game_json.hpp, as game
// records write them) and of the table (src/io/table_json.hpp).
using bs::json_io::action_json;
using bs::json_io::facts_json;
using bs::json_io::ruling_json;
using bs::json_io::strike_json;

ojson ints_json(const std::vector<int>& v) {
  ojson a = ojson::array();
  for (const int i : v) a.push_back(i);
  return a;
}

std::string_view action_kind(const bs::Action& a) {
  if (std::holds_alternative<bs::PlaceCueBall>(a)) return "place";
  if (std::holds_alternative<bs::Shoot>(a)) return "shoot";
  return "decide";
}

// ---------------------------------------------------------------------------
// Games

/// An action in the records' form (src/io/game_json.hpp), every field
/// required.
bs::Action read_action(const json& doc) {
  Reader r;
  bs::Action action;
  r.must(r.action(doc, "", action));
  return action;
}

bs::AiLevel web_level(const std::string& name, const std::optional<std::int64_t>& budget) {
  const bs::PlayerName n = bs::read_player_name(name);
  bs::AiLevel l = bs::ai_level(n.base);
  if (n.noise) l.noise = *n.noise;  // it plans with the noise it shoots with
  l.threads = 1;
  l.time_budget = 0.0;
  l.simulation_budget = budget ? *budget : web_budget(n.base);
  return l;
}

}  // namespace

/// Simulations per AI decision in the browser (see the top of this file).
/// Each is above what the level's own search takes in nearly every
/// position (measured: the decisions with and without the budget agree),
/// so the budget only bounds the rare long decision.
std::int64_t web_budget(std::string_view level) {
  if (level == "amateur") return 600;
  if (level == "club") return 2000;
  if (level == "expert") return 4000;
  if (level == "champion") return 24000;
  return 100;  // beginner: samples nothing, the budget is never taken
}

bs::GameType game_type(const json& v, const std::string& path) {
  Reader r;
  std::string name;
  r.must(r.text_of(v, path, "game",
                    {"eight_ball", "nine_ball", "ten_ball", "snooker", "three_cushion"}, name));
  return *bs::parse_game_type(name);
}

bs::GameConfig game_config(bs::GameType game) {
  if (game == bs::GameType::snooker) return bs::snooker_config();
  if (game == bs::GameType::three_cushion) return bs::three_cushion_config();
  bs::GameConfig c;
  c.game = game;
  return c;
}

bs::CaromRules carom_rules(const json& v, const std::string& path, bs::GameType game) {
  if (game != bs::GameType::three_cushion) bad(path, "only three_cushion games have this field");
  const json& k = object(v, path, {"target", "innings_limit", "equalizing_inning"});
  bs::CaromRules c;
  if (const json* t = find(k, "target")) {
    c.target = static_cast<int>(integer(*t, path + ".target", 1, 10000));
  }
  if (const json* n = find(k, "innings_limit")) {
    c.innings_limit = static_cast<int>(integer(*n, path + ".innings_limit", 0, 10000));
  }
  if (const json* e = find(k, "equalizing_inning")) {
    if (!e->is_boolean()) bad(path + ".equalizing_inning", "expected true or false");
    c.equalizing_inning = e->get<bool>();
  }
  return c;
}

std::string players_json(const char* game) {
  if (game == nullptr) bad("game", "missing (a null pointer)");
  const bs::GameType type = game_type(json(std::string(game)), "game");
  ojson j = ojson::object();
  j["game"] = bs::to_string(type);
  ojson players = ojson::array();
  for (const std::string& p : computer_players(type)) players.push_back(p);
  j["players"] = players;
  return j.dump();
}

std::string table_size(const json& v, const std::string& path, bs::GameType game) {
  Reader r;
  r.game_context = game;
  std::string size;
  r.must(r.table_size(v, path, size));
  return size;
}

GameConfigInput read_config(const json& doc) {
  // "carom" is a key of three-cushion's configs only: the other games'
  // messages keep their list of keys.
  const json* game = doc.is_object() ? find(doc, "game") : nullptr;
  if (game != nullptr && game->is_string() &&
      game->get_ref<const std::string&>() == "three_cushion") {
    object(doc, "", {"game", "table", "seed", "breaker", "players", "ai_budget", "physics", "carom"});
  } else {
    object(doc, "", {"game", "table", "seed", "breaker", "players", "ai_budget", "physics"});
  }
  GameConfigInput in;
  in.config = game_config(game_type(required(doc, "", "game"), "game"));
  if (const json* k = find(doc, "carom")) {
    in.config.carom = carom_rules(*k, "carom", in.config.game);
  }
  if (const json* t = find(doc, "table")) {
    in.config.table_size = table_size(*t, "table", in.config.game);
  }
  if (const json* s = find(doc, "seed")) in.seed = seed_value(*s, "seed");
  if (const json* b = find(doc, "breaker")) in.breaker = static_cast<int>(integer(*b, "breaker", 0, 1));
  const json& players = required(doc, "", "players");
  if (!players.is_array() || players.size() != 2) {
    bad("players", "expected an array of two seats (\"human\" or an AI level)");
  }
  for (std::size_t k = 0; k < 2; ++k) {
    in.seats[k] = seat_name(players[k], index_path("players", k), in.config.game);
  }
  if (const json* n = find(doc, "ai_budget")) in.ai_budget = integer(*n, "ai_budget", 1, kMaxBudget);
  if (const json* ph = find(doc, "physics")) {
    // The choices a game may change from GamePhysics's defaults; the
    // others keep them.
    const json& phys = object(*ph, "physics", {"airborne"});
    if (const json* a = find(phys, "airborne")) {
      if (!a->is_boolean()) bad("physics.airborne", "expected true or false");
      in.config.physics.airborne = a->get<bool>();
    }
  }
  return in;
}

std::unique_ptr<BsGame> make_game(const GameConfigInput& in) {
  return std::make_unique<BsGame>(in.config, in.seats, in.seed, in.breaker, in.ai_budget);
}

ojson state_json(const BsGame& g) {
  const bs::GameState& s = g.state();
  ojson j = bs::json_io::state_json(s);
  j["players"] = ojson::array({g.seats[0], g.seats[1]});
  j["actions"] = g.record().actions.size();
  j["legal"] = bs::json_io::legal_actions_json(g.rules().legal_actions(s), s.game);
  if (s.game == bs::GameType::snooker) j["snooker_figures"] = bs::json_io::snooker_figures_json(s);
  if (s.game == bs::GameType::three_cushion) {
    j["carom_figures"] = bs::json_io::carom_figures_json(g.rules(), s, g.record());
  }
  return j;
}

ojson table_json(const BsGame& g) { return bs::json_io::game_table_json(g.rules()); }

ojson turn_json(const bs::RecordedAction& ra) {
  const bs::GameState& after = ra.after;
  ojson j = ojson::object();
  const bool over = after.phase == bs::Phase::game_over;
  j["next"] = over ? -1 : after.player;
  const char* why = "passes";
  if (over) {
    why = "game_over";
  } else if (after.phase == bs::Phase::break_shot) {
    why = "breaks";
  } else if (after.phase != bs::Phase::shot) {
    why = "decides";  // a decision phase: push_out_choice, foul_choice, ...
  } else if (!std::holds_alternative<bs::Shoot>(ra.action) ? after.player == ra.player
                                                           : ra.ruling.turn_continues) {
    why = "continues";
  } else if (!ra.ruling.fouls.empty()) {
    why = "foul";
  }
  j["why"] = why;
  return j;
}

std::string turns_json(const BsGame& g) {
  ojson turns = ojson::array();
  for (const bs::RecordedAction& ra : g.record().actions) turns.push_back(turn_json(ra));
  ojson j = ojson::object();
  j["turns"] = turns;
  return j.dump();
}

std::optional<ojson> play(BsGame& g, const bs::Action& action, std::string& why) {
  if (auto reason = g.session.check(action)) {
    why = *reason;
    return std::nullopt;
  }
  const std::size_t i = g.session.actions();
  bs::Outcome out;
  try {
    out = g.session.play(action);
  } catch (const std::exception& e) {
    why = std::string("the action as executed was refused: ") + e.what();
    return std::nullopt;
  }
  const bs::RecordedAction& ra = g.record().actions.back();
  ojson j = ojson::object();
  j["index"] = i;
  j["player"] = ra.player;
  j["kind"] = action_kind(ra.action);
  j["executed"] = action_json(ra.action);
  if (ra.intended) {
    std::vector<int> numbers;
    (void)g.rules().shot_scenario(g.state_before(i), std::get<bs::Shoot>(ra.action).strike,
                                  &numbers);
    j["intended"] = strike_json(*ra.intended);
    j["numbers"] = ints_json(numbers);
  }
  j["ruling"] = ruling_json(out.ruling);
  j["turn"] = turn_json(ra);
  j["facts"] = facts_json(out.facts);
  j["state"] = state_json(g);
  return j;
}

std::string act_json(BsGame& g, const char* action_text) {
  const bs::Action action = read_action(parse_text(action_text, "action"));
  std::string why;
  std::optional<ojson> j = play(g, action, why);
  if (!j) return error_json(why);
  return j->dump();
}

std::string ai_action_json(BsGame& g, const char* level) {
  const bs::GameState& state = g.state();
  if (state.phase == bs::Phase::game_over) bad("", "the game is over");
  std::string name;
  const bool snooker = state.game == bs::GameType::snooker;
  if (level != nullptr && level[0] != '\0') {
    name = level;
    if (name == kHuman) bad("level", "\"human\" is not an AI level");
    if (state.game == bs::GameType::three_cushion) {
      // a player of three-cushion (players.hpp), by the seats' rule
      (void)seat_name(json(name), "level", state.game);
    } else if (!(snooker && is_baseline(name))) {
      try {
        (void)bs::ai_level(bs::read_player_name(name).base);
      } catch (const std::invalid_argument& e) {
        bad("level", e.what());
      }
    }
  } else {
    name = g.seats[static_cast<std::size_t>(state.player)];
    if (name == kHuman) {
      bad("level", "the seat to act (" + std::to_string(state.player) +
                       ") is human: name an AI level for a hint");
    }
  }
  const std::unique_ptr<bs::Player> ai = is_baseline(name)
                                             ? bs::make_baseline_player()
                                             : bs::make_ai_player(web_level(name, g.ai_budget));
  const bs::Action a = ai->decide(g.rules(), state, g.session.next_player_seed());
  ojson j = ojson::object();
  j["action"] = action_json(a);
  return j.dump();
}

std::string check_placement_json(const BsGame& g, double x, double y) {
  ojson j = ojson::object();
  const auto why = g.rules().check_placement(g.state(), {x, y});
  j["ok"] = !why;
  if (why) j["reason"] = *why;
  return j.dump();
}

std::unique_ptr<BsPlayback> shot_playback(const BsGame& g, int index) {
  const std::size_t n = g.record().actions.size();
  if (index < 0 || static_cast<std::size_t>(index) >= n) {
    bad("index", "must be in [0, " + std::to_string(n) + "), not " + std::to_string(index));
  }
  const bs::RecordedAction& ra = g.record().actions[static_cast<std::size_t>(index)];
  const auto* shot = std::get_if<bs::Shoot>(&ra.action);
  if (shot == nullptr) {
    bad("index", "action " + std::to_string(index) + " is not a shot (" +
                     std::string(action_kind(ra.action)) + ")");
  }
  std::vector<int> numbers;
  auto pb = std::make_unique<BsPlayback>(g.rules().shot_scenario(
      g.state_before(static_cast<std::size_t>(index)), shot->strike, &numbers));
  if (ra.ruling.carom) {
    pb->numbers = std::move(numbers);
    pb->carom_struck = ra.ruling.carom->cue_ball;
  }
  return pb;
}

std::string undo_to_json(BsGame& g, int n) {
  const std::size_t size = g.record().actions.size();
  if (n < 0 || static_cast<std::size_t>(n) > size) {
    bad("n", "must be in [0, " + std::to_string(size) + "], not " + std::to_string(n));
  }
  g.session.take_back_to(static_cast<std::size_t>(n));
  return state_json(g).dump();
}

}  // namespace facade
