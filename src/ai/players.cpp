// The computer players by name (include/breakshot/players.hpp).
#include "breakshot/players.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "breakshot/ai.hpp"
#include "breakshot/noise.hpp"

namespace breakshot {

std::vector<std::string> player_names() {
  std::vector<std::string> names{"baseline"};
  for (const std::string& l : ai_level_names()) names.push_back(l);
  return names;
}

std::vector<std::string> player_names(GameType /*game*/) { return player_names(); }

PlayerName read_player_name(std::string_view name) {
  PlayerName out;
  const std::size_t at = name.find('@');
  out.base = std::string(name.substr(0, at));
  if (at == std::string_view::npos) return out;
  const auto bad = [&](const std::string& why) {
    throw std::invalid_argument("player \"" + std::string(name) + "\": " + why +
                                " (a player at a named noise is NAME@NOISE, for example "
                                "champion@0.5x)");
  };
  out.noise_spec = std::string(name.substr(at + 1));
  if (out.base.empty()) bad("no player before the '@'");
  if (out.noise_spec.empty()) bad("no noise after the '@'");
  if (out.noise_spec.find('@') != std::string::npos) bad("more than one '@'");
  try {
    out.noise = parse_noise(out.noise_spec);
  } catch (const std::invalid_argument& e) {
    // parse_noise's message begins "noise: " and lists the accepted specs.
    throw std::invalid_argument("player \"" + std::string(name) + "\": " + e.what());
  }
  return out;
}

std::optional<std::string> check_player(std::string_view full_name, GameType game) {
  std::string_view name = full_name;
  PlayerName read;
  try {
    read = read_player_name(full_name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  name = read.base;
  const std::vector<std::string> all = player_names();
  const std::vector<std::string> able = player_names(game);
  std::string known;
  for (const std::string& n : able) known += (known.empty() ? "" : ", ") + n;
  if (std::find(all.begin(), all.end(), name) == all.end()) {
    std::string every;
    for (const std::string& n : all) every += (every.empty() ? "" : ", ") + n;
    return "unknown player \"" + std::string(name) + "\" (known players: " + every +
           "; any of them also as NAME@NOISE)";
  }
  if (std::find(able.begin(), able.end(), name) == able.end()) {
    return "player \"" + std::string(name) + "\" does not play " + std::string(to_string(game)) +
           " (players of " + std::string(to_string(game)) + ": " + known + ")";
  }
  return std::nullopt;
}

namespace {

/// A player at a named noise: the inner player's decisions, its own name
/// and noise.
class NamedNoisePlayer final : public Player {
 public:
  NamedNoisePlayer(std::unique_ptr<Player> inner, std::string name, NoiseModel noise)
      : inner_(std::move(inner)), name_(std::move(name)), noise_(noise) {}
  std::string name() const override { return name_; }
  std::optional<NoiseModel> noise() const override { return noise_; }
  Action decide(const Rules& rules, const GameState& state, std::uint64_t seed) override {
    return inner_->decide(rules, state, seed);
  }

 private:
  std::unique_ptr<Player> inner_;
  std::string name_;
  NoiseModel noise_;
};

std::unique_ptr<Player> named_player(std::string_view full_name, std::optional<int> threads) {
  const PlayerName read = read_player_name(full_name);
  const std::string& name = read.base;
  const auto named = [&](std::unique_ptr<Player> p) -> std::unique_ptr<Player> {
    if (!read.noise) return p;
    return std::make_unique<NamedNoisePlayer>(std::move(p), std::string(full_name), *read.noise);
  };
  if (name == "baseline") return named(make_baseline_player());
  // The AI levels (include/breakshot/ai.hpp) by their names; one named at
  // a noise plans with it too.
  const std::vector<std::string> levels = ai_level_names();
  if (std::find(levels.begin(), levels.end(), name) != levels.end()) {
    AiLevel level = ai_level(name);
    if (threads) level.threads = *threads;
    if (read.noise) level.noise = *read.noise;
    return named(make_ai_player(level));
  }
  std::string known;
  for (const std::string& n : player_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown player \"" + std::string(name) + "\" (known players: " +
                              known + "; any of them also as NAME@NOISE)");
}

}  // namespace

std::unique_ptr<Player> make_player(std::string_view name) {
  return named_player(name, std::nullopt);
}

std::unique_ptr<Player> make_player(std::string_view name, int threads) {
  if (threads < 0) {
    throw std::invalid_argument("threads: must be 0 (every core) or more, not " +
                                std::to_string(threads));
  }
  return named_player(name, threads);
}

NoiseModel seat_noise(std::string_view name) {
  if (name == kHumanSeat) return NoiseModel{};
  const PlayerName read = read_player_name(name);
  if (read.noise) return *read.noise;
  // The baseline has no noise of its own: at a table with people, it
  // shoots at tournament noise.
  return make_player(name)->noise().value_or(parse_noise("tournament"));
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
  const int games_at_once = match_threads(options.jobs, options.games);
  const PlayerFactory make = [&](int seat) {
    const std::string& name = options.players[static_cast<std::size_t>(seat)];
    // One game at a time: its decisions use every core (the level's own
    // setting); several: each its share.
    if (games_at_once == 1) return make_player(name);
    const int cores = static_cast<int>(std::thread::hardware_concurrency());
    return make_player(name, std::max(1, cores / games_at_once));
  };
  return play_match(options, make, sink);
}

}  // namespace breakshot
