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
 * "friction", "pool"} (each bs_physics_default's fields by name)}. */
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

#ifdef __cplusplus
}
#endif

#endif /* BREAKSHOT_H */
