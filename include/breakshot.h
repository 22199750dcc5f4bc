/* breakshot's C API: the engine, the games and the AI for C and for every
 * language that binds C (docs/c-api.md has every call, its errors and
 * examples).
 *
 * C99, usable from C++. Plain structs and opaque handles; nothing throws
 * across this boundary. Every call that can fail returns a BsStatus and
 * leaves a message, which bs_error_message reads: on the handle the call
 * was given when that handle is valid, else (constructors, a NULL or bad
 * handle) on the calling thread. A call that succeeds clears the message
 * it would have written.
 *
 * Memory: handles are freed with their own bs_*_free (NULL is accepted).
 * A `char**` out-argument receives a NUL-terminated UTF-8 string that the
 * caller owns and frees with bs_string_free. A `const char*` out-argument
 * points into a handle and is valid until that handle is freed. Structs
 * carry no pointers the caller must free.
 *
 * Threads: a handle is used by one thread at a time; distinct handles are
 * independent. bs_simulate_batch and the AI players use threads of their
 * own.
 *
 * Stability: every declaration here is stable in the API version
 * BS_API_VERSION (1): it will keep its name, arguments and meaning, and
 * the structs their layout, for as long as the API version stays 1; calls
 * may be added. The shared library exports only the symbols declared
 * here (bs_*), at the version node BREAKSHOT_C_1.
 *
 * The calls and structs marked "Experimental" (the games as the browser
 * page plays them, playbacks, the frame layout) are in the library and
 * the symbol map as the others are, but may still change their arguments
 * or their JSON within API version 1; docs/c-api.md says so of each.
 */
#ifndef BREAKSHOT_H
#define BREAKSHOT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(BREAKSHOT_C_BUILD) && defined(__GNUC__)
#define BS_API __attribute__((visibility("default")))
#else
#define BS_API
#endif

/** The API version of this header (see "Stability" above). */
#define BS_API_VERSION 1

/* ------------------------------------------------------------------------
 * Status, errors, strings */

typedef enum BsStatus {
  BS_OK = 0,
  BS_ERROR_NULL = 1,         /**< a required pointer argument is NULL */
  BS_ERROR_BAD_HANDLE = 2,   /**< not a live handle of the expected type */
  BS_ERROR_BAD_JSON = 3,     /**< not JSON, or not the expected document */
  BS_ERROR_OUT_OF_RANGE = 4, /**< a number, index or enum value out of range */
  BS_ERROR_INVALID = 5,      /**< a scenario or record the engine refuses */
  BS_ERROR_ILLEGAL = 6,      /**< the rules refuse the action */
  BS_ERROR_STATE = 7,        /**< not possible now (the game is over, ...) */
  BS_ERROR_NO_MEMORY = 8,
  BS_ERROR_INTERNAL = 9
} BsStatus;

/** "BS_OK", "BS_ERROR_NULL", ...; "BS_UNKNOWN_STATUS" for another value. */
BS_API const char* bs_status_name(BsStatus status);

/** The message of the last failed call on `handle` (any handle of this
 * API), or of the calling thread's last failed call that had no valid
 * handle to keep it when `handle` is NULL. "" when the last such call
 * succeeded. Valid until the next call on that handle (or thread). */
BS_API const char* bs_error_message(const void* handle);

/** Frees a string this API returned through a `char**` (NULL is fine). */
BS_API void bs_string_free(char* text);

/* ------------------------------------------------------------------------
 * Version and physics options */

typedef struct BsVersion {
  int32_t major;
  int32_t minor;
  int32_t patch;
  int32_t api;      /**< BS_API_VERSION of the library */
  const char* text; /**< "0.1.0", static */
} BsVersion;

BS_API BsStatus bs_version(BsVersion* out);

/** The physics options this library supports, as JSON: {"version",
 * "models", "cushion_models", "ball_ball_models", "table_shapes",
 * "pool_table_sizes", "racks", "games", "players", "defaults": {"ideal",
 * "friction", "pool"} (each bs_physics_default's fields by name), "ball":
 * {"radius", "mass", "wall_restitution"} (what a NaN field of BsBall
 * takes), "pool_cushion_restitution"}. */
BS_API BsStatus bs_physics_options_json(char** out);

/* ------------------------------------------------------------------------
 * Physics */

typedef enum BsModel { BS_MODEL_IDEAL = 0, BS_MODEL_FRICTION = 1, BS_MODEL_POOL = 2 } BsModel;

typedef enum BsBallBallModel {
  BS_BALL_BALL_FRICTION = 0,
  BS_BALL_BALL_MATHAVAN_2014 = 1
} BsBallBallModel;

/** Every physics parameter of a scenario (docs/scenario.md). Fill it with
 * bs_physics_default, then change fields. */
typedef struct BsPhysics {
  int32_t model;           /**< BsModel */
  int32_t ball_ball_model; /**< BsBallBallModel (pool model) */
  double ball_ball_restitution;
  /** 1: ball-ball friction is the curve a + b exp(-c v) of the slip speed
   * (friction_curve); 0: the constant ball_ball_friction. */
  int32_t ball_ball_friction_fit;
  int32_t ball_clusters; /**< 0 or 1 */
  double ball_ball_friction;
  double friction_curve[3]; /**< a, b, c */
  double gravity;
  double deceleration; /**< friction model */
  double sliding_friction;
  double rolling_friction;
  double spinning_friction;
  double collapse_speed;
  int32_t airborne; /**< 0 or 1 (pool model) */
  int32_t reserved; /**< 0 */
  double slate_restitution;
  double min_bounce_height;
} BsPhysics;

/** The defaults of `model`, every field set. */
BS_API BsStatus bs_physics_default(BsModel model, BsPhysics* out);

/* ------------------------------------------------------------------------
 * Scenarios */

typedef struct BsScenario BsScenario;

typedef enum BsTableShape {
  BS_TABLE_RECTANGLE = 0,
  BS_TABLE_POLYGON = 1,
  BS_TABLE_POOL = 2,
  BS_TABLE_SNOOKER = 3,
  BS_TABLE_CAROM = 4
} BsTableShape;

typedef enum BsCushionModel {
  BS_CUSHION_DEFAULT = -1,
  BS_CUSHION_HAN_2005_V0 = 0,
  BS_CUSHION_HAN_2005 = 1,
  BS_CUSHION_MATHAVAN_2010 = 2,
  BS_CUSHION_IMPULSE_FRICTIONAL = 3,
  BS_CUSHION_STRONGE_COMPLIANT = 4
} BsCushionModel;

/** A table. Fill it with bs_table_default; a NaN cushion field (and
 * cushion_model BS_CUSHION_DEFAULT) takes the scenario format's default. */
typedef struct BsTable {
  int32_t shape;         /**< BsTableShape */
  int32_t cushion_model; /**< BsCushionModel */
  double min[2];         /**< rectangle */
  double max[2];
  const double* vertices; /**< polygon: x0, y0, x1, y1, ... (copied) */
  size_t vertex_count;
  const char* size; /**< pool: "7ft", "8ft" or "9ft" (copied) */
  double cushion_restitution;
  double cushion_friction;
  double nose_height;
  double cushion_height;
  double cushion_compliance_ratio;
} BsTable;

BS_API BsStatus bs_table_default(BsTableShape shape, BsTable* out);

/** A ball. Fill it with bs_ball_default; NaN radius, mass or
 * wall_restitution take the defaults. */
typedef struct BsBall {
  const char* id; /**< unique in the scenario (copied) */
  double position[2];
  double velocity[3]; /**< vz: pool model with airborne only */
  double spin[3];     /**< pool model only */
  double radius;
  double mass;
  double wall_restitution;
} BsBall;

BS_API BsStatus bs_ball_default(BsBall* out);

/** A cue strike (docs/contract.md, "cue"): speed m/s, phi and theta in
 * degrees, tip offsets a and b as fractions of the radius. */
typedef struct BsStrike {
  double speed;
  double phi;
  double theta;
  double a;
  double b;
} BsStrike;

/** An empty scenario: the ideal model's physics, no table, no balls. */
BS_API BsStatus bs_scenario_new(BsScenario** out);
/** A scenario read from the scenario format's text (`len` bytes; the
 * text need not end with NUL). BS_ERROR_BAD_JSON for text that is not
 * JSON, BS_ERROR_INVALID for a scenario the format refuses; the message
 * names the field ("balls[1].radius: ..."). */
BS_API BsStatus bs_scenario_from_json(const char* text, size_t len, BsScenario** out);
BS_API BsStatus bs_scenario_clone(const BsScenario* scenario, BsScenario** out);
BS_API void bs_scenario_free(BsScenario* scenario);

BS_API BsStatus bs_scenario_set_physics(BsScenario* scenario, const BsPhysics* physics);
BS_API BsStatus bs_scenario_set_table(BsScenario* scenario, const BsTable* table);
/** Adds a ball after the others; its index (scenario order) in *index
 * when `index` is not NULL. */
BS_API BsStatus bs_scenario_add_ball(BsScenario* scenario, const BsBall* ball, size_t* index);
/** The regulation rack of `game` ("eight_ball", "nine_ball", "ten_ball",
 * "snooker", "three_cushion") from `seed`; `game` NULL removes it. */
BS_API BsStatus bs_scenario_set_rack(BsScenario* scenario, const char* game, uint64_t seed);
BS_API BsStatus bs_scenario_set_pair_restitution(BsScenario* scenario, const char* ball_a,
                                                 const char* ball_b, double restitution);
/** The run ends at time t (> 0). */
BS_API BsStatus bs_scenario_set_until_time(BsScenario* scenario, double t);
/** The run ends when every ball is at rest (not in the ideal model). */
BS_API BsStatus bs_scenario_set_until_rest(BsScenario* scenario);
BS_API BsStatus bs_scenario_set_max_events(BsScenario* scenario, uint64_t max_events);
/** A cue strike at t = 0 on the ball `ball_id` (pool model); a NULL
 * strike removes it. */
BS_API BsStatus bs_scenario_strike(BsScenario* scenario, const char* ball_id,
                                   const BsStrike* strike);
/** Checks the scenario as bs_simulate will: BS_ERROR_INVALID with the
 * field named as in the scenario format. */
BS_API BsStatus bs_scenario_validate(const BsScenario* scenario);
/** The balls of the scenario (rack included) once valid. */
BS_API BsStatus bs_scenario_ball_count(const BsScenario* scenario, size_t* out);
/** The scenario in the scenario format's text. */
BS_API BsStatus bs_scenario_to_json(const BsScenario* scenario, char** out);

/* ------------------------------------------------------------------------
 * Simulations: a run to the scenario's end, its events and each ball's
 * state at any time of it */

typedef struct BsSimulation BsSimulation;

typedef enum BsEventKind {
  BS_EVENT_CUE_STRIKE = 0,
  BS_EVENT_BALL_BALL = 1,
  BS_EVENT_BALL_CUSHION = 2,
  BS_EVENT_BALL_POCKET = 3,
  BS_EVENT_STATE_CHANGE = 4,
  BS_EVENT_BALL_SLATE = 5,
  BS_EVENT_BALL_OFF_TABLE = 6
} BsEventKind;

typedef enum BsMotion {
  BS_MOTION_STATIONARY = 0,
  BS_MOTION_MOVING = 1,
  BS_MOTION_SLIDING = 2,
  BS_MOTION_ROLLING = 3,
  BS_MOTION_SPINNING = 4,
  BS_MOTION_POCKETED = 5,
  BS_MOTION_AIRBORNE = 6,
  BS_MOTION_OFF_TABLE = 7
} BsMotion;

/** One event. Balls index the scenario's balls, `wall` and `pocket` the
 * table's (bs_simulation_wall_name, bs_simulation_pocket_name); -1 where
 * the kind has none. */
typedef struct BsEvent {
  double time;
  int32_t kind; /**< BsEventKind */
  int32_t ball;
  int32_t other; /**< ball_ball: the second ball */
  int32_t wall;  /**< ball_cushion, ball_off_table (or -1) */
  int32_t pocket;
  int32_t from; /**< state_change, ball_slate: BsMotion */
  int32_t to;
  int32_t reserved;
} BsEvent;

/** A ball at one instant. */
typedef struct BsBallState {
  double position[2];
  double velocity[2];
  double spin[3]; /**< rad/s */
  double z;       /**< height of the centre above its resting height, m */
  double vz;
  int32_t motion; /**< BsMotion */
  int32_t reserved;
} BsBallState;

typedef struct BsSimulationInfo {
  size_t balls;
  size_t events;
  double end_time; /**< the time of the final state */
  int32_t complete; /**< 0 when max_events stopped the run */
  int32_t airborne; /**< 1 when some ball left the cloth */
} BsSimulationInfo;

/** Runs `scenario` to its end (BS_ERROR_INVALID if it is not valid). A
 * run stopped by max_events is BS_OK with info.complete 0. The run costs
 * what the engine's simulate() costs: the balls' trajectories are not
 * kept until the first bs_simulation_states_at asks for them. */
BS_API BsStatus bs_simulate(const BsScenario* scenario, BsSimulation** out);
/** Runs n scenarios on `threads` threads (0: every core); out[k] is
 * bs_simulate(scenarios[k]). On failure nothing is returned (every out[k]
 * NULL) and the message names the first scenario refused. */
BS_API BsStatus bs_simulate_batch(const BsScenario* const* scenarios, size_t n, int32_t threads,
                                  BsSimulation** out);
BS_API void bs_simulation_free(BsSimulation* simulation);

BS_API BsStatus bs_simulation_info(const BsSimulation* simulation, BsSimulationInfo* out);
/** Events [first, first + n) into out[0 .. n). */
BS_API BsStatus bs_simulation_events(const BsSimulation* simulation, size_t first, size_t n,
                                     BsEvent* out);
/** Every ball's state at time t into out[0 .. n), n the number of balls
 * (BS_ERROR_OUT_OF_RANGE otherwise): exactly what the engine advanced to
 * t gives. t is clamped to [0, end_time]; NaN is out of range. The first
 * call on a simulation records its trajectories by running the scenario
 * once more (the same run; about the cost of bs_simulate, and memory
 * that bs_simulation_free releases); later calls allocate nothing. */
BS_API BsStatus bs_simulation_states_at(const BsSimulation* simulation, double t,
                                        BsBallState* out, size_t n);
BS_API BsStatus bs_simulation_ball_id(const BsSimulation* simulation, size_t ball,
                                      const char** out);
BS_API BsStatus bs_simulation_wall_name(const BsSimulation* simulation, int32_t wall,
                                        const char** out);
BS_API BsStatus bs_simulation_pocket_name(const BsSimulation* simulation, int32_t pocket,
                                          const char** out);
/** The result file, exactly `breakshot simulate`'s bytes. */
BS_API BsStatus bs_simulation_result_json(const BsSimulation* simulation, char** out);
/** The result file of a run of `scenario`, exactly `breakshot simulate`'s
 * bytes (bs_simulation_result_json of bs_simulate's run), without keeping
 * the run: cheaper when the file is all that is wanted. BS_ERROR_INVALID
 * if the scenario is not valid. */
BS_API BsStatus bs_simulate_result_json(const BsScenario* scenario, char** out);

/* ------------------------------------------------------------------------
 * Games: a session of one game between two seats, its legal actions,
 * actions applied, rulings, the record and its replay. Actions, states
 * and rulings are JSON in the game records' encoding (docs/c-api.md). */

typedef struct BsGame BsGame;

typedef struct BsGameConfig {
  const char* game;  /**< "eight_ball", "nine_ball", "ten_ball", "snooker", "three_cushion" */
  const char* table; /**< NULL: the game's own ("9ft"; "12ft"; "10ft") */
  uint64_t seed;
  int32_t breaker; /**< 0 or 1 */
  int32_t reserved;
  /** Each seat "human" (its shots played as given) or a computer player
   * (bs_player_new's names), whose shots are played with its noise; NULL
   * is "human". */
  const char* seats[2];
  /** NULL, or the game's physics as a record writes it ({"cushion_model",
   * "ball_ball_model", "ball_ball_friction", ...}). */
  const char* physics_json;
} BsGameConfig;

typedef struct BsGameInfo {
  size_t actions;  /**< actions played */
  int32_t player;  /**< the seat to act, 0 or 1 */
  int32_t over;    /**< 1 once the game is over */
  int32_t winner;  /**< -1: none (yet), or a draw */
  int32_t balls;   /**< balls of the game, the cue ball included */
} BsGameInfo;

/** bs_game_new_config with two human seats, the game's own table and
 * breaker 0. */
BS_API BsStatus bs_game_new(const char* game, uint64_t seed, BsGame** out);
BS_API BsStatus bs_game_new_config(const BsGameConfig* config, BsGame** out);
/** A game rebuilt from a record (`breakshot replay`'s check first:
 * BS_ERROR_INVALID names the first difference). */
BS_API BsStatus bs_game_from_record_json(const char* text, size_t len, BsGame** out);
BS_API void bs_game_free(BsGame* game);

BS_API BsStatus bs_game_info(const BsGame* game, BsGameInfo* out);
/** The state now, as game records write it. */
BS_API BsStatus bs_game_state_json(const BsGame* game, char** out);
/** What the seat to act may do: {"place", "must_place", "shoot",
 * "push_out", "call", "targets", "choices"} (snooker also "nominate",
 * "must_nominate"). */
BS_API BsStatus bs_game_legal_actions_json(const BsGame* game, char** out);
/** Plays an action (records' encoding, as chosen) for the seat to act:
 * BS_ERROR_BAD_JSON for a bad document, BS_ERROR_ILLEGAL when the rules
 * refuse it (the message says why), BS_ERROR_STATE once the game is over. */
BS_API BsStatus bs_game_apply_json(BsGame* game, const char* action, size_t len);
/** The ruling of action `index` (records' encoding). */
BS_API BsStatus bs_game_ruling_json(const BsGame* game, size_t index, char** out);
/** The game's record, exactly as `breakshot replay` reads it. */
BS_API BsStatus bs_game_record_json(const BsGame* game, char** out);
/** The run of action `index` (a shot, as executed) from the state before
 * it, for drawing: balls in the order of the game's numbers still on the
 * table (bs_simulation_ball_id gives each one's id). */
BS_API BsStatus bs_game_shot_simulation(const BsGame* game, size_t index, BsSimulation** out);

/* ------------------------------------------------------------------------
 * Computer players */

typedef struct BsPlayer BsPlayer;

/** A computer player by name: "baseline", an AI level ("beginner",
 * "amateur", "club", "expert", "champion"), either at a named noise
 * ("champion@0.5x"). `threads` for one decision (0: every core); its
 * decisions are the same for any count. */
BS_API BsStatus bs_player_new(const char* name, int32_t threads, BsPlayer** out);
BS_API void bs_player_free(BsPlayer* player);
/** The action the player chooses for the seat to act in `game` (records'
 * encoding), with the game's seed for that action, as `breakshot match`
 * gives it. Pass it to bs_game_apply_json. */
BS_API BsStatus bs_player_decide_json(BsPlayer* player, const BsGame* game, char** action);

/* ------------------------------------------------------------------------
 * Experimental: games as the browser page plays them (web/api is a thin
 * layer on these calls). A game may be made from the page's config
 * document or a link, and carries a budget of simulations for its
 * computer players. JSON in the game records' encoding (src/io), as for
 * the calls above; docs/c-api.md gives each reply's fields. */

/** Experimental. A game from the page's config: {"game", "table", "seed"
 * (a decimal string, or an integer up to 2^53), "breaker", "players": [two
 * seats, "human" or a computer player of the game (bs_game_players_json),
 * either at a named noise], "ai_budget" (simulations per decision of the
 * game's computer players; bs_player_new_for_game), "physics": {"airborne"},
 * "carom": {"target", "innings_limit", "equalizing_inning"} (three_cushion
 * only)}. BS_ERROR_BAD_JSON names the field ("players[1]: ..."). */
BS_API BsStatus bs_game_new_json(const char* config, size_t len, BsGame** out);
/** Experimental. The computer players a seat of `game` may be:
 * {"game", "players": [names]} (the AI levels that play it, and "baseline"
 * where it plays). */
BS_API BsStatus bs_game_players_json(const char* game, char** out);
/** Experimental. The name of seat `seat` (0 or 1): "human" or a player. */
BS_API BsStatus bs_game_seat(const BsGame* game, int32_t seat, const char** out);
/** Experimental. The game's budget of simulations per computer decision
 * ("ai_budget", a link's "n"); 0 when it has none (each level its own). */
BS_API BsStatus bs_game_ai_budget(const BsGame* game, int64_t* out);
/** Experimental. bs_game_apply_json, and what the action did: {"index",
 * "player", "kind" ("place", "shoot", "decide"), "executed" (the action as
 * played, after noise), "intended" and "numbers" (shots: the strike chosen,
 * and the ball number of each ball of the shot's scenario), "ruling",
 * "turn" (as bs_game_turns_json), "facts"}. Messages name the field from
 * the action's root ("strike.speed: ..."); the rules' refusal is
 * BS_ERROR_ILLEGAL with their reason, the game unchanged. */
BS_API BsStatus bs_game_act_json(BsGame* game, const char* action, size_t len, char** out);
/** Experimental. Whose turn it is after each action, and why: {"turns":
 * [{"next": seat (-1 once over), "why": "continues" | "passes" | "foul" |
 * "decides" | "breaks" | "game_over"}, ...]}. */
BS_API BsStatus bs_game_turns_json(const BsGame* game, char** out);
/** Experimental. Takes the game back to its first n actions (n up to
 * bs_game_info's actions; BS_ERROR_OUT_OF_RANGE otherwise). */
BS_API BsStatus bs_game_undo_to(BsGame* game, size_t n);
/** Experimental. The game's table as src/io's table encoding writes it,
 * its markings included. */
BS_API BsStatus bs_game_table_json(const BsGame* game, char** out);
/** Experimental. BS_OK when the seat to act may place the cue ball at
 * (x, y) now, BS_ERROR_ILLEGAL with the rules' reason as the game's
 * message when not. */
BS_API BsStatus bs_game_check_placement(const BsGame* game, double x, double y);
/** Experimental. A snooker game's figures now: {"balls_on",
 * "points_remaining", "snookers_required": [2]}; BS_ERROR_STATE for
 * another game. */
BS_API BsStatus bs_game_snooker_figures_json(const BsGame* game, char** out);
/** Experimental. A three-cushion game's figures now: {"cue_ball" (the
 * ball the player to act strikes), "general_average": [2], "highest_run":
 * [2]}; BS_ERROR_STATE for another game. */
BS_API BsStatus bs_game_carom_figures_json(const BsGame* game, char** out);
/** Experimental. The game as a link: "v2." and the base64url of its
 * config, seats, budget and actions as chosen (docs/c-api.md). */
BS_API BsStatus bs_game_link(const BsGame* game, char** out);
/** Experimental. A game from a link ("v2.", or "v1." read with the legacy
 * physics; the link may sit in a URL's "game=" parameter), its actions
 * replayed through the rules: BS_ERROR_BAD_JSON names the first thing
 * refused ("link.a[7]: refused: ..."). */
BS_API BsStatus bs_game_from_link(const char* link, size_t len, BsGame** out);

/** Experimental. The AI levels and the budget each decides with in
 * bs_player_new_for_game: {"levels": [...], "budgets": {level: n}}. */
BS_API BsStatus bs_ai_levels_json(char** out);
/** Experimental. The computer player of the seat to act in `game` (`name`
 * NULL or "") or the one named (a hint for a human seat), as the page's
 * AI decides: one thread, no time limit and a budget of simulations per
 * decision (the game's, else the level's: bs_ai_levels_json), so that its
 * decisions are the same on every machine. BS_ERROR_OUT_OF_RANGE ("level:
 * ...") for a name that does not play the game, or a human seat to act
 * without a name; BS_ERROR_STATE once the game is over. Decide with
 * bs_player_decide_json on the same game. */
BS_API BsStatus bs_player_new_for_game(const BsGame* game, const char* name, BsPlayer** out);

/* ------------------------------------------------------------------------
 * Experimental: playbacks, a scenario run forward frame by frame for
 * drawing (a simulation advanced to each frame's time). */

typedef struct BsPlayback BsPlayback;

/* A frame (bs_playback_frame) as doubles:
 *   [0] t  [1] events so far  [2] at_rest (1|0)  [3] complete (1|0: 0
 *   once max_events stopped the run)  [4] energy (J)  [5] px  [6] py
 *   [7] n, the number of balls
 * then BS_FRAME_STRIDE per ball, in scenario order, from
 * [BS_FRAME_HEADER + BS_FRAME_STRIDE i]: x, y, on_table (1|0: 0 in a pocket
 * or off the table), vx, vy, energy, px, py;
 * then the flight block from [BS_FRAME_HEADER + BS_FRAME_STRIDE n]: a
 * flag, 1 when a ball of the frame is off the cloth (in flight or off the
 * table) else 0, then BS_FLIGHT_STRIDE per ball: z (the height of the
 * centre above its resting height, m) and its place (0 on the cloth or in
 * a pocket, 1 in flight, 2 off the table). */
#define BS_FRAME_HEADER 8
#define BS_FRAME_STRIDE 8
#define BS_FLIGHT_STRIDE 2

/** Experimental. A playback of `scenario` (BS_ERROR_INVALID if it is not
 * valid), at its start. */
BS_API BsStatus bs_playback_new(const BsScenario* scenario, BsPlayback** out);
/** Experimental. The playback of action `index` of `game` (a shot, as
 * executed) from the state before it: balls as bs_game_shot_simulation
 * orders them. */
BS_API BsStatus bs_game_shot_playback(const BsGame* game, size_t index, BsPlayback** out);
BS_API void bs_playback_free(BsPlayback* playback);
/** Experimental. Advances the playback to time t (finite, not earlier than
 * the last frame's: BS_ERROR_OUT_OF_RANGE) and gives its frame: *out
 * points to *n doubles in the layout above, owned by the playback and
 * valid until its next call. A run that ends at a time stays there. */
BS_API BsStatus bs_playback_frame(BsPlayback* playback, double t, const double** out, size_t* n);
/** Experimental. Where a playback stands. */
typedef struct BsPlaybackInfo {
  size_t balls;
  size_t events;    /**< events played so far */
  double time;      /**< the playback's time (its last frame's; 0 at the start) */
  int32_t at_rest;  /**< 1 when no ball moves */
  int32_t complete; /**< 0 once max_events stopped the run */
} BsPlaybackInfo;

/** Experimental. */
BS_API BsStatus bs_playback_info(const BsPlayback* playback, BsPlaybackInfo* out);
/** Experimental. Every ball's state at the playback's time (its last
 * frame's, or the start) into out[0 .. n), n the number of balls. */
BS_API BsStatus bs_playback_states(const BsPlayback* playback, BsBallState* out, size_t n);
/** Experimental. The events so far from index `from` (up to the number
 * played: BS_ERROR_OUT_OF_RANGE beyond): {"from", "events": [...]}, each
 * as the result file writes it. */
BS_API BsStatus bs_playback_events_json(const BsPlayback* playback, size_t from, char** out);
/** Experimental. A three-cushion shot's count over its events so far
 * (bs_game_shot_playback of a three-cushion shot; BS_ERROR_STATE for
 * another playback): {"cushions", "hit" (ball numbers, in order), "done",
 * "made"}, as the rules count. */
BS_API BsStatus bs_playback_carom_count_json(const BsPlayback* playback, char** out);

#ifdef __cplusplus
}
#endif

#endif /* BREAKSHOT_H */
