// libFuzzer entry point: any bytes go to read_scenario(); a scenario it
// accepts is simulated with caps that keep one input fast, and its result
// written. Every input must return: no crash, no hang, no sanitizer report.
//
// Build and run:  cmake --preset fuzz && cmake --build --preset fuzz
//                 build/fuzz/fuzz/breakshot_fuzz -dict=fuzz/scenario.dict \
//                     CORPUS_DIR fuzz/corpus
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "breakshot/breakshot.hpp"

namespace {

// The caps. A valid scenario may legitimately ask for millions of events,
// a long run or dense samples; the fuzzer needs each input to finish in
// milliseconds, so it clips those requests instead of rejecting them.
constexpr std::size_t kMaxBalls = 200;
constexpr std::uint64_t kMaxEvents = 2000;
constexpr double kMaxTime = 10.0;
constexpr double kMaxSamples = 1000.0;
constexpr std::size_t kTracePoints = 50;
constexpr std::size_t kTraceFrames = 5000;

// A broken promise of the API: abort so that libFuzzer keeps the input.
void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "breakshot_fuzz: check failed: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto parsed = breakshot::read_scenario(text);
  if (std::holds_alternative<breakshot::ScenarioError>(parsed)) {
    const auto& err = std::get<breakshot::ScenarioError>(parsed);
    check(!err.reason.empty(), "an error gives a reason");
    return 0;
  }
  auto scenario = std::get<breakshot::Scenario>(std::move(parsed));
  check(!breakshot::validate(scenario).has_value(),
        "what read_scenario accepts, validate accepts");
  if (scenario.balls.size() > kMaxBalls) return 0;

  scenario.max_events = std::min<std::uint64_t>(scenario.max_events, kMaxEvents);
  if (!scenario.until.rest) {
    scenario.until.time = std::min(scenario.until.time, kMaxTime);
  }
  // Samples: at most kMaxSamples of them. For a run to rest the end time
  // is known only after the run, so run once without samples first.
  if (scenario.sample_dt) {
    double end = scenario.until.time;
    if (scenario.until.rest) {
      auto probe = scenario;
      probe.sample_dt.reset();
      end = breakshot::simulate(probe).final_time;
    }
    if (!(end / *scenario.sample_dt <= kMaxSamples)) scenario.sample_dt.reset();
  }

  const breakshot::RunResult result = breakshot::simulate(scenario);
  check(result.final_balls.size() == scenario.balls.size(), "one final state per ball");
  for (std::size_t k = 1; k < result.events.size(); ++k) {
    check(result.events[k - 1].time <= result.events[k].time, "events in time order");
  }
  const std::string json = breakshot::write_result(scenario, result);
  check(!json.empty() && json.back() == '\n', "result ends with a newline");

  // The lab's dense trace runs its own copy of the simulation.
  const auto frames = breakshot::trace(scenario, kTracePoints, kTraceFrames);
  (void)frames;
  return 0;
}
