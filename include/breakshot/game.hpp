// Games: 8-ball and 9-ball by the WPA rules, snooker by the WPBSA rules,
// three-cushion billiards by the UMB rules (docs/rules.md).
//
// A game is a plain value (GameState) and the rules are a function of it:
// Rules::apply(state, action) returns the next state, the shot's events
// and the ruling. Outcomes are read from the shot's event list (first ball
// hit, cushion contacts, pockets), so the rules and the physics never
// disagree. Balls are numbered as on the table: 0 is the cue ball, then
// 1-15 (8-ball) or 1-9 (9-ball); in snooker 1-15 are the reds and 16-21
// the yellow, green, brown, blue, pink and black (values 2-7); in
// three-cushion 0 is the white (the breaker's cue ball), 1 the yellow (the
// other player's) and 2 the red. Index = number in every array here.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "breakshot/ball.hpp"
#include "breakshot/event.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "breakshot/vec.hpp"

namespace breakshot {

namespace detail {
class Ruleset;
}

/// The fastest cue stick a game accepts (m/s); a hard break is about 11.
inline constexpr double kMaxCueSpeed = 20.0;

enum class GameType : std::uint8_t { eight_ball, nine_ball, snooker, three_cushion, ten_ball };
std::string_view to_string(GameType g);
/// "eight_ball", "nine_ball", "snooker", "three_cushion" or "ten_ball"; nullopt
/// otherwise.
std::optional<GameType> parse_game_type(std::string_view s);
/// The names of every game the library plays, in GameType order.
std::vector<std::string> game_type_names();

namespace detail {
/// The pool model's defaults, where GamePhysics takes its own from.
inline constexpr PhysicsParams kPoolDefaults = default_physics(Model::pool);
}  // namespace detail

/// The physics a game is played with: the choices of the pool model that
/// a game may make (docs/rules.md, "Physics"). The rest of the physics is
/// default_physics(Model::pool) with ball clusters on, as for every game.
/// The defaults are the engine's defaults (those of a scenario that
/// names nothing), taken from their one home: CushionParams's law
/// (han_2005) and default_physics(Model::pool) for the rest (TP B-3's
/// friction curve, balls that may leave the cloth, the measured spinning
/// friction). kLegacyGamePhysics is breakshot 0.1's.
struct GamePhysics {
  /// The cushion law (`table.cushion_model`), with its own restitution
  /// (default_cushion_restitution) as in a scenario; mathavan_2010 also
  /// its own nose height, 0.7 of the diameter (kMathavanNoseHeight).
  CushionModel cushion_model = CushionParams{}.model;
  /// The ball-ball impact law (`physics.ball_ball_model`).
  BallBallModel ball_ball_model = detail::kPoolDefaults.ball_ball_model;
  /// The ball-ball friction (`physics.ball_ball_friction`): the curve
  /// ball_ball_friction_curve when ball_ball_friction_fit is set, else the
  /// constant ball_ball_friction.
  bool ball_ball_friction_fit = detail::kPoolDefaults.ball_ball_friction_fit;
  FrictionCurve ball_ball_friction_curve = detail::kPoolDefaults.ball_ball_friction_curve;
  double ball_ball_friction = detail::kPoolDefaults.ball_ball_friction;
  /// Balls may leave the cloth (`physics.airborne`): jump shots, hops,
  /// balls off the table.
  bool airborne = detail::kPoolDefaults.airborne;
  /// The spinning friction (`physics.spinning_friction`): side spin
  /// decays at 5 mu_sp g / (2R) (kSpinningFriction, measured).
  double spinning_friction = detail::kPoolDefaults.spinning_friction;
  bool operator==(const GamePhysics&) const = default;
};

/// The physics of breakshot 0.1's games, by its names: "han_2005_v0"
/// cushions, "friction" ball-ball impacts with Alciatore's TP A-28
/// friction curve (kThrowFitTPA28), balls that stay on the cloth, FastFiz's
/// spinning friction (kLegacySpinningFriction). Version
/// 1 game records and
/// "v1." share links were played with it, and replay on it. Spelled out
/// field by field: it stays this physics when GamePhysics's defaults move.
/// The preset "legacy" (game_physics_preset).
inline constexpr GamePhysics kLegacyGamePhysics{CushionModel::han_2005_v0, BallBallModel::friction,
                                                true, kThrowFitTPA28, 0.0, false,
                                                kLegacySpinningFriction};

/// The named physics presets, in the order help texts list them:
/// "default" (GamePhysics{}, the engine's) and "legacy"
/// (kLegacyGamePhysics). `breakshot match --physics NAME` and Python's
/// physics="NAME" choose one; an explicit physics option given with it
/// wins over the preset's value for that option (docs/rules.md,
/// "Physics").
inline constexpr std::string_view kGamePhysicsPresets[] = {"default", "legacy"};

/// The physics of a preset's name; nullopt for an unknown name.
std::optional<GamePhysics> game_physics_preset(std::string_view name);

/// Why `physics` cannot be played (a friction curve that is no curve, a
/// negative or non-finite constant friction), naming the field; nullopt
/// when it can.
std::optional<std::string> check_game_physics(const GamePhysics& physics);

/// Three-cushion's options (GameConfig::carom): how a game ends
/// (docs/rules.md, "Three-cushion").
struct CaromRules {
  /// Points that win the game (the distance), at least 1.
  int target = 40;
  /// The game ends when both players have played this many innings (the
  /// higher score wins; equal scores draw). 0: no limit.
  int innings_limit = 50;
  /// When the player who broke reaches the target, the other player has
  /// one more inning (the equalizing inning); reaching the target in it
  /// draws the game.
  bool equalizing_inning = true;
  bool operator==(const CaromRules&) const = default;
};

/// Equipment and limits of a game. Everything else is fixed by the rules.
/// Snooker is played on the "12ft" table with snooker balls
/// (snooker_config gives them), three-cushion on the "10ft" carom table
/// with carom balls (three_cushion_config).
struct GameConfig {
  GameType game = GameType::eight_ball;
  std::string table_size = "9ft";  ///< "7ft", "8ft" or "9ft"; snooker "12ft"; three-cushion "10ft"
  double ball_radius = kPoolBallRadius;  ///< m (WPA 2.25 in)
  double ball_mass = kPoolBallMass;      ///< kg
  /// A game still going after this many shots is ended as a draw (the
  /// stalemate clause, docs/rules.md; in snooker a safety limit, not a
  /// rule). 0: no limit.
  int max_shots = 400;
  /// The physics choices (cushion and ball-ball laws, ball-ball friction).
  GamePhysics physics;
  /// Three-cushion's target score, innings limit and equalizing inning;
  /// unused (and left at its defaults) in the other games.
  CaromRules carom;
  bool operator==(const GameConfig&) const = default;
};

/// 8-ball groups. `none` while the table is open.
enum class Group : std::uint8_t { none, solids, stripes };
std::string_view to_string(Group g);
std::optional<Group> parse_group(std::string_view s);

/// What the game waits for.
enum class Phase : std::uint8_t {
  break_shot,             ///< `player` breaks (cue ball in hand behind the head string)
  shot,                   ///< `player` shoots, placing the cue ball first if in hand
  push_out_choice,        ///< 9-ball: `player` takes the table after a push-out or passes it back
  illegal_break_choice,   ///< 8-ball: `player` (incoming) decides after an illegal break
  eight_on_break_choice,  ///< 8-ball: `player` decides after the 8 fell on the break
  game_over,
  /// snooker: `player` (incoming) decides after the opponent's foul: play
  /// on, have the offender play again, or (after a miss) have the balls
  /// replaced and the offender play again
  foul_choice,
};
std::string_view to_string(Phase p);
std::optional<Phase> parse_phase(std::string_view s);

/// Where the cue ball may be placed before the next shot.
enum class BallInHand : std::uint8_t {
  none,
  kitchen,
  anywhere,
  d,  ///< snooker: within the D (on its lines included)
};
std::string_view to_string(BallInHand b);
std::optional<BallInHand> parse_ball_in_hand(std::string_view s);

/// Decisions the rules leave to a player.
enum class Choice : std::uint8_t {
  shoot,                   ///< after a push-out: take the table as it is
  pass_back,               ///< after a push-out: the pushing player must shoot
  accept_table,            ///< after an illegal 8-ball break: shoot from here
  rerack_and_break,        ///< after an illegal break or the 8 on the break: re-rack, I break
  rerack_opponent_breaks,  ///< after an illegal break: re-rack, the original breaker breaks again
  respot_eight,            ///< after the 8 on the break: spot the 8 and play on
  play_on,                 ///< snooker, after a foul: play from where the balls lie
  offender_again,          ///< snooker, after a foul: the offender plays again as the balls lie
  replace_balls,           ///< snooker, after a miss: balls replaced, the offender plays again
  concede,                 ///< snooker: the player to act concedes the frame
};
std::string_view to_string(Choice c);
std::optional<Choice> parse_choice(std::string_view s);

enum class Foul : std::uint8_t {
  scratch,             ///< cue ball pocketed
  no_contact,          ///< the cue ball touched no object ball (a miscue included)
  wrong_ball_first,    ///< first ball touched not a legal target (8-ball: the 8 on an open table)
  no_rail,             ///< after contact, nothing pocketed and no ball reached a cushion
  illegal_break,       ///< nothing pocketed and fewer than four object balls reached a cushion
  behind_head_string,  ///< from the kitchen, first contact with a ball behind the head string
  /// a ball left the table: it flew over a rail or landed outside the
  /// table (EventType::ball_off_table; only with GamePhysics::airborne)
  ball_off_table,
  in_off,             ///< snooker: the cue ball entered a pocket
  wrong_ball_potted,  ///< snooker: a ball not on entered a pocket
  /// snooker: after a free ball, the cue ball was left snookered by the
  /// free ball (WPBSA 3.9(c), 3.11(a)(vii))
  free_ball_snooker,
  /// three-cushion: the shot struck a ball other than the player's own
  /// cue ball (UMB: playing the wrong ball)
  wrong_cue_ball,
  /// three-cushion: the cue ball met an object ball while the tip could
  /// still be on it (within kCaromTipContact of the strike): a push or a
  /// double hit (UMB: "pushed through")
  push_through,
};
std::string_view to_string(Foul f);
std::optional<Foul> parse_foul(std::string_view s);
/// The foul in words, as every ruling's text says it ("the wrong ball hit
/// first"); to_string gives its name in records and summaries.
std::string_view foul_words(Foul f);

/// Snooker's part of the state (GameState::snooker): the score and what
/// the striker is on. The ball on follows from it and the table
/// (snooker_balls_on).
struct SnookerState {
  std::array<int, 2> score{0, 0};
  /// Points of the visit in progress (the break of `GameState::player`).
  int break_points = 0;
  /// A red was potted this visit: the ball on is a colour the striker
  /// nominates (Shoot::nominate).
  bool colour_on = false;
  /// After a foul the striker is snookered: any ball may be nominated as
  /// the ball on (WPBSA 3.9).
  bool free_ball = false;
  /// The scores were equal after the last black: it was re-spotted and
  /// the next score or foul ends the frame (WPBSA 3.3(k)).
  bool respotted_black = false;
  /// Misses in a row of the player to act (or of the offender, in
  /// foul_choice) from replaced balls with a full ball on (WPBSA 3.14(c)):
  /// the third such miss loses the frame.
  int misses = 0;
  /// After a miss (phase foul_choice): the table before the missed
  /// stroke, which replace_balls restores. Empty otherwise.
  std::vector<Vec2> replace_position;
  std::vector<std::uint8_t> replace_on_table;
  bool replace_colour_on = false;
  bool replace_free_ball = false;
  bool operator==(const SnookerState&) const = default;
};

/// Three-cushion's part of the state (GameState::carom).
struct CaromState {
  std::array<int, 2> score{0, 0};
  /// Points of the inning in progress (the run of `GameState::player`).
  int run = 0;
  /// Innings begun by each player (the break is the breaker's first).
  std::array<int, 2> innings{0, 0};
  /// The inning in progress is the equalizing inning: the breaker has
  /// reached the target, and the other player's inning ends the game.
  bool equalizing = false;
  bool operator==(const CaromState&) const = default;
};

/// The state between shots: every ball at rest.
struct GameState {
  GameType game = GameType::eight_ball;
  std::vector<Vec2> position;       ///< by ball number; meaningful where on_table
  std::vector<std::uint8_t> on_table;  ///< by ball number: 1 on the table, 0 pocketed
  Phase phase = Phase::break_shot;
  int player = 0;                   ///< 0 or 1: who acts next
  int breaker = 0;                  ///< who broke (or breaks) this rack
  BallInHand ball_in_hand = BallInHand::kitchen;
  /// The cue ball was placed behind the head string for the coming
  /// (non-break) shot: it must first contact a ball outside the kitchen.
  bool kitchen_shot = false;
  std::array<Group, 2> group{Group::none, Group::none};  ///< 8-ball
  std::array<int, 2> fouls_in_a_row{0, 0};               ///< 9-ball three-foul rule
  bool push_out_allowed = false;  ///< 9-ball: the next shot may be declared a push-out
  bool after_push_out = false;    ///< 9-ball: the last shot was a push-out
  bool scratch_on_break = false;  ///< 8-ball: set with eight_on_break_choice
  int winner = -1;                ///< -1: none yet (or a draw once game_over)
  std::string result;             ///< why the game ended, in words
  int shots = 0;                  ///< shots taken in this game
  int innings = 0;                ///< turns at the table begun in this game
  std::uint64_t rack_seed = 0;    ///< seed of the current rack's jitter
  int racks = 1;                  ///< racks set up in this game (re-racks add one)
  /// Snooker's part; empty in the other games.
  std::optional<SnookerState> snooker;
  /// Three-cushion's part; empty in the other games.
  std::optional<CaromState> carom;

  bool operator==(const GameState&) const = default;
};

/// 8-ball calls: the ball and the pocket (index into Table::pockets).
struct Call {
  int ball = -1;
  int pocket = -1;
  bool operator==(const Call&) const = default;
};

struct PlaceCueBall {
  Vec2 position;
  bool operator==(const PlaceCueBall&) const = default;
};

struct Shoot {
  CueStrike strike;
  /// 8-ball: the called ball and pocket. Without a call a shot counts
  /// only as an obvious one (docs/rules.md); the 8 must always be called.
  /// 9-ball: optional and informational (the rules ignore it); it marks
  /// the shot as a pot attempt for statistics.
  std::optional<Call> call;
  bool safety = false;    ///< 8-ball: declared safety, the turn ends after it
  bool push_out = false;  ///< 9-ball: declared push-out
  /// Snooker: the ball nominated as the ball on. Required when the ball
  /// on is a colour of the striker's choosing (after a red), and to take
  /// a free ball (any ball not otherwise on); else optional, and then it
  /// must be a ball on. Never in the other games.
  std::optional<int> nominate;
  /// Three-cushion: the ball the cue strikes. Absent: the player's own cue
  /// ball (Rules::cue_ball). Another ball is played, and is a foul
  /// (Foul::wrong_cue_ball). Never in the other games.
  std::optional<int> cue_ball;
  bool operator==(const Shoot&) const = default;
};

struct Decide {
  Choice choice = Choice::shoot;
  bool operator==(const Decide&) const = default;
};

using Action = std::variant<PlaceCueBall, Shoot, Decide>;

/// What the player to act may do now.
struct LegalActions {
  BallInHand place = BallInHand::none;  ///< may place the cue ball (and must, if it is off the table)
  bool must_place = false;              ///< the cue ball is off the table
  bool shoot = false;
  bool push_out = false;                ///< a shot may be declared a push-out
  bool call = false;                    ///< 8-ball: shots carry calls
  std::vector<int> targets;             ///< balls the cue ball may legally hit first
  /// Decisions on offer: a decision phase's; in snooker's shot phases
  /// also `concede`, beside the shot.
  std::vector<Choice> choices;
  /// Snooker: balls a shot may nominate (Shoot::nominate), and whether
  /// it must.
  std::vector<int> nominate;
  bool must_nominate = false;
};

/// What a shot did, read from its events. Ball numbers, not indices.
struct ShotFacts {
  bool miscue = false;
  int first_hit = -1;              ///< first object ball the cue ball touched, -1: none
  std::vector<int> pocketed;       ///< in order, the cue ball (0) included
  std::vector<int> pocket_of;      ///< pocket index for each entry of `pocketed`
  bool cushion_after_contact = false;  ///< any ball touched a cushion after the first contact
  int object_balls_to_cushion = 0;     ///< distinct object balls that touched a cushion
  /// Balls that left the table (EventType::ball_off_table), in order, the
  /// cue ball (0) included.
  std::vector<int> off_table;
  bool operator==(const ShotFacts&) const = default;
};

/// Snooker's part of a ruling (Ruling::snooker).
struct SnookerRuling {
  int points = 0;   ///< scored by the shooter with this shot
  int penalty = 0;  ///< given to the opponent for a foul (0: none)
  /// The foul was a miss: the ball on could have been hit full in a
  /// straight line from the cue ball (WPBSA 3.14(c)).
  bool miss = false;
  bool free_ball = false;  ///< the shot was played as a free ball
  int nominated = -1;      ///< the ball on the shot nominated, -1: none
  bool operator==(const SnookerRuling&) const = default;
};

/// Three-cushion's part of a shot's ruling (Ruling::carom), read from the
/// events of the ball struck.
struct CaromRuling {
  bool point = false;  ///< the shot scored (no foul, both balls, three cushions first)
  int cue_ball = 0;    ///< the ball struck
  /// The object balls the struck ball touched, in the order of their first
  /// contact (0, 1 or 2 of them).
  std::vector<int> hit;
  /// Cushions the struck ball touched before its first contact with the
  /// second object ball; all its cushions when it touched fewer than two.
  int cushions = 0;
  bool kiss = false;  ///< the object balls touched each other
  bool operator==(const CaromRuling&) const = default;
};

struct Ruling {
  std::vector<Foul> fouls;       ///< empty: no foul
  bool legal_break = true;       ///< break shots only
  bool turn_continues = false;   ///< the same player shoots again
  Group assigned = Group::none;  ///< 8-ball: the group the shooter got with this shot
  std::vector<int> spotted;      ///< balls put back on the table
  int winner = -1;               ///< set when the game ended with this action
  std::string text;              ///< the ruling in words
  /// The shot carried a call and the called ball fell in the called
  /// pocket with no foul (a pot attempt that succeeded; match statistics).
  bool call_made = false;
  /// Snooker's part of a shot's ruling; empty otherwise.
  std::optional<SnookerRuling> snooker;
  /// Three-cushion's part of a shot's ruling; empty otherwise.
  std::optional<CaromRuling> carom;
  bool operator==(const Ruling&) const = default;
};

struct Outcome {
  GameState state;            ///< after the action
  std::vector<Event> events;  ///< the shot's events; ball fields are ball numbers
  ShotFacts facts;
  Ruling ruling;
};

/// Snooker: the gap (m) up to which the cue ball at rest counts as
/// touching a ball (WPBSA 3.7): the simulator leaves balls that came to
/// rest against each other a hair apart.
inline constexpr double kSnookerTouching = 1e-4;

/// Snooker: the 12 ft table and snooker balls (breakshot/snooker.hpp);
/// the other fields GameConfig's defaults.
GameConfig snooker_config();
/// Snooker: the value of ball number `ball`: a red 1, the yellow, green,
/// brown, blue, pink and black 2 to 7, anything else 0.
int snooker_value(int ball);
/// Snooker: the balls on for the player to act, a free ball aside: every
/// red on the table; after a red every colour; once the reds are gone the
/// lowest-valued colour left; on a re-spotted black the black. Throws
/// std::invalid_argument for a state without snooker's part.
std::vector<int> snooker_balls_on(const GameState& state);
/// Snooker: the most points the player to act can still score from the
/// table as it stands: each red with a black after it (8), the colour
/// after a red potted this visit (7), then the colours (27); once the
/// reds are gone, the colours left. Throws as snooker_balls_on.
int snooker_points_remaining(const GameState& state);
/// Snooker: the snookers `player` (0 or 1) needs to be able to draw
/// level: 0 while the deficit is at most snooker_points_remaining, else
/// the deficit beyond it divided by the least penalty a snooker can earn
/// (4 while reds remain, else the higher of 4 and the value of the
/// lowest colour left), rounded up. Throws as snooker_balls_on, or for a
/// player that is not 0 or 1.
int snookers_required(const GameState& state, int player);

/// Three-cushion: the gap (m) up to which balls at rest count as touching
/// (they are then re-spotted before the next shot, docs/rules.md).
inline constexpr double kCaromTouching = 1e-4;
/// Three-cushion: how long the cue tip stays on the ball (s): a cue ball
/// that meets an object ball sooner after the strike was pushed
/// (Foul::push_through). Alciatore gives about 1 ms for the tip's contact.
inline constexpr double kCaromTipContact = 1e-3;

/// Three-cushion's count of a shot, read from its events (ball fields are
/// ball numbers) as the struck ball goes: the one count behind the rules'
/// CaromRuling and the page's count while a shot is played back
/// (docs/rules.md, "Three-cushion").
struct CaromCount {
  /// The object balls the struck ball touched, in the order of their first
  /// contact (0, 1 or 2 of them).
  std::vector<int> hit;
  /// Cushions the struck ball touched before its first contact with the
  /// second object ball; all its cushions while it has touched fewer.
  int cushions = 0;
  bool kiss = false;            ///< the object balls touched each other
  double strike = 0.0;          ///< time of the cue's strike on the struck ball
  double first_contact = -1.0;  ///< time of its first ball contact, -1: none yet
  /// The struck ball has met both object balls: the count is complete.
  bool done() const { return hit.size() == 2; }
  /// The count makes a point (fouls aside): both balls, three cushions first.
  bool made() const { return done() && cushions >= 3; }
};

/// Three-cushion: the count of the ball `struck` over `events` (a shot's,
/// or the first of them while it runs).
CaromCount carom_count(const std::vector<Event>& events, int struck);

/// Three-cushion: the 10 ft carom table, carom balls and CaromRules'
/// defaults; the other fields GameConfig's defaults.
GameConfig three_cushion_config();

/// The config of `game` with its own equipment: snooker_config,
/// three_cushion_config, else GameConfig's defaults for that game.
GameConfig default_game_config(GameType game);

/// Where a game stands for each side, as its rules count it: what the
/// AI's value of a table (src/ai/evaluate.cpp) and other readers weigh,
/// without knowing the game (docs/rules.md, "Standing").
struct Standing {
  /// Points each player has: snooker's frame score, three-cushion's
  /// points; 0 in the games that do not count points.
  std::array<int, 2> score{0, 0};
  /// The most points the player to act can still score from the table
  /// (snooker_points_remaining); -1 where points are not scored from the
  /// table.
  int points_left = -1;
  /// Balls each player must still pocket before the game ball: 8-ball's
  /// group balls on the table once the groups are set; -1 where the game
  /// has no such count or the table is open.
  std::array<int, 2> balls_to_go{-1, -1};
  bool operator==(const Standing&) const = default;
};

/// Memory one thread reuses from shot to shot in Rules::apply: the shot's
/// scenario, its balls' numbers and its simulation, re-armed for each
/// shot. Not to be shared between threads.
struct ShotWorkspace {
  Scenario scenario;
  std::vector<int> numbers;
  std::optional<Simulation> simulation;
};

/// The rules of one game type on one table. Immutable once built; all
/// functions are pure functions of their arguments.
class Rules {
 public:
  /// Throws std::invalid_argument for an unknown table size, bad sizes or
  /// physics that check_game_physics refuses.
  explicit Rules(GameConfig config);

  const GameConfig& config() const { return config_; }
  const Table& table() const { return table_; }
  /// Number of balls including the cue ball: 16, 10, (snooker) 22 or
  /// (three-cushion) 3.
  int ball_count() const;
  /// The ball the player to act strikes: 0 but in three-cushion, where it
  /// is the white (0) for the player who broke and the yellow (1) for the
  /// other.
  int cue_ball(const GameState& state) const;
  /// x of the head string: the kitchen is x <= head_string().
  double head_string() const;

  /// A new game: rack from `rack_seed`, cue ball on the head spot,
  /// `breaker` (0 or 1) to break.
  GameState start(std::uint64_t rack_seed, int breaker) const;

  LegalActions legal_actions(const GameState& state) const;
  /// Balls the player to act may legally hit first.
  std::vector<int> targets(const GameState& state) const;
  /// The balls on for the player to act: the balls a rule names as the
  /// ones to play (snooker_balls_on; a free ball is not one of them); in
  /// the other games, targets(state).
  std::vector<int> balls_on(const GameState& state) const;
  /// Points a legal pot of ball number `ball` scores: snooker's values
  /// (snooker_value); 1 for an object ball of the pool games; 0 for the
  /// cue ball, a number the game has not, and three-cushion's balls.
  int ball_value(int ball) const;
  /// Where `state` stands for each side (Standing).
  Standing standing(const GameState& state) const;
  /// The foul kinds of this game, in the order match summaries list them:
  /// ball_off_table only when the physics is airborne (no ball can leave
  /// the table otherwise).
  std::vector<Foul> foul_kinds() const;
  /// Why `action` is not allowed now, or nullopt if it is.
  std::optional<std::string> check(const GameState& state, const Action& action) const;
  /// Why the cue ball may not be placed at p now, or nullopt.
  std::optional<std::string> check_placement(const GameState& state, Vec2 p) const;
  /// Plays `action`. Throws std::invalid_argument with check()'s reason if
  /// it is not allowed.
  Outcome apply(const GameState& state, const Action& action) const;
  /// The same, keeping the shot's scenario and simulation in `work` and
  /// re-arming them for the next shot (Simulation::reset) instead of
  /// making new ones: for many shots on one thread (the AI's rollouts).
  /// The outcome is exactly apply(state, action)'s.
  Outcome apply(const GameState& state, const Action& action, ShotWorkspace& work) const;
  /// Rules `shot` from `state` as if the physics had played it with these
  /// `events` (ball fields as ball numbers): balls with a ball_pocket or
  /// ball_off_table event leave the table (keeping their positions from
  /// `state`, as in apply()), every other ball on the table comes to rest
  /// at `rest[ball number]`. `miscue` as the cue strike
  /// reported it. For rulings from hand-made event lists; apply() is this
  /// with the events the engine simulated. Throws std::invalid_argument
  /// with check()'s reason if the shot is not allowed, if `rest` does not
  /// have ball_count() entries or a ball on the table a finite position
  /// there, or if an event names no ball of the game.
  Outcome apply_events(const GameState& state, const Shoot& shot, std::vector<Event> events,
                       const std::vector<Vec2>& rest, bool miscue = false) const;

  /// The physics of a shot from `state` (balls on the table only, in
  /// number order), the strike on cue_ball(state), and each scenario
  /// ball's number.
  Scenario shot_scenario(const GameState& state, const CueStrike& strike,
                         std::vector<int>* numbers = nullptr) const;
  /// The same with the strike on ball number `cue` (on the table).
  Scenario shot_scenario(const GameState& state, const CueStrike& strike, int cue,
                         std::vector<int>* numbers) const;
  /// The same written over `out`, reusing its memory.
  void shot_scenario(const GameState& state, const CueStrike& strike, int cue,
                     std::vector<int>* numbers, Scenario& out) const;
  /// The facts of a shot from its events (ball fields as ball numbers),
  /// `cue` being the ball struck.
  ShotFacts facts(const std::vector<Event>& events, int cue = 0) const;

  /// Lowest legal spot for `ball` on the long string, from the foot spot
  /// toward the foot rail, then toward the head (WPA spotting). Snooker:
  /// a colour's own spot, else the highest-valued free spot, else the
  /// nearest free place from its own spot toward the top cushion, else
  /// toward the bottom cushion (WPBSA 3.6, docs/rules.md).
  Vec2 spot_position(const GameState& state, int ball) const;

  // Snooker's geometry of the table between shots (docs/rules.md). Each
  // throws std::invalid_argument for a state that is not snooker's.

  /// Object balls the cue ball touches at rest: centres at most 2R +
  /// kSnookerTouching apart.
  std::vector<int> touching(const GameState& state) const;
  /// The cue ball (on the table) is snookered: no ball on (a free ball
  /// aside) can be hit at both its extreme edges along a straight path
  /// that keeps clear of every ball not on (WPBSA Section 2,
  /// "Snookered"). Only balls obstruct: the cushions' jaws (WPBSA's
  /// "angled") are not considered.
  bool snookered(const GameState& state) const;
  /// Some ball on can be hit full, centre on centre, along a straight
  /// path clear of every other ball (the computable form of WPBSA 3.14's
  /// miss).
  bool full_ball_on(const GameState& state) const;

 private:
  GameConfig config_;
  std::shared_ptr<const detail::Ruleset> ruleset_;  // the game's own rulings (src/game/ruleset.hpp)
  Table table_;
  Scenario base_;  // physics, table and ball specs of a full rack

  // The ruling of a shot whose events, facts and resting balls are in `out`.
  void rule_shot(const GameState& state, const Shoot& shot, Outcome& out) const;
};

}  // namespace breakshot
