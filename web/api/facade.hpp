// The parts of the facade of the browser version (web/api/web_api.hpp,
// docs/web.md) and what they share. Internal: only web/api/*.cpp include
// it.
//
//   facade.cpp    errors, and the reading of JSON input
//   playback.cpp  playbacks (BsPlayback): frames and events
//   game.cpp      games (BsGame): configs, actions, the AI's, state,
//                 table, undo
//   link.cpp      links: a game as "v2." text and back ("v1." read too)
//   web_api.cpp   the C API's entry points, each a call into the parts,
//                 and bs_version with the engine's defaults
//
// Replies are built with nlohmann::ordered_json and dumped compactly: its
// number printing (Grisu2 on the bits, integer arithmetic only) and its
// parsing (strtod, correctly rounded in glibc and musl) are the same code
// native and wasm, so a reply is the same bytes on both. Doubles are
// printed so that they read back exactly (JavaScript's JSON.parse too).

#ifndef BREAKSHOT_WEB_FACADE_HPP
#define BREAKSHOT_WEB_FACADE_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <initializer_list>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/players.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/session.hpp"
#include "breakshot/simulation.hpp"
#include "io/game_json.hpp"
#include "io/json_read.hpp"

namespace bs = breakshot;
using ojson = nlohmann::ordered_json;
using json = nlohmann::json;

namespace facade {

inline constexpr std::string_view kHuman = "human";

// ---------------------------------------------------------------------------
// Errors never cross the boundary: every entry point catches everything
// and answers {"error": "..."} (those that return a pointer: NULL, and
// the error in bs_last_error); input errors name the JSON path.

/// A bad input: its path and what is wrong with it.
struct BadInput {
  std::string message;
};

[[noreturn]] void bad(const std::string& path, const std::string& what);

std::string error_json(const std::string& message);

/// bs_last_error's reply, and whether it holds an error: a failed call
/// that returns NULL sets both; every call that succeeds clears the flag
/// (a flag, so that clearing costs no allocation on the page's per-frame
/// calls), and bs_last_error then answers {"error": "no error"}.
extern thread_local std::string g_last_error;
extern thread_local bool g_has_error;
/// bs_last_error's text: the error, or {"error": "no error"}.
const char* last_error();

/// Runs `body`, turning any exception into {"error"}; a success clears
/// bs_last_error.
template <class F>
std::string guarded(F&& body) {
  try {
    std::string reply = body();
    g_has_error = false;
    return reply;
  } catch (const BadInput& e) {
    return error_json(e.message);
  } catch (const std::bad_alloc&) {
    return error_json("out of memory");
  } catch (const std::exception& e) {
    return error_json(std::string("internal error: ") + e.what());
  } catch (...) {
    return error_json("internal error");
  }
}

template <class T>
T* fail_null(const std::string& message) {
  g_last_error = error_json(message);
  g_has_error = true;
  return nullptr;
}

/// Runs a body that returns a pointer: the pointer (bs_last_error
/// cleared), or NULL with bs_last_error set to the error.
template <class T, class F>
T* guarded_ptr(F&& body) {
  try {
    T* p = body();
    g_has_error = false;
    return p;
  } catch (const BadInput& e) {
    return fail_null<T>(e.message);
  } catch (const std::bad_alloc&) {
    return fail_null<T>("out of memory");
  } catch (const std::exception& e) {
    return fail_null<T>(std::string("internal error: ") + e.what());
  } catch (...) {
    return fail_null<T>("internal error");
  }
}

/// Runs a *_new body: the handle, or NULL with bs_last_error set.
template <class T, class F>
T* guarded_new(F&& body) {
  return guarded_ptr<T>([&] { return body().release(); });
}

/// A reply kept in a handle's slot until the next call on it.
const char* keep(std::string& slot, std::string text);

// The replies of calls on a NULL handle.
const char* null_handle();

/// A reply the caller owns (bs_free).
char* copy_out(const std::string& s);

// ---------------------------------------------------------------------------
// Reading JSON input: io/json_read.hpp's strict reading, its problems
// thrown as bad inputs. JSON input is read as strictly as scenarios and
// records, by the same code: repeated keys and unknown fields are errors.

using bs::json_io::index_path;

/// The readers of io/game_json.hpp, with must() to throw the first
/// problem found.
struct Reader : bs::json_io::GameReader {
  void must(bool ok) const {
    if (!ok) bad(error->path, error->reason);
  }
};

const json* find(const json& obj, std::string_view key);

/// The JSON text of an argument named `what`, parsed strictly (a repeated
/// key is an error too); `root` is the path of the document in messages.
json parse_text(const char* text, const std::string& what, const std::string& root = "");

/// An object whose keys must all be in `known`.
const json& object(const json& v, const std::string& path,
                   std::initializer_list<std::string_view> known);

const json& required(const json& obj, const std::string& path, std::string_view key);

std::int64_t integer(const json& v, const std::string& path, std::int64_t lo, std::int64_t hi);

const std::string& text(const json& v, const std::string& path);

/// A seed: a decimal string, or an integer number up to 2^53.
std::uint64_t seed_value(const json& v, const std::string& path);

/// A computer player's name read (NAME or NAME@NOISE, players.hpp), or
/// an error at `path` naming what is wrong.
bs::PlayerName computer_name(const std::string& name, const std::string& path);

/// "human" or a known AI level (either at a named noise: LEVEL@NOISE).
std::string seat_name(const json& v, const std::string& path);
/// "human" or a computer player of `game` (computer_players).
std::string seat_name(const json& v, const std::string& path, bs::GameType game);

/// The computer players a seat of `game` may be, by name: the AI levels,
/// and in snooker also the baseline player; in three-cushion the AI
/// levels that play it (players.hpp's check_player), then the baseline.
std::vector<std::string> computer_players(bs::GameType game);
/// Whether the player `name` (one of computer_players, at a named noise
/// or not) is the baseline.
bool is_baseline(std::string_view name);

}  // namespace facade

// ---------------------------------------------------------------------------
// Playbacks (playback.cpp)

struct BsPlayback {
  explicit BsPlayback(const bs::Scenario& s) : scenario(s), sim(scenario) {}
  bs::Scenario scenario;
  bs::Simulation sim;
  bool limit = false;  // max_events stopped a frame
  std::string reply;
  std::vector<double> frame;  // the last frame (layout: kFrame* in playback.cpp)
  std::vector<double> spins;  // bs_playback_spins's buffer: wx, wy, wz per ball
  /// A three-cushion shot's playback (bs_game_shot_playback): the ball
  /// number of each scenario ball, and the ball struck; -1 otherwise.
  std::vector<int> numbers;
  int carom_struck = -1;
};

namespace facade {

/// bs_playback_frame's reply: the frame computed by compute_frame, as JSON.
std::string frame_json(BsPlayback& pb, double t);
/// bs_playback_frame_data's reply: the same frame as doubles, in pb.frame.
const double* frame_data(BsPlayback& pb, double t);
/// bs_playback_spins's reply: the balls' spins at the playback's time (its
/// last frame's, or the start), in pb.spins (3 per ball).
const double* spins_data(BsPlayback& pb);
/// {"from": from, "events": [...]}, each event as the result file writes
/// it (io/result_json.hpp: ids for balls, names for cushions and pockets).
std::string events_json(const BsPlayback& pb, int from);
/// bs_playback_carom_count's reply: the count of a three-cushion shot's
/// playback over its events so far (carom_count, game.hpp):
/// {"cushions", "hit" (ball numbers), "done", "made"}.
std::string carom_count_json(const BsPlayback& pb);
/// A scenario given as JSON text (read_scenario, scenario_io.hpp).
bs::Scenario scenario_from(const char* scenario_json);

}  // namespace facade

// ---------------------------------------------------------------------------
// Games (game.cpp)

struct BsGame {
  BsGame(const bs::GameConfig& config, const std::array<std::string, 2>& seat_names,
         std::uint64_t seed, int breaker, std::optional<std::int64_t> budget)
      : session(config, seats_of(seat_names), seed, breaker), seats(seat_names), ai_budget(budget) {}

  /// A human seat plays without noise; a computer named at a noise
  /// (LEVEL@NOISE) with that noise; an AI seat with its level's noise; the
  /// baseline (which has no noise of its own) with tournament noise.
  static bs::Seats seats_of(const std::array<std::string, 2>& names) {
    bs::Seats s;
    s.names = names;
    for (std::size_t k = 0; k < 2; ++k) s.noise[k] = bs::seat_noise(names[k]);
    return s;
  }

  const bs::Rules& rules() const { return session.rules(); }
  const bs::GameRecord& record() const { return session.record(); }
  const bs::GameState& state() const { return session.state(); }
  const bs::GameState& state_before(std::size_t i) const { return session.state_before(i); }

  bs::GameSession session;
  std::array<std::string, 2> seats;
  std::optional<std::int64_t> ai_budget;
  std::string reply;
};

namespace facade {

/// Simulations per AI decision in the browser, by level (game.cpp).
std::int64_t web_budget(std::string_view level);

struct GameConfigInput {
  bs::GameConfig config;
  std::array<std::string, 2> seats;
  std::uint64_t seed = 0;
  int breaker = 0;
  std::optional<std::int64_t> ai_budget;
};

inline constexpr std::int64_t kMaxBudget = 1'000'000'000;

bs::GameType game_type(const json& v, const std::string& path);
/// A table size of `game`: "7ft", "8ft" or "9ft"; snooker "12ft".
std::string table_size(const json& v, const std::string& path, bs::GameType game);
/// The config of a game type with its own defaults (snooker_config,
/// three_cushion_config).
bs::GameConfig game_config(bs::GameType game);
/// Three-cushion's rules ({"target", "innings_limit",
/// "equalizing_inning"}, each optional); any other game refuses them.
bs::CaromRules carom_rules(const json& v, const std::string& path, bs::GameType game);
/// {"game": game, "players": computer_players(game)}.
std::string players_json(const char* game);
/// bs_game_new's config: {"game", "table", "seed", "breaker", "players",
/// "ai_budget", "physics": {"airborne"}}. Snooker starts from
/// snooker_config (the 12 ft table, snooker balls).
GameConfigInput read_config(const json& doc);
std::unique_ptr<BsGame> make_game(const GameConfigInput& in);

/// bs_game_state's reply: the state as game records write it
/// (src/io/game_json.hpp), then the seats, the number of actions and what
/// the rules allow next (legal_actions_json); in snooker also
/// "snooker_figures" (snooker_figures_json), in three-cushion
/// "carom_figures" (carom_figures_json).
ojson state_json(const BsGame& g);
/// bs_game_table's reply: the table as src/io/table_json.hpp encodes it
/// (game_table_json), its markings included.
ojson table_json(const BsGame& g);
/// bs_game_check_placement's reply: {"ok"} and, if not, {"reason"}.
std::string check_placement_json(const BsGame& g, double x, double y);

/// Plays `action` (as chosen) for the seat to act; nullopt and the game
/// unchanged if the rules refuse it (`why` says why).
std::optional<ojson> play(BsGame& g, const bs::Action& action, std::string& why);
/// Whose turn it is after a recorded action, and why: {"next": seat (-1
/// once the game is over), "why": "continues" (the same player shoots
/// again), "passes" (the turn passes without a foul), "foul" (it passes
/// after a foul), "decides" (a decision is due: `next` makes it),
/// "breaks" (`next` breaks a new rack) or "game_over"}.
ojson turn_json(const bs::RecordedAction& ra);
/// bs_game_turns's reply: {"turns": [turn_json of each action]}.
std::string turns_json(const BsGame& g);
/// bs_game_act's reply: the action played, its ruling, whose turn it is
/// next ("turn", turn_json) and the state after (play), or {"error"} if
/// the rules refuse it.
std::string act_json(BsGame& g, const char* action_text);
/// bs_game_ai_action's reply: {"action"} as the AI of `level` (or of the
/// seat to act, when null or empty) chooses it.
std::string ai_action_json(BsGame& g, const char* level);

/// bs_game_shot_playback's playback: the scenario of action `index` (a
/// shot) from the state before it.
std::unique_ptr<BsPlayback> shot_playback(const BsGame& g, int index);
/// bs_game_undo_to's reply: the state once the game is taken back to its
/// first `n` actions.
std::string undo_to_json(BsGame& g, int n);

}  // namespace facade

// ---------------------------------------------------------------------------
// Links (link.cpp)

namespace facade {

/// bs_game_link's reply: {"link": "v2...."}.
std::string link_json(const BsGame& g);
/// bs_game_from_link's game: the link's actions replayed through the
/// rules; a bad input naming the first action refused.
std::unique_ptr<BsGame> game_from_link(const char* link);

}  // namespace facade

#endif  // BREAKSHOT_WEB_FACADE_HPP
