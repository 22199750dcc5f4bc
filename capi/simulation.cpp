// Simulations (BsSimulation): a run of a scenario, its events and result
// file, and the state of every ball at any time, read from the run's
// record (the engine's run record, src/physics/run_record.hpp): one
// binary search and one polynomial per ball, bit for bit what a
// Simulation advanced to that time gives. The record is made by the first
// states query, by running the scenario once more with the record on (the
// same run: the engine is deterministic), so that a run asked only for its
// result costs what simulate() costs. Batches share the scenarios among
// threads.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "breakshot.h"
#include "breakshot/event.hpp"
#include "breakshot/scenario_io.hpp"
#include "capi.hpp"
#include "physics/motion.hpp"

namespace capi {

namespace {

static_assert(static_cast<int>(bs::EventType::cue_strike) == BS_EVENT_CUE_STRIKE);
static_assert(static_cast<int>(bs::EventType::ball_off_table) == BS_EVENT_BALL_OFF_TABLE);
static_assert(static_cast<int>(bs::EventType::ball_slate) == BS_EVENT_BALL_SLATE);
static_assert(static_cast<int>(bs::MotionState::stationary) == BS_MOTION_STATIONARY);
static_assert(static_cast<int>(bs::MotionState::pocketed) == BS_MOTION_POCKETED);
static_assert(static_cast<int>(bs::MotionState::off_table) == BS_MOTION_OFF_TABLE);

}  // namespace

std::unique_ptr<BsSimulation> run(std::shared_ptr<const bs::Scenario> scenario) {
  // The handle is made after the run (in a batch, on the worker).
  bs::RunResult result = bs::simulate(*scenario);
  auto sim = std::make_unique<BsSimulation>();
  sim->scenario = std::move(scenario);
  sim->result = std::move(result);
  return sim;
}

const BsSimulation::Trajectories& trajectories_of(const BsSimulation& s) {
  if (s.trajectories) return *s.trajectories;
  auto made = std::make_unique<BsSimulation::Trajectories>();
  // The same run again, recorded: simulate_recorded's result is
  // simulate()'s, and a run is deterministic.
  const bs::RunResult again = bs::detail::simulate_recorded(*s.scenario, made->record);
  if (again.events.size() != s.result.events.size() || again.final_time != s.result.final_time) {
    fail(BS_ERROR_INTERNAL, "the recorded run differs from the run");
  }
  // The changes ball by ball (a counting sort, stable: each ball's stay in
  // event order, which is time order).
  const std::size_t n = made->record.start.size();
  const auto& changes = made->record.changes;
  std::vector<std::size_t>& first = made->first;
  first.assign(n + 1, 0);
  for (const auto& c : changes) ++first[static_cast<std::size_t>(c.ball) + 1];
  for (std::size_t i = 0; i < n; ++i) first[i + 1] += first[i];
  made->order.resize(changes.size());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (std::size_t k = 0; k < changes.size(); ++k) {
    made->order[next[static_cast<std::size_t>(changes[k].ball)]++] = static_cast<std::uint32_t>(k);
  }
  s.trajectories = std::move(made);
  return *s.trajectories;
}

void to_c(const bs::BallState& s, BsBallState& o) {
  o.position[0] = s.position.x;
  o.position[1] = s.position.y;
  o.velocity[0] = s.velocity.x;
  o.velocity[1] = s.velocity.y;
  o.spin[0] = s.spin.x;
  o.spin[1] = s.spin.y;
  o.spin[2] = s.spin.z;
  o.z = s.z;
  o.vz = s.vz;
  o.motion = static_cast<std::int32_t>(s.state);
  o.reserved = 0;
}

}  // namespace capi

using namespace capi;

extern "C" {

BsStatus bs_simulate(const BsScenario* scenario, BsSimulation** out) {
  if (out != nullptr) *out = nullptr;
  BsSimulation* made = nullptr;
  const BsStatus st = on_handle(scenario, kScenarioTag, "scenario", [&](const BsScenario& s) {
    need(out, "out");
    *out = nullptr;
    made = run(shared_scenario_of(s)).release();
  });
  if (st == BS_OK) *out = made;
  return st;
}

BsStatus bs_simulate_batch(const BsScenario* const* scenarios, std::size_t n, std::int32_t threads,
                           BsSimulation** out) {
  return on_thread([&] {
    need(out, "out");
    std::fill(out, out + n, nullptr);
    if (n > 0) need(scenarios, "scenarios");
    if (threads < 0) {
      fail(BS_ERROR_OUT_OF_RANGE,
           "threads: must be 0 (every core) or more, not " + std::to_string(threads));
    }
    // Every scenario is read here, on the calling thread, so that the
    // workers only run.
    std::vector<std::shared_ptr<const bs::Scenario>> read(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::string where = "scenarios[" + std::to_string(k) + "]";
      const BsScenario* s = scenarios[k];
      if (s == nullptr) fail(BS_ERROR_NULL, where + ": a null handle");
      if (s->tag != kScenarioTag) fail(BS_ERROR_BAD_HANDLE, where + ": not a live scenario handle");
      try {
        read[k] = shared_scenario_of(*s);
      } catch (const Failure& f) {
        fail(f.status, where + ": " + f.message);
      }
    }
    std::vector<std::unique_ptr<BsSimulation>> sims(n);
    unsigned workers = threads > 0 ? static_cast<unsigned>(threads)
                                   : std::max(1u, std::thread::hardware_concurrency());
    workers = static_cast<unsigned>(std::min<std::size_t>(workers, n));
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_lock;
    const auto work = [&] {
      for (std::size_t k = next++; k < n; k = next++) {
        try {
          sims[k] = run(read[k]);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(error_lock);
          if (!error) error = std::current_exception();
        }
      }
    };
    if (workers <= 1) {
      work();
    } else {
      std::vector<std::thread> pool;
      pool.reserve(workers - 1);
      for (unsigned w = 1; w < workers; ++w) pool.emplace_back(work);
      work();
      for (std::thread& t : pool) t.join();
    }
    if (error) std::rethrow_exception(error);
    for (std::size_t k = 0; k < n; ++k) out[k] = sims[k].release();
  });
}

void bs_simulation_free(BsSimulation* simulation) {
  if (simulation == nullptr || simulation->tag != kSimulationTag) return;
  simulation->tag = kFreed;
  delete simulation;
}

BsStatus bs_simulation_info(const BsSimulation* simulation, BsSimulationInfo* out) {
  return on_handle(simulation, kSimulationTag, "simulation", [&](const BsSimulation& s) {
    need(out, "out");
    out->balls = s.scenario->balls.size();
    out->events = s.result.events.size();
    out->end_time = s.result.final_time;
    out->complete = s.result.complete ? 1 : 0;
    out->airborne = s.result.airborne ? 1 : 0;
  });
}

BsStatus bs_simulation_events(const BsSimulation* simulation, std::size_t first, std::size_t n,
                              BsEvent* out) {
  return on_handle(simulation, kSimulationTag, "simulation", [&](const BsSimulation& s) {
    if (n > 0) need(out, "out");
    const std::size_t count = s.result.events.size();
    if (first > count || n > count - first) {
      fail(BS_ERROR_OUT_OF_RANGE, "events [" + std::to_string(first) + ", " +
                                      std::to_string(first) + " + " + std::to_string(n) +
                                      ") are not within the " + std::to_string(count) +
                                      " events of the run");
    }
    for (std::size_t k = 0; k < n; ++k) {
      const bs::Event& e = s.result.events[first + k];
      BsEvent& o = out[k];
      o.time = e.time;
      o.kind = static_cast<std::int32_t>(e.type);
      o.ball = e.ball;
      o.other = e.other;
      o.wall = e.wall;
      o.pocket = e.pocket;
      const bool states =
          e.type == bs::EventType::state_change || e.type == bs::EventType::ball_slate;
      o.from = states ? static_cast<std::int32_t>(e.from) : -1;
      o.to = states ? static_cast<std::int32_t>(e.to) : -1;
      o.reserved = 0;
    }
  });
}

BsStatus bs_simulation_states_at(const BsSimulation* simulation, double t, BsBallState* out,
                                 std::size_t n) {
  return on_handle(simulation, kSimulationTag, "simulation", [&](const BsSimulation& s) {
    need(out, "out");
    const std::size_t balls = s.result.final_balls.size();
    if (n != balls) {
      fail(BS_ERROR_OUT_OF_RANGE,
           "n: the run has " + std::to_string(balls) + " balls, not " + std::to_string(n));
    }
    if (std::isnan(t)) fail(BS_ERROR_OUT_OF_RANGE, "t: not a number");
    t = std::clamp(t, 0.0, s.result.final_time);
    const BsSimulation::Trajectories& tj = trajectories_of(s);
    const auto& changes = tj.record.changes;
    const std::uint32_t* order = tj.order.data();
    const std::size_t* first = tj.first.data();
    for (std::size_t i = 0; i < balls; ++i) {
      // The last of the ball's changes at or before t (every change with
      // time <= t has been taken at t), else its start.
      std::size_t lo = first[i];
      std::size_t hi = first[i + 1];
      while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (changes[order[mid]].time <= t) {
          lo = mid + 1;
        } else {
          hi = mid;
        }
      }
      const bs::Simulation::Trajectory& tr =
          lo == first[i] ? tj.record.start[i] : changes[order[lo - 1]].trajectory;
      to_c(bs::detail::state_at(tr, t), out[i]);
    }
  });
}

BsStatus bs_simulation_ball_id(const BsSimulation* simulation, std::size_t ball, const char** out) {
  return on_handle(simulation, kSimulationTag, "simulation", [&](const BsSimulation& s) {
    need(out, "out");
    if (ball >= s.scenario->balls.size()) {
      fail(BS_ERROR_OUT_OF_RANGE, "ball: " + std::to_string(ball) + " is not below the " +
                                      std::to_string(s.scenario->balls.size()) + " balls");
    }
    *out = s.scenario->balls[ball].id.c_str();
  });
}

BsStatus bs_simulation_wall_name(const BsSimulation* simulation, std::int32_t wall,
                                 const char** out) {
  return on_handle(simulation, kSimulationTag, "simulation", [&](const BsSimulation& s) {
    need(out, "out");
    const auto& walls = s.scenario->table.walls;
    if (wall < 0 || static_cast<std::size_t>(wall) >= walls.size()) {
      fail(BS_ERROR_OUT_OF_RANGE, "wall: " + std::to_string(wall) + " is not in [0, " +
                                      std::to_string(walls.size()) + ")");
    }
    *out = walls[static_cast<std::size_t>(wall)].name.c_str();
  });
}

BsStatus bs_simulation_pocket_name(const BsSimulation* simulation, std::int32_t pocket,
                                   const char** out) {
  return on_handle(simulation, kSimulationTag, "simulation", [&](const BsSimulation& s) {
    need(out, "out");
    const auto& pockets = s.scenario->table.pockets;
    if (pocket < 0 || static_cast<std::size_t>(pocket) >= pockets.size()) {
      fail(BS_ERROR_OUT_OF_RANGE, "pocket: " + std::to_string(pocket) + " is not in [0, " +
                                      std::to_string(pockets.size()) + ")");
    }
    *out = pockets[static_cast<std::size_t>(pocket)].name.c_str();
  });
}

BsStatus bs_simulation_result_json(const BsSimulation* simulation, char** out) {
  return on_handle(simulation, kSimulationTag, "simulation", [&](const BsSimulation& s) {
    need(out, "out");
    *out = nullptr;
    *out = copy_out(bs::write_result(*s.scenario, s.result));
  });
}

BsStatus bs_simulate_result_json(const BsScenario* scenario, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(scenario, kScenarioTag, "scenario", [&](const BsScenario& s) {
    need(out, "out");
    const bs::Scenario& read = scenario_of(s);
    *out = copy_out(bs::write_result(read, bs::simulate(read)));
  });
}

}  // extern "C"
