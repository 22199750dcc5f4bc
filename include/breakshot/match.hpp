// Games and matches between computer players, with shot noise, recorded
// action by action (record.hpp) and summed up per player.
//
// Everything random comes from seeds derived from the match seed with
// mix_seed, so a match is a pure function of its options: the same
// options give the same records and the same summary, byte for byte.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/record.hpp"

namespace breakshot {

/// Plays one game to its end. `breaker` (0 or 1) breaks the first rack;
/// the rack comes from a seed derived from `game_seed`. Each seat shoots
/// with its player's own noise (Player::noise()) or, for a player without
/// one, with `noise`; the record keeps both seats' noise. For action i the
/// acting player decides with a seed derived from game_seed and i, and a
/// shot is played as perturb(strike, the seat's noise, ball radius,
/// noise_seed) with noise_seed = mix_seed(game_seed, i). Throws
/// std::logic_error naming the player and the reason if a player chooses
/// an action the rules refuse, or if the game runs far beyond the rules'
/// max_shots (a guard: the stalemate clause should have ended it).
GameRecord play_game(const Rules& rules, Player& p0, Player& p1, int breaker,
                     std::uint64_t game_seed, const NoiseModel& noise);

struct MatchOptions {
  GameType game = GameType::eight_ball;
  /// "7ft", "8ft" or "9ft"; snooker "12ft" (with snooker balls:
  /// snooker_config); three-cushion "10ft" (three_cushion_config).
  std::string table_size = "9ft";
  /// The physics the games are played with (GameConfig::physics).
  GamePhysics physics;
  /// Three-cushion's target, innings limit and equalizing inning
  /// (GameConfig::carom); left at its defaults in the other games.
  CaromRules carom;
  std::array<std::string, 2> players;  ///< the seats' names (players.hpp: make_player)
  int games = 1;
  /// The index of the first game played: a match of `games` games plays
  /// games first_game .. first_game + games - 1, each exactly as one long
  /// match from game 0 plays it (game g is seeded by g alone), so a long
  /// match can be played in chunks and their summaries added
  /// (add_summary). At least 0, and first_game + games must fit an int.
  int first_game = 0;
  std::uint64_t seed = 0;
  /// The noise of players without a noise of their own (Player::noise()).
  NoiseModel noise;
  /// Measure how long each player's decisions take (wall clock) and put
  /// the figures in the summary. Off by default: times differ from run to
  /// run, and without them the summary is a function of the options.
  bool timing = false;
  /// When a game fails (play_game throws), throw a MatchGameError naming
  /// the game and its seed instead of the game's own exception, so that
  /// the game can be played again alone (first_game = g, games = 1). Off
  /// by default.
  bool name_failing_game = false;
  /// Games played at once, each on its own thread with its own pair of
  /// players (0: one per core). The summary, the records and the order
  /// the sink receives them in are the same for any number: game g is a
  /// function of g alone, and finished games are added in index order.
  /// Only the decision times (timing) differ, as the threads share the
  /// cores. Used by the overload of play_match that makes players.
  int jobs = 1;
};

/// A game of a match failed (MatchOptions::name_failing_game). what() is
/// "game G (seed S): " and the game's own message; S is the game's seed,
/// mix_seed(match seed, G).
class MatchGameError : public std::runtime_error {
 public:
  MatchGameError(int game, std::uint64_t game_seed, const std::string& reason);
  int game() const { return game_; }
  std::uint64_t game_seed() const { return game_seed_; }
  /// The game's own message.
  const std::string& reason() const { return reason_; }

 private:
  int game_;
  std::uint64_t game_seed_;
  std::string reason_;
};

/// A snooker player's figures over a match (PlayerStats::snooker). A
/// visit is a turn at the table; its break is the points it scored.
struct SnookerStats {
  /// Points at the end of the player's frames (the frame scores: pots
  /// and the opponent's fouls), summed.
  int points = 0;
  int highest_break = 0;
  int breaks_50 = 0;   ///< visits that scored 50 points or more
  int breaks_100 = 0;  ///< visits that scored 100 points or more
  /// Visits that scored at least one point, and their points summed.
  int scoring_visits = 0;
  int break_points = 0;
  /// Penalty points the player's fouls gave the opponent.
  int foul_points_given = 0;
  /// The player's fouls that were misses (a ball on could have been hit
  /// full: SnookerRuling::miss).
  int misses = 0;
  /// break_points / scoring_visits (0 without such visits): the mean
  /// break over visits that scored.
  double mean_break() const;
  bool operator==(const SnookerStats&) const = default;
};

/// A three-cushion player's figures over a match (PlayerStats::carom). A
/// run is the points of one inning.
struct CaromStats {
  int points = 0;       ///< points scored, summed over the games
  int highest_run = 0;  ///< the most points of one inning
  /// The innings that scored at least one point.
  int scoring_innings = 0;
  bool operator==(const CaromStats&) const = default;
};

/// One player's figures over a match. Everything counts only the
/// player's own actions.
struct PlayerStats {
  std::string name;
  /// The noise the player's shots are played with, as a to_string(NoiseModel)
  /// spec: its own (Player::noise()), else the match's.
  std::string noise;
  int games_won = 0;
  /// Break shots taken (a break after a re-rack counts again).
  int breaks = 0;
  /// Racks won from the player's own break without the opponent taking a
  /// single shot after it (a decision such as passing a push-out back is
  /// not a shot).
  int break_and_runs = 0;
  /// Turns at the table begun, as GameState::innings counts them (the
  /// break is the breaker's first inning; every time the turn passes, the
  /// incoming player begins one).
  int innings = 0;
  int shots = 0;
  /// Object balls pocketed on the player's shots, fouls and breaks
  /// included, and balls spotted again after falling (the 9 on a foul)
  /// too. The cue ball never counts.
  int balls_pocketed = 0;
  /// Fouls by kind, by the names of to_string(Foul); every kind is
  /// listed, 0 included. One shot may commit several.
  std::map<std::string, int> fouls;
  /// Seconds per decision, in order (MatchOptions::timing only).
  std::vector<double> decision_seconds;

  /// balls_pocketed / innings (0 without innings).
  double balls_per_inning() const;
  /// Pot attempts: shots other than breaks that carried a call (8-ball
  /// calls; 9-ball players may call too, for this count). Made: the
  /// called ball fell in the called pocket with no foul
  /// (Ruling::call_made).
  int pot_attempts = 0;
  int pots_made = 0;
  /// pots_made / pot_attempts (0 without attempts).
  double pot_rate() const;
  /// Snooker's figures; empty in the other games.
  std::optional<SnookerStats> snooker;
  /// Three-cushion's figures; empty in the other games.
  std::optional<CaromStats> carom;
  /// Three-cushion: carom->points / innings, the general average (0
  /// without innings or outside three-cushion).
  double general_average() const;
};

/// Games first .. first + count - 1 of a match.
struct GameRange {
  int first = 0;
  int count = 0;
  bool operator==(const GameRange&) const = default;
};

struct MatchSummary {
  GameType game = GameType::eight_ball;
  std::string table_size = "9ft";
  std::uint64_t seed = 0;
  NoiseModel noise;  ///< the match's noise (MatchOptions::noise)
  GamePhysics physics;  ///< MatchOptions::physics
  CaromRules carom;     ///< MatchOptions::carom
  /// The games the summary covers, by index: ascending, disjoint and
  /// never adjacent (adjacent ranges are one range). play_match sets one
  /// range (first_game, games); add_summary joins two summaries' ranges.
  /// Empty for an empty_summary; add_game leaves it alone (a record does
  /// not know its index).
  std::vector<GameRange> ranges;
  int games_played = 0;
  /// Games without a winner: ended by the stalemate clause or, in
  /// three-cushion, drawn (docs/rules.md).
  int draws = 0;
  std::array<PlayerStats, 2> players;
};

/// A summary with no games yet: the options' settings, the player names,
/// each seat's effective noise (`seat_noise`: the player's own, else
/// options.noise), every foul kind of the game at 0. Throws
/// std::invalid_argument for a game whose rules cannot be built (an
/// unknown table size).
MatchSummary empty_summary(const MatchOptions& options,
                           const std::array<NoiseModel, 2>& seat_noise);

/// Adds a finished game (phase game_over at the end) to the summary; the
/// record's seat 0 is summary.players[0]. Throws std::invalid_argument for
/// a game that is not over.
void add_game(MatchSummary& summary, const GameRecord& record);

/// Adds `part`, the summary of other games of the same match, into
/// `into`: every count (games, draws, each player's wins, breaks,
/// innings, shots, balls, pot attempts and pots made, fouls by kind, the
/// snooker and three-cushion figures) is
/// summed, decision times are appended, and the game ranges are joined.
/// The rates (balls_per_inning, pot_rate) are derived from the summed
/// counts, so adding the summaries of chunks that cover games 0 .. N-1,
/// in any grouping and any order, gives the summary of one match of N
/// games, equal in every field. Throws std::invalid_argument naming the
/// field (nothing added) when the two are not of the same match (game,
/// table_size, physics, the three-cushion options, seed, noise, a player's name or noise, the foul
/// kinds) or when their games overlap.
void add_summary(MatchSummary& into, const MatchSummary& part);

/// Where a match sends each finished game's record: game g (from 0) and
/// its record. io's record_files (match_io.hpp) writes them to a folder.
using RecordSink = std::function<void(int game, const GameRecord& record)>;

/// Plays options.games games between p0 (seat 0) and p1, games
/// options.first_game .. first_game + games - 1: game g is broken by seat
/// g % 2, with the game seed mix_seed(options.seed, g). Each record goes
/// to `sink` (if any) with its index g as soon as the game ends.
/// options.players are the names the summary gives the seats. Throws
/// std::invalid_argument for bad options (an unknown table, fewer than one
/// game, a negative first_game or a first_game + games beyond INT_MAX),
/// and whatever play_game and the sink throw.
MatchSummary play_match(const MatchOptions& options, Player& p0, Player& p1,
                        const RecordSink& sink = {});

/// A fresh player for seat 0 or 1.
using PlayerFactory = std::function<std::unique_ptr<Player>(int seat)>;

/// play_match with options.jobs games at once (0: one per core, never
/// more than the games): each worker thread gets its own two players from
/// `make` (made before any game starts) and takes the next game index;
/// finished games are added to the summary and handed to `sink` in index
/// order, from whichever thread finishes the game that completes the
/// order (the sink is never called twice at once). The summary equals the
/// one-thread summary field for field (decision times apart); the first
/// failing game in index order is the error thrown, as with one thread,
/// after every worker has stopped. Throws std::invalid_argument for
/// options.jobs < 0.
MatchSummary play_match(const MatchOptions& options, const PlayerFactory& make,
                        const RecordSink& sink = {});

/// The number of game threads options.jobs asks for, for `games` games:
/// jobs, or the cores for 0, never more than the games, at least 1.
int match_threads(int jobs, int games);

}  // namespace breakshot
