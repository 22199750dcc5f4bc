// The scenario reader's class, shared by the files that read a scenario
// (scenario_json.cpp: the document, physics and the end of the run;
// scenario_balls_json.cpp: the table, the balls, the rack, the pairs and
// the cue). Internal: not installed.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "breakshot/scenario.hpp"
#include "io/json_read.hpp"
#include "io/json_write.hpp"

namespace breakshot::json_io {

/// The largest magnitude accepted for any real number in a scenario.
/// The engine squares positions and velocities and multiplies the
/// results again (the ball-ball contact quadratic needs (dp.dv)^2), so
/// a coordinate near 1e100 would overflow to infinity in the middle of a
/// run and put "inf" into the result. 1e12 (a million kilometres, or a
/// million km/s) keeps every product the engine forms far from overflow
/// while excluding no scenario that means anything physically.
constexpr double kMaxMagnitude = 1e12;

/// Builds a Scenario from a parsed document. Every reading function
/// returns false after recording the first problem in `error`; the first
/// problem stops the whole read.
class ScenarioReader : public Reader {
 public:
  ScenarioReader() : Reader("extra") {}

  bool read(const json& doc, Scenario& s);
  ScenarioError take_error() const {
    return ScenarioError{error->path, error->reason, unsupported_};
  }

 private:
  bool fail_unsupported(std::string path, std::string reason) {
    unsupported_ = true;
    return fail(std::move(path), std::move(reason));
  }

  /// A finite number no larger than kMaxMagnitude.
  bool number(const json& v, const std::string& path, double& out) override {
    if (!Reader::number(v, path, out)) return false;
    if (std::fabs(out) > kMaxMagnitude) {
      return fail(path, format_number(out) + " is too large (the limit is 1e12 in magnitude)");
    }
    return true;
  }

  /// An optional number member: leaves `out` (its default) alone if absent.
  bool optional_number(const json& obj, const std::string& path,
                       std::string_view key, double& out) {
    const json* v = find(obj, key);
    return v == nullptr || number(*v, member_path(path, key), out);
  }

  bool restitution(double x, const std::string& path) {
    if (x >= 0.0 && x <= 1.0) return true;
    return fail(path, "restitution must be in [0, 1], not " + format_number(x));
  }

  bool read_physics(const json& doc, Scenario& s);
  bool read_table(const json& doc, Scenario& s);
  bool read_cushion(const json& t, Scenario& s);
  bool read_balls(const json& doc, Scenario& s);
  bool read_ball(const json& v, const std::string& path, Scenario& s);
  bool read_rack(const json& v, Scenario& s);
  void add_placed_ball(std::string id, Vec2 position, Scenario& s);
  bool read_pairs(const json& doc, Scenario& s);
  bool read_cue(const json& doc, Scenario& s);
  bool read_until(const json& doc, Scenario& s);
  bool read_samples(const json& doc, Scenario& s);
  bool read_max_events(const json& doc, Scenario& s);
  bool check_run_ends(const json& doc, const Scenario& s);
  bool check_sample_count(const Scenario& s);
  ScenarioError locate(ScenarioError e, const Scenario& s) const;

  bool unsupported_ = false;

  std::unordered_map<std::string, std::int32_t> index_of_;  // ball id -> index
  /// wall_restitution of a ball that does not give one: the table's
  /// cushion_restitution, else the model's default.
  double default_wall_restitution_ = 1.0;
  /// Balls [0, given_balls_) come from "balls"; the rest were placed by
  /// the rack (the cue ball on the head spot, then the object balls).
  std::size_t given_balls_ = 0;
};

}  // namespace breakshot::json_io
