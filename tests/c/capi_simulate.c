/* `breakshot simulate FILE` through the C API: the result file on
 * standard output, so that a test compares the bytes with the command's
 * (tests/c/compare_simulate.cmake); bs_simulate_result_json's bytes must
 * be the same (exit 3 if not). */
#include "check.h"

int main(int argc, char** argv) {
  size_t len = 0;
  char* text;
  BsScenario* s = NULL;
  BsSimulation* sim = NULL;
  char* result = NULL;
  char* direct = NULL;
  BsStatus st;
  if (argc != 2) {
    fprintf(stderr, "usage: capi_simulate SCENARIO.json\n");
    return 1;
  }
  text = read_file(argv[1], &len);
  if (text == NULL) {
    fprintf(stderr, "capi_simulate: cannot read %s\n", argv[1]);
    return 1;
  }
  st = bs_scenario_from_json(text, len, &s);
  free(text);
  if (st == BS_OK) st = bs_simulate(s, &sim);
  if (st == BS_OK) st = bs_simulation_result_json(sim, &result);
  if (st != BS_OK) {
    fprintf(stderr, "capi_simulate: %s: %s\n", bs_status_name(st),
            bs_error_message(sim != NULL ? (const void*)sim : (const void*)s));
    bs_scenario_free(s);
    bs_simulation_free(sim);
    return 2;
  }
  st = bs_simulate_result_json(s, &direct);
  if (st != BS_OK || strcmp(direct, result) != 0) {
    fprintf(stderr, "capi_simulate: bs_simulate_result_json differs (%s)\n", bs_status_name(st));
    bs_string_free(direct);
    bs_string_free(result);
    bs_simulation_free(sim);
    bs_scenario_free(s);
    return 3;
  }
  bs_string_free(direct);
  fputs(result, stdout);
  bs_string_free(result);
  bs_simulation_free(sim);
  bs_scenario_free(s);
  return 0;
}
