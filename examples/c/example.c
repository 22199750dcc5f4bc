/* breakshot's C API from C (include/breakshot.h, docs/c-api.md):
 *
 *   1. two balls in a box: a scenario built by calls, its events, and the
 *      balls drawn at 60 frames a second (here: printed at a few frames);
 *   2. an 8-ball break: the events, by name;
 *   3. a game of 9-ball against the AI: the seat to act asks the player for
 *      its action and plays it; the rulings as they come.
 *
 * Built against the installed library (examples/c/CMakeLists.txt, or
 * `cc -std=c99 example.c $(pkg-config --cflags --libs breakshot)`).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <breakshot.h>

/* Stops the program with the failed call's message. */
static void check(BsStatus status, const void* handle, const char* what) {
  if (status != BS_OK) {
    fprintf(stderr, "%s: %s: %s\n", what, bs_status_name(status), bs_error_message(handle));
    exit(1);
  }
}

static const char* kind_name(int32_t kind) {
  static const char* names[] = {"cue_strike",   "ball_ball",  "ball_cushion", "ball_pocket",
                                "state_change", "ball_slate", "ball_off_table"};
  return kind >= 0 && kind < 7 ? names[kind] : "?";
}

static void two_balls(void) {
  BsScenario* s = NULL;
  BsSimulation* sim = NULL;
  BsTable table;
  BsBall ball;
  BsSimulationInfo info;
  BsBallState states[2];
  BsEvent events[16];
  size_t k;
  int frame;

  check(bs_scenario_new(&s), NULL, "bs_scenario_new");
  check(bs_table_default(BS_TABLE_RECTANGLE, &table), NULL, "bs_table_default");
  check(bs_scenario_set_table(s, &table), s, "bs_scenario_set_table");
  check(bs_ball_default(&ball), NULL, "bs_ball_default");
  ball.id = "white";
  ball.position[0] = -0.5;
  ball.velocity[0] = 1.0;
  ball.velocity[1] = 0.02;
  check(bs_scenario_add_ball(s, &ball, NULL), s, "bs_scenario_add_ball");
  ball.id = "black";
  ball.position[0] = 0.5;
  ball.velocity[0] = 0.0;
  ball.velocity[1] = 0.0;
  check(bs_scenario_add_ball(s, &ball, NULL), s, "bs_scenario_add_ball");
  check(bs_scenario_set_until_time(s, 2.0), s, "bs_scenario_set_until_time");

  check(bs_simulate(s, &sim), s, "bs_simulate");
  check(bs_simulation_info(sim, &info), sim, "bs_simulation_info");
  printf("two balls: %lu events until t = %g\n", (unsigned long)info.events, info.end_time);
  if (info.events > 16) info.events = 16;
  check(bs_simulation_events(sim, 0, info.events, events), sim, "bs_simulation_events");
  for (k = 0; k < info.events; ++k) {
    printf("  t = %.6f  %s  ball %d", events[k].time, kind_name(events[k].kind), events[k].ball);
    if (events[k].kind == BS_EVENT_BALL_BALL) printf(" and %d", events[k].other);
    if (events[k].kind == BS_EVENT_BALL_CUSHION) {
      const char* wall = NULL;
      check(bs_simulation_wall_name(sim, events[k].wall, &wall), sim, "bs_simulation_wall_name");
      printf(" on %s", wall);
    }
    printf("\n");
  }
  /* A game asks for every frame; here every 30th of 60 a second. */
  for (frame = 0; frame <= 120; frame += 30) {
    check(bs_simulation_states_at(sim, frame / 60.0, states, 2), sim, "bs_simulation_states_at");
    printf("  frame %3d: white (%.4f, %.4f)  black (%.4f, %.4f)\n", frame, states[0].position[0],
           states[0].position[1], states[1].position[0], states[1].position[1]);
  }
  bs_simulation_free(sim);
  bs_scenario_free(s);
}

static void break_shot(void) {
  BsScenario* s = NULL;
  BsSimulation* sim = NULL;
  BsPhysics physics;
  BsTable table;
  BsStrike strike = {10.0, 0.0, 0.0, 0.0, -0.2};
  BsSimulationInfo info;
  BsEvent* events;
  size_t k, shown = 0;

  check(bs_scenario_new(&s), NULL, "bs_scenario_new");
  check(bs_physics_default(BS_MODEL_POOL, &physics), NULL, "bs_physics_default");
  physics.ball_clusters = 1; /* the rack spreads as in the games */
  check(bs_scenario_set_physics(s, &physics), s, "bs_scenario_set_physics");
  check(bs_table_default(BS_TABLE_POOL, &table), NULL, "bs_table_default");
  check(bs_scenario_set_table(s, &table), s, "bs_scenario_set_table");
  check(bs_scenario_set_rack(s, "eight_ball", 7), s, "bs_scenario_set_rack");
  check(bs_scenario_strike(s, "cue", &strike), s, "bs_scenario_strike");
  check(bs_simulate(s, &sim), s, "bs_simulate");
  check(bs_simulation_info(sim, &info), sim, "bs_simulation_info");
  printf("8-ball break: %lu events, at rest at t = %.3f s\n", (unsigned long)info.events,
         info.end_time);
  events = (BsEvent*)malloc(info.events * sizeof *events);
  if (events == NULL) exit(1);
  check(bs_simulation_events(sim, 0, info.events, events), sim, "bs_simulation_events");
  for (k = 0; k < info.events; ++k) {
    const char* id = NULL;
    const BsEvent* e = &events[k];
    /* the first few events, then the pockets */
    if (k >= 8 && e->kind != BS_EVENT_BALL_POCKET) continue;
    check(bs_simulation_ball_id(sim, (size_t)e->ball, &id), sim, "bs_simulation_ball_id");
    printf("  t = %.6f  %-12s %s", e->time, kind_name(e->kind), id);
    if (e->kind == BS_EVENT_BALL_BALL) {
      check(bs_simulation_ball_id(sim, (size_t)e->other, &id), sim, "bs_simulation_ball_id");
      printf(" - %s", id);
    } else if (e->kind == BS_EVENT_BALL_POCKET) {
      check(bs_simulation_pocket_name(sim, e->pocket, &id), sim, "bs_simulation_pocket_name");
      printf(" in %s", id);
    }
    printf("\n");
    if (++shown == 8 && k + 1 < info.events) printf("  ...\n");
  }
  free(events);
  bs_simulation_free(sim);
  bs_scenario_free(s);
}

/* The value of "key":"..." in a JSON text, for printing. */
static void print_field(const char* json, const char* key) {
  const char* at = strstr(json, key);
  if (at == NULL) return;
  at += strlen(key);
  printf("%.*s", (int)strcspn(at, "\""), at);
}

static void game_against_the_ai(void) {
  BsGameConfig config;
  BsGame* game = NULL;
  BsPlayer* you = NULL; /* stands in for the person at seat 0 */
  BsPlayer* ai = NULL;
  BsGameInfo info;

  memset(&config, 0, sizeof config);
  config.game = "nine_ball";
  config.seed = 2024;
  config.seats[0] = "human";
  config.seats[1] = "amateur";
  check(bs_game_new_config(&config, &game), NULL, "bs_game_new_config");
  check(bs_player_new("beginner@none", 1, &you), NULL, "bs_player_new");
  check(bs_player_new("amateur", 1, &ai), NULL, "bs_player_new");
  printf("9-ball, you (seat 0) against the amateur (seat 1):\n");
  check(bs_game_info(game, &info), game, "bs_game_info");
  while (!info.over && info.actions < 60) {
    char* action = NULL;
    char* ruling = NULL;
    BsPlayer* who = info.player == 0 ? you : ai;
    check(bs_player_decide_json(who, game, &action), who, "bs_player_decide_json");
    check(bs_game_apply_json(game, action, strlen(action)), game, "bs_game_apply_json");
    check(bs_game_ruling_json(game, info.actions, &ruling), game, "bs_game_ruling_json");
    printf("  %2lu %s: ", (unsigned long)info.actions, info.player == 0 ? "you" : " ai");
    print_field(ruling, "\"text\":\"");
    printf("\n");
    bs_string_free(ruling);
    bs_string_free(action);
    check(bs_game_info(game, &info), game, "bs_game_info");
  }
  if (info.over) {
    printf("game over after %lu actions: %s\n", (unsigned long)info.actions,
           info.winner == 0 ? "you win" : info.winner == 1 ? "the AI wins" : "a draw");
  }
  bs_player_free(you);
  bs_player_free(ai);
  bs_game_free(game);
}

int main(void) {
  BsVersion v;
  check(bs_version(&v), NULL, "bs_version");
  printf("breakshot %s (C API %d)\n", v.text, (int)v.api);
  two_balls();
  break_shot();
  game_against_the_ai();
  return 0;
}
