// Playbacks (BsPlayback): the exact states of a scenario at frame times,
// and its events.
//
// Frames. bs_playback_frame_data gives a frame as doubles in a buffer of
// the playback (no text: a 1000-ball frame as JSON costs ~10 ms in wasm);
// bs_playback_frame writes its JSON from the same buffer, so the two
// always carry the same numbers. Playback events are written as the
// result file writes them (src/io/result_json.hpp).

#include "facade.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "io/json_write.hpp"
#include "io/result_json.hpp"

namespace facade {

namespace {

// A frame as doubles (bs_playback_frame_data's buffer, from which
// bs_playback_frame's JSON is written): a header, then kFrameStride
// doubles per ball in scenario order.
enum FrameHeader : std::size_t {
  kFrameT,         // the simulation's time
  kFrameEvents,    // events so far (exact: below 2^53)
  kFrameAtRest,    // 1 or 0
  kFrameComplete,  // 1, or 0 once max_events stopped the run
  kFrameEnergy,    // total kinetic energy (J), summed in scenario order
  kFramePx,        // total momentum (kg m/s)
  kFramePy,
  kFrameBalls,     // the number of balls
  kFrameHeaderSize
};
// Per ball: x, y, on_table (1 or 0), vx, vy, energy, px, py.
constexpr std::size_t kFrameStride = 8;
// After the balls: the flight block. Its first double is 1 when a ball of
// the frame is off the cloth (in flight or off the table), else 0; then
// kFlightStride doubles per ball in scenario order: z (the height of the
// centre above its resting height, m) and its FlightCode. The JSON frame
// carries them (per ball, after py) only when the flag is 1, so that a
// frame whose balls are all on the cloth or in pockets has 8 numbers per
// ball.
constexpr std::size_t kFlightStride = 2;
enum FlightCode : int { kOnCloth = 0, kAirborne = 1, kOffTable = 2 };

FlightCode flight_code(bs::MotionState s) {
  if (s == bs::MotionState::airborne) return kAirborne;
  if (s == bs::MotionState::off_table) return kOffTable;
  return kOnCloth;
}

/// Where the flight block of a frame of n balls starts.
std::size_t flight_at(std::size_t n) { return kFrameHeaderSize + kFrameStride * n; }

/// Advances the playback to t and writes its frame into pb.frame: the one
/// computation of a frame, for both the JSON and the binary reply.
void compute_frame(BsPlayback& pb, double t) {
  if (!std::isfinite(t)) bad("t", "not a finite number");
  if (t < pb.sim.time()) {
    bad("t", "the frame time goes backwards (" + bs::json_io::format_number(t) + " < " +
                 bs::json_io::format_number(pb.sim.time()) + ")");
  }
  // A run that ends at a time ends there (as simulate() does).
  const double target = pb.scenario.until.rest ? t : std::fmin(t, pb.scenario.until.time);
  if (!pb.limit && pb.sim.advance_to(target) == bs::StopReason::event_limit) pb.limit = true;
  const std::size_t n = pb.sim.ball_count();
  std::vector<double>& d = pb.frame;
  d.assign(flight_at(n) + 1 + kFlightStride * n, 0.0);
  double energy = 0.0;
  bool off_cloth = false;
  bs::Vec2 p;
  for (std::size_t i = 0; i < n; ++i) {
    const bs::BallState st = pb.sim.ball(i);
    const bs::BallSpec& spec = pb.scenario.balls[i];
    const double e = bs::kinetic_energy(spec, st);
    const bs::Vec2 m = bs::momentum(spec, st);
    // Summed in scenario order, as the result file's samples are.
    energy += e;
    p += m;
    double* b = d.data() + kFrameHeaderSize + kFrameStride * i;
    b[0] = st.position.x;
    b[1] = st.position.y;
    // Out of play: in a pocket, or off the table.
    const bool out =
        st.state == bs::MotionState::pocketed || st.state == bs::MotionState::off_table;
    b[2] = out ? 0.0 : 1.0;
    b[3] = st.velocity.x;
    b[4] = st.velocity.y;
    b[5] = e;
    b[6] = m.x;
    b[7] = m.y;
    const FlightCode code = flight_code(st.state);
    off_cloth = off_cloth || code != kOnCloth;
    double* f = d.data() + flight_at(n) + 1 + kFlightStride * i;
    f[0] = st.z;
    f[1] = static_cast<double>(code);
  }
  d[flight_at(n)] = off_cloth ? 1.0 : 0.0;
  d[kFrameT] = pb.sim.time();
  d[kFrameEvents] = static_cast<double>(pb.sim.events().size());
  d[kFrameAtRest] = pb.sim.at_rest() ? 1.0 : 0.0;
  d[kFrameComplete] = pb.limit ? 0.0 : 1.0;
  d[kFrameEnergy] = energy;
  d[kFramePx] = p.x;
  d[kFramePy] = p.y;
  d[kFrameBalls] = static_cast<double>(n);
}

}  // namespace

std::string frame_json(BsPlayback& pb, double t) {
  compute_frame(pb, t);
  const std::vector<double>& d = pb.frame;
  const auto n = static_cast<std::size_t>(d[kFrameBalls]);
  ojson j = ojson::object();
  j["t"] = d[kFrameT];
  const bool flight = d[flight_at(n)] != 0.0;
  ojson balls = ojson::array();
  for (std::size_t i = 0; i < n; ++i) {
    const double* b = d.data() + kFrameHeaderSize + kFrameStride * i;
    ojson ball = ojson::array({b[0], b[1], b[2] != 0.0 ? 1 : 0, b[3], b[4], b[5], b[6], b[7]});
    if (flight) {
      const double* f = d.data() + flight_at(n) + 1 + kFlightStride * i;
      ball.push_back(f[0]);
      ball.push_back(static_cast<int>(f[1]));
    }
    balls.push_back(std::move(ball));
  }
  j["balls"] = balls;
  j["energy"] = d[kFrameEnergy];
  j["momentum"] = ojson::array({d[kFramePx], d[kFramePy]});
  j["events"] = static_cast<std::size_t>(d[kFrameEvents]);
  j["at_rest"] = d[kFrameAtRest] != 0.0;
  j["complete"] = d[kFrameComplete] != 0.0;
  return j.dump();
}

const double* frame_data(BsPlayback& pb, double t) {
  compute_frame(pb, t);
  return pb.frame.data();
}

const double* spins_data(BsPlayback& pb) {
  const std::size_t n = pb.sim.ball_count();
  pb.spins.assign(3 * n + 1, 0.0);  // one more: a valid pointer with no ball
  for (std::size_t i = 0; i < n; ++i) {
    const bs::Vec3 w = pb.sim.ball(i).spin;
    pb.spins[3 * i] = w.x;
    pb.spins[3 * i + 1] = w.y;
    pb.spins[3 * i + 2] = w.z;
  }
  return pb.spins.data();
}

std::string events_json(const BsPlayback& pb, int from) {
  const std::vector<bs::Event>& ev = pb.sim.events();
  if (from < 0 || static_cast<std::size_t>(from) > ev.size()) {
    bad("from", "must be in [0, " + std::to_string(ev.size()) + "], not " + std::to_string(from));
  }
  std::string out = "{\"from\":" + std::to_string(from) + ",\"events\":[";
  bs::json_io::JsonWriter w(out);
  for (std::size_t k = static_cast<std::size_t>(from); k < ev.size(); ++k) {
    if (k > static_cast<std::size_t>(from)) out += ',';
    bs::json_io::write_event(w, pb.scenario, ev[k]);
  }
  out += "]}";
  return out;
}

std::string carom_count_json(const BsPlayback& pb) {
  if (pb.carom_struck < 0) bad("playback", "not the playback of a three-cushion shot");
  // The simulation's events name balls by scenario index: by number here.
  const auto number = [&](std::int32_t i) {
    return i >= 0 && static_cast<std::size_t>(i) < pb.numbers.size()
               ? pb.numbers[static_cast<std::size_t>(i)]
               : i;
  };
  std::vector<bs::Event> events = pb.sim.events();
  for (bs::Event& e : events) {
    e.ball = number(e.ball);
    if (e.type == bs::EventType::ball_ball) e.other = number(e.other);
  }
  const bs::CaromCount c = bs::carom_count(events, pb.carom_struck);
  ojson j = ojson::object();
  j["cushions"] = c.cushions;
  ojson hit = ojson::array();
  for (const int b : c.hit) hit.push_back(b);
  j["hit"] = hit;
  j["done"] = c.done();
  j["made"] = c.made();
  return j.dump();
}

bs::Scenario scenario_from(const char* scenario_json) {
  if (scenario_json == nullptr) bad("scenario", "missing (a null pointer)");
  auto parsed = bs::read_scenario(scenario_json);
  if (const auto* err = std::get_if<bs::ScenarioError>(&parsed)) {
    bad(err->path, (err->unsupported ? "not supported: " : "") + err->reason);
  }
  return std::get<bs::Scenario>(std::move(parsed));
}

}  // namespace facade
