// simulate(): a scenario run once to its `until`, with the samples it asks
// for. A run until rest learns when it ends as it goes, so that its last
// sample can be at that moment without running the shot twice.
#include <cstdint>
#include <utility>

#include "physics/engine.hpp"
#include "physics/run_record.hpp"

namespace breakshot {

namespace detail {

namespace {

// The clock of a run to rest that has ended (Engine::rest_by): the time
// of its last event, or 0 before any. That is the time advance_to_rest()
// leaves on the clock of a fresh simulation: it takes events in time
// order and the clock follows them.
double rest_time(const Engine& sim) {
  return sim.events().empty() ? 0.0 : sim.events().back().time;
}

RunResult run(const Scenario& scenario, RunRecord* record) {
  RunResult result;
  Engine sim(scenario);
  if (record != nullptr) sim.start_record(*record);
  // Until rest, the end is known once the run to rest is over.
  bool end_known = !scenario.until.rest;
  double end = scenario.until.time;
  bool complete = true;
  if (scenario.sample_dt) {
    const double dt = *scenario.sample_dt;
    for (std::uint64_t k = 0;; ++k) {
      double t = static_cast<double>(k) * dt;
      if (!end_known && sim.rest_by(t)) {
        end_known = true;
        end = rest_time(sim);
      }
      // Until the end is known it is later than t.
      const bool last = end_known && t >= end;
      if (last) t = end;
      if (sim.advance_to(t) == StopReason::event_limit) {
        complete = false;
        break;
      }
      result.samples.push_back({t, sim.balls()});
      if (last) break;
    }
  }
  if (complete) {
    const StopReason r = scenario.until.rest ? sim.advance_to_rest() : sim.advance_to(end);
    complete = r == StopReason::reached;
  }
  if (record != nullptr) sim.finish_record();
  result.complete = complete;
  result.cue = sim.cue_result();
  result.final_time = sim.time();
  result.final_balls = sim.balls();
  result.airborne = sim.left_cloth();
  result.events = std::move(sim.events());
  return result;
}

}  // namespace

RunResult simulate_recorded(const Scenario& scenario, RunRecord& record) {
  return run(scenario, &record);
}

}  // namespace detail

RunResult simulate(const Scenario& scenario) { return detail::run(scenario, nullptr); }

}  // namespace breakshot
