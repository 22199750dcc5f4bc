/* The C API's tests, in C, of the experimental calls (include/breakshot.h,
 * docs/c-api.md, "Games as the page plays them" and "Playbacks"): games
 * from a config document and from links, acts and their reports, turns,
 * undo, the table, placement checks, the snooker and carom figures, the
 * AI of a game, and playbacks; and bad input on every call (null
 * pointers, bad handles, bad JSON, values out of range), each a status and
 * a message, never a crash.
 *
 *   test_capi_page
 */
#include <math.h>
#include <stdint.h>

#include "check.h"

static const char* kBreak =
    "{\"type\": \"shoot\", \"strike\": {\"speed\": 7, \"phi\": 0, \"theta\": 0, \"a\": 0, "
    "\"b\": 0}, \"call\": null, \"safety\": false, \"push_out\": false}";

static int starts_with(const char* text, const char* head) {
  return strncmp(text, head, strlen(head)) == 0;
}

static BsGame* new_json(const char* config) {
  BsGame* g = NULL;
  OK(bs_game_new_json(config, strlen(config), &g));
  return g;
}

static void test_config(void) {
  BsGame* g = NULL;
  BsGameInfo info;
  const char* seat = NULL;
  int64_t budget = -1;
  char* text = NULL;
  g = new_json("{\"game\": \"nine_ball\", \"seed\": \"7\", \"breaker\": 1, "
               "\"players\": [\"human\", \"club@0.5x\"], \"ai_budget\": 50}");
  CHECK(g != NULL);
  OK(bs_game_info(g, &info));
  CHECK(info.player == 1 && info.balls == 10 && info.actions == 0);
  OK(bs_game_seat(g, 0, &seat));
  CHECK(seat != NULL && strcmp(seat, "human") == 0);
  OK(bs_game_seat(g, 1, &seat));
  CHECK(seat != NULL && strcmp(seat, "club@0.5x") == 0);
  OK(bs_game_ai_budget(g, &budget));
  CHECK(budget == 50);
  FAILS(bs_game_seat(g, 2, &seat), BS_ERROR_OUT_OF_RANGE, g, "seat");
  FAILS(bs_game_seat(g, 0, NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_game_seat(NULL, 0, &seat), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_ai_budget(g, NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_game_ai_budget(NULL, &budget), BS_ERROR_NULL, NULL, "game");
  bs_game_free(g);

  g = new_json("{\"game\": \"eight_ball\", \"players\": [\"human\", \"human\"]}");
  OK(bs_game_ai_budget(g, &budget));
  CHECK(budget == 0);
  bs_game_free(g);

  /* bad configs: a status, a message naming the field, no game */
  g = NULL;
  FAILS(bs_game_new_json("{\"game\": ", 9, &g), BS_ERROR_BAD_JSON, NULL, "config: not valid JSON");
  CHECK(g == NULL);
  {
    const char* c = "{\"game\": \"pool\", \"players\": [\"human\", \"human\"]}";
    FAILS(bs_game_new_json(c, strlen(c), &g), BS_ERROR_BAD_JSON, NULL, "game");
  }
  {
    const char* c = "{\"game\": \"nine_ball\", \"players\": [\"human\", \"grandmaster\"]}";
    FAILS(bs_game_new_json(c, strlen(c), &g), BS_ERROR_BAD_JSON, NULL, "players[1]");
  }
  {
    const char* c = "{\"game\": \"nine_ball\", \"players\": [\"human\", \"human\"], \"speed\": 1}";
    FAILS(bs_game_new_json(c, strlen(c), &g), BS_ERROR_BAD_JSON, NULL, "speed");
  }
  {
    const char* c =
        "{\"game\": \"nine_ball\", \"players\": [\"human\", \"human\"], \"carom\": {}}";
    FAILS(bs_game_new_json(c, strlen(c), &g), BS_ERROR_BAD_JSON, NULL, "carom");
  }
  {
    const char* c = "{\"game\": \"nine_ball\", \"players\": [\"human\", \"human\"], \"breaker\": 2}";
    FAILS(bs_game_new_json(c, strlen(c), &g), BS_ERROR_BAD_JSON, NULL, "breaker");
  }
  FAILS(bs_game_new_json(NULL, 3, &g), BS_ERROR_NULL, NULL, "config");
  FAILS(bs_game_new_json("{}", 2, NULL), BS_ERROR_NULL, NULL, "out");
  CHECK(g == NULL);

  /* the players of a game */
  OK(bs_game_players_json("snooker", &text));
  CHECK(text != NULL && strstr(text, "\"baseline\"") != NULL && strstr(text, "\"champion\"") != NULL);
  bs_string_free(text);
  OK(bs_game_players_json("nine_ball", &text));
  CHECK(text != NULL && strstr(text, "\"baseline\"") == NULL);
  bs_string_free(text);
  FAILS(bs_game_players_json("pool", &text), BS_ERROR_BAD_JSON, NULL, "game");
  FAILS(bs_game_players_json(NULL, &text), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_players_json("snooker", NULL), BS_ERROR_NULL, NULL, "out");
  OK(bs_ai_levels_json(&text));
  CHECK(text != NULL && strstr(text, "\"budgets\"") != NULL && strstr(text, "\"champion\":24000") != NULL);
  bs_string_free(text);
  FAILS(bs_ai_levels_json(NULL), BS_ERROR_NULL, NULL, "out");
}

static void test_acts(void) {
  BsGame* g = new_json("{\"game\": \"nine_ball\", \"seed\": 3, \"players\": [\"human\", \"human\"]}");
  BsGame* back = NULL;
  BsGameInfo info;
  BsPlayback* pb = NULL;
  char* text = NULL;
  char* link = NULL;
  char* record = NULL;
  char* record2 = NULL;

  /* bad acts: a status and a message, the game unchanged */
  FAILS(bs_game_act_json(g, "{\"type\":", 8, &text), BS_ERROR_BAD_JSON, g, "action: not valid JSON");
  CHECK(text == NULL);
  FAILS(bs_game_act_json(g, "{\"type\": \"dance\"}", 17, &text), BS_ERROR_BAD_JSON, g, "type");
  FAILS(bs_game_act_json(g, NULL, 0, &text), BS_ERROR_NULL, g, "action");
  FAILS(bs_game_act_json(g, kBreak, strlen(kBreak), NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_game_act_json(NULL, kBreak, strlen(kBreak), &text), BS_ERROR_NULL, NULL, "game");
  {
    const char* decide = "{\"type\": \"decide\", \"choice\": \"shoot\"}";
    FAILS(bs_game_act_json(g, decide, strlen(decide), &text), BS_ERROR_ILLEGAL, g, "");
  }
  OK(bs_game_info(g, &info));
  CHECK(info.actions == 0);

  /* the break, and its report */
  OK(bs_game_act_json(g, kBreak, strlen(kBreak), &text));
  CHECK(text != NULL && starts_with(text, "{\"index\":0,\"player\":0,\"kind\":\"shoot\""));
  CHECK(text != NULL && strstr(text, "\"intended\"") != NULL && strstr(text, "\"facts\"") != NULL);
  CHECK(text != NULL && strstr(text, "\"turn\":{\"next\":") != NULL);
  bs_string_free(text);
  OK(bs_game_turns_json(g, &text));
  CHECK(text != NULL && starts_with(text, "{\"turns\":[{\"next\":"));
  bs_string_free(text);
  FAILS(bs_game_turns_json(g, NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_game_turns_json(NULL, &text), BS_ERROR_NULL, NULL, "game");

  /* the link, and the game made again from it (in a URL too) */
  OK(bs_game_link(g, &link));
  CHECK(link != NULL && starts_with(link, "v2."));
  OK(bs_game_from_link(link, strlen(link), &back));
  OK(bs_game_record_json(g, &record));
  OK(bs_game_record_json(back, &record2));
  CHECK(record != NULL && record2 != NULL && strcmp(record, record2) == 0);
  bs_string_free(record2);
  bs_game_free(back);
  {
    char url[4096];
    snprintf(url, sizeof url, "https://example.org/#game=%s&x=1", link);
    OK(bs_game_from_link(url, strlen(url), &back));
    bs_game_free(back);
  }
  back = NULL;
  FAILS(bs_game_from_link("v9.abc", 6, &back), BS_ERROR_BAD_JSON, NULL, "link");
  FAILS(bs_game_from_link("v2.!!!!", 7, &back), BS_ERROR_BAD_JSON, NULL, "base64url");
  FAILS(bs_game_from_link("v2.e30", 6, &back), BS_ERROR_BAD_JSON, NULL, "link");
  FAILS(bs_game_from_link(link, 10, &back), BS_ERROR_BAD_JSON, NULL, "link");
  FAILS(bs_game_from_link(NULL, 4, &back), BS_ERROR_NULL, NULL, "link");
  FAILS(bs_game_from_link(link, strlen(link), NULL), BS_ERROR_NULL, NULL, "out");
  CHECK(back == NULL);
  FAILS(bs_game_link(g, NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_game_link(NULL, &text), BS_ERROR_NULL, NULL, "game");
  bs_string_free(link);
  bs_string_free(record);

  /* the shot's playback */
  OK(bs_game_shot_playback(g, 0, &pb));
  {
    const double* d = NULL;
    size_t n = 0;
    BsPlaybackInfo pi;
    OK(bs_playback_frame(pb, 10.0, &d, &n));
    CHECK(d != NULL && n == BS_FRAME_HEADER + 10 * BS_FRAME_STRIDE + 1 + 10 * BS_FLIGHT_STRIDE);
    OK(bs_playback_info(pb, &pi));
    CHECK(pi.balls == 10 && pi.events > 10 && pi.time == 10.0);
    FAILS(bs_playback_carom_count_json(pb, &text), BS_ERROR_STATE, pb, "three-cushion");
  }
  bs_playback_free(pb);
  pb = NULL;
  FAILS(bs_game_shot_playback(g, 1, &pb), BS_ERROR_OUT_OF_RANGE, g, "index");
  FAILS(bs_game_shot_playback(g, 0, NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_game_shot_playback(NULL, 0, &pb), BS_ERROR_NULL, NULL, "game");
  CHECK(pb == NULL);

  /* undo */
  FAILS(bs_game_undo_to(g, 2), BS_ERROR_OUT_OF_RANGE, g, "n");
  FAILS(bs_game_undo_to(NULL, 0), BS_ERROR_NULL, NULL, "game");
  OK(bs_game_undo_to(g, 0));
  OK(bs_game_info(g, &info));
  CHECK(info.actions == 0 && info.player == 0);
  OK(bs_game_undo_to(g, 0));

  /* the table, placement */
  OK(bs_game_table_json(g, &text));
  CHECK(text != NULL && strstr(text, "\"pockets\"") != NULL);
  bs_string_free(text);
  FAILS(bs_game_table_json(g, NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_game_table_json(NULL, &text), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_check_placement(g, 100.0, 100.0), BS_ERROR_ILLEGAL, g, "");
  FAILS(bs_game_check_placement(NULL, 0.5, 0.5), BS_ERROR_NULL, NULL, "game");

  /* figures of another game */
  FAILS(bs_game_snooker_figures_json(g, &text), BS_ERROR_STATE, g, "snooker");
  FAILS(bs_game_carom_figures_json(g, &text), BS_ERROR_STATE, g, "three_cushion");
  FAILS(bs_game_snooker_figures_json(NULL, &text), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_carom_figures_json(NULL, &text), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_snooker_figures_json(g, NULL), BS_ERROR_NULL, g, "out");
  bs_game_free(g);
}

static void test_figures_and_ai(void) {
  BsGame* g = new_json("{\"game\": \"snooker\", \"seed\": 5, \"players\": [\"human\", \"baseline\"]}");
  BsGame* human = new_json("{\"game\": \"eight_ball\", \"players\": [\"human\", \"human\"]}");
  BsPlayer* p = NULL;
  BsGameInfo info;
  char* text = NULL;
  char* action = NULL;
  OK(bs_game_snooker_figures_json(g, &text));
  CHECK(text != NULL && strstr(text, "\"points_remaining\"") != NULL);
  bs_string_free(text);

  /* the AI of a seat: a human seat needs a name; names that do not play */
  FAILS(bs_player_new_for_game(g, NULL, &p), BS_ERROR_OUT_OF_RANGE, g, "human");
  CHECK(p == NULL);
  FAILS(bs_player_new_for_game(g, "human", &p), BS_ERROR_OUT_OF_RANGE, g, "level");
  FAILS(bs_player_new_for_game(g, "grandmaster", &p), BS_ERROR_OUT_OF_RANGE, g, "level");
  FAILS(bs_player_new_for_game(human, "baseline", &p), BS_ERROR_OUT_OF_RANGE, human, "level");
  FAILS(bs_player_new_for_game(NULL, "beginner", &p), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_player_new_for_game(g, "beginner", NULL), BS_ERROR_NULL, g, "out");
  FAILS(bs_player_new_for_game((const BsGame*)"not a game", "beginner", &p), BS_ERROR_BAD_HANDLE,
        NULL, "game");
  /* a hint for the human seat, played, then the baseline's own decision */
  OK(bs_player_new_for_game(g, "beginner", &p));
  OK(bs_player_decide_json(p, g, &action));
  CHECK(action != NULL && strstr(action, "\"type\"") != NULL);
  if (action != NULL) OK(bs_game_apply_json(g, action, strlen(action)));
  bs_string_free(action);
  bs_player_free(p);
  p = NULL;
  OK(bs_game_info(g, &info));
  if (info.player == 1 && info.over == 0) {
    OK(bs_player_new_for_game(g, NULL, &p));
    OK(bs_player_decide_json(p, g, &action));
    CHECK(action != NULL);
    bs_string_free(action);
    bs_player_free(p);
  }
  bs_game_free(g);
  bs_game_free(human);

  g = new_json("{\"game\": \"three_cushion\", \"players\": [\"human\", \"human\"], "
               "\"carom\": {\"target\": 2}}");
  OK(bs_game_carom_figures_json(g, &text));
  CHECK(text != NULL && strstr(text, "\"general_average\"") != NULL);
  bs_string_free(text);
  FAILS(bs_game_snooker_figures_json(g, &text), BS_ERROR_STATE, g, "snooker");
  bs_game_free(g);
}

static void test_playbacks(void) {
  static const char* scenario =
      "{\"physics\": {\"model\": \"ideal\"},"
      " \"table\": {\"shape\": \"rectangle\", \"min\": [-1, -1], \"max\": [1, 1]},"
      " \"balls\": [{\"id\": \"a\", \"position\": [-0.5, 0], \"velocity\": [1, 0]},"
      "             {\"id\": \"b\", \"position\": [0.5, 0], \"velocity\": [0, 0]}],"
      " \"until\": {\"time\": 2}}";
  BsScenario* s = NULL;
  BsPlayback* pb = NULL;
  BsPlaybackInfo info;
  BsBallState st[2];
  const double* d = NULL;
  size_t n = 0;
  char* text = NULL;
  OK(bs_scenario_from_json(scenario, strlen(scenario), &s));
  /* the result file without the run kept: the bytes of the run's */
  {
    BsSimulation* sim = NULL;
    char* a = NULL;
    char* b = NULL;
    BsScenario* empty = NULL;
    OK(bs_simulate(s, &sim));
    OK(bs_simulation_result_json(sim, &a));
    OK(bs_simulate_result_json(s, &b));
    CHECK(a != NULL && b != NULL && strcmp(a, b) == 0);
    bs_string_free(a);
    bs_string_free(b);
    bs_simulation_free(sim);
    FAILS(bs_simulate_result_json(s, NULL), BS_ERROR_NULL, s, "out");
    FAILS(bs_simulate_result_json(NULL, &b), BS_ERROR_NULL, NULL, "scenario");
    FAILS(bs_simulate_result_json((const BsScenario*)"nope", &b), BS_ERROR_BAD_HANDLE, NULL,
          "scenario");
    OK(bs_scenario_new(&empty));
    FAILS(bs_simulate_result_json(empty, &b), BS_ERROR_INVALID, empty, "");
    CHECK(b == NULL);
    bs_scenario_free(empty);
  }
  OK(bs_playback_new(s, &pb));
  if (pb == NULL) return;
  OK(bs_playback_info(pb, &info));
  CHECK(info.balls == 2 && info.events == 0 && info.time == 0.0 && info.complete == 1);
  OK(bs_playback_states(pb, st, 2));
  CHECK(st[0].motion == BS_MOTION_MOVING && st[1].motion == BS_MOTION_STATIONARY);
  OK(bs_playback_frame(pb, 1.0, &d, &n));
  CHECK(n == BS_FRAME_HEADER + 2 * BS_FRAME_STRIDE + 1 + 2 * BS_FLIGHT_STRIDE);
  CHECK(d[0] == 1.0 && d[7] == 2.0 && d[1] >= 1.0);
  /* after the exchange the first ball stands, the second moves */
  CHECK(d[BS_FRAME_HEADER + 3] == 0.0 && d[BS_FRAME_HEADER + BS_FRAME_STRIDE + 3] == 1.0);
  OK(bs_playback_states(pb, st, 2));
  CHECK(st[0].motion == BS_MOTION_STATIONARY && st[1].motion == BS_MOTION_MOVING);
  CHECK(st[1].position[0] == d[BS_FRAME_HEADER + BS_FRAME_STRIDE]);
  OK(bs_playback_events_json(pb, 0, &text));
  CHECK(text != NULL && starts_with(text, "{\"from\":0,\"events\":[{"));
  CHECK(text != NULL && strstr(text, "\"ball_ball\"") != NULL);
  bs_string_free(text);
  OK(bs_playback_info(pb, &info));
  OK(bs_playback_events_json(pb, info.events, &text));
  CHECK(text != NULL && strstr(text, "\"events\":[]") != NULL);
  bs_string_free(text);
  /* a run that ends at a time stays there */
  OK(bs_playback_frame(pb, 5.0, &d, &n));
  CHECK(d[0] == 2.0);

  /* bad input */
  FAILS(bs_playback_frame(pb, 1.0, &d, &n), BS_ERROR_OUT_OF_RANGE, pb, "backwards");
  FAILS(bs_playback_frame(pb, NAN, &d, &n), BS_ERROR_OUT_OF_RANGE, pb, "finite");
  FAILS(bs_playback_frame(pb, INFINITY, &d, &n), BS_ERROR_OUT_OF_RANGE, pb, "finite");
  FAILS(bs_playback_frame(pb, 6.0, NULL, &n), BS_ERROR_NULL, pb, "out");
  FAILS(bs_playback_frame(pb, 6.0, &d, NULL), BS_ERROR_NULL, pb, "n");
  FAILS(bs_playback_frame(NULL, 6.0, &d, &n), BS_ERROR_NULL, NULL, "playback");
  FAILS(bs_playback_frame((BsPlayback*)s, 6.0, &d, &n), BS_ERROR_BAD_HANDLE, NULL, "playback");
  FAILS(bs_playback_states(pb, st, 3), BS_ERROR_OUT_OF_RANGE, pb, "2 balls");
  FAILS(bs_playback_states(pb, NULL, 2), BS_ERROR_NULL, pb, "out");
  FAILS(bs_playback_states(NULL, st, 2), BS_ERROR_NULL, NULL, "playback");
  FAILS(bs_playback_info(pb, NULL), BS_ERROR_NULL, pb, "out");
  FAILS(bs_playback_info(NULL, &info), BS_ERROR_NULL, NULL, "playback");
  FAILS(bs_playback_events_json(pb, 1000, &text), BS_ERROR_OUT_OF_RANGE, pb, "from");
  FAILS(bs_playback_events_json(pb, 0, NULL), BS_ERROR_NULL, pb, "out");
  FAILS(bs_playback_events_json(NULL, 0, &text), BS_ERROR_NULL, NULL, "playback");
  FAILS(bs_playback_carom_count_json(pb, &text), BS_ERROR_STATE, pb, "three-cushion");
  FAILS(bs_playback_carom_count_json(NULL, &text), BS_ERROR_NULL, NULL, "playback");
  /* a success clears the handle's message */
  OK(bs_playback_info(pb, &info));
  CHECK(strcmp(bs_error_message(pb), "") == 0);
  bs_playback_free(pb);
  bs_playback_free(NULL);

  pb = NULL;
  FAILS(bs_playback_new(NULL, &pb), BS_ERROR_NULL, NULL, "scenario");
  FAILS(bs_playback_new(s, NULL), BS_ERROR_NULL, s, "out");
  {
    BsScenario* empty = NULL;
    OK(bs_scenario_new(&empty));
    FAILS(bs_playback_new(empty, &pb), BS_ERROR_INVALID, empty, "");
    bs_scenario_free(empty);
  }
  CHECK(pb == NULL);
  bs_scenario_free(s);
}

static void test_three_cushion_count(void) {
  BsGame* g = new_json("{\"game\": \"three_cushion\", \"seed\": 2, \"players\": [\"human\", \"human\"]}");
  BsPlayback* pb = NULL;
  const double* d = NULL;
  size_t n = 0;
  char* text = NULL;
  const char* shot =
      "{\"type\": \"shoot\", \"strike\": {\"speed\": 3, \"phi\": 30, \"theta\": 0, \"a\": 0, "
      "\"b\": 0}, \"call\": null, \"safety\": false, \"push_out\": false}";
  OK(bs_game_act_json(g, shot, strlen(shot), &text));
  bs_string_free(text);
  OK(bs_game_shot_playback(g, 0, &pb));
  OK(bs_playback_frame(pb, 30.0, &d, &n));
  OK(bs_playback_carom_count_json(pb, &text));
  CHECK(text != NULL && starts_with(text, "{\"cushions\":") && strstr(text, "\"made\"") != NULL);
  bs_string_free(text);
  bs_playback_free(pb);
  bs_game_free(g);
}

int main(void) {
  test_config();
  test_acts();
  test_figures_and_ai();
  test_playbacks();
  test_three_cushion_count();
  return check_summary("test_capi_page");
}
