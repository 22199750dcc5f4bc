// Runs on the engine and the aim's correction (shot_generator.hpp). The
// geometric aim is corrected on noiseless simulations of the real shot:
// the ball meant to drop is followed from the contact that sets it moving
// until its run ends (a pocket, a ball, a cushion beyond the one it is
// meant to bank off, or a stop), and the signed distance by which the
// straight continuation of its last motion passes the pocket's aim point
// is driven to zero by secant steps on phi. The slope the secant measures
// (metres of miss per degree of phi) is also the shot's sensitivity to
// aim error, which gives the prior. The run of the last correction is
// left where its probe stopped, to be continued to rest and judged.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "shot_generator.hpp"

namespace breakshot::ai_detail::shot_gen {

namespace {

using ai::kInf;
constexpr double kAcceptMiss = 0.0008;  // m: aim good enough, stop refining
constexpr double kMaxStep = 2.0;        // degrees a secant step may turn the aim

}  // namespace

/// A run of the shot with this strike: a spare simulation re-armed
/// (Simulation::reset) when there is one, else a new one.
Simulation Generator::start(double phi, double speed, double b, double a, double theta) const {
  CueStrike& strike = run_.cue->strike;
  strike.speed = speed;
  strike.phi = phi;
  strike.b = b;
  strike.a = a;
  strike.theta = theta;
  ++simulations_;
  if (spare_.empty()) return Simulation(run_);
  Simulation sim = std::move(spare_.back());
  spare_.pop_back();
  sim.reset(run_);
  return sim;
}

/// A run no longer needed, kept for start() to re-arm.
void Generator::recycle(Simulation&& sim) const { spare_.push_back(std::move(sim)); }

/// Steps `sim` until the watched run ends and measures it. The
/// simulation is left where it stopped, to be continued.
Probe Generator::follow(Simulation& sim, const Watch& w) {
  Probe out;
  bool started = w.from_start;
  int cushions = 0;
  std::size_t seen = sim.events().size();
  while (true) {
    const double t = sim.next_event_time();
    if (!std::isfinite(t)) return out;  // at rest: the run never ended
    const Simulation::Trajectory before = sim.trajectory(static_cast<std::size_t>(w.ball));
    if (sim.advance_to(t) != StopReason::reached) return out;
    const std::vector<Event>& ev = sim.events();
    bool ended = false;
    bool stopped = false;
    for (; seen < ev.size(); ++seen) {
      const Event& e = ev[seen];
      const bool mine = e.ball == w.ball || (e.type == EventType::ball_ball && e.other == w.ball);
      if (!mine || ended) continue;
      if (e.type == EventType::state_change) {
        if (started && e.to == MotionState::stationary) ended = stopped = true;
        continue;
      }
      if (e.type == EventType::cue_strike) continue;
      if (!started) {
        if (e.type == EventType::ball_ball) started = true;
        else return out;  // moved by something else first: not this shot
        continue;
      }
      if (e.type == EventType::ball_cushion && cushions < w.pass_cushions) {
        ++cushions;
        continue;
      }
      if (cushions < w.pass_cushions) return out;  // ended before the bank
      ended = true;
    }
    if (!ended) continue;
    const double dt = t - before.t0;
    const Vec2 p = before.p0 + before.v0 * dt + before.acc * (0.5 * dt * dt);
    Vec2 v = before.v0 + before.acc * dt;
    if (norm(v) < 1e-6) v = before.v0;
    if (norm(v) < 1e-9) return out;
    const Vec2 vu = unit(v);
    const double along = dot(vu, w.dir);
    if (along < 0.05) return out;  // moving away from the aim line
    const double s = dot(w.aim - p, w.dir) / along;
    const Vec2 q = p + vu * s;
    out.ok = true;
    out.miss = cross(w.dir, q - w.aim);
    out.reached = !stopped || dot(p - w.aim, w.dir) > -0.06;
    return out;
  }
}

/// Secant iterations on phi that drive watch's miss to zero, from phi0
/// with `slope` (0: measure it first). Once the miss has been seen on
/// both sides of zero, steps stay inside that bracket (bisecting when a
/// secant step would leave it), and an aim that gives no measure (the
/// run ends some other way) is backed off halfway toward the best aim.
/// At most `iterations` + 2 simulations.
std::optional<Generator::Refined> Generator::refine(double phi0, double speed, double b,
                                                    const Watch& w, double slope, int iterations,
                                                    double a, double theta) const {
  Refined best;
  bool have = false;
  double best_abs = kInf;
  std::optional<std::pair<double, double>> prev;  // last measured (phi, miss)
  std::optional<double> below, above;             // phi with miss < 0, > 0
  double phi = phi0;
  for (int it = 0; it < iterations + 2; ++it) {
    Simulation sim = start(phi, speed, b, a, theta);
    const Probe p = follow(sim, w);
    if (!p.ok) {
      recycle(std::move(sim));
      if (!have) return std::nullopt;
      phi = 0.5 * (phi + best.phi);
      continue;
    }
    if (std::abs(p.miss) < best_abs) {
      best_abs = std::abs(p.miss);
      best.phi = phi;
      best.probe = p;
      if (best.sim) recycle(std::move(*best.sim));
      best.sim = std::move(sim);
      have = true;
    } else {
      recycle(std::move(sim));
    }
    (p.miss < 0.0 ? below : above) = phi;
    if (prev && std::abs(phi - prev->first) > 1e-12) {
      const double s = (p.miss - prev->second) / (phi - prev->first);
      // Keep the sign of a measured slope: a secant across a kink that
      // flips it would send the aim the wrong way.
      if (slope == 0.0 || s * slope > 0.0) slope = s;
    }
    prev = std::make_pair(phi, p.miss);
    if (std::abs(p.miss) < kAcceptMiss) break;
    if (slope == 0.0) {
      phi += 0.05;  // a small step gives the first slope
      continue;
    }
    double next = best.phi - std::clamp(best.probe.miss / slope, -kMaxStep, kMaxStep);
    if (below && above) {
      const double lo = std::min(*below, *above);
      const double hi = std::max(*below, *above);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    }
    phi = next;
  }
  if (!have) return std::nullopt;
  if (slope == 0.0) {
    // Right on the first try: one more run for the slope, which the
    // variants and the prior need.
    Simulation sim = start(best.phi + 0.05, speed, b, a, theta);
    const Probe p = follow(sim, w);
    if (p.ok) slope = (p.miss - best.probe.miss) / 0.05;
    recycle(std::move(sim));
  }
  best.slope = slope;
  return best;
}

}  // namespace breakshot::ai_detail::shot_gen
