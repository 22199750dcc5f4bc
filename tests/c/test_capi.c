/* The C API's tests, in C (include/breakshot.h, docs/c-api.md):
 * scenarios built by calls and read from text, simulations, events and
 * states, batches, games, players, records; and bad input on every call
 * (null pointers, bad handles, bad JSON, values out of range), each a
 * status and a message, never a crash.
 *
 *   test_capi SOURCE_DIR
 */
#include <math.h>
#include <stdint.h>

#include "check.h"

static const char* g_source = ".";

/* Two balls in a box, the ideal model, until t = 2. */
static BsScenario* two_balls(void) {
  BsScenario* s = NULL;
  BsTable t;
  BsBall b;
  OK(bs_scenario_new(&s));
  OK(bs_table_default(BS_TABLE_RECTANGLE, &t));
  OK(bs_scenario_set_table(s, &t));
  OK(bs_ball_default(&b));
  b.id = "a";
  b.position[0] = -0.5;
  b.velocity[0] = 1.0;
  OK(bs_scenario_add_ball(s, &b, NULL));
  b.id = "b";
  b.position[0] = 0.5;
  b.velocity[0] = 0.0;
  OK(bs_scenario_add_ball(s, &b, NULL));
  OK(bs_scenario_set_until_time(s, 2.0));
  return s;
}

/* An 8-ball break on the 9 ft table. */
static BsScenario* break_8ball(uint64_t seed, double phi) {
  BsScenario* s = NULL;
  BsPhysics p;
  BsTable t;
  BsStrike k = {10.0, 0.0, 0.0, 0.0, 0.0};
  k.phi = phi;
  OK(bs_scenario_new(&s));
  OK(bs_physics_default(BS_MODEL_POOL, &p));
  p.ball_clusters = 1;
  OK(bs_scenario_set_physics(s, &p));
  OK(bs_table_default(BS_TABLE_POOL, &t));
  OK(bs_scenario_set_table(s, &t));
  OK(bs_scenario_set_rack(s, "eight_ball", seed));
  OK(bs_scenario_strike(s, "cue", &k));
  return s;
}

static void test_version(void) {
  BsVersion v;
  char* json = NULL;
  OK(bs_version(&v));
  CHECK(v.api == BS_API_VERSION);
  CHECK(v.text != NULL && strlen(v.text) >= 5);
  CHECK(v.major >= 0 && v.minor >= 0 && v.patch >= 0);
  OK(bs_physics_options_json(&json));
  CHECK(json != NULL && strstr(json, "\"cushion_models\"") != NULL);
  CHECK(json != NULL && strstr(json, "\"stronge_compliant\"") != NULL);
  CHECK(json != NULL && strstr(json, "\"defaults\"") != NULL);
  bs_string_free(json);
  CHECK(strcmp(bs_status_name(BS_ERROR_ILLEGAL), "BS_ERROR_ILLEGAL") == 0);
  CHECK(strcmp(bs_status_name((BsStatus)99), "BS_UNKNOWN_STATUS") == 0);
  FAILS(bs_version(NULL), BS_ERROR_NULL, NULL, "out");
  FAILS(bs_physics_options_json(NULL), BS_ERROR_NULL, NULL, "out");
  /* A success clears the thread's message. */
  OK(bs_version(&v));
  CHECK(strcmp(bs_error_message(NULL), "") == 0);
  bs_string_free(NULL);
}

static void test_two_balls(void) {
  BsScenario* s = two_balls();
  BsSimulation* sim = NULL;
  BsSimulationInfo info;
  BsEvent ev[8];
  BsBallState st[2];
  size_t n = 0, k;
  const char* id = NULL;
  int hit = 0;
  OK(bs_scenario_ball_count(s, &n));
  CHECK(n == 2);
  OK(bs_simulate(s, &sim));
  OK(bs_simulation_info(sim, &info));
  CHECK(info.balls == 2);
  CHECK(info.complete == 1);
  CHECK(info.end_time == 2.0);
  CHECK(info.events >= 1 && info.events <= 8);
  OK(bs_simulation_events(sim, 0, info.events, ev));
  for (k = 0; k < info.events; ++k) {
    if (ev[k].kind == BS_EVENT_BALL_BALL && !hit) {
      hit = 1;
      CHECK(ev[k].ball == 0 && ev[k].other == 1);
      /* equal balls, elastic: they meet when the gap of 1 - 2r closes */
      CHECK(fabs(ev[k].time - (1.0 - 2 * 0.028575)) < 1e-9);
      CHECK(ev[k].from == -1 && ev[k].to == -1);
    }
  }
  CHECK(hit);
  OK(bs_simulation_states_at(sim, 0.0, st, 2));
  CHECK(st[0].position[0] == -0.5 && st[0].velocity[0] == 1.0);
  CHECK(st[0].motion == BS_MOTION_MOVING && st[1].motion == BS_MOTION_STATIONARY);
  OK(bs_simulation_states_at(sim, 1.0, st, 2));
  /* after the exchange the first ball stands, the second moves */
  CHECK(st[0].velocity[0] == 0.0 && st[1].velocity[0] == 1.0);
  /* times beyond the run are clamped to its end */
  OK(bs_simulation_states_at(sim, 1e9, st, 2));
  {
    BsBallState end[2];
    OK(bs_simulation_states_at(sim, 2.0, end, 2));
    CHECK(memcmp(st, end, sizeof st) == 0);
  }
  OK(bs_simulation_ball_id(sim, 1, &id));
  CHECK(id != NULL && strcmp(id, "b") == 0);
  OK(bs_simulation_wall_name(sim, 0, &id));
  CHECK(id != NULL && strlen(id) > 0);

  /* bad input on the simulation's calls */
  FAILS(bs_simulation_states_at(sim, 0.5, st, 3), BS_ERROR_OUT_OF_RANGE, sim, "2 balls");
  FAILS(bs_simulation_states_at(sim, NAN, st, 2), BS_ERROR_OUT_OF_RANGE, sim, "t");
  FAILS(bs_simulation_states_at(sim, 0.5, NULL, 2), BS_ERROR_NULL, sim, "out");
  FAILS(bs_simulation_events(sim, info.events, 1, ev), BS_ERROR_OUT_OF_RANGE, sim, "events");
  FAILS(bs_simulation_events(sim, (size_t)-1, 2, ev), BS_ERROR_OUT_OF_RANGE, sim, "events");
  FAILS(bs_simulation_events(sim, 0, 1, NULL), BS_ERROR_NULL, sim, "out");
  FAILS(bs_simulation_ball_id(sim, 2, &id), BS_ERROR_OUT_OF_RANGE, sim, "ball");
  FAILS(bs_simulation_ball_id(sim, 0, NULL), BS_ERROR_NULL, sim, "out");
  FAILS(bs_simulation_wall_name(sim, -1, &id), BS_ERROR_OUT_OF_RANGE, sim, "wall");
  FAILS(bs_simulation_pocket_name(sim, 0, &id), BS_ERROR_OUT_OF_RANGE, sim, "pocket");
  FAILS(bs_simulation_info(sim, NULL), BS_ERROR_NULL, sim, "out");
  FAILS(bs_simulation_result_json(sim, NULL), BS_ERROR_NULL, sim, "out");
  FAILS(bs_simulation_info(NULL, &info), BS_ERROR_NULL, NULL, "simulation");
  /* a handle of another type */
  FAILS(bs_simulation_info((const BsSimulation*)s, &info), BS_ERROR_BAD_HANDLE, NULL, "simulation");
  FAILS(bs_scenario_validate((const BsScenario*)sim), BS_ERROR_BAD_HANDLE, NULL, "scenario");
  /* a success on the handle clears its message */
  OK(bs_simulation_info(sim, &info));
  CHECK(strcmp(bs_error_message(sim), "") == 0);
  CHECK(strstr(bs_error_message((const void*)"not a handle"), "not a live handle") != NULL);
  bs_simulation_free(sim);
  bs_scenario_free(s);
  bs_scenario_free(NULL);
  bs_simulation_free(NULL);
}

static void test_scenario_errors(void) {
  BsScenario* s = NULL;
  BsPhysics p;
  BsTable t;
  BsBall b;
  BsStrike k = {2.0, 0.0, 0.0, 0.0, 0.0};
  BsSimulation* sim = NULL;
  char* text = NULL;
  double square[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  FAILS(bs_scenario_new(NULL), BS_ERROR_NULL, NULL, "out");
  FAILS(bs_physics_default((BsModel)5, &p), BS_ERROR_OUT_OF_RANGE, NULL, "model");
  FAILS(bs_physics_default(BS_MODEL_POOL, NULL), BS_ERROR_NULL, NULL, "out");
  FAILS(bs_table_default((BsTableShape)9, &t), BS_ERROR_OUT_OF_RANGE, NULL, "shape");
  FAILS(bs_table_default(BS_TABLE_POOL, NULL), BS_ERROR_NULL, NULL, "out");
  FAILS(bs_ball_default(NULL), BS_ERROR_NULL, NULL, "out");
  OK(bs_scenario_new(&s));

  /* physics: enums, flags, non-finite numbers, ranges the format refuses */
  OK(bs_physics_default(BS_MODEL_FRICTION, &p));
  p.model = 3;
  FAILS(bs_scenario_set_physics(s, &p), BS_ERROR_OUT_OF_RANGE, s, "physics.model");
  OK(bs_physics_default(BS_MODEL_FRICTION, &p));
  p.ball_ball_restitution = 1.5;
  FAILS(bs_scenario_set_physics(s, &p), BS_ERROR_OUT_OF_RANGE, s, "physics.ball_ball_restitution");
  OK(bs_physics_default(BS_MODEL_FRICTION, &p));
  p.gravity = INFINITY;
  FAILS(bs_scenario_set_physics(s, &p), BS_ERROR_OUT_OF_RANGE, s, "physics.gravity");
  OK(bs_physics_default(BS_MODEL_FRICTION, &p));
  p.airborne = 1; /* airborne balls need the pool model */
  FAILS(bs_scenario_set_physics(s, &p), BS_ERROR_OUT_OF_RANGE, s, "physics.airborne");
  OK(bs_physics_default(BS_MODEL_POOL, &p));
  p.ball_clusters = 2;
  FAILS(bs_scenario_set_physics(s, &p), BS_ERROR_OUT_OF_RANGE, s, "physics.ball_clusters");
  OK(bs_physics_default(BS_MODEL_POOL, &p));
  p.ball_ball_model = 7;
  FAILS(bs_scenario_set_physics(s, &p), BS_ERROR_OUT_OF_RANGE, s, "ball_ball_model");
  OK(bs_physics_default(BS_MODEL_POOL, &p));
  p.friction_curve[2] = -1.0;
  FAILS(bs_scenario_set_physics(s, &p), BS_ERROR_OUT_OF_RANGE, s, "ball_ball_friction.c");
  FAILS(bs_scenario_set_physics(s, NULL), BS_ERROR_NULL, s, "physics");
  FAILS(bs_scenario_set_physics(NULL, &p), BS_ERROR_NULL, NULL, "scenario");
  OK(bs_physics_default(BS_MODEL_POOL, &p));
  OK(bs_scenario_set_physics(s, &p));
  CHECK(strcmp(bs_error_message(s), "") == 0);

  /* tables */
  OK(bs_table_default(BS_TABLE_POOL, &t));
  t.size = "11ft";
  FAILS(bs_scenario_set_table(s, &t), BS_ERROR_OUT_OF_RANGE, s, "table.size");
  OK(bs_table_default(BS_TABLE_POOL, &t));
  t.cushion_model = 12;
  FAILS(bs_scenario_set_table(s, &t), BS_ERROR_OUT_OF_RANGE, s, "cushion_model");
  OK(bs_table_default(BS_TABLE_POOL, &t));
  t.cushion_restitution = 1.5;
  FAILS(bs_scenario_set_table(s, &t), BS_ERROR_OUT_OF_RANGE, s, "table.cushion_restitution");
  OK(bs_table_default(BS_TABLE_POLYGON, &t));
  t.vertex_count = 4;
  FAILS(bs_scenario_set_table(s, &t), BS_ERROR_NULL, s, "table.vertices");
  t.vertices = square;
  t.vertex_count = 2;
  FAILS(bs_scenario_set_table(s, &t), BS_ERROR_OUT_OF_RANGE, s, "table");
  t.vertex_count = 4;
  OK(bs_scenario_set_table(s, &t));
  OK(bs_table_default(BS_TABLE_RECTANGLE, &t));
  t.min[0] = NAN;
  FAILS(bs_scenario_set_table(s, &t), BS_ERROR_OUT_OF_RANGE, s, "table.min[0]");
  FAILS(bs_scenario_set_table(s, NULL), BS_ERROR_NULL, s, "table");
  OK(bs_table_default(BS_TABLE_POOL, &t));
  OK(bs_scenario_set_table(s, &t));

  /* balls: the scenario is checked as a whole when validated */
  OK(bs_ball_default(&b));
  FAILS(bs_scenario_add_ball(s, &b, NULL), BS_ERROR_NULL, s, "ball.id");
  FAILS(bs_scenario_add_ball(s, NULL, NULL), BS_ERROR_NULL, s, "ball");
  b.id = "cue";
  b.position[0] = NAN;
  FAILS(bs_scenario_add_ball(s, &b, NULL), BS_ERROR_OUT_OF_RANGE, s, "ball.position[0]");
  b.position[0] = 0.5;
  b.position[1] = 0.6;
  {
    size_t index = 99;
    OK(bs_scenario_add_ball(s, &b, &index));
    CHECK(index == 0);
  }
  b.id = "cue"; /* the same id again */
  b.position[0] = 1.5;
  OK(bs_scenario_add_ball(s, &b, NULL));
  FAILS(bs_scenario_validate(s), BS_ERROR_INVALID, s, "balls[1].id");
  FAILS(bs_simulate(s, &sim), BS_ERROR_INVALID, s, "balls[1].id");
  CHECK(sim == NULL);
  bs_scenario_free(s);

  /* a strike the format refuses, until, rack, pairs */
  s = break_8ball(1, 0.0);
  k.theta = 95.0;
  OK(bs_scenario_strike(s, "cue", &k));
  FAILS(bs_scenario_validate(s), BS_ERROR_INVALID, s, "cue.theta");
  k.theta = 0.0;
  k.speed = NAN;
  FAILS(bs_scenario_strike(s, "cue", &k), BS_ERROR_OUT_OF_RANGE, s, "strike.speed");
  FAILS(bs_scenario_strike(s, NULL, &k), BS_ERROR_NULL, s, "ball_id");
  k.speed = 3.0;
  OK(bs_scenario_strike(s, "nobody", &k));
  FAILS(bs_scenario_validate(s), BS_ERROR_INVALID, s, "cue.ball");
  OK(bs_scenario_strike(s, NULL, NULL));
  OK(bs_scenario_validate(s));
  OK(bs_scenario_set_rack(s, "pétanque", 1));
  FAILS(bs_scenario_validate(s), BS_ERROR_INVALID, s, "rack.game");
  OK(bs_scenario_set_rack(s, "nine_ball", UINT64_MAX));
  OK(bs_scenario_validate(s));
  FAILS(bs_scenario_set_until_time(s, NAN), BS_ERROR_OUT_OF_RANGE, s, "t");
  OK(bs_scenario_set_until_time(s, -1.0));
  FAILS(bs_scenario_validate(s), BS_ERROR_INVALID, s, "until.time");
  OK(bs_scenario_set_until_rest(s));
  FAILS(bs_scenario_set_pair_restitution(s, "1", NULL, 0.5), BS_ERROR_NULL, s, "ball_b");
  FAILS(bs_scenario_set_pair_restitution(s, "1", "2", NAN), BS_ERROR_OUT_OF_RANGE, s, "restitution");
  OK(bs_scenario_set_pair_restitution(s, "1", "2", 2.0));
  FAILS(bs_scenario_validate(s), BS_ERROR_INVALID, s, "pair_restitution[0]");
  FAILS(bs_scenario_ball_count(s, NULL), BS_ERROR_NULL, s, "out");
  FAILS(bs_scenario_to_json(s, NULL), BS_ERROR_NULL, s, "out");
  OK(bs_scenario_to_json(s, &text));
  CHECK(text != NULL && strstr(text, "\"nine_ball\"") != NULL);
  bs_string_free(text);
  FAILS(bs_scenario_set_max_events(NULL, 5), BS_ERROR_NULL, NULL, "scenario");
  FAILS(bs_scenario_set_until_rest((BsScenario*)&k), BS_ERROR_BAD_HANDLE, NULL, "scenario");
  bs_scenario_free(s);

  /* text */
  FAILS(bs_scenario_from_json(NULL, 3, &s), BS_ERROR_NULL, NULL, "text");
  FAILS(bs_scenario_from_json("{}", 2, NULL), BS_ERROR_NULL, NULL, "out");
  FAILS(bs_scenario_from_json("{\"physics\":", 11, &s), BS_ERROR_BAD_JSON, NULL, "");
  CHECK(s == NULL);
  FAILS(bs_scenario_from_json("{\"physics\": {}, \"physics\": {}}", 30, &s), BS_ERROR_INVALID, NULL,
        "physics");
  FAILS(bs_scenario_from_json("{\"physics\": {\"model\": \"ideal\"}}", 31, &s), BS_ERROR_INVALID,
        NULL, "table");
  /* the length bounds the text: a NUL is not needed */
  {
    const char* doc =
        "{\"physics\": {\"model\": \"ideal\"}, \"table\": {\"shape\": \"rectangle\", \"min\": [-1, -1],"
        " \"max\": [1, 1]}, \"balls\": [], \"until\": {\"time\": 1}}garbage";
    BsScenario* none = NULL;
    OK(bs_scenario_from_json(doc, strlen(doc) - 7, &s));
    FAILS(bs_scenario_from_json(doc, strlen(doc), &none), BS_ERROR_BAD_JSON, NULL, "");
    CHECK(none == NULL);
    {
      BsScenario* copy = NULL;
      char* a = NULL;
      char* b = NULL;
      OK(bs_scenario_clone(s, &copy));
      OK(bs_scenario_to_json(s, &a));
      OK(bs_scenario_to_json(copy, &b));
      CHECK(a != NULL && b != NULL && strcmp(a, b) == 0);
      bs_string_free(a);
      bs_string_free(b);
      bs_scenario_free(copy);
    }
    bs_scenario_free(s);
  }
  FAILS(bs_scenario_clone(NULL, &s), BS_ERROR_NULL, NULL, "scenario");
}

static void test_break_and_states(void) {
  BsScenario* s = break_8ball(3, 0.3);
  BsSimulation* sim = NULL;
  BsSimulationInfo info;
  BsEvent* ev;
  BsBallState st[16], st2[16];
  size_t k, pockets = 0;
  double t;
  OK(bs_simulate(s, &sim));
  OK(bs_simulation_info(sim, &info));
  CHECK(info.balls == 16);
  CHECK(info.events > 50);
  ev = (BsEvent*)malloc(info.events * sizeof *ev);
  OK(bs_simulation_events(sim, 0, info.events, ev));
  CHECK(ev[0].kind == BS_EVENT_CUE_STRIKE && ev[0].time == 0.0);
  for (k = 1; k < info.events; ++k) CHECK(ev[k].time >= ev[k - 1].time);
  for (k = 0; k < info.events; ++k) {
    if (ev[k].kind == BS_EVENT_BALL_POCKET) {
      const char* name = NULL;
      ++pockets;
      OK(bs_simulation_pocket_name(sim, ev[k].pocket, &name));
      CHECK(name != NULL && strlen(name) > 0);
    }
    if (ev[k].kind == BS_EVENT_STATE_CHANGE) CHECK(ev[k].from >= 0 && ev[k].to >= 0);
  }
  /* a pocketed ball is pocketed at the end */
  OK(bs_simulation_states_at(sim, info.end_time, st, 16));
  {
    size_t pocketed = 0;
    for (k = 0; k < 16; ++k) {
      if (st[k].motion == BS_MOTION_POCKETED) ++pocketed;
      else CHECK(st[k].motion == BS_MOTION_STATIONARY);
    }
    CHECK(pocketed == pockets);
  }
  /* frames at 60 fps: repeatable, and the same forwards and backwards */
  for (t = 0.0; t < info.end_time; t += 1.0 / 60.0) {
    OK(bs_simulation_states_at(sim, t, st, 16));
    OK(bs_simulation_states_at(sim, t, st2, 16));
    CHECK(memcmp(st, st2, sizeof st) == 0);
  }
  /* between the events the balls move as the result file's samples say:
   * a scenario with samples gives the same numbers at the sample times */
  free(ev);
  bs_simulation_free(sim);
  bs_scenario_free(s);
}

/* bs_simulation_states_at against the engine advanced to the sample
 * times: a scenario with "samples" writes them in its result file. */
static void test_states_match_samples(void) {
  char path[1024];
  char* text;
  size_t len = 0;
  BsScenario* s = NULL;
  BsSimulation* sim = NULL;
  char* result = NULL;
  BsBallState st[2];
  snprintf(path, sizeof path, "%s/examples/lab/two_balls.json", g_source);
  text = read_file(path, &len);
  CHECK(text != NULL);
  if (text == NULL) return;
  OK(bs_scenario_from_json(text, len, &s));
  OK(bs_simulate(s, &sim));
  OK(bs_simulation_result_json(sim, &result));
  /* the first sample is at t = 0, the start */
  OK(bs_simulation_states_at(sim, 0.0, st, 2));
  CHECK(result != NULL && strstr(result, "\"samples\"") != NULL);
  bs_string_free(result);
  bs_simulation_free(sim);
  bs_scenario_free(s);
  free(text);
}

static void test_batch(void) {
  enum { N = 6 };
  BsScenario* s[N];
  BsSimulation* one[N];
  BsSimulation* many[N];
  BsScenario* saved;
  int k;
  for (k = 0; k < N; ++k) s[k] = break_8ball((uint64_t)k, 0.5 * k);
  for (k = 0; k < N; ++k) OK(bs_simulate(s[k], &one[k]));
  OK(bs_simulate_batch((const BsScenario* const*)s, N, 2, many));
  for (k = 0; k < N; ++k) {
    char* a = NULL;
    char* b = NULL;
    OK(bs_simulation_result_json(one[k], &a));
    OK(bs_simulation_result_json(many[k], &b));
    CHECK(a != NULL && b != NULL && strcmp(a, b) == 0);
    bs_string_free(a);
    bs_string_free(b);
    bs_simulation_free(one[k]);
    bs_simulation_free(many[k]);
  }
  FAILS(bs_simulate_batch((const BsScenario* const*)s, N, -1, many), BS_ERROR_OUT_OF_RANGE, NULL,
        "threads");
  FAILS(bs_simulate_batch(NULL, N, 0, many), BS_ERROR_NULL, NULL, "scenarios");
  FAILS(bs_simulate_batch((const BsScenario* const*)s, N, 0, NULL), BS_ERROR_NULL, NULL, "out");
  {
    BsStrike bad = {1.0, 0.0, 120.0, 0.0, 0.0};
    OK(bs_scenario_strike(s[3], "cue", &bad));
    FAILS(bs_simulate_batch((const BsScenario* const*)s, N, 0, many), BS_ERROR_INVALID, NULL,
          "scenarios[3]: cue.theta");
    for (k = 0; k < N; ++k) CHECK(many[k] == NULL);
    saved = s[4];
    s[4] = (BsScenario*)many; /* not a handle */
    FAILS(bs_simulate_batch((const BsScenario* const*)s, N, 0, many), BS_ERROR_INVALID, NULL,
          "scenarios[3]");
    bs_scenario_free(s[3]);
    s[3] = NULL;
    s[4] = saved;
    FAILS(bs_simulate_batch((const BsScenario* const*)s, N, 0, many), BS_ERROR_NULL, NULL,
          "scenarios[3]");
  }
  OK(bs_simulate_batch(NULL, 0, 0, many));
  for (k = 0; k < N; ++k) {
    if (k != 3) bs_scenario_free(s[k]);
  }
}

/* Plays a game between two computer players to its end (or `limit`
 * actions); returns the number of actions. */
static size_t play(BsGame* g, BsPlayer* p0, BsPlayer* p1, size_t limit) {
  BsGameInfo info;
  OK(bs_game_info(g, &info));
  while (!info.over && info.actions < limit) {
    char* action = NULL;
    BsStatus st = bs_player_decide_json(info.player == 0 ? p0 : p1, g, &action);
    CHECK(st == BS_OK);
    if (st != BS_OK) break;
    OK(bs_game_apply_json(g, action, strlen(action)));
    bs_string_free(action);
    OK(bs_game_info(g, &info));
  }
  return info.actions;
}

static void test_games(void) {
  BsGame* g = NULL;
  BsGame* again = NULL;
  BsPlayer* p = NULL;
  BsGameInfo info;
  char* text = NULL;
  char* record = NULL;
  char* record2 = NULL;
  BsSimulation* sim = NULL;
  size_t n, k;
  OK(bs_game_new("nine_ball", 11, &g));
  OK(bs_game_info(g, &info));
  CHECK(info.actions == 0 && info.player == 0 && info.over == 0 && info.balls == 10);
  OK(bs_game_legal_actions_json(g, &text));
  CHECK(text != NULL && strstr(text, "\"shoot\":true") != NULL);
  bs_string_free(text);
  OK(bs_game_state_json(g, &text));
  CHECK(text != NULL && strstr(text, "\"phase\":\"break_shot\"") != NULL);
  bs_string_free(text);

  /* bad actions */
  FAILS(bs_game_apply_json(g, "{\"type\":", 8), BS_ERROR_BAD_JSON, g, "action");
  FAILS(bs_game_apply_json(g, "{\"type\": \"dance\"}", 17), BS_ERROR_BAD_JSON, g, "action");
  FAILS(bs_game_apply_json(g, NULL, 3), BS_ERROR_NULL, g, "action");
  {
    const char* decide = "{\"type\": \"decide\", \"choice\": \"shoot\"}";
    FAILS(bs_game_apply_json(g, decide, strlen(decide)), BS_ERROR_ILLEGAL, g, "");
  }
  {
    const char* fast =
        "{\"type\": \"shoot\", \"strike\": {\"speed\": 99, \"phi\": 0, \"theta\": 0, \"a\": 0, "
        "\"b\": 0}, \"call\": null, \"safety\": false, \"push_out\": false}";
    FAILS(bs_game_apply_json(g, fast, strlen(fast)), BS_ERROR_ILLEGAL, g, "speed");
  }
  OK(bs_game_info(g, &info));
  CHECK(info.actions == 0);

  /* a game against the AI's beginner, both seats */
  OK(bs_player_new("beginner", 1, &p));
  n = play(g, p, p, 5000);
  CHECK(n > 0);
  OK(bs_game_info(g, &info));
  CHECK(info.over == 1);
  for (k = 0; k < n; ++k) {
    OK(bs_game_ruling_json(g, k, &text));
    CHECK(text != NULL && strstr(text, "\"fouls\"") != NULL);
    bs_string_free(text);
  }
  FAILS(bs_game_ruling_json(g, n, &text), BS_ERROR_OUT_OF_RANGE, g, "index");
  FAILS(bs_game_ruling_json(g, 0, NULL), BS_ERROR_NULL, g, "out");
  OK(bs_game_shot_simulation(g, 0, &sim));
  {
    BsSimulationInfo si;
    BsBallState st[10];
    OK(bs_simulation_info(sim, &si));
    CHECK(si.balls == 10 && si.events > 10);
    OK(bs_simulation_states_at(sim, 0.5, st, 10));
  }
  bs_simulation_free(sim);
  FAILS(bs_game_shot_simulation(g, n, &sim), BS_ERROR_OUT_OF_RANGE, g, "index");
  CHECK(sim == NULL);
  {
    char* action = NULL;
    const char* any =
        "{\"type\": \"shoot\", \"strike\": {\"speed\": 2, \"phi\": 0, \"theta\": 0, \"a\": 0, "
        "\"b\": 0}, \"call\": null, \"safety\": false, \"push_out\": false}";
    FAILS(bs_player_decide_json(p, g, &action), BS_ERROR_STATE, p, "over");
    CHECK(action == NULL);
    FAILS(bs_game_apply_json(g, any, strlen(any)), BS_ERROR_STATE, g, "over");
  }

  /* the record, and the game rebuilt from it */
  OK(bs_game_record_json(g, &record));
  CHECK(record != NULL && strstr(record, "breakshot-game-record") != NULL);
  OK(bs_game_from_record_json(record, strlen(record), &again));
  OK(bs_game_record_json(again, &record2));
  CHECK(record2 != NULL && strcmp(record, record2) == 0);
  bs_string_free(record2);
  bs_game_free(again);
  FAILS(bs_game_from_record_json(record, 10, &again), BS_ERROR_BAD_JSON, NULL, "record");
  {
    /* a record whose first strike was changed: replay finds it */
    char* changed = (char*)malloc(strlen(record) + 1);
    char* at;
    strcpy(changed, record);
    at = strstr(changed, "\"strike\":{\"speed\":");
    CHECK(at != NULL);
    if (at != NULL) {
      at += 18;
      *at = *at == '9' ? '8' : (char)(*at + 1);
      FAILS(bs_game_from_record_json(changed, strlen(changed), &again), BS_ERROR_INVALID, NULL,
            "record");
    }
    free(changed);
  }
  FAILS(bs_game_from_record_json(NULL, 0, &again), BS_ERROR_NULL, NULL, "text");
  bs_string_free(record);
  bs_game_free(again);
  bs_game_free(g);

  /* configs */
  {
    BsGameConfig c;
    memset(&c, 0, sizeof c);
    FAILS(bs_game_new_config(&c, &g), BS_ERROR_NULL, NULL, "game");
    c.game = "croquet";
    FAILS(bs_game_new_config(&c, &g), BS_ERROR_OUT_OF_RANGE, NULL, "game");
    c.game = "snooker";
    c.table = "9ft";
    FAILS(bs_game_new_config(&c, &g), BS_ERROR_OUT_OF_RANGE, NULL, "table");
    c.table = NULL;
    c.breaker = 2;
    FAILS(bs_game_new_config(&c, &g), BS_ERROR_OUT_OF_RANGE, NULL, "breaker");
    c.breaker = 1;
    c.seats[1] = "grandmaster";
    FAILS(bs_game_new_config(&c, &g), BS_ERROR_OUT_OF_RANGE, NULL, "seats[1]");
    c.seats[1] = "champion@0.5x";
    c.physics_json = "{\"cushion_model\": 5}";
    FAILS(bs_game_new_config(&c, &g), BS_ERROR_BAD_JSON, NULL, "physics_json");
    c.physics_json = "{\"cushion_model\": \"han_2005\"";
    FAILS(bs_game_new_config(&c, &g), BS_ERROR_BAD_JSON, NULL, "physics_json");
    c.physics_json = NULL;
    OK(bs_game_new_config(&c, &g));
    OK(bs_game_info(g, &info));
    CHECK(info.player == 1 && info.balls == 22);
    OK(bs_game_legal_actions_json(g, &text));
    CHECK(text != NULL && strstr(text, "\"nominate\"") != NULL);
    bs_string_free(text);
    bs_game_free(g);
    FAILS(bs_game_new_config(NULL, &g), BS_ERROR_NULL, NULL, "config");
    CHECK(g == NULL);
    FAILS(bs_game_new_config(&c, NULL), BS_ERROR_NULL, NULL, "out");
  }

  /* players */
  bs_player_free(p);
  FAILS(bs_player_new("grandmaster", 1, &p), BS_ERROR_OUT_OF_RANGE, NULL, "grandmaster");
  FAILS(bs_player_new("champion@loud", 1, &p), BS_ERROR_OUT_OF_RANGE, NULL, "noise");
  FAILS(bs_player_new(NULL, 1, &p), BS_ERROR_NULL, NULL, "name");
  FAILS(bs_player_new("beginner", -2, &p), BS_ERROR_OUT_OF_RANGE, NULL, "threads");
  OK(bs_player_new("beginner", 1, &p));
  {
    char* action = NULL;
    FAILS(bs_player_decide_json(p, NULL, &action), BS_ERROR_NULL, p, "game");
    FAILS(bs_player_decide_json(p, (const BsGame*)p, &action), BS_ERROR_BAD_HANDLE, p, "game");
    FAILS(bs_player_decide_json(NULL, g, &action), BS_ERROR_NULL, NULL, "player");
  }
  FAILS(bs_game_info(NULL, &info), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_info((const BsGame*)p, &info), BS_ERROR_BAD_HANDLE, NULL, "game");
  FAILS(bs_game_state_json(NULL, &text), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_legal_actions_json(NULL, &text), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_record_json(NULL, &text), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_new(NULL, 1, &g), BS_ERROR_NULL, NULL, "game");
  FAILS(bs_game_new("eight_ball", 1, NULL), BS_ERROR_NULL, NULL, "out");
  bs_player_free(p);
  bs_player_free(NULL);
  bs_game_free(NULL);
}

int main(int argc, char** argv) {
  if (argc > 1) g_source = argv[1];
  test_version();
  test_two_balls();
  test_scenario_errors();
  test_break_and_states();
  test_states_match_samples();
  test_batch();
  test_games();
  return check_summary("test_capi");
}
