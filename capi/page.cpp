// Games as the browser page plays them (include/breakshot.h's
// experimental calls; web/api is a thin layer on them): a game from the
// page's config document, an act with its report, whose turn it is and
// why, undo, the table, placement checks, the snooker and carom figures,
// and the computer player of a game as the page's AI decides.
//
// The page's AI decides with one thread, no time budget and a budget in
// simulations per decision (AiLevel::simulation_budget), so that a
// decision is the same on every machine and, in wasm, quick enough for a
// page (measured in docs/web.md):
//   beginner 100 (it samples nothing)   amateur 600   club 2000
//   expert 4000   champion 24000 (its 9-ball lookahead alone can take 12000,
//   and its sampling of up to 105 candidates before that 9000)
// A game's config may set "ai_budget" to override them all (tests).

#include "page.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "breakshot.h"
#include "breakshot/ai.hpp"
#include "breakshot/carom.hpp"
#include "breakshot/game.hpp"
#include "breakshot/player.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"
#include "breakshot/session.hpp"
#include "breakshot/snooker.hpp"
#include "capi.hpp"
#include "io/table_json.hpp"

namespace capi::page {

// ---------------------------------------------------------------------------
// Reading JSON input

[[noreturn]] void bad(const std::string& path, const std::string& what) {
  fail(BS_ERROR_BAD_JSON, path.empty() ? what : path + ": " + what);
}

const json* find(const json& obj, std::string_view key) { return Reader::find(obj, key); }

json parse_text(const char* text, std::size_t len, const std::string& what,
                const std::string& root) {
  if (text == nullptr) fail(BS_ERROR_NULL, what + ": missing (a null pointer)");
  json doc;
  bs::json_io::ParseOptions options;
  options.root_path = root;
  if (auto problem = bs::json_io::parse_strict(std::string(text, len), doc, options)) {
    if (problem->syntax) bad(what, "not valid JSON: " + problem->error.reason);
    bad(problem->error.path, problem->error.reason);
  }
  return doc;
}

const json& object(const json& v, const std::string& path,
                   std::initializer_list<std::string_view> known) {
  Reader r;
  r.must(r.object(v, path, known));
  return v;
}

const json& required(const json& obj, const std::string& path, std::string_view key) {
  Reader r;
  const json* v = nullptr;
  r.must(r.required(obj, path, key, v));
  return *v;
}

std::int64_t integer(const json& v, const std::string& path, std::int64_t lo, std::int64_t hi) {
  Reader r;
  std::int64_t i = 0;
  r.must(r.integer(v, path, lo, hi, i));
  return i;
}

const std::string& text(const json& v, const std::string& path) {
  Reader r;
  std::string unused;
  r.must(r.text(v, path, unused));
  return v.get_ref<const std::string&>();
}

std::uint64_t seed_value(const json& v, const std::string& path) {
  if (v.is_number_integer()) {
    return static_cast<std::uint64_t>(integer(v, path, 0, std::int64_t{1} << 53));
  }
  Reader r;
  std::uint64_t seed = 0;
  r.must(r.seed(v, path, seed));
  return seed;
}

namespace {

bs::PlayerName computer_name(const std::string& name, const std::string& path) {
  try {
    return bs::read_player_name(name);
  } catch (const std::invalid_argument& e) {
    bad(path, e.what());
  }
}

/// "human" or a known AI level (either at a named noise: LEVEL@NOISE).
std::string level_seat(const json& v, const std::string& path) {
  const std::string& s = text(v, path);
  if (s == kHuman) return s;
  const bs::PlayerName n = computer_name(s, path);
  try {
    (void)bs::ai_level(n.base);
  } catch (const std::invalid_argument& e) {
    bad(path, std::string("\"human\" or ") + e.what());
  }
  return s;
}

}  // namespace

std::vector<std::string> computer_players(bs::GameType game) {
  if (game == bs::GameType::three_cushion) {
    // Whoever plays three-cushion (players.hpp): the AI levels that do,
    // then the baseline.
    std::vector<std::string> out;
    for (const std::string& l : bs::ai_level_names()) {
      if (!bs::check_player(l, game)) out.push_back(l);
    }
    out.emplace_back("baseline");
    return out;
  }
  std::vector<std::string> out = bs::ai_level_names();
  if (game == bs::GameType::snooker) out.push_back("baseline");
  return out;
}

bool is_baseline(std::string_view name) { return name.substr(0, name.find('@')) == "baseline"; }

std::string seat_name(const json& v, const std::string& path, bs::GameType game) {
  if (game == bs::GameType::three_cushion) {
    const std::string& s = text(v, path);
    if (s == kHuman) return s;
    const std::string base = computer_name(s, path).base;
    const std::vector<std::string> known = computer_players(game);
    for (const std::string& k : known) {
      if (k == base) return s;
    }
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "\"" : ", \"") + k + "\"";
    bad(path, "\"human\" or a player of three_cushion (" + list + "), not \"" + s + "\"");
  }
  if (game == bs::GameType::snooker && is_baseline(text(v, path))) return text(v, path);
  return level_seat(v, path);
}

// ---------------------------------------------------------------------------
// Configs

std::int64_t level_budget(std::string_view level) {
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

std::string table_size(const json& v, const std::string& path, bs::GameType game) {
  Reader r;
  r.game_context = game;
  std::string size;
  r.must(r.table_size(v, path, size));
  return size;
}

GameInput read_config(const json& doc) {
  // "carom" is a key of three-cushion's configs only: the other games'
  // messages keep their list of keys.
  const json* game = doc.is_object() ? find(doc, "game") : nullptr;
  if (game != nullptr && game->is_string() &&
      game->get_ref<const std::string&>() == "three_cushion") {
    object(doc, "",
           {"game", "table", "seed", "breaker", "players", "ai_budget", "physics", "carom"});
  } else {
    object(doc, "", {"game", "table", "seed", "breaker", "players", "ai_budget", "physics"});
  }
  GameInput in;
  in.config = game_config(game_type(required(doc, "", "game"), "game"));
  if (const json* k = find(doc, "carom")) {
    in.config.carom = carom_rules(*k, "carom", in.config.game);
  }
  if (const json* t = find(doc, "table")) {
    in.config.table_size = table_size(*t, "table", in.config.game);
  }
  if (const json* s = find(doc, "seed")) in.seed = seed_value(*s, "seed");
  if (const json* b = find(doc, "breaker")) {
    in.breaker = static_cast<int>(integer(*b, "breaker", 0, 1));
  }
  const json& players = required(doc, "", "players");
  if (!players.is_array() || players.size() != 2) {
    bad("players", "expected an array of two seats (\"human\" or an AI level)");
  }
  for (std::size_t k = 0; k < 2; ++k) {
    in.seats[k] = seat_name(players[k], index_path("players", k), in.config.game);
  }
  if (const json* n = find(doc, "ai_budget")) {
    in.ai_budget = integer(*n, "ai_budget", 1, kMaxBudget);
  }
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

std::unique_ptr<BsGame> make_game(const GameInput& in) {
  // A human seat plays without noise; a computer named at a noise
  // (LEVEL@NOISE) with that noise; an AI seat with its level's noise; the
  // baseline (which has no noise of its own) with tournament noise.
  bs::Seats seats;
  seats.names = in.seats;
  for (std::size_t k = 0; k < 2; ++k) seats.noise[k] = bs::seat_noise(in.seats[k]);
  auto g = std::make_unique<BsGame>(in.config, seats, in.seed, in.breaker);
  g->ai_budget = in.ai_budget;
  return g;
}

// ---------------------------------------------------------------------------
// Acts

namespace {

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

/// Whose turn it is after a recorded action, and why (bs_game_turns_json).
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

}  // namespace

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
  const bs::RecordedAction& ra = g.session.record().actions.back();
  ojson j = ojson::object();
  j["index"] = i;
  j["player"] = ra.player;
  j["kind"] = action_kind(ra.action);
  j["executed"] = bs::json_io::action_json(ra.action);
  if (ra.intended) {
    std::vector<int> numbers;
    (void)g.session.rules().shot_scenario(g.session.state_before(i),
                                          std::get<bs::Shoot>(ra.action).strike, &numbers);
    j["intended"] = bs::json_io::strike_json(*ra.intended);
    j["numbers"] = ints_json(numbers);
  }
  j["ruling"] = bs::json_io::ruling_json(out.ruling);
  j["turn"] = turn_json(ra);
  j["facts"] = bs::json_io::facts_json(out.facts);
  return j;
}

namespace {

bs::AiLevel page_level(const std::string& name, const std::optional<std::int64_t>& budget) {
  const bs::PlayerName n = bs::read_player_name(name);
  bs::AiLevel l = bs::ai_level(n.base);
  if (n.noise) l.noise = *n.noise;  // it plans with the noise it shoots with
  l.threads = 1;
  l.time_budget = 0.0;
  l.simulation_budget = budget ? *budget : level_budget(n.base);
  return l;
}

/// The player named for `g` (or the seat to act's): page_level's AI, or
/// the baseline.
std::unique_ptr<bs::Player> game_player(const BsGame& g, const char* level) {
  const bs::GameState& state = g.session.state();
  if (state.phase == bs::Phase::game_over) fail(BS_ERROR_STATE, "the game is over");
  std::string name;
  const bool snooker = state.game == bs::GameType::snooker;
  const auto out_of_range = [](const std::string& what) { fail(BS_ERROR_OUT_OF_RANGE, what); };
  if (level != nullptr && level[0] != '\0') {
    name = level;
    if (name == kHuman) out_of_range("level: \"human\" is not an AI level");
    if (state.game == bs::GameType::three_cushion) {
      // a player of three-cushion (players.hpp), by the seats' rule
      try {
        (void)seat_name(json(name), "level", state.game);
      } catch (const Failure& f) {
        out_of_range(f.message);
      }
    } else if (!(snooker && is_baseline(name))) {
      try {
        (void)bs::ai_level(bs::read_player_name(name).base);
      } catch (const std::invalid_argument& e) {
        out_of_range(std::string("level: ") + e.what());
      }
    }
  } else {
    name = g.session.record().players[static_cast<std::size_t>(state.player)];
    if (name == kHuman) {
      out_of_range("level: the seat to act (" + std::to_string(state.player) +
                   ") is human: name an AI level for a hint");
    }
  }
  return is_baseline(name) ? bs::make_baseline_player()
                           : bs::make_ai_player(page_level(name, g.ai_budget));
}

}  // namespace

}  // namespace capi::page

using namespace capi;
using namespace capi::page;

extern "C" {

BsStatus bs_game_new_json(const char* config, std::size_t len, BsGame** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    *out = make_game(read_config(parse_text(config, len, "config"))).release();
  });
}

BsStatus bs_game_players_json(const char* game, char** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    if (game == nullptr) fail(BS_ERROR_NULL, "game: missing (a null pointer)");
    const bs::GameType type = game_type(json(std::string(game)), "game");
    ojson j = ojson::object();
    j["game"] = bs::to_string(type);
    ojson players = ojson::array();
    for (const std::string& p : computer_players(type)) players.push_back(p);
    j["players"] = players;
    *out = copy_out(j.dump());
  });
}

BsStatus bs_game_seat(const BsGame* game, std::int32_t seat, const char** out) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    if (seat != 0 && seat != 1) {
      fail(BS_ERROR_OUT_OF_RANGE, "seat: 0 or 1, not " + std::to_string(seat));
    }
    *out = g.session.record().players[static_cast<std::size_t>(seat)].c_str();
  });
}

BsStatus bs_game_ai_budget(const BsGame* game, std::int64_t* out) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    *out = g.ai_budget ? *g.ai_budget : 0;
  });
}

BsStatus bs_game_act_json(BsGame* game, const char* action, std::size_t len, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(game, kGameTag, "game", [&](BsGame& g) {
    need(out, "out");
    Reader r;
    bs::Action a;
    r.must(r.action(parse_text(action, len, "action"), "", a));
    std::string why;
    std::optional<ojson> j = play(g, a, why);
    if (!j) fail(BS_ERROR_ILLEGAL, why);
    *out = copy_out(j->dump());
  });
}

BsStatus bs_game_turns_json(const BsGame* game, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    ojson turns = ojson::array();
    for (const bs::RecordedAction& ra : g.session.record().actions) turns.push_back(turn_json(ra));
    ojson j = ojson::object();
    j["turns"] = turns;
    *out = copy_out(j.dump());
  });
}

BsStatus bs_game_undo_to(BsGame* game, std::size_t n) {
  return on_handle(game, kGameTag, "game", [&](BsGame& g) {
    const std::size_t size = g.session.actions();
    if (n > size) {
      fail(BS_ERROR_OUT_OF_RANGE,
           "n: must be in [0, " + std::to_string(size) + "], not " + std::to_string(n));
    }
    g.session.take_back_to(n);
  });
}

BsStatus bs_game_table_json(const BsGame* game, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    *out = copy_out(bs::json_io::game_table_json(g.session.rules()).dump());
  });
}

BsStatus bs_game_check_placement(const BsGame* game, double x, double y) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    if (auto why = g.session.rules().check_placement(g.session.state(), {x, y})) {
      fail(BS_ERROR_ILLEGAL, *why);
    }
  });
}

BsStatus bs_game_snooker_figures_json(const BsGame* game, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    const bs::GameState& s = g.session.state();
    if (s.game != bs::GameType::snooker) fail(BS_ERROR_STATE, "not a snooker game");
    *out = copy_out(bs::json_io::snooker_figures_json(s).dump());
  });
}

BsStatus bs_game_carom_figures_json(const BsGame* game, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    const bs::GameState& s = g.session.state();
    if (s.game != bs::GameType::three_cushion) fail(BS_ERROR_STATE, "not a three_cushion game");
    *out = copy_out(
        bs::json_io::carom_figures_json(g.session.rules(), s, g.session.record()).dump());
  });
}

BsStatus bs_ai_levels_json(char** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    ojson levels = ojson::array();
    ojson budgets = ojson::object();
    for (const std::string& l : bs::ai_level_names()) {
      levels.push_back(l);
      budgets[l] = level_budget(l);
    }
    ojson j = ojson::object();
    j["levels"] = levels;
    j["budgets"] = budgets;
    *out = copy_out(j.dump());
  });
}

BsStatus bs_player_new_for_game(const BsGame* game, const char* name, BsPlayer** out) {
  if (out != nullptr) *out = nullptr;
  BsPlayer* made = nullptr;
  const BsStatus st = on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    made = std::make_unique<BsPlayer>(game_player(g, name)).release();
  });
  if (st == BS_OK) *out = made;
  return st;
}

}  // extern "C"
