// Simulation, the public face of the engine (src/physics/engine.hpp): a
// copyable value that owns the working state of one run.
#include "breakshot/simulation.hpp"

#include <utility>

#include "physics/engine.hpp"

namespace breakshot {

Simulation::Simulation(const Scenario& scenario)
    : engine_(std::make_unique<detail::Engine>(scenario)) {}

Simulation::Simulation(Scenario&& scenario)
    : engine_(std::make_unique<detail::Engine>(std::move(scenario))) {}

Simulation::Simulation(const Simulation& other)
    : engine_(other.engine_ ? std::make_unique<detail::Engine>(*other.engine_) : nullptr) {}

Simulation& Simulation::operator=(const Simulation& other) {
  if (this == &other) return *this;
  if (engine_ && other.engine_) {
    *engine_ = *other.engine_;
  } else {
    engine_ = other.engine_ ? std::make_unique<detail::Engine>(*other.engine_) : nullptr;
  }
  return *this;
}

Simulation::Simulation(Simulation&& other) noexcept = default;
Simulation& Simulation::operator=(Simulation&& other) noexcept = default;
Simulation::~Simulation() = default;

void Simulation::reset(const Scenario& scenario) { engine_->reset(scenario); }

double Simulation::time() const { return engine_->time(); }
StopReason Simulation::advance_to(double t) { return engine_->advance_to(t); }
StopReason Simulation::advance_to_rest() { return engine_->advance_to_rest(); }
double Simulation::next_event_time() { return engine_->next_event_time(); }
bool Simulation::at_rest() const { return engine_->at_rest(); }
bool Simulation::left_cloth() const { return engine_->left_cloth(); }
BallState Simulation::ball(std::size_t i) const { return engine_->ball(i); }
std::vector<BallState> Simulation::balls() const { return engine_->balls(); }
std::size_t Simulation::ball_count() const { return engine_->ball_count(); }
const std::vector<Event>& Simulation::events() const { return engine_->events(); }
std::uint64_t Simulation::event_count() const { return engine_->event_count(); }
const Scenario& Simulation::scenario() const { return engine_->scenario(); }
const std::optional<StrikeResult>& Simulation::cue_result() const {
  return engine_->cue_result();
}
const Simulation::Trajectory& Simulation::trajectory(std::size_t i) const {
  return engine_->trajectory(i);
}

}  // namespace breakshot
