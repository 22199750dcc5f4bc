// Games (BsGame) and computer players (BsPlayer). A BsGame is a
// GameSession (session.hpp), the one place a game advances, so a game
// played here is the game `breakshot match` and the page play with the
// same seed, seats and choices. Actions, states and rulings cross as the
// game records' JSON (src/io/game_json.hpp); a record is write_record's,
// and a record read back is checked by replay() before it is played
// again.

#include "breakshot/game.hpp"

#include <array>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "breakshot.h"
#include "breakshot/player.hpp"
#include "breakshot/players.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/session.hpp"
#include "capi.hpp"
#include "io/game_json.hpp"
#include "io/json_read.hpp"

namespace capi {

namespace {

using bs::json_io::GameReader;

/// A JSON document given as text (`what` names it in messages).
json parse(const char* text, std::size_t len, const char* what) {
  const std::string t = text_arg(text, len, what);
  json doc;
  bs::json_io::ParseOptions options;
  options.root_path = what;
  if (auto problem = bs::json_io::parse_strict(t, doc, options)) {
    fail(BS_ERROR_BAD_JSON, (problem->syntax ? std::string(what) : problem->error.path) + ": " +
                                problem->error.reason);
  }
  return doc;
}

bs::GameType game_type(const char* name) {
  need(name, "game");
  GameReader r;
  bs::GameType g{};
  if (!r.game_type(json(std::string(name)), "game", g)) {
    fail(BS_ERROR_OUT_OF_RANGE, r.error->path + ": " + r.error->reason);
  }
  return g;
}

std::string seat(const char* name, std::size_t k, bs::GameType game) {
  const std::string s = name == nullptr ? std::string(bs::kHumanSeat) : std::string(name);
  if (s == bs::kHumanSeat) return s;
  if (auto why = bs::check_player(s, game)) {
    fail(BS_ERROR_OUT_OF_RANGE, "seats[" + std::to_string(k) + "]: \"human\" or a player: " + *why);
  }
  return s;
}

std::unique_ptr<BsGame> new_game(const BsGameConfig& c) {
  bs::GameConfig config = bs::default_game_config(game_type(c.game));
  if (c.table != nullptr) {
    GameReader r;
    r.game_context = config.game;
    if (!r.table_size(json(std::string(c.table)), "table", config.table_size)) {
      fail(BS_ERROR_OUT_OF_RANGE, r.error->path + ": " + r.error->reason);
    }
  }
  if (c.physics_json != nullptr) {
    const json doc = parse(c.physics_json, std::strlen(c.physics_json), "physics_json");
    GameReader r;
    if (!r.physics(doc, "physics_json", config.physics)) {
      fail(BS_ERROR_BAD_JSON, r.error->path + ": " + r.error->reason);
    }
  }
  if (c.breaker != 0 && c.breaker != 1) {
    fail(BS_ERROR_OUT_OF_RANGE, "breaker: 0 or 1, not " + std::to_string(c.breaker));
  }
  bs::Seats seats;
  for (std::size_t k = 0; k < 2; ++k) {
    seats.names[k] = seat(c.seats[k], k, config.game);
    seats.noise[k] = bs::seat_noise(seats.names[k]);
  }
  try {
    return std::make_unique<BsGame>(config, seats, c.seed, c.breaker);
  } catch (const std::invalid_argument& e) {
    fail(BS_ERROR_OUT_OF_RANGE, e.what());
  }
}

void not_over(const BsGame& g) {
  if (g.session.over()) fail(BS_ERROR_STATE, "the game is over");
}

std::size_t action_index(const BsGame& g, std::size_t index) {
  if (index >= g.session.actions()) {
    fail(BS_ERROR_OUT_OF_RANGE, "index: " + std::to_string(index) + " is not below the " +
                                    std::to_string(g.session.actions()) + " actions played");
  }
  return index;
}

}  // namespace

}  // namespace capi

using namespace capi;

extern "C" {

BsStatus bs_game_new(const char* game, std::uint64_t seed, BsGame** out) {
  BsGameConfig c{};
  c.game = game;
  c.seed = seed;
  return bs_game_new_config(&c, out);
}

BsStatus bs_game_new_config(const BsGameConfig* config, BsGame** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    need(config, "config");
    *out = new_game(*config).release();
  });
}

BsStatus bs_game_from_record_json(const char* text, std::size_t len, BsGame** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    const std::string t = text_arg(text, len, "text");
    auto read = bs::read_record(t);
    if (auto* e = std::get_if<bs::RecordError>(&read)) {
      fail(BS_ERROR_BAD_JSON, "record: " + e->path + ": " + e->reason);
    }
    const bs::GameRecord& rec = std::get<bs::GameRecord>(read);
    const bs::ReplayReport report = bs::replay(rec);
    if (!report.identical) fail(BS_ERROR_INVALID, "record: " + report.message);
    const bs::Seats seats{rec.players, rec.noise};
    auto g = std::make_unique<BsGame>(rec.config, seats, rec.seed, rec.start.rack_seed,
                                      rec.start.breaker);
    for (const bs::RecordedAction& ra : rec.actions) {
      (void)g->session.play_executed(ra.action, ra.intended, ra.noise_seed);
    }
    *out = g.release();
  });
}

void bs_game_free(BsGame* game) {
  if (game == nullptr || game->tag != kGameTag) return;
  game->tag = kFreed;
  delete game;
}

BsStatus bs_game_info(const BsGame* game, BsGameInfo* out) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    const bs::GameState& s = g.session.state();
    out->actions = g.session.actions();
    out->player = s.player;
    out->over = g.session.over() ? 1 : 0;
    out->winner = s.winner;
    out->balls = g.session.rules().ball_count();
  });
}

BsStatus bs_game_state_json(const BsGame* game, char** out) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    *out = nullptr;
    *out = copy_out(bs::json_io::state_json(g.session.state()).dump());
  });
}

BsStatus bs_game_legal_actions_json(const BsGame* game, char** out) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    *out = nullptr;
    const bs::GameState& s = g.session.state();
    *out = copy_out(
        bs::json_io::legal_actions_json(g.session.rules().legal_actions(s), s.game).dump());
  });
}

BsStatus bs_game_apply_json(BsGame* game, const char* action, std::size_t len) {
  return on_handle(game, kGameTag, "game", [&](BsGame& g) {
    const json doc = parse(action, len, "action");
    GameReader r;
    r.game_context = g.session.state().game;
    bs::Action a;
    if (!r.action(doc, "action", a)) {
      fail(BS_ERROR_BAD_JSON, r.error->path + ": " + r.error->reason);
    }
    not_over(g);
    if (auto why = g.session.check(a)) fail(BS_ERROR_ILLEGAL, *why);
    try {
      (void)g.session.play(a);
    } catch (const bs::GameSession::ExecutedRefused& e) {
      fail(BS_ERROR_ILLEGAL,
           std::string("the action as executed (after noise) was refused: ") + e.what());
    } catch (const std::invalid_argument& e) {
      fail(BS_ERROR_ILLEGAL, e.what());
    }
  });
}

BsStatus bs_game_ruling_json(const BsGame* game, std::size_t index, char** out) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    *out = nullptr;
    const auto& ra = g.session.record().actions[action_index(g, index)];
    *out = copy_out(bs::json_io::ruling_json(ra.ruling).dump());
  });
}

BsStatus bs_game_record_json(const BsGame* game, char** out) {
  return on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    *out = nullptr;
    *out = copy_out(bs::write_record(g.session.record()));
  });
}

BsStatus bs_game_shot_simulation(const BsGame* game, std::size_t index, BsSimulation** out) {
  if (out != nullptr) *out = nullptr;
  BsSimulation* made = nullptr;
  const BsStatus st = on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    const auto& ra = g.session.record().actions[action_index(g, index)];
    const auto* shot = std::get_if<bs::Shoot>(&ra.action);
    if (shot == nullptr) {
      fail(BS_ERROR_OUT_OF_RANGE, "index: action " + std::to_string(index) + " is not a shot");
    }
    const bs::GameState& before = g.session.state_before(index);
    const int cue = shot->cue_ball ? *shot->cue_ball : g.session.rules().cue_ball(before);
    std::vector<int> numbers;
    made = run(std::make_shared<const bs::Scenario>(
                   g.session.rules().shot_scenario(before, shot->strike, cue, &numbers)))
               .release();
  });
  if (st == BS_OK) *out = made;
  return st;
}

BsStatus bs_player_new(const char* name, std::int32_t threads, BsPlayer** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    need(name, "name");
    if (threads < 0) {
      fail(BS_ERROR_OUT_OF_RANGE,
           "threads: must be 0 (every core) or more, not " + std::to_string(threads));
    }
    std::unique_ptr<bs::Player> p;
    try {
      p = bs::make_player(name, threads);
    } catch (const std::invalid_argument& e) {
      fail(BS_ERROR_OUT_OF_RANGE, std::string("name: ") + e.what());
    }
    *out = std::make_unique<BsPlayer>(std::move(p)).release();
  });
}

void bs_player_free(BsPlayer* player) {
  if (player == nullptr || player->tag != kPlayerTag) return;
  player->tag = kFreed;
  delete player;
}

BsStatus bs_player_decide_json(BsPlayer* player, const BsGame* game, char** action) {
  return on_handle(player, kPlayerTag, "player", [&](BsPlayer& p) {
    need(action, "action");
    *action = nullptr;
    need(game, "game");
    if (game->tag != kGameTag) fail(BS_ERROR_BAD_HANDLE, "game: not a live game handle");
    not_over(*game);
    const bs::GameState& s = game->session.state();
    if (auto why = bs::check_player(p.player->name(), s.game)) fail(BS_ERROR_ILLEGAL, *why);
    const bs::Action a =
        p.player->decide(game->session.rules(), s, game->session.next_player_seed());
    *action = copy_out(bs::json_io::action_json(a).dump());
  });
}

}  // extern "C"
