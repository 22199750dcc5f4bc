// One game in progress (include/breakshot/session.hpp).
#include "breakshot/session.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace breakshot {

namespace {

// Stream tags ("player", "rack" in ASCII): arbitrary constants that keep
// the players' and the rack's seeds apart from the noise seeds.
constexpr std::uint64_t kPlayerStream = 0x706c61796572ULL;
constexpr std::uint64_t kRackStream = 0x7261636bULL;

}  // namespace

std::uint64_t GameSeeds::rack(std::uint64_t game_seed) {
  return mix_seed(game_seed ^ kRackStream, 0);
}

std::uint64_t GameSeeds::noise(std::uint64_t game_seed, std::size_t action) {
  return mix_seed(game_seed, action);
}

std::uint64_t GameSeeds::player(std::uint64_t game_seed, std::size_t action) {
  return mix_seed(mix_seed(game_seed, kPlayerStream), action);
}

GameSession::GameSession(const GameConfig& config, const Seats& seats, std::uint64_t game_seed,
                         int breaker)
    : GameSession(config, seats, game_seed, GameSeeds::rack(game_seed), breaker) {}

GameSession::GameSession(const GameConfig& config, const Seats& seats, std::uint64_t game_seed,
                         std::uint64_t rack_seed, int breaker)
    : rules_(config) {
  record_.config = config;
  record_.players = seats.names;
  record_.seed = game_seed;
  record_.noise = seats.noise;
  record_.start = rules_.start(rack_seed, breaker);
}

const GameState& GameSession::state() const {
  return record_.actions.empty() ? record_.start : record_.actions.back().after;
}

const GameState& GameSession::state_before(std::size_t i) const {
  return i == 0 ? record_.start : record_.actions[i - 1].after;
}

std::uint64_t GameSession::next_noise_seed() const {
  return GameSeeds::noise(record_.seed, record_.actions.size());
}

std::uint64_t GameSession::next_player_seed() const {
  return GameSeeds::player(record_.seed, record_.actions.size());
}

CueStrike GameSession::executed(const CueStrike& intended, int seat,
                                std::uint64_t noise_seed) const {
  return perturb(intended, record_.noise[static_cast<std::size_t>(seat)],
                 record_.config.ball_radius, noise_seed);
}

std::optional<std::string> GameSession::check(const Action& action) const {
  return rules_.check(state(), action);
}

Outcome GameSession::play(const Action& chosen) {
  if (auto why = check(chosen)) throw std::invalid_argument(*why);
  const std::uint64_t noise_seed = next_noise_seed();
  Action action = chosen;
  std::optional<CueStrike> intended;
  if (auto* shoot = std::get_if<Shoot>(&action)) {
    intended = shoot->strike;
    shoot->strike = executed(shoot->strike, state().player, noise_seed);
  }
  try {
    return play_executed(action, intended, noise_seed);
  } catch (const std::invalid_argument& e) {
    throw ExecutedRefused(e.what());
  }
}

Outcome GameSession::play_executed(const Action& executed_action,
                                   const std::optional<CueStrike>& intended,
                                   std::uint64_t noise_seed) {
  const GameState& before = state();
  Outcome out = rules_.apply(before, executed_action);
  RecordedAction ra;
  ra.player = before.player;
  ra.action = executed_action;
  ra.intended = intended;
  ra.noise_seed = noise_seed;
  ra.ruling = out.ruling;
  ra.after = out.state;
  record_.actions.push_back(std::move(ra));
  return out;
}

void GameSession::take_back_to(std::size_t n) {
  if (n > record_.actions.size()) {
    throw std::invalid_argument("cannot take back to action " + std::to_string(n) + " of " +
                                std::to_string(record_.actions.size()));
  }
  record_.actions.erase(record_.actions.begin() + static_cast<std::ptrdiff_t>(n),
                        record_.actions.end());
}

}  // namespace breakshot
