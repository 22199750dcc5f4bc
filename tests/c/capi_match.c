/* A game of `breakshot match` played again through the C API: the
 * record's game, seed and breaker, two computer players by the record's
 * names, each action the player's decision; the record must come out
 * byte for byte the command's (tests/c/match_record.cmake).
 *
 *   capi_match GAME RECORD.json
 */
#include <inttypes.h>

#include "check.h"

/* The text after `key` (the first time it occurs after `from`), or NULL. */
static const char* after(const char* from, const char* key) {
  const char* at = strstr(from, key);
  return at == NULL ? NULL : at + strlen(key);
}

/* The quoted string after `key` into out (at most cap - 1 characters). */
static int quoted(const char* from, const char* key, char* out, size_t cap) {
  const char* at = after(from, key);
  size_t n = 0;
  if (at == NULL || *at != '"') return 0;
  ++at;
  while (at[n] != '"' && at[n] != '\0' && n + 1 < cap) ++n;
  memcpy(out, at, n);
  out[n] = '\0';
  return at[n] == '"';
}

int main(int argc, char** argv) {
  char* want;
  char* got = NULL;
  char seats[2][64];
  char seed_text[32];
  const char* players;
  const char* start;
  BsGameConfig c;
  BsGame* g = NULL;
  BsPlayer* p[2] = {NULL, NULL};
  BsGameInfo info;
  if (argc != 3) {
    fprintf(stderr, "usage: capi_match GAME RECORD.json\n");
    return 1;
  }
  want = read_file(argv[2], NULL);
  CHECK(want != NULL);
  if (want == NULL) return check_summary("capi_match");
  players = after(want, "\"players\": [");
  start = after(want, "\"start\": {");
  CHECK(players != NULL && start != NULL);
  CHECK(quoted(want, "\"seed\": ", seed_text, sizeof seed_text));
  if (players == NULL || start == NULL) return check_summary("capi_match");
  while (*players == ' ' || *players == '\n') ++players;
  {
    const char* q = strchr(players, '"');
    const char* r = q != NULL ? strchr(q + 1, '"') : NULL;
    const char* q2 = r != NULL ? strchr(r + 1, '"') : NULL;
    const char* r2 = q2 != NULL ? strchr(q2 + 1, '"') : NULL;
    CHECK(r2 != NULL);
    if (r2 == NULL) return check_summary("capi_match");
    snprintf(seats[0], sizeof seats[0], "%.*s", (int)(r - q - 1), q + 1);
    snprintf(seats[1], sizeof seats[1], "%.*s", (int)(r2 - q2 - 1), q2 + 1);
  }
  memset(&c, 0, sizeof c);
  c.game = argv[1];
  c.seed = strtoull(seed_text, NULL, 10);
  CHECK(after(start, "\"breaker\":") != NULL);
  if (after(start, "\"breaker\":") == NULL) return check_summary("capi_match");
  c.breaker = atoi(after(start, "\"breaker\":"));
  c.seats[0] = seats[0];
  c.seats[1] = seats[1];
  printf("capi_match: %s, seed %" PRIu64 ", breaker %d, %s v %s\n", c.game, c.seed,
         (int)c.breaker, seats[0], seats[1]);
  OK(bs_game_new_config(&c, &g));
  OK(bs_player_new(seats[0], 1, &p[0]));
  OK(bs_player_new(seats[1], 1, &p[1]));
  OK(bs_game_info(g, &info));
  while (!info.over) {
    char* action = NULL;
    BsStatus st = bs_player_decide_json(p[info.player], g, &action);
    CHECK(st == BS_OK);
    if (st != BS_OK) break;
    OK(bs_game_apply_json(g, action, strlen(action)));
    bs_string_free(action);
    OK(bs_game_info(g, &info));
  }
  OK(bs_game_record_json(g, &got));
  CHECK(got != NULL && strcmp(got, want) == 0);
  if (got != NULL && strcmp(got, want) != 0) {
    size_t k = 0;
    while (got[k] == want[k]) ++k;
    fprintf(stderr, "capi_match: the records differ at byte %lu: ...%.60s\n", (unsigned long)k,
            got + (k > 20 ? k - 20 : 0));
  }
  bs_string_free(got);
  bs_player_free(p[0]);
  bs_player_free(p[1]);
  bs_game_free(g);
  free(want);
  return check_summary("capi_match");
}
