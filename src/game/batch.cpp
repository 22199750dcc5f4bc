// Batch shots (include/breakshot/batch.hpp): k cue strikes run on worker
// threads. Each shot is a pure function of its scenario, its strike, the
// noise model, the seed and its index, and writes only its own entries,
// so the arrays are the same for any thread count.
#include "breakshot/batch.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "breakshot/simulation.hpp"

namespace breakshot {

namespace {

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

/// Index of the ball "cue", or -1.
std::int32_t cue_ball(const Scenario& s) {
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    if (s.balls[i].id == "cue") return static_cast<std::int32_t>(i);
  }
  return -1;
}

/// Threads to start for n shots: `requested`, every core for 0, never more
/// than the shots.
std::size_t worker_count(unsigned requested, std::size_t n) {
  std::size_t w = requested;
  if (w == 0) w = std::thread::hardware_concurrency();
  w = std::max<std::size_t>(w, 1);
  return std::min(w, std::max<std::size_t>(n, 1));
}

/// One shot, written into its entries of `out`.
void play_one(Simulation& sim, std::size_t k, ShotBatch& out) {
  const std::size_t n = out.balls;
  const Scenario& work = sim.scenario();
  const StopReason r = work.until.rest ? sim.advance_to_rest() : sim.advance_to(work.until.time);
  out.complete[k] = r == StopReason::reached ? 1 : 0;
  out.final_times[k] = sim.time();
  out.event_counts[k] = sim.event_count();
  out.miscue[k] = sim.cue_result() && sim.cue_result()->miscue ? 1 : 0;
  for (std::size_t i = 0; i < n; ++i) {
    out.final_positions[k * n + i] = sim.ball(i).position;
  }
  const std::int32_t cue = work.cue->ball;
  std::int32_t first = -1;
  std::int32_t before = 0;
  for (const Event& e : sim.events()) {
    switch (e.type) {
      case EventType::ball_ball:
        if (first < 0 && (e.ball == cue || e.other == cue))
          first = e.ball == cue ? e.other : e.ball;
        break;
      case EventType::ball_cushion:
        if (e.ball >= 0 && static_cast<std::size_t>(e.ball) < n) {
          ++out.cushions[k * n + static_cast<std::size_t>(e.ball)];
          if (e.ball == cue && first < 0) ++before;
        }
        break;
      case EventType::ball_pocket:
        if (e.ball >= 0 && static_cast<std::size_t>(e.ball) < n) {
          out.pockets[k * n + static_cast<std::size_t>(e.ball)] = e.pocket;
        }
        break;
      case EventType::ball_off_table:
        if (e.ball >= 0 && static_cast<std::size_t>(e.ball) < n) {
          out.pockets[k * n + static_cast<std::size_t>(e.ball)] = kLeftTable;
        }
        break;
      case EventType::cue_strike:
      case EventType::state_change:
      case EventType::ball_slate:
        break;
    }
  }
  out.first_hit[k] = first;
  out.cushions_before_hit[k] = before;
}

}  // namespace

std::optional<ScenarioError> check_shot_scenario(const Scenario& s, const std::string& where) {
  if (s.physics.model != Model::pool) {
    return ScenarioError{where + "physics.model", "shots need the pool model"};
  }
  if (s.cue) {
    return ScenarioError{where + "cue",
                         "the scenario has a cue strike of its own; shots give the strikes"};
  }
  const std::int32_t cue = cue_ball(s);
  if (cue < 0) {
    return ScenarioError{where + "balls",
                         "no ball has the id 'cue' (the ball the strikes play; a rack adds it)"};
  }
  // As the scenario reader does for a "cue" in the file: a struck ball
  // that never stops would run to max_events.
  if (s.until.rest) {
    const PhysicsParams& ph = s.physics;
    const std::pair<const char*, double> frictions[] = {
        {"gravity", ph.gravity},
        {"sliding_friction", ph.sliding_friction},
        {"rolling_friction", ph.rolling_friction},
        {"spinning_friction", ph.spinning_friction}};
    for (const auto& [name, value] : frictions) {
      if (!(value > 0.0)) {
        return ScenarioError{where + "physics." + name,
                             "is 0, so a struck ball never comes to rest; give {\"time\": T}"};
      }
    }
  }
  const BallState& b = s.start[static_cast<std::size_t>(cue)];
  if (b.velocity != Vec2{} || b.spin != Vec3{}) {
    return ScenarioError{where + "balls[" + std::to_string(cue) + "]",
                         "ball 'cue' has a velocity or spin; the ball a cue strikes must be at "
                         "rest"};
  }
  return std::nullopt;
}

std::optional<ScenarioError> check_strike(const CueStrike& k, std::size_t index) {
  // The path is built only for a refusal: this runs once a shot.
  const auto at = [index](const char* field) {
    return "strikes[" + std::to_string(index) + "]." + field;
  };
  if (!(std::isfinite(k.speed) && k.speed > 0.0)) {
    return ScenarioError{at("speed"), "must be finite and positive, not " + num(k.speed)};
  }
  if (!std::isfinite(k.phi)) return ScenarioError{at("phi"), "must be finite, not " + num(k.phi)};
  if (!(k.theta >= 0.0 && k.theta < 90.0)) {
    return ScenarioError{at("theta"),
                         "the cue elevation must be in [0, 90) degrees, not " + num(k.theta)};
  }
  if (!std::isfinite(k.a)) return ScenarioError{at("a"), "must be finite, not " + num(k.a)};
  if (!std::isfinite(k.b)) return ScenarioError{at("b"), "must be finite, not " + num(k.b)};
  return std::nullopt;
}

ShotBatch play_shots(std::span<const Scenario* const> scenarios, std::span<const CueStrike> strikes,
                     const ShotBatchOptions& options) {
  const auto refuse = [](const ScenarioError& e) {
    throw std::invalid_argument(e.path + ": " + e.reason);
  };
  const std::size_t k_count = strikes.size();
  if (scenarios.empty()) throw std::invalid_argument("scenarios: none given");
  if (scenarios.size() != 1 && scenarios.size() != k_count) {
    throw std::invalid_argument("scenarios: " + std::to_string(scenarios.size()) +
                                " scenarios for " + std::to_string(k_count) +
                                " strikes (give one scenario, or one per strike)");
  }
  const bool one = scenarios.size() == 1;
  const std::size_t n = scenarios[0]->balls.size();
  for (std::size_t j = 0; j < scenarios.size(); ++j) {
    // The path's prefix is built only for a refusal.
    const auto where = [&] { return one ? "" : "scenarios[" + std::to_string(j) + "]."; };
    if (auto e = check_shot_scenario(*scenarios[j], "")) {
      e->path = where() + e->path;
      refuse(*e);
    }
    if (scenarios[j]->balls.size() != n) {
      refuse({where() + "balls", "has " + std::to_string(scenarios[j]->balls.size()) +
                                     " balls, scenarios[0] has " + std::to_string(n) +
                                     " (every scenario of a batch has the same number)"});
    }
  }
  for (std::size_t k = 0; k < k_count; ++k) {
    if (auto e = check_strike(strikes[k], k)) refuse(*e);
  }
  // Noise none plays the strikes as given (perturb would clamp them).
  const bool noisy = !(options.noise == NoiseModel{});

  ShotBatch out;
  out.shots = k_count;
  out.balls = n;
  out.final_positions.assign(k_count * n, Vec2{});
  out.pockets.assign(k_count * n, -1);
  out.cushions.assign(k_count * n, 0);
  out.cue_index.assign(k_count, -1);
  out.first_hit.assign(k_count, -1);
  out.cushions_before_hit.assign(k_count, 0);
  out.event_counts.assign(k_count, 0);
  out.final_times.assign(k_count, 0.0);
  out.complete.assign(k_count, 0);
  out.miscue.assign(k_count, 0);
  out.played.assign(k_count, CueStrike{});

  std::atomic<std::size_t> next{0};
  const std::size_t workers = worker_count(options.threads, k_count);
  // Threads take runs of consecutive shots, so that neighbouring shots'
  // entries (which share cache lines) are mostly written by one thread;
  // runs stay short enough to keep the threads' shares even.
  const std::size_t chunk = std::clamp<std::size_t>(k_count / (workers * 16), 1, 16);
  std::vector<std::exception_ptr> errors(workers);
  const auto work = [&](std::size_t w) {
    try {
      // The thread's copy of the scenario and its one simulation. With one
      // scenario the copy is made once and only its cue changes from shot
      // to shot; with one scenario per shot each shot's is copied in. The
      // simulation is re-armed for each shot (Simulation::reset), so that
      // after the first shot, shots of one size allocate nothing.
      Scenario scene;
      bool loaded = false;
      std::optional<Simulation> sim;
      for (std::size_t first = next.fetch_add(chunk); first < k_count;
           first = next.fetch_add(chunk)) {
        for (std::size_t k = first; k < std::min(first + chunk, k_count); ++k) {
          if (!one || !loaded) scene = *scenarios[one ? 0 : k];
          loaded = true;
          const std::int32_t cue = cue_ball(scene);
          CueStrike strike = strikes[k];
          if (noisy) {
            strike =
                perturb(strike, options.noise, scene.balls[static_cast<std::size_t>(cue)].radius,
                        mix_seed(options.seed, k));
          }
          scene.cue = CueSpec{cue, strike, CueParams{}};
          out.cue_index[k] = cue;
          out.played[k] = strike;
          if (sim) {
            sim->reset(scene);
          } else {
            sim.emplace(scene);
          }
          play_one(*sim, k, out);
        }
      }
    } catch (...) {
      errors[w] = std::current_exception();
      next.store(k_count);  // the others stop taking shots
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(workers - 1);
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return out;
}

ShotBatch play_shots(const Scenario& scenario, std::span<const CueStrike> strikes,
                     const ShotBatchOptions& options) {
  const Scenario* one[] = {&scenario};
  return play_shots(std::span<const Scenario* const>(one), strikes, options);
}

}  // namespace breakshot
