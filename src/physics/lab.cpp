// The physics lab: energy and momentum of a ball, and dense traces of a
// run for plotting (the plots themselves are in src/io/svg_plot.cpp,
// plot.hpp).

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "breakshot/lab.hpp"
#include "physics/run_record.hpp"

namespace breakshot {

double kinetic_energy(const BallSpec& spec, const BallState& state) {
  // A solid sphere: I = 2/5 m r^2 about any axis through its centre, so
  // the rotational energy is 1/2 I |w|^2 whatever the spin axis.
  const double inertia = 0.4 * spec.mass * spec.radius * spec.radius;
  const Vec3& w = state.spin;
  const double w2 = w.x * w.x + w.y * w.y + w.z * w.z;
  // A ball in flight adds its vertical motion (0 for every other ball,
  // so the sum is unchanged bit for bit).
  const double v2 = norm2(state.velocity) + state.vz * state.vz;
  return 0.5 * spec.mass * v2 + 0.5 * inertia * w2;
}

Vec2 momentum(const BallSpec& spec, const BallState& state) {
  return spec.mass * state.velocity;
}

namespace {

// Frames hold every ball's state, so the memory of a trace is frames x
// balls. max_frames alone does not bound it: 200000 frames of a
// 1000-disk gas would be 12.8 GB. I cap the total number of ball states
// as well: 2^22 of them, 256 MB at 64 bytes a state. A 16-ball table
// never meets this cap (262144 frames); a 1000-ball gas gets 4194
// frames, still more than a plot can show.
constexpr std::size_t kMaxBallStates = std::size_t{1} << 22;

// `count` indices spread evenly over [0, n), first and last included.
// Requires 0 < count <= n.
std::vector<std::size_t> even_indices(std::size_t n, std::size_t count) {
  std::vector<std::size_t> out;
  out.reserve(count);
  if (count == 1) {
    out.push_back(n - 1);
    return out;
  }
  // Integer arithmetic keeps the choice exact and deterministic.
  for (std::size_t k = 0; k < count; ++k) {
    out.push_back(k * (n - 1) / (count - 1));
  }
  return out;
}

// How the frame times are chosen:
//  - The end time is where a run to scenario.until.time, or to rest,
//    leaves the clock. If the max_events guard stops the run, the end is
//    the time of the last event processed.
//  - Grid frames: `points` evenly spaced times from 0 to the end (0 and
//    the end always included, so points < 2 counts as 2).
//  - Event frames: every distinct event time of the run. The state is
//    read just after the event (advance_to(t) processes every event with
//    time <= t), so an event at t = 0, such as a cue strike, shows in the
//    frame at 0.
//  - Budget: at most max_frames frames (and at most kMaxBallStates ball
//    states in all). The grid comes first (it is what the time plots
//    need); if the distinct event times do not fit in what is left,
//    they are thinned evenly by event index, first and last kept, so
//    the frames stay densest where events are densest. Then not every
//    event time has a frame.
//  - Times are merged in order and exact duplicates dropped.
//  - The states at those times are read from the record of the run
//    (run_record.hpp), exactly as a simulation advanced through the
//    times gives them: the physics runs once.
std::vector<Sample> frames_of(const Scenario& scenario, const RunResult& result,
                              const detail::RunRecord& record, std::size_t points,
                              std::size_t max_frames) {
  // Where the run leaves the clock: at until.time if it got there; else
  // (at rest, at max_events, or out of events) at its last event.
  const bool at_until = !scenario.until.rest && result.complete && scenario.until.time >= 0.0;
  const double end = at_until               ? scenario.until.time
                     : result.events.empty() ? 0.0
                                             : result.events.back().time;
  std::vector<double> event_times;
  event_times.reserve(result.events.size());
  for (const Event& e : result.events) {
    if (event_times.empty() || e.time != event_times.back()) {
      event_times.push_back(e.time);
    }
  }

  std::size_t budget = std::max<std::size_t>(max_frames, 2);
  const std::size_t n_balls = std::max<std::size_t>(scenario.balls.size(), 1);
  budget = std::min(budget, std::max<std::size_t>(kMaxBallStates / n_balls, 2));

  const std::size_t grid_points =
      std::min(std::max<std::size_t>(points, 2), budget);
  std::vector<double> times;
  times.reserve(budget);
  for (std::size_t k = 0; k + 1 < grid_points; ++k) {
    times.push_back(end * static_cast<double>(k) /
                    static_cast<double>(grid_points - 1));
  }
  // Set, not computed: end * (n-1) / (n-1) need not round back to end.
  times.push_back(end);

  const std::size_t event_budget = budget - grid_points;
  if (event_times.size() <= event_budget) {
    times.insert(times.end(), event_times.begin(), event_times.end());
  } else if (event_budget > 0) {
    for (std::size_t i : even_indices(event_times.size(), event_budget)) {
      times.push_back(event_times[i]);
    }
  }
  event_times = {};  // a big gas has a million of them; free them now

  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());

  // The state at every frame time.
  std::vector<Sample> frames;
  frames.reserve(times.size());
  detail::Replay sim(record);
  for (double t : times) {
    const StopReason reason = sim.advance_to(t);
    Sample s{sim.time(), sim.balls()};
    // Under event_limit the clock stops at the last event, which may be
    // the time of the previous frame: keep times strictly increasing.
    if (!frames.empty() && frames.back().time >= s.time) {
      frames.back() = std::move(s);
    } else {
      frames.push_back(std::move(s));
    }
    if (reason == StopReason::event_limit) {
      break;
    }
  }
  return frames;
}

}  // namespace

TracedRun simulate_traced(const Scenario& scenario, std::size_t points,
                          std::size_t max_frames) {
  TracedRun out;
  detail::RunRecord record;
  out.result = detail::simulate_recorded(scenario, record);
  out.frames = frames_of(scenario, out.result, record, points, max_frames);
  return out;
}

std::vector<Sample> trace(const Scenario& scenario, std::size_t points,
                          std::size_t max_frames) {
  return simulate_traced(scenario, points, max_frames).frames;
}

}  // namespace breakshot
