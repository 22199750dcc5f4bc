// The computer players by name (include/breakshot/players.hpp).
#include "breakshot/players.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "breakshot/ai.hpp"

namespace breakshot {

std::vector<std::string> player_names() {
  std::vector<std::string> names{"baseline"};
  for (const std::string& l : ai_level_names()) names.push_back(l);
  return names;
}

std::vector<std::string> player_names(GameType /*game*/) { return player_names(); }

std::optional<std::string> check_player(std::string_view name, GameType game) {
  const std::vector<std::string> all = player_names();
  const std::vector<std::string> able = player_names(game);
  std::string known;
  for (const std::string& n : able) known += (known.empty() ? "" : ", ") + n;
  if (std::find(all.begin(), all.end(), name) == all.end()) {
    std::string every;
    for (const std::string& n : all) every += (every.empty() ? "" : ", ") + n;
    return "unknown player \"" + std::string(name) + "\" (known players: " + every + ")";
  }
  if (std::find(able.begin(), able.end(), name) == able.end()) {
    return "player \"" + std::string(name) + "\" does not play " + std::string(to_string(game)) +
           " (players of " + std::string(to_string(game)) + ": " + known + ")";
  }
  return std::nullopt;
}

std::unique_ptr<Player> make_player(std::string_view name) {
  if (name == "baseline") return make_baseline_player();
  // The AI levels (include/breakshot/ai.hpp) by their names.
  const std::vector<std::string> levels = ai_level_names();
  if (std::find(levels.begin(), levels.end(), name) != levels.end()) {
    return make_ai_player(ai_level(name));
  }
  std::string known;
  for (const std::string& n : player_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown player \"" + std::string(name) + "\" (known players: " +
                              known + ")");
}

MatchSummary empty_summary(const MatchOptions& options) {
  std::array<NoiseModel, 2> noise;
  for (std::size_t p = 0; p < 2; ++p) {
    noise[p] = make_player(options.players[p])->noise().value_or(options.noise);
  }
  return empty_summary(options, noise);
}

MatchSummary play_match(const MatchOptions& options, const RecordSink& sink) {
  if (options.games < 1) {
    throw std::invalid_argument("the number of games must be at least 1, not " +
                                std::to_string(options.games));
  }
  for (const std::string& name : options.players) {
    if (auto why = check_player(name, options.game)) throw std::invalid_argument(*why);
  }
  const std::unique_ptr<Player> p0 = make_player(options.players[0]);
  const std::unique_ptr<Player> p1 = make_player(options.players[1]);
  return play_match(options, *p0, *p1, sink);
}

}  // namespace breakshot
