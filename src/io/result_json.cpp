// Writing a result file (the Result section of
// docs/contract.md).
//
// A gas run can have a million events, so the text is written straight
// into one string instead of building a JSON tree first: the tree costs a
// heap node per number and is several times slower to dump. Numbers are
// printed with std::to_chars, the shortest text that reads back as the
// same double (io/json_write.hpp), so the result is exact and the bytes
// depend only on the values (the same run gives the same file).
//
// Layout: one event per line, one ball per line in "final", one sample
// per line. Readable in an editor and easy to grep, and still compact.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "breakshot/lab.hpp"
#include "breakshot/scenario_io.hpp"
#include "io/result_json.hpp"

namespace breakshot::json_io {
namespace {

/// The id of ball i, or null for an index the scenario does not have
/// (a broken result must still be valid JSON).
void write_ball_id(JsonWriter& w, const Scenario& s, std::int64_t i) {
  if (i >= 0 && static_cast<std::size_t>(i) < s.balls.size()) {
    w.string(s.balls[static_cast<std::size_t>(i)].id);
  } else {
    w.raw("null");
  }
}

}  // namespace

void write_event(JsonWriter& w, const Scenario& s, const Event& e) {
  w.raw("{\"time\": ");
  w.number(e.time);
  w.raw(", \"type\": ");
  w.string(to_string(e.type));
  w.raw(", \"balls\": [");
  write_ball_id(w, s, e.ball);
  if (e.type == EventType::ball_ball) {
    w.raw(", ");
    write_ball_id(w, s, e.other);
  }
  w.raw("]");
  switch (e.type) {
    case EventType::ball_cushion:
      w.raw(", \"cushion\": ");
      if (e.wall >= 0 && static_cast<std::size_t>(e.wall) < s.table.walls.size()) {
        w.string(s.table.walls[static_cast<std::size_t>(e.wall)].name);
      } else {
        w.raw("null");
      }
      break;
    case EventType::ball_pocket:
      w.raw(", \"pocket\": ");
      if (e.pocket >= 0 && static_cast<std::size_t>(e.pocket) < s.table.pockets.size()) {
        w.string(s.table.pockets[static_cast<std::size_t>(e.pocket)].name);
      } else {
        w.raw("null");
      }
      break;
    case EventType::ball_off_table:
      // The rail it flew over; none when it landed beyond a pocket.
      if (e.wall >= 0 && static_cast<std::size_t>(e.wall) < s.table.walls.size()) {
        w.raw(", \"cushion\": ");
        w.string(s.table.walls[static_cast<std::size_t>(e.wall)].name);
      }
      break;
    case EventType::ball_slate:
    case EventType::state_change:
      w.raw(", \"from\": ");
      w.string(to_string(e.from));
      w.raw(", \"to\": ");
      w.string(to_string(e.to));
      break;
    case EventType::cue_strike:
    case EventType::ball_ball:
      break;
  }
  w.raw("}");
}

namespace {

class ResultWriter {
 public:
  ResultWriter(const Scenario& s, std::string& out) : s_(s), w_(out) {}

  void write(const RunResult& r) {
    airborne_ = r.airborne;
    w_.raw("{\n  \"complete\": ");
    w_.raw(r.complete ? "true" : "false");
    if (r.cue) cue(*r.cue);
    w_.raw(",\n  \"events\": [");
    for (std::size_t k = 0; k < r.events.size(); ++k) {
      w_.raw(k == 0 ? "\n    " : ",\n    ");
      write_event(w_, s_, r.events[k]);
    }
    w_.raw(r.events.empty() ? "],\n" : "\n  ],\n");

    w_.raw("  \"final\": {\n    \"time\": ");
    w_.number(r.final_time);
    w_.raw(",\n    \"balls\": [");
    for (std::size_t i = 0; i < r.final_balls.size(); ++i) {
      w_.raw(i == 0 ? "\n      " : ",\n      ");
      ball(i, r.final_balls[i], false);
    }
    w_.raw(r.final_balls.empty() ? "]\n  }" : "\n    ]\n  }");

    // Samples appear when they were asked for, even if a run stopped
    // before the first one.
    if (s_.sample_dt || !r.samples.empty()) {
      w_.raw(",\n  \"samples\": [");
      for (std::size_t k = 0; k < r.samples.size(); ++k) {
        w_.raw(k == 0 ? "\n    " : ",\n    ");
        sample(r.samples[k]);
      }
      w_.raw(r.samples.empty() ? "]" : "\n  ]");
    }
    w_.raw("\n}\n");
  }

 private:
  /// What the cue strike did (an extension of the contract): the ball's
  /// velocity and spin as the tip leaves it, the squirt in degrees, and
  /// whether it was a miscue (then nothing was played: no cue_strike
  /// event, and the velocity and spin are zero).
  void cue(const StrikeResult& c) {
    w_.raw(",\n  \"cue\": {\"miscue\": ");
    w_.raw(c.miscue ? "true" : "false");
    w_.raw(", \"velocity\": ");
    w_.vec2(c.velocity);
    w_.raw(", \"spin\": ");
    w_.vec3(c.spin);
    w_.raw(", \"squirt\": ");
    w_.number(c.squirt);
    w_.raw("}");
  }

  /// One ball of "final" (with its state) or of a sample (with its
  /// kinetic energy, a per-ball breakdown the contract allows).
  void ball(std::size_t i, const BallState& b, bool in_sample) {
    w_.raw("{\"id\": ");
    write_ball_id(w_, s_, static_cast<std::int64_t>(i));
    w_.raw(", \"position\": ");
    w_.vec2(b.position);
    w_.raw(", \"velocity\": ");
    w_.vec2(b.velocity);
    w_.raw(", \"spin\": ");
    w_.vec3(b.spin);
    if (airborne_) {
      w_.raw(", \"z\": ");
      w_.number(b.z);
    }
    if (in_sample) {
      w_.raw(", \"kinetic_energy\": ");
      w_.number(i < s_.balls.size() ? kinetic_energy(s_.balls[i], b) : 0.0);
    } else {
      w_.raw(", \"state\": ");
      w_.string(to_string(b.state));
    }
    w_.raw("}");
  }

  void sample(const Sample& smp) {
    w_.raw("{\"time\": ");
    w_.number(smp.time);
    w_.raw(", \"balls\": [");
    double energy = 0.0;
    Vec2 p;
    for (std::size_t i = 0; i < smp.balls.size(); ++i) {
      if (i > 0) w_.raw(", ");
      ball(i, smp.balls[i], true);
      // Summed in scenario order, so the totals are the same every run.
      if (i < s_.balls.size()) {
        energy += kinetic_energy(s_.balls[i], smp.balls[i]);
        p += momentum(s_.balls[i], smp.balls[i]);
      }
    }
    w_.raw("], \"kinetic_energy\": ");
    w_.number(energy);
    w_.raw(", \"momentum\": ");
    w_.vec2(p);
    w_.raw("}");
  }

  const Scenario& s_;
  JsonWriter w_;
  bool airborne_ = false;  // some ball left the cloth: every ball has "z"
};

}  // namespace

}  // namespace breakshot::json_io

namespace breakshot {

std::string write_result(const Scenario& scenario, const RunResult& result) {
  std::string out;
  // About 90 bytes per event and per ball of a sample: one allocation
  // for most results instead of a doubling series.
  std::size_t balls_in_samples = 0;
  for (const Sample& smp : result.samples) balls_in_samples += smp.balls.size();
  out.reserve(256 + 90 * result.events.size() + 160 * result.final_balls.size() +
              160 * balls_in_samples);
  json_io::ResultWriter(scenario, out).write(result);
  return out;
}

}  // namespace breakshot
