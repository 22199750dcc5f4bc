// The computer players by name, and matches between players named so.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "breakshot/match.hpp"
#include "breakshot/player.hpp"

namespace breakshot {

/// A player's name read: `NAME`, or `NAME@NOISE` for that player at a
/// noise of its own choosing (docs/ai.md, "A player at a named noise"):
/// NOISE is any spec parse_noise reads (`0.5x`, `none`, `tournament`,
/// `custom:...`), absolute, not relative to the player's own. An AI level
/// so named also plans with that noise; the plain name keeps the level's
/// own (the baseline's: the match's).
struct PlayerName {
  std::string base;                 ///< "champion", "baseline", ...
  std::optional<NoiseModel> noise;  ///< the noise after '@', when written
  std::string noise_spec;           ///< its text ("" without '@')
};

/// `name` split at its '@'. Throws std::invalid_argument naming the
/// player and what is wrong: nothing before the '@', nothing after it, a
/// second '@', or a noise parse_noise refuses. Whether the base names a
/// player is check_player's question.
PlayerName read_player_name(std::string_view name);

/// The baseline player: ghost-ball aim at every legal ball and pocket,
/// the easiest unblocked shot (docs/rules.md, "Baseline player"). Its
/// aim uses libm (atan2, sin, cos), so its choices are reproducible on
/// one maths library; records store the executed actions, so a replay
/// never depends on that.
std::unique_ptr<Player> make_baseline_player();

/// A player by name ("baseline", "champion", "champion@0.5x"); throws
/// std::invalid_argument for an unknown name, listing the known ones, or a
/// bad name (read_player_name). A player named at a noise says that noise
/// (Player::noise) and its full name (Player::name).
std::unique_ptr<Player> make_player(std::string_view name);

/// make_player, with an AI level's worker threads for one decision set to
/// `threads` (0: every core; AiLevel::threads). Its decisions are the
/// same for any count; the baseline has no threads.
std::unique_ptr<Player> make_player(std::string_view name, int threads);

/// The names make_player knows: "baseline", then the AI levels (each
/// also as NAME@NOISE).
std::vector<std::string> player_names();

/// The names of the players that play `game`: every player plays every
/// game.
std::vector<std::string> player_names(GameType game);

/// Why the player `name` cannot play `game` (a bad or unknown name, or a
/// player that does not play that game), naming the game; nullopt when it
/// can.
std::optional<std::string> check_player(std::string_view name, GameType game);

/// The seat name of a person in a game played through the browser's
/// facade or the C API: their strikes are played as given.
inline constexpr std::string_view kHumanSeat = "human";

/// The noise a seat of such a game shoots with, by the seat's name: none
/// for kHumanSeat; a player named at a noise (NAME@NOISE), that noise; an
/// AI level, its own; the baseline, tournament noise. Throws
/// std::invalid_argument for a name make_player does not know.
NoiseModel seat_noise(std::string_view name);

/// empty_summary (match.hpp) for the players named in options.players,
/// with each one's own noise (make_player(name)->noise(), else
/// options.noise). Throws std::invalid_argument for an unknown name.
MatchSummary empty_summary(const MatchOptions& options);

/// play_match (match.hpp) between make_player(options.players[0]) and
/// make_player(options.players[1]), options.jobs games at once: with more
/// than one, each game thread's AI players decide on their share of the
/// cores (at least one thread each). Throws std::invalid_argument for an
/// unknown player name, a player that does not play the game
/// (check_player) or bad options.
MatchSummary play_match(const MatchOptions& options, const RecordSink& sink = {});

}  // namespace breakshot
