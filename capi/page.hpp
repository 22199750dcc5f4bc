// What the calls of games as the browser page plays them share
// (capi/page.cpp, link.cpp, playback.cpp): the strict reading of their
// JSON input (io/json_read.hpp's, by the same code as scenarios and
// records: repeated keys and unknown fields are errors) and the seats,
// configs and acts of a game. Internal: only capi/*.cpp include it.

#ifndef BREAKSHOT_CAPI_PAGE_HPP
#define BREAKSHOT_CAPI_PAGE_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "breakshot/game.hpp"
#include "breakshot/players.hpp"
#include "capi.hpp"
#include "io/game_json.hpp"
#include "io/json_read.hpp"

namespace capi::page {

using ojson = nlohmann::ordered_json;
using bs::json_io::index_path;

inline constexpr std::string_view kHuman = "human";
inline constexpr std::int64_t kMaxBudget = 1'000'000'000;

/// A bad input: BS_ERROR_BAD_JSON with "path: what" (what alone for an
/// empty path).
[[noreturn]] void bad(const std::string& path, const std::string& what);

/// The readers of io/game_json.hpp, with must() to throw the first
/// problem found as a bad input.
struct Reader : bs::json_io::GameReader {
  void must(bool ok) const {
    if (!ok) bad(error->path, error->reason);
  }
};

const json* find(const json& obj, std::string_view key);

/// JSON text of `len` bytes named `what`, parsed strictly; `root` is the
/// path of the document in messages.
json parse_text(const char* text, std::size_t len, const std::string& what,
                const std::string& root = "");

/// An object whose keys must all be in `known`.
const json& object(const json& v, const std::string& path,
                   std::initializer_list<std::string_view> known);
const json& required(const json& obj, const std::string& path, std::string_view key);
std::int64_t integer(const json& v, const std::string& path, std::int64_t lo, std::int64_t hi);
const std::string& text(const json& v, const std::string& path);
/// A seed: a decimal string, or an integer number up to 2^53.
std::uint64_t seed_value(const json& v, const std::string& path);

/// "human" or a computer player of `game` (computer_players), either at a
/// named noise (LEVEL@NOISE).
std::string seat_name(const json& v, const std::string& path, bs::GameType game);
/// The computer players a seat of `game` may be, by name: the AI levels,
/// and in snooker also the baseline player; in three-cushion the AI
/// levels that play it (players.hpp's check_player), then the baseline.
std::vector<std::string> computer_players(bs::GameType game);
/// Whether the player `name` (at a named noise or not) is the baseline.
bool is_baseline(std::string_view name);

bs::GameType game_type(const json& v, const std::string& path);
/// A table size of `game`: "7ft", "8ft" or "9ft"; snooker "12ft".
std::string table_size(const json& v, const std::string& path, bs::GameType game);
/// The config of a game type with its own defaults (snooker_config,
/// three_cushion_config).
bs::GameConfig game_config(bs::GameType game);
/// Three-cushion's rules ({"target", "innings_limit",
/// "equalizing_inning"}, each optional); any other game refuses them.
bs::CaromRules carom_rules(const json& v, const std::string& path, bs::GameType game);

/// A game's config, seats, seed, breaker and budget.
struct GameInput {
  bs::GameConfig config;
  std::array<std::string, 2> seats;
  std::uint64_t seed = 0;
  int breaker = 0;
  std::optional<std::int64_t> ai_budget;
};

/// bs_game_new_json's config document.
GameInput read_config(const json& doc);
std::unique_ptr<BsGame> make_game(const GameInput& in);

/// Plays `action` (as chosen) for the seat to act: its report
/// (bs_game_act_json), or nullopt and the game unchanged if the rules
/// refuse it (`why` says why).
std::optional<ojson> play(BsGame& g, const bs::Action& action, std::string& why);

/// Simulations per decision of the page's AI, by level (page.cpp).
std::int64_t level_budget(std::string_view level);

}  // namespace capi::page

#endif  // BREAKSHOT_CAPI_PAGE_HPP
