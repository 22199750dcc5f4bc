// Reading a scenario file: JSON text to a validated Scenario, or the
// first problem found as a JSON path and a reason. The format is the
// contract in docs/contract.md.
//
// The reader is strict on purpose: a scenario is usually written by hand,
// and a typo in a field name that silently falls back to a default gives
// a result that looks right and is not. So unknown fields, duplicate keys
// and wrong types are all errors, each reported with its exact path.
// Only objects named "extra" are free for the user's own data.
//
// This file reads the document, the physics and the end of the run, and
// runs the checks of the whole scenario; scenario_balls_json.cpp reads the
// table, the balls, the rack, the pairs and the cue (the class they share
// is in scenario_reader.hpp).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

#include "breakshot/scenario.hpp"
#include "breakshot/scenario_io.hpp"
#include "io/json_read.hpp"
#include "io/json_write.hpp"
#include "io/scenario_json.hpp"
#include "io/scenario_reader.hpp"

namespace breakshot::json_io {
namespace {

/// A run that asks for more samples than this is refused up front: each
/// sample holds the state of every ball, so a tiny dt would otherwise end
/// as an out-of-memory crash after a long wait.
constexpr double kMaxSamples = 1e7;

}  // namespace

bool ScenarioReader::read(const json& doc, Scenario& s) {
  if (!require_object(doc, "")) return false;
  if (!known_fields(doc, "",
                    {"physics", "table", "balls", "pair_restitution", "rack", "cue",
                     "until", "samples", "max_events"})) {
    return false;
  }
  // The physics come first: the model decides what the rest may contain.
  if (!read_physics(doc, s)) return false;
  // The table next: its cushion fields give the balls' default
  // wall_restitution, and a rack needs it.
  if (!read_table(doc, s)) return false;
  if (!read_balls(doc, s)) return false;
  if (!read_pairs(doc, s)) return false;
  if (!read_cue(doc, s)) return false;
  if (!read_until(doc, s)) return false;
  if (!read_samples(doc, s)) return false;
  if (!read_max_events(doc, s)) return false;
  if (!check_run_ends(doc, s)) return false;
  if (!check_sample_count(s)) return false;
  // Geometry (inside the table, out of the pockets, no overlaps) and
  // everything a scenario built in code must also satisfy.
  if (auto problem = validate(s)) {
    ScenarioError e = locate(std::move(*problem), s);
    unsupported_ = e.unsupported;
    return fail(std::move(e.path), std::move(e.reason));
  }
  return true;
}

/// validate() names balls by their index in Scenario::balls. The balls a
/// rack placed come after the given ones and have no entry in the file's
/// "balls", so a problem with one of them is reported at "rack".
ScenarioError ScenarioReader::locate(ScenarioError e, const Scenario& s) const {
  constexpr std::string_view prefix = "balls[";
  if (e.path.compare(0, prefix.size(), prefix) != 0) return e;
  const std::size_t close = e.path.find(']');
  if (close == std::string::npos) return e;
  std::size_t index = 0;
  for (std::size_t k = prefix.size(); k < close; ++k) {
    const char c = e.path[k];
    if (c < '0' || c > '9') return e;
    index = index * 10 + static_cast<std::size_t>(c - '0');
  }
  if (index < given_balls_ || index >= s.balls.size()) return e;
  e.reason = "ball '" + s.balls[index].id + "' placed by the rack: " + e.reason;
  e.path = "rack";
  return e;
}

bool ScenarioReader::read_physics(const json& doc, Scenario& s) {
  const json* p = find(doc, "physics");
  if (p == nullptr) return fail("physics", "missing required field");
  const std::string path = "physics";
  if (!require_object(*p, path)) return false;
  if (!known_fields(*p, path,
                    {"model", "ball_ball_restitution", "ball_ball_friction", "gravity",
                     "deceleration", "sliding_friction", "rolling_friction",
                     "spinning_friction", "collapse_speed", "ball_clusters",
                     "ball_ball_model", "airborne", "slate_restitution",
                     "min_bounce_height"})) {
    return false;
  }

  const json* m = find(*p, "model");
  const std::string model_path = "physics.model";
  if (m == nullptr) {
    return fail(model_path, "missing required field (\"ideal\", \"friction\" or \"pool\")");
  }
  if (!m->is_string()) return fail(model_path, expected("a string", *m));
  const std::string model = m->get<std::string>();
  PhysicsParams& ph = s.physics;
  // Every field not given keeps the model's default (default_physics).
  if (model == "ideal") {
    ph = default_physics(Model::ideal);
  } else if (model == "friction") {
    ph = default_physics(Model::friction);
  } else if (model == "pool") {
    ph = default_physics(Model::pool);
  } else {
    return fail(model_path, "unknown model \"" + model +
                                "\" (expected \"ideal\", \"friction\" or \"pool\")");
  }

  // Read in the contract's order so that the first problem reported is
  // the first one in a file written in that order.
  if (!optional_number(*p, path, "ball_ball_restitution", ph.ball_ball_restitution) ||
      !restitution(ph.ball_ball_restitution, member_path(path, "ball_ball_restitution"))) {
    return false;
  }
  // Pool: the friction between balls falls with the slip speed. Without
  // the field, the engine uses the default curve mu(v) (physics.hpp,
  // kThrowFitTPA28); a number is a constant mu for every impact; an object
  // {"a", "b", "c"} (extension) is the curve a + b exp(-c v).
  if (const json* f = find(*p, "ball_ball_friction"); f != nullptr && f->is_object()) {
    const std::string fpath = member_path(path, "ball_ball_friction");
    if (!exact_object(*f, fpath, {"a", "b", "c"})) return false;
    FrictionCurve& k = ph.ball_ball_friction_curve;
    if (!number(f->at("a"), member_path(fpath, "a"), k.a) ||
        !number(f->at("b"), member_path(fpath, "b"), k.b) ||
        !number(f->at("c"), member_path(fpath, "c"), k.c)) {
      return false;
    }
    if (auto bad = check_friction_curve(k)) {
      return fail(member_path(fpath, std::string(1, bad->member)), std::move(bad->reason));
    }
    ph.ball_ball_friction_fit = true;
  } else if (f != nullptr) {
    if (!f->is_number()) {
      return fail(member_path(path, "ball_ball_friction"), expected("a number or an object {\"a\", \"b\", \"c\"}", *f));
    }
    if (!number(*f, member_path(path, "ball_ball_friction"), ph.ball_ball_friction) ||
        !non_negative(ph.ball_ball_friction, member_path(path, "ball_ball_friction"))) {
      return false;
    }
    ph.ball_ball_friction_fit = false;
  }
  if (!optional_number(*p, path, "gravity", ph.gravity) ||
      !non_negative(ph.gravity, member_path(path, "gravity"))) {
    return false;
  }
  const bool has_deceleration = find(*p, "deceleration") != nullptr;
  if (!optional_number(*p, path, "deceleration", ph.deceleration) ||
      !non_negative(ph.deceleration, member_path(path, "deceleration"))) {
    return false;
  }
  if (!optional_number(*p, path, "sliding_friction", ph.sliding_friction) ||
      !non_negative(ph.sliding_friction, member_path(path, "sliding_friction"))) {
    return false;
  }
  if (!optional_number(*p, path, "rolling_friction", ph.rolling_friction) ||
      !non_negative(ph.rolling_friction, member_path(path, "rolling_friction"))) {
    return false;
  }
  if (!optional_number(*p, path, "spinning_friction", ph.spinning_friction) ||
      !non_negative(ph.spinning_friction, member_path(path, "spinning_friction"))) {
    return false;
  }
  // The pool model's collapse_speed is larger (kPoolCollapseSpeed, 1 mm/s,
  // far below anything a player sees): balls pushing a frozen cluster are
  // in contact for a long time, and each re-contact of a pressed pair is
  // an event.
  if (!optional_number(*p, path, "collapse_speed", ph.collapse_speed) ||
      !positive(ph.collapse_speed, member_path(path, "collapse_speed"))) {
    return false;
  }
  // Extension: impacts on clusters resolved at once (Hertz contacts).
  if (const json* c = find(*p, "ball_clusters")) {
    if (!c->is_boolean()) return fail(member_path(path, "ball_clusters"), expected("true or false", *c));
    ph.ball_clusters = c->get<bool>();
  }
  // Extension: the pool model's ball-ball impact law.
  if (const json* b = find(*p, "ball_ball_model")) {
    const std::string bpath = member_path(path, "ball_ball_model");
    std::string law;
    if (!text_of(*b, bpath, "ball-ball model", {"friction", "mathavan_2014"}, law)) return false;
    ph.ball_ball_model = law == "friction" ? BallBallModel::friction : BallBallModel::mathavan_2014;
    if (ph.ball_ball_model != BallBallModel::friction && ph.model != Model::pool) {
      return fail(bpath, "\"" + law + "\" needs the pool model");
    }
  }
  // Extension: balls that leave the cloth (pool model).
  if (const json* a = find(*p, "airborne")) {
    const std::string apath = member_path(path, "airborne");
    if (!a->is_boolean()) return fail(apath, expected("true or false", *a));
    ph.airborne = a->get<bool>();
    if (ph.airborne && ph.model != Model::pool) return fail(apath, "true needs the pool model");
    if (ph.airborne && !(ph.gravity > 0.0)) {
      return fail(apath, "true needs a positive physics.gravity (a ball would never land)");
    }
  }
  // Without gravity nothing lands: the default is then balls on the cloth.
  if (find(*p, "airborne") == nullptr && !(ph.gravity > 0.0)) ph.airborne = false;
  for (const char* key : {"slate_restitution", "min_bounce_height"}) {
    if (find(*p, key) != nullptr && !ph.airborne) {
      return fail(member_path(path, key), "needs physics.airborne true");
    }
  }
  if (!optional_number(*p, path, "slate_restitution", ph.slate_restitution)) return false;
  if (!(ph.slate_restitution >= 0.0 && ph.slate_restitution < 1.0)) {
    return fail(member_path(path, "slate_restitution"),
                "must be in [0, 1) (at 1 a ball would bounce forever), not " +
                    format_number(ph.slate_restitution));
  }
  if (!optional_number(*p, path, "min_bounce_height", ph.min_bounce_height) ||
      !positive(ph.min_bounce_height, member_path(path, "min_bounce_height"))) {
    return false;
  }
  // Without an explicit deceleration a ball slows as a rolling ball does
  // on cloth: mu_r g (0.0981 m/s^2 with the defaults). The pool model
  // does not use it (its balls slow by the three frictions); a given
  // value is accepted there, as the contract's example lists every
  // field, and ignored.
  if (!has_deceleration) ph.deceleration = ph.rolling_friction * ph.gravity;
  return true;
}

bool ScenarioReader::read_until(const json& doc, Scenario& s) {
  const json* u = find(doc, "until");
  const std::string path = "until";
  if (u == nullptr) {
    // The ideal model never comes to rest by itself, so it needs a time.
    if (s.physics.model == Model::ideal) {
      return fail(path, "missing required field: the ideal model needs {\"time\": T}");
    }
    s.until = Until{};
    return true;
  }
  if (u->is_string()) {
    if (u->get<std::string>() != "rest") {
      return fail(path, "expected \"rest\" or {\"time\": T}, not \"" +
                            u->get<std::string>() + "\"");
    }
    s.until = Until{};
    return true;
  }
  if (!u->is_object()) return fail(path, expected("\"rest\" or {\"time\": T}", *u));
  if (!known_fields(*u, path, {"time"})) return false;
  const json* t = find(*u, "time");
  const std::string t_path = "until.time";
  if (t == nullptr) return fail(t_path, "missing required field");
  Until until;
  until.rest = false;
  if (!number(*t, t_path, until.time) || !positive(until.time, t_path)) return false;
  s.until = until;
  return true;
}

bool ScenarioReader::read_samples(const json& doc, Scenario& s) {
  s.sample_dt.reset();
  const json* v = find(doc, "samples");
  if (v == nullptr) return true;
  const std::string path = "samples";
  if (!require_object(*v, path)) return false;
  if (!known_fields(*v, path, {"dt"})) return false;
  const json* dt = find(*v, "dt");
  const std::string dt_path = "samples.dt";
  if (dt == nullptr) return fail(dt_path, "missing required field");
  double h = 0.0;
  if (!number(*dt, dt_path, h) || !positive(h, dt_path)) return false;
  s.sample_dt = h;
  return true;
}

bool ScenarioReader::read_max_events(const json& doc, Scenario& s) {
  const json* v = find(doc, "max_events");
  if (v == nullptr) return true;  // keeps the default
  const std::string path = "max_events";
  if (v->is_number_unsigned()) {
    s.max_events = v->get<std::uint64_t>();
  } else if (v->is_number_integer()) {
    // nlohmann gives signed integers only to negative numbers.
    return fail(path, "must be a positive integer, not " + v->dump());
  } else if (v->is_number_float()) {
    // 1e6 is a float in JSON but a fine count; 2.5 is not.
    const double x = v->get<double>();
    if (!(x >= 1.0 && x < 18446744073709551616.0 && std::floor(x) == x)) {
      return fail(path, "must be a positive integer, not " + format_number(x));
    }
    s.max_events = static_cast<std::uint64_t>(x);
  } else {
    return fail(path, expected("a positive integer", *v));
  }
  if (s.max_events == 0) return fail(path, "must be a positive integer, not 0");
  return true;
}

/// "rest" must come (check_run_ends, src/physics/validate.cpp). When the
/// file gives no "until", the message says that "rest" is the default.
bool ScenarioReader::check_run_ends(const json& doc, const Scenario& s) {
  auto problem = breakshot::check_run_ends(s);
  if (!problem) return true;
  if (find(doc, "until") == nullptr)
    problem->reason = "no \"until\" given and the default " + problem->reason;
  return fail(std::move(problem->path), std::move(problem->reason));
}

bool ScenarioReader::check_sample_count(const Scenario& s) {
  // With "rest" the end is unknown until the run is over, so the count
  // cannot be checked here.
  if (!s.sample_dt || s.until.rest) return true;
  const double count = s.until.time / *s.sample_dt;
  if (count > kMaxSamples) {
    return fail("samples.dt", "would make about " + format_number(std::floor(count)) +
                                  " samples up to until.time (at most 10,000,000 are allowed)");
  }
  return true;
}

}  // namespace breakshot::json_io

namespace breakshot {

using json_io::json;
using json_io::kDocumentPath;

std::variant<Scenario, ScenarioError> read_scenario(std::string_view json_text) {
  try {
    // Syntax errors, and numbers too large for a double (1e400), come
    // back with the line and column; repeated keys with their path.
    // Content inside "extra" objects is the user's and is not checked.
    json doc;
    json_io::ParseOptions options;
    options.free_key = "extra";
    if (auto problem = json_io::parse_strict(json_text, doc, options)) {
      return ScenarioError{std::move(problem->error.path), std::move(problem->error.reason)};
    }
    return json_io::read_scenario_tree(doc);
  } catch (const std::bad_alloc&) {
    return ScenarioError{kDocumentPath, "out of memory while reading the scenario"};
  } catch (const std::exception& e) {
    return ScenarioError{kDocumentPath, std::string("internal error: ") + e.what()};
  }
}

std::variant<Scenario, ScenarioError> json_io::read_scenario_tree(const json& doc) {
  try {
    Scenario scenario;
    ScenarioReader reader;
    if (!reader.read(doc, scenario)) return reader.take_error();
    return scenario;
  } catch (const std::bad_alloc&) {
    return ScenarioError{kDocumentPath, "out of memory while reading the scenario"};
  } catch (const std::exception& e) {
    // Not expected: every check above reports instead of throwing. Kept
    // so that a bug here is an error message, never a crash.
    return ScenarioError{kDocumentPath, std::string("internal error: ") + e.what()};
  }
}

}  // namespace breakshot
