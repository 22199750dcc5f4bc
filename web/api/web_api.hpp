/* The engine, the rules and the AI behind a C API that passes JSON text:
 * the facade of the browser version (docs/web.md, "The C API"). It is
 * compiled natively (library breakshot_web_api) and to wasm
 * (web/CMakeLists.txt); both give the same bytes for the same calls
 * (web/tests/identity.mjs).
 *
 * Every function takes and returns UTF-8 JSON text (but
 * bs_playback_frame_data, which returns doubles). A returned
 * `const char*` is owned by the handle and stays valid until the next
 * call on the same handle (bs_version's forever; bs_last_error's until
 * the next call on the same thread). bs_simulate's `char*` belongs to the
 * caller, who releases it with bs_free. Nothing throws across this
 * boundary: a bad input or a failure is answered with
 * {"error": "<what is wrong, naming the field>"}. Handles are not
 * thread-safe; distinct handles are independent (no shared state but
 * bs_last_error's buffer, which is per thread).
 */
#ifndef BREAKSHOT_WEB_API_HPP
#define BREAKSHOT_WEB_API_HPP

#ifdef __cplusplus
extern "C" {
#endif

typedef struct BsPlayback BsPlayback;
typedef struct BsGame BsGame;

/* {"version": "...", "levels": [...], "ai_budgets": {...},
 *  "snooker_players": [...] (the computer players of a snooker seat),
 *  "defaults": {"ball": {"radius", "mass", "wall_restitution"},
 *               "pool_cushion_restitution",
 *               "physics": {"ideal": {...}, "friction": {...}, "pool": {...}}}}
 * where "physics" is default_physics(model) (physics.hpp) field by field,
 * every field of PhysicsParams by its name: numbers and booleans as they
 * are, "model" and "ball_ball_model" by their names ("pool", "friction"),
 * "ball_ball_friction_curve" as {"a", "b", "c"}. */
const char* bs_version(void);

/* The computer players a seat of `game` ("eight_ball", "nine_ball",
 * "ten_ball", "snooker" or "three_cushion") may be: {"game": game, "players":
 * [names]} (the AI levels that play the game, and "baseline" where it
 * plays), or {"error"}. Valid until the next call of bs_game_players. */
const char* bs_game_players(const char* game);

/* The result file of a scenario (docs/contract.md),
 * exactly as `breakshot simulate` writes it, or {"error"}. Release the
 * text with bs_free. */
char* bs_simulate(const char* scenario_json);
void bs_free(char* p);

/* Playback: the exact states of a scenario at frame times. NULL on error
 * (see bs_last_error). */
BsPlayback* bs_playback_new(const char* scenario_json);
const char* bs_playback_frame(BsPlayback* pb, double t);
/* The frame of bs_playback_frame (the same rules for t, the same
 * numbers: its JSON is written from this) as doubles, without text:
 *   [0] t  [1] events  [2] at_rest (1|0)  [3] complete (1|0)
 *   [4] energy  [5] px  [6] py  [7] n, the number of balls
 * then 8 per ball, in scenario order, from [8 + 8 i]:
 *   x, y, on_table (1|0: 0 in a pocket or off the table), vx, vy,
 *   energy, px, py;
 * then the flight block, from [8 + 8 n]: a flag, 1 when a ball of the
 * frame is off the cloth (in flight or off the table, physics.airborne)
 * else 0, then 2 per ball from [9 + 8 n + 2 i]: z (the height of the
 * centre above its resting height, m) and its place: 0 on the cloth (or
 * in a pocket), 1 in flight, 2 off the table. bs_playback_frame's JSON
 * appends z and the place to each ball's array only when the flag is 1:
 * a frame whose balls are all on the cloth or in pockets has 8 numbers
 * per ball.
 * The buffer belongs to the playback and stays valid until the next call
 * on it (bs_playback_frame included) or bs_playback_free. NULL on error
 * (a null handle, t not finite or earlier than the last frame's): see
 * bs_last_error. */
const double* bs_playback_frame_data(BsPlayback* pb, double t);
/* The spins of the balls at the playback's time (its last frame's, or
 * the start before any frame): 3 doubles per ball in scenario order, wx,
 * wy, wz (rad/s, table axes; zero in the ideal and friction models). For
 * drawing (the page rolls the balls' markings with them). The buffer
 * belongs to the playback and stays valid until its next call; NULL for a
 * null handle (see bs_last_error). */
const double* bs_playback_spins(BsPlayback* pb);
const char* bs_playback_events(BsPlayback* pb, int from);
/* A three-cushion shot's count over the playback's events so far (up to
 * its last frame): {"cushions", "hit" (the object balls the struck ball
 * touched, by number, in order), "done" (it has met both), "made" (both,
 * three cushions first: a point, fouls aside)}; the rules count the same
 * way (game.hpp's carom_count). {"error"} for another playback. */
const char* bs_playback_carom_count(BsPlayback* pb);
void bs_playback_free(BsPlayback* pb);

/* Games between two seats, each "human" or an AI level name. */
BsGame* bs_game_new(const char* config_json);
BsGame* bs_game_from_link(const char* link);
const char* bs_game_table(BsGame* g);
const char* bs_game_state(BsGame* g);
const char* bs_game_check_placement(BsGame* g, double x, double y);
const char* bs_game_act(BsGame* g, const char* action_json);
const char* bs_game_ai_action(BsGame* g, const char* level_or_null);
BsPlayback* bs_game_shot_playback(BsGame* g, int index);
const char* bs_game_link(BsGame* g);
const char* bs_game_record(BsGame* g);
/* Whose turn it is after each action, and why: {"turns": [{"next": seat
 * (-1 once the game is over), "why": "continues" | "passes" | "foul" |
 * "decides" | "breaks" | "game_over"}, ...]}, one per action; bs_game_act's
 * reply carries its action's as "turn". */
const char* bs_game_turns(BsGame* g);
const char* bs_game_undo_to(BsGame* g, int n);
void bs_game_free(BsGame* g);

/* {"error": "..."} of the last *_new call (or bs_game_from_link,
 * bs_game_shot_playback, bs_playback_frame_data, bs_playback_spins) that
 * returned NULL, until a call succeeds: every call that succeeds clears
 * it, and it is then {"error": "no error"} (as before any call). Per
 * thread. */
const char* bs_last_error(void);

#ifdef __cplusplus
}
#endif

#endif /* BREAKSHOT_WEB_API_HPP */
