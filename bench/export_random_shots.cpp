// Not a benchmark: writes the layouts and strikes of bench_pool's
// BM_RandomShot15 (bench/random_shots.hpp) as JSON, for the Python
// benchmark bench/python_shots.py (numpy has no mt19937_64):
//
//   build/release/bench/export_random_shots [count] > shots.json
//
// {"scenarios": [scenario without "cue", ...], "strikes": [[phi, theta,
// speed, a, b], ...]} with count entries (default 4096). Before writing,
// every scenario is read back with read_scenario and run with its strike:
// the result must equal the scenario built in code, bit for bit.
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <variant>

#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "random_shots.hpp"

using namespace breakshot;

namespace {

std::string number(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

/// The scenario as the file format has it, without its cue: the pool
/// model and 9 ft table with their defaults, and the balls' ids and
/// positions (every other ball field is the default).
std::string scenario_json(const Scenario& s) {
  std::string out = R"({"physics": {"model": "pool"}, "table": {"shape": "pool", "size": "9ft"}, "balls": [)";
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    if (i > 0) out += ", ";
    out += R"({"id": ")" + s.balls[i].id + R"(", "position": [)" +
           number(s.start[i].position.x) + ", " + number(s.start[i].position.y) + "]}";
  }
  return out + "]}";
}

bool same(const RunResult& x, const RunResult& y) {
  if (x.events != y.events || x.final_balls.size() != y.final_balls.size()) return false;
  for (std::size_t i = 0; i < x.final_balls.size(); ++i) {
    if (x.final_balls[i].position != y.final_balls[i].position) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t count = 4096;
  if (argc > 2 || (argc == 2 && (count = std::strtoull(argv[1], nullptr, 10)) == 0)) {
    std::cerr << "usage: export_random_shots [count > 0]\n";
    return 2;
  }
  const auto shots = bench::random_shots(count);
  std::string out = "{\"scenarios\": [\n";
  std::string strikes = "\"strikes\": [\n";
  for (std::size_t k = 0; k < shots.size(); ++k) {
    const Scenario& s = shots[k];
    const std::string text = scenario_json(s);
    auto parsed = read_scenario(text);
    if (auto* e = std::get_if<ScenarioError>(&parsed)) {
      std::cerr << "export_random_shots: layout " << k << " does not read back: " << e->path
                << ": " << e->reason << '\n';
      return 1;
    }
    Scenario back = std::get<Scenario>(std::move(parsed));
    back.cue = s.cue;
    if (!same(simulate(back), simulate(s))) {
      std::cerr << "export_random_shots: layout " << k << " read back plays differently\n";
      return 1;
    }
    const CueStrike& c = s.cue->strike;
    const char* sep = k + 1 < shots.size() ? ",\n" : "\n";
    out += "  " + text + sep;
    strikes += "  [" + number(c.phi) + ", " + number(c.theta) + ", " + number(c.speed) + ", " +
               number(c.a) + ", " + number(c.b) + "]" + sep;
  }
  std::cout << out << "],\n" << strikes << "]}\n";
  return 0;
}
