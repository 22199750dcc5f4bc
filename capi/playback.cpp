// Playbacks (BsPlayback): a scenario's simulation advanced to frame
// times, each frame's numbers as doubles (breakshot.h's layout: no text;
// a 1000-ball frame as JSON costs ~10 ms in wasm), the balls' states at
// the playback's time, the events so far as the result file writes them
// (src/io/result_json.hpp), and a three-cushion shot's count.

#include "page.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "breakshot.h"
#include "breakshot/game.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "io/json_write.hpp"
#include "io/result_json.hpp"

namespace capi {

namespace {

using ojson = nlohmann::ordered_json;

// The frame's header (breakshot.h: BS_FRAME_HEADER doubles).
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
static_assert(kFrameHeaderSize == BS_FRAME_HEADER);
// Per ball: x, y, on_table (1 or 0), vx, vy, energy, px, py.
constexpr std::size_t kFrameStride = BS_FRAME_STRIDE;
// After the balls: the flight block, a flag then kFlightStride doubles
// per ball: z and its FlightCode.
constexpr std::size_t kFlightStride = BS_FLIGHT_STRIDE;
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
  if (!std::isfinite(t)) fail(BS_ERROR_OUT_OF_RANGE, "t: not a finite number");
  if (t < pb.sim.time()) {
    fail(BS_ERROR_OUT_OF_RANGE, "t: the frame time goes backwards (" +
                                    bs::json_io::format_number(t) + " < " +
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

std::string events_json(const BsPlayback& pb, std::size_t from) {
  const std::vector<bs::Event>& ev = pb.sim.events();
  if (from > ev.size()) {
    fail(BS_ERROR_OUT_OF_RANGE, "from: must be in [0, " + std::to_string(ev.size()) +
                                    "], not " + std::to_string(from));
  }
  std::string out = "{\"from\":" + std::to_string(from) + ",\"events\":[";
  bs::json_io::JsonWriter w(out);
  for (std::size_t k = from; k < ev.size(); ++k) {
    if (k > from) out += ',';
    bs::json_io::write_event(w, pb.scenario, ev[k]);
  }
  out += "]}";
  return out;
}

std::string carom_count_json(const BsPlayback& pb) {
  if (pb.carom_struck < 0) {
    fail(BS_ERROR_STATE, "playback: not the playback of a three-cushion shot");
  }
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

}  // namespace

}  // namespace capi

using namespace capi;

extern "C" {

BsStatus bs_playback_new(const BsScenario* scenario, BsPlayback** out) {
  if (out != nullptr) *out = nullptr;
  BsPlayback* made = nullptr;
  const BsStatus st = on_handle(scenario, kScenarioTag, "scenario", [&](const BsScenario& s) {
    need(out, "out");
    made = std::make_unique<BsPlayback>(scenario_of(s)).release();
  });
  if (st == BS_OK) *out = made;
  return st;
}

BsStatus bs_game_shot_playback(const BsGame* game, std::size_t index, BsPlayback** out) {
  if (out != nullptr) *out = nullptr;
  BsPlayback* made = nullptr;
  const BsStatus st = on_handle(game, kGameTag, "game", [&](const BsGame& g) {
    need(out, "out");
    const std::size_t n = g.session.actions();
    if (index >= n) {
      fail(BS_ERROR_OUT_OF_RANGE,
           "index: must be in [0, " + std::to_string(n) + "), not " + std::to_string(index));
    }
    const bs::RecordedAction& ra = g.session.record().actions[index];
    const auto* shot = std::get_if<bs::Shoot>(&ra.action);
    if (shot == nullptr) {
      const char* kind = std::holds_alternative<bs::PlaceCueBall>(ra.action) ? "place" : "decide";
      fail(BS_ERROR_OUT_OF_RANGE, "index: action " + std::to_string(index) +
                                      " is not a shot (" + kind + ")");
    }
    std::vector<int> numbers;
    auto pb = std::make_unique<BsPlayback>(
        g.session.rules().shot_scenario(g.session.state_before(index), shot->strike, &numbers));
    if (ra.ruling.carom) {
      pb->numbers = std::move(numbers);
      pb->carom_struck = ra.ruling.carom->cue_ball;
    }
    made = pb.release();
  });
  if (st == BS_OK) *out = made;
  return st;
}

void bs_playback_free(BsPlayback* playback) {
  if (playback == nullptr || playback->tag != kPlaybackTag) return;
  playback->tag = kFreed;
  delete playback;
}

BsStatus bs_playback_frame(BsPlayback* playback, double t, const double** out, std::size_t* n) {
  return on_handle(playback, kPlaybackTag, "playback", [&](BsPlayback& pb) {
    need(out, "out");
    need(n, "n");
    compute_frame(pb, t);
    *out = pb.frame.data();
    *n = pb.frame.size();
  });
}

BsStatus bs_playback_info(const BsPlayback* playback, BsPlaybackInfo* out) {
  return on_handle(playback, kPlaybackTag, "playback", [&](const BsPlayback& pb) {
    need(out, "out");
    out->balls = pb.sim.ball_count();
    out->events = pb.sim.events().size();
    out->time = pb.sim.time();
    out->at_rest = pb.sim.at_rest() ? 1 : 0;
    out->complete = pb.limit ? 0 : 1;
  });
}

BsStatus bs_playback_states(const BsPlayback* playback, BsBallState* out, std::size_t n) {
  return on_handle(playback, kPlaybackTag, "playback", [&](const BsPlayback& pb) {
    const std::size_t balls = pb.sim.ball_count();
    if (n > 0) need(out, "out");
    if (n != balls) {
      fail(BS_ERROR_OUT_OF_RANGE,
           "n: the playback has " + std::to_string(balls) + " balls, not " + std::to_string(n));
    }
    for (std::size_t i = 0; i < balls; ++i) to_c(pb.sim.ball(i), out[i]);
  });
}

BsStatus bs_playback_events_json(const BsPlayback* playback, std::size_t from, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(playback, kPlaybackTag, "playback", [&](const BsPlayback& pb) {
    need(out, "out");
    *out = copy_out(events_json(pb, from));
  });
}

BsStatus bs_playback_carom_count_json(const BsPlayback* playback, char** out) {
  if (out != nullptr) *out = nullptr;
  return on_handle(playback, kPlaybackTag, "playback", [&](const BsPlayback& pb) {
    need(out, "out");
    *out = copy_out(carom_count_json(pb));
  });
}

}  // extern "C"
