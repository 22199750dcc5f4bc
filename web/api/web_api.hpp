/* The facade of the browser version (docs/web.md, "The C API"): the C API
 * (include/breakshot.h) in the calling convention of the page's
 * JavaScript, JSON text in and out. Every function here is a thin layer
 * on breakshot.h's calls: it turns their statuses and per-handle messages
 * into {"error": "..."} replies and one last-error string, and writes the
 * page's replies from theirs. It is compiled natively (library
 * breakshot_web_api, which links the C API) and to wasm
 * (web/CMakeLists.txt: the C API and the facade in one module); both give
 * the same bytes for the same calls (web/tests/identity.mjs). Its names
 * are bs_web_* and its handles BsWeb*, apart from breakshot.h's.
 *
 * Every function takes and returns UTF-8 JSON text (but
 * bs_web_playback_frame_data, bs_web_playback_spins and
 * bs_web_playback_motions, which return doubles). A returned
 * `const char*` is owned by the handle and stays valid until the next
 * call on the same handle (bs_web_version's forever; bs_web_last_error's
 * until the next call on the same thread). bs_web_simulate's `char*`
 * belongs to the caller, who releases it with bs_web_free. Nothing throws
 * across this boundary: a bad input or a failure is answered with
 * {"error": "<what is wrong, naming the field>"} (the C API's message).
 * Handles are not thread-safe; distinct handles are independent (no
 * shared state but bs_web_last_error's buffer, which is per thread).
 */
#ifndef BREAKSHOT_WEB_API_HPP
#define BREAKSHOT_WEB_API_HPP

#ifdef __cplusplus
extern "C" {
#endif

typedef struct BsWebPlayback BsWebPlayback;
typedef struct BsWebGame BsWebGame;

/* {"version": "...", "levels": [...], "ai_budgets": {...} (bs_ai_levels_json),
 *  "snooker_players": [...] (the computer players of a snooker seat),
 *  "defaults": {"ball": {"radius", "mass", "wall_restitution"},
 *               "pool_cushion_restitution",
 *               "physics": {"ideal": {...}, "friction": {...}, "pool": {...}}}}
 * where "physics" is bs_physics_options_json's defaults of each model,
 * every field of PhysicsParams by its name: numbers and booleans as they
 * are, "model" and "ball_ball_model" by their names ("pool", "friction"),
 * "ball_ball_friction_curve" as {"a", "b", "c"}. */
const char* bs_web_version(void);

/* bs_game_players_json: the computer players a seat of `game`
 * ("eight_ball", "nine_ball", "ten_ball", "snooker" or "three_cushion")
 * may be: {"game": game, "players": [names]}, or {"error"}. Valid until
 * the next call of bs_web_game_players. */
const char* bs_web_game_players(const char* game);

/* The result file of a scenario (docs/contract.md), exactly as
 * `breakshot simulate` writes it (bs_scenario_from_json,
 * bs_simulate_result_json), or {"error"}. Release the text with
 * bs_web_free. */
char* bs_web_simulate(const char* scenario_json);
void bs_web_free(char* p);

/* Playback (bs_playback_*): the exact states of a scenario at frame
 * times. NULL on error (see bs_web_last_error). */
BsWebPlayback* bs_web_playback_new(const char* scenario_json);
/* The frame at t as JSON: {"t", "balls": [[x, y, on_table (1|0), vx, vy,
 * energy, px, py], ...], "energy", "momentum": [px, py], "events",
 * "at_rest", "complete"}, written from bs_web_playback_frame_data's
 * doubles; each ball's array also carries z and its place (0 on the
 * cloth or in a pocket, 1 in flight, 2 off the table) when a ball of the
 * frame is off the cloth (the flight block's flag). */
const char* bs_web_playback_frame(BsWebPlayback* pb, double t);
/* The frame of bs_playback_frame as doubles, without text, in
 * breakshot.h's layout (BS_FRAME_HEADER, BS_FRAME_STRIDE,
 * BS_FLIGHT_STRIDE):
 *   [0] t  [1] events  [2] at_rest (1|0)  [3] complete (1|0)
 *   [4] energy  [5] px  [6] py  [7] n, the number of balls
 * then 8 per ball, in scenario order, from [8 + 8 i]:
 *   x, y, on_table (1|0: 0 in a pocket or off the table), vx, vy,
 *   energy, px, py;
 * then the flight block, from [8 + 8 n]: a flag, 1 when a ball of the
 * frame is off the cloth (in flight or off the table, physics.airborne)
 * else 0, then 2 per ball from [9 + 8 n + 2 i]: z and its place.
 * The buffer belongs to the playback and stays valid until the next call
 * on it (bs_web_playback_frame included) or bs_web_playback_free. NULL on
 * error (a null handle, t not finite or earlier than the last frame's):
 * see bs_web_last_error. */
const double* bs_web_playback_frame_data(BsWebPlayback* pb, double t);
/* The spins of the balls at the playback's time (its last frame's, or
 * the start before any frame; bs_playback_states): 3 doubles per ball in
 * scenario order, wx, wy, wz (rad/s, table axes; zero in the ideal and
 * friction models). For drawing (the page rolls the balls' markings with
 * them). The buffer belongs to the playback and stays valid until its
 * next call; NULL for a null handle (see bs_web_last_error). */
const double* bs_web_playback_spins(BsWebPlayback* pb);
/* The motion state of each ball at the playback's time, as
 * bs_web_playback_spins: 1 double per ball, breakshot.h's BsMotion
 * (0 stationary, 1 moving, 2 sliding, 3 rolling, 4 spinning, 5 pocketed,
 * 6 airborne, 7 off the table). */
const double* bs_web_playback_motions(BsWebPlayback* pb);
/* {"from": from, "events": [...]}: the events so far from index `from`
 * (bs_playback_events_json). */
const char* bs_web_playback_events(BsWebPlayback* pb, int from);
/* A three-cushion shot's count over the playback's events so far (up to
 * its last frame): {"cushions", "hit" (the object balls the struck ball
 * touched, by number, in order), "done" (it has met both), "made" (both,
 * three cushions first: a point, fouls aside)}; the rules count the same
 * way (bs_playback_carom_count_json). {"error"} for another playback. */
const char* bs_web_playback_carom_count(BsWebPlayback* pb);
void bs_web_playback_free(BsWebPlayback* pb);

/* Games between two seats, each "human" or a computer player
 * (bs_game_new_json's config; bs_game_from_link). */
BsWebGame* bs_web_game_new(const char* config_json);
BsWebGame* bs_web_game_from_link(const char* link);
/* bs_game_table_json. */
const char* bs_web_game_table(BsWebGame* g);
/* The state as game records write it (bs_game_state_json), then
 * "players" (the seats, bs_game_seat), "actions" (the number played),
 * "legal" (bs_game_legal_actions_json), and in snooker
 * "snooker_figures", in three-cushion "carom_figures". */
const char* bs_web_game_state(BsWebGame* g);
/* {"ok": true}, or {"ok": false, "reason"} (bs_game_check_placement). */
const char* bs_web_game_check_placement(BsWebGame* g, double x, double y);
/* bs_game_act_json's report with "state" (bs_web_game_state's) after it,
 * or {"error"} (the game unchanged). */
const char* bs_web_game_act(BsWebGame* g, const char* action_json);
/* {"action"}: the decision of bs_player_new_for_game's player (the seat
 * to act's, or `level_or_null`'s for a hint), in the form act takes. */
const char* bs_web_game_ai_action(BsWebGame* g, const char* level_or_null);
BsWebPlayback* bs_web_game_shot_playback(BsWebGame* g, int index);
/* {"link": "v2...."} (bs_game_link). */
const char* bs_web_game_link(BsWebGame* g);
/* bs_game_record_json. */
const char* bs_web_game_record(BsWebGame* g);
/* Whose turn it is after each action, and why: {"turns": [{"next": seat
 * (-1 once the game is over), "why": "continues" | "passes" | "foul" |
 * "decides" | "breaks" | "game_over"}, ...]}, one per action
 * (bs_game_turns_json); bs_web_game_act's reply carries its action's as
 * "turn". */
const char* bs_web_game_turns(BsWebGame* g);
/* bs_game_undo_to, then bs_web_game_state's reply. */
const char* bs_web_game_undo_to(BsWebGame* g, int n);
void bs_web_game_free(BsWebGame* g);

/* {"error": "..."} of the last *_new call (or bs_web_game_from_link,
 * bs_web_game_shot_playback, bs_web_playback_frame_data,
 * bs_web_playback_spins, bs_web_playback_motions) that returned NULL,
 * until a call succeeds: every call that succeeds clears it, and it is
 * then {"error": "no error"} (as before any call). Per thread. */
const char* bs_web_last_error(void);

#ifdef __cplusplus
}
#endif

#endif /* BREAKSHOT_WEB_API_HPP */
