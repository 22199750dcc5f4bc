// Reading a scenario file: the table (its shape and cushions), the
// balls, the rack, the pair restitutions and the cue strike, each problem
// reported at its JSON path (the reader's class is in scenario_reader.hpp;
// scenario_json.cpp reads the rest and runs the whole-scenario checks).

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

#include "breakshot/carom.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/snooker.hpp"
#include "io/json_read.hpp"
#include "io/json_write.hpp"
#include "io/scenario_reader.hpp"

namespace breakshot::json_io {
namespace {

/// How far a given ball may overlap a ball the rack places and still
/// count as touching: validate()'s tolerance (src/physics/validate.cpp).
constexpr double kTouchTolerance = 1e-9;

/// The default ball of a table: the snooker ball on the snooker table,
/// the carom ball on the carom table (docs/scenario.md, "Defaults"), else
/// the pool ball.
BallSpec default_ball(const Table& table) {
  BallSpec spec;
  if (table.shape == TableShape::snooker) {
    spec.radius = kSnookerBallRadius;
    spec.mass = kSnookerBallMass;
  } else if (table.shape == TableShape::carom) {
    spec.radius = kCaromBallRadius;
    spec.mass = kCaromBallMass;
  }
  return spec;
}

}  // namespace

bool ScenarioReader::read_table(const json& doc, Scenario& s) {
  const json* t = find(doc, "table");
  const std::string path = "table";
  if (t == nullptr) return fail(path, "missing required field");
  if (!require_object(*t, path)) return false;

  const json* shape_v = find(*t, "shape");
  const std::string shape_path = "table.shape";
  if (shape_v == nullptr) return fail(shape_path, "missing required field");
  if (!shape_v->is_string()) return fail(shape_path, expected("a string", *shape_v));
  const std::string name = shape_v->get<std::string>();
  TableShape shape{};
  if (!parse_table_shape(name, shape)) {
    return fail(shape_path, "unknown shape \"" + name +
                                "\" (expected rectangle, polygon, pool, snooker or carom)");
  }

  if (shape == TableShape::rectangle) {
    if (!known_fields(*t, path, {"shape", "min", "max", "cushion_restitution",
                                 "cushion_friction", "nose_height", "cushion_model", "cushion_height",
                                 "cushion_compliance_ratio"})) {
      return false;
    }
    const json* lo = find(*t, "min");
    const json* hi = find(*t, "max");
    if (lo == nullptr) return fail("table.min", "missing required field");
    if (hi == nullptr) return fail("table.max", "missing required field");
    Vec2 min;
    Vec2 max;
    if (!vec2(*lo, "table.min", min) || !vec2(*hi, "table.max", max)) return false;
    if (!(min.x < max.x && min.y < max.y)) {
      return fail("table.max", "must be greater than table.min in both x and y");
    }
    try {
      s.table = make_rectangle(min, max);
    } catch (const std::exception& e) {
      return fail("table", e.what());
    }
    return read_cushion(*t, s);
  }

  if (shape == TableShape::polygon) {
    if (!known_fields(*t, path, {"shape", "vertices", "cushion_restitution",
                                 "cushion_friction", "nose_height", "cushion_model", "cushion_height",
                                 "cushion_compliance_ratio"})) {
      return false;
    }
    const json* vs = find(*t, "vertices");
    const std::string vpath = "table.vertices";
    if (vs == nullptr) return fail(vpath, "missing required field");
    if (!vs->is_array()) return fail(vpath, expected("an array of [x, y] points", *vs));
    std::vector<Vec2> vertices(vs->size());
    for (std::size_t i = 0; i < vs->size(); ++i) {
      if (!vec2((*vs)[i], index_path(vpath, i), vertices[i])) return false;
    }
    try {
      s.table = make_polygon(vertices);
    } catch (const std::exception& e) {
      // make_polygon says what is wrong: too few vertices, a repeated
      // vertex, zero area or edges that cross.
      return fail(vpath, e.what());
    }
    return read_cushion(*t, s);
  }

  if (shape == TableShape::pool) {
    if (!known_fields(*t, path, {"shape", "size", "cushion_restitution", "cushion_friction",
                                 "nose_height", "cushion_model", "cushion_height",
                                 "cushion_compliance_ratio"})) {
      return false;
    }
    const json* size_v = find(*t, "size");
    const std::string size_path = "table.size";
    if (size_v == nullptr) {
      return fail(size_path, "missing required field (\"7ft\", \"8ft\" or \"9ft\")");
    }
    std::string size;
    if (!text_of(*size_v, size_path, "table size", {"7ft", "8ft", "9ft"}, size)) return false;
    try {
      s.table = make_pool_table(size);
    } catch (const std::exception& e) {
      return fail(size_path, e.what());
    }
    return read_cushion(*t, s);
  }

  if (shape == TableShape::snooker) {
    if (!known_fields(*t, path,
                      {"shape", "cushion_restitution", "cushion_friction", "nose_height",
                       "cushion_model", "cushion_height",
                       "cushion_compliance_ratio"})) {
      return false;
    }
    s.table = make_snooker_table();
    return read_cushion(*t, s);
  }

  // TableShape::carom
  if (!known_fields(*t, path,
                    {"shape", "cushion_restitution", "cushion_friction", "nose_height",
                     "cushion_model", "cushion_height", "cushion_compliance_ratio"})) {
    return false;
  }
  s.table = make_carom_table();
  return read_cushion(*t, s);
}

/// The optional cushion fields of a table object, read after the table
/// is built. cushion_restitution is the default wall_restitution of
/// every ball on any table; the other fields (the cushion law, its
/// friction and its contact height) only mean something for the pool
/// model's cushions: they are read on pool tables, and on any table when
/// the physics model is "pool" (the lab's tables); elsewhere they are
/// errors rather than values silently unused.
bool ScenarioReader::read_cushion(const json& t, Scenario& s) {
  const TableShape shape = s.table.shape;
  const bool pool_cushions = shape == TableShape::pool || shape == TableShape::snooker ||
                             shape == TableShape::carom || s.physics.model == Model::pool;
  for (const char* key : {"cushion_friction", "nose_height", "cushion_model", "cushion_height",
                          "cushion_compliance_ratio"}) {
    if (find(t, key) != nullptr && !pool_cushions) {
      return fail(member_path("table", key),
                  "only the pool model's cushions have this field (a pool, snooker or "
                  "carom table, or \"physics\": {\"model\": \"pool\"})");
    }
  }
  CushionParams& cp = s.table.cushion;
  if (const json* m = find(t, "cushion_model")) {
    std::string name;
    if (!text(*m, "table.cushion_model", name)) return false;
    if (!parse_cushion_model(name, cp.model)) {
      return fail("table.cushion_model",
                  unknown("cushion model", name, json_io::cushion_model_names()));
    }
  }
  // Each law's own restitution (default_cushion_restitution); Mathavan
  // et al. 2010's contact height is that model's.
  cp.restitution = default_cushion_restitution(cp.model);
  if (cp.model == CushionModel::mathavan_2010) cp.nose_height = kMathavanNoseHeight;
  default_wall_restitution_ =
      s.physics.model == Model::pool ? cp.restitution : 1.0;
  if (const json* v = find(t, "cushion_restitution")) {
    const std::string path = "table.cushion_restitution";
    double e = 0.0;
    if (!number(*v, path, e) || !restitution(e, path)) return false;
    default_wall_restitution_ = e;
    cp.restitution = e;
  }
  const std::string friction_path = "table.cushion_friction";
  if (!optional_number(t, "table", "cushion_friction", cp.friction) ||
      !non_negative(cp.friction, friction_path)) {
    return false;
  }
  const std::string nose_path = "table.nose_height";
  if (!optional_number(t, "table", "nose_height", cp.nose_height)) return false;
  const double h = cp.nose_height;
  if (!(h > 0.5 && h < 1.0)) {
    // At or below half the diameter the nose would push the ball down
    // into the cloth or meet it below its centre; at 1 it would miss it.
    return fail(nose_path, "must be between 0.5 and 1 (a fraction of the ball's diameter, "
                           "above its centre), not " + format_number(h));
  }
  if (const json* v = find(t, "cushion_height")) {
    const std::string path = "table.cushion_height";
    double height = 0.0;
    if (!number(*v, path, height)) return false;
    if (!(std::isfinite(height) && height > 0.0)) {
      return fail(path, "must be a positive height in metres, not " + format_number(height));
    }
    // Against each ball's radius: validate() (the balls come next).
    cp.height = height;
  }
  if (const json* v = find(t, "cushion_compliance_ratio")) {
    const std::string path = "table.cushion_compliance_ratio";
    if (cp.model != CushionModel::stronge_compliant) {
      return fail(path, "only the \"stronge_compliant\" cushion law has this field (table."
                        "cushion_model is \"" + std::string(cushion_model_name(cp.model)) + "\")");
    }
    double eta2 = 0.0;
    if (!number(*v, path, eta2)) return false;
    if (!(eta2 >= kMinComplianceRatio && eta2 <= kMaxComplianceRatio)) {
      return fail(path, "must be between 0.01 and 100 (the tangential over the normal "
                        "compliance; elastic bodies have 1 to 1.5), not " + format_number(eta2));
    }
    cp.compliance_ratio = eta2;
  }
  return true;
}

bool ScenarioReader::read_balls(const json& doc, Scenario& s) {
  const json* bs = find(doc, "balls");
  const json* rack = find(doc, "rack");
  const std::string path = "balls";
  s.balls.clear();
  s.start.clear();
  if (bs == nullptr && rack == nullptr) {
    return fail(path, "missing required field (it may be left out when a \"rack\" is given)");
  }
  if (bs != nullptr) {
    if (!bs->is_array()) return fail(path, expected("an array of balls", *bs));
    s.balls.reserve(bs->size());
    s.start.reserve(bs->size());
    index_of_.reserve(bs->size());
    for (std::size_t i = 0; i < bs->size(); ++i) {
      if (!read_ball((*bs)[i], index_path(path, i), s)) return false;
    }
  }
  given_balls_ = s.balls.size();
  return rack == nullptr || read_rack(*rack, s);
}

/// "rack": the regulation rack on a pool table, and a cue ball "cue" on
/// the head spot unless one is given; the snooker rack on the snooker
/// table, and "cue" on the break-off spot in the D; or the three-cushion
/// starting position on the carom table (white, yellow and red, no "cue").
/// The placed balls come after the given ones: "cue" (if placed), then
/// "1", "2", ... in numeric order, or "red1" ... "red15", "yellow" ...
/// "black", or "white", "yellow", "red".
bool ScenarioReader::read_rack(const json& v, Scenario& s) {
  const std::string path = "rack";
  if (!require_object(v, path)) return false;
  const TableShape shape = s.table.shape;
  if (shape != TableShape::pool && shape != TableShape::snooker && shape != TableShape::carom) {
    return fail(path,
                "a rack needs a pool table (\"table\": {\"shape\": \"pool\", ...}), "
                "the snooker table (\"table\": {\"shape\": \"snooker\"}) or the carom "
                "table (\"table\": {\"shape\": \"carom\"})");
  }
  if (!known_fields(v, path, {"game", "seed"})) return false;

  const json* game_v = find(v, "game");
  const std::string game_path = "rack.game";
  if (game_v == nullptr) {
    return fail(game_path,
                "missing required field (\"eight_ball\", \"nine_ball\", \"ten_ball\", "
                "\"snooker\" or \"three_cushion\")");
  }
  if (!game_v->is_string()) return fail(game_path, expected("a string", *game_v));
  const std::string game = game_v->get<std::string>();
  if (game != "eight_ball" && game != "nine_ball" && game != "ten_ball" && game != "snooker" &&
      game != "three_cushion") {
    return fail(game_path, "unknown game \"" + game +
                               "\" (expected \"eight_ball\", \"nine_ball\", \"ten_ball\", "
                               "\"snooker\" or \"three_cushion\")");
  }
  const bool snooker = game == "snooker";
  const bool carom = game == "three_cushion";
  if (snooker && shape != TableShape::snooker) {
    return fail(game_path,
                "the snooker rack needs the snooker table (\"table\": {\"shape\": "
                "\"snooker\"}), not a " +
                    std::string(to_string(shape)) + " table");
  }
  if (carom && shape != TableShape::carom) {
    return fail(game_path,
                "the three_cushion rack needs the carom table (\"table\": {\"shape\": "
                "\"carom\"}), not a " +
                    std::string(to_string(shape)) + " table");
  }
  if (!snooker && !carom && shape != TableShape::pool) {
    return fail(game_path, "the " + game +
                               " rack needs a pool table (\"table\": {\"shape\": "
                               "\"pool\", ...}), not the " +
                               std::string(to_string(shape)) + " table");
  }

  // The seed of the rack's tiny random gaps: a whole number >= 0, so that
  // the same file always gives the same rack.
  std::uint64_t seed = 0;
  if (const json* seed_v = find(v, "seed")) {
    const std::string seed_path = "rack.seed";
    if (seed_v->is_number_unsigned()) {
      seed = seed_v->get<std::uint64_t>();
    } else if (seed_v->is_number_integer()) {
      return fail(seed_path, "must be a whole number >= 0, not " + seed_v->dump());
    } else if (seed_v->is_number_float()) {
      const double x = seed_v->get<double>();
      if (!(x >= 0.0 && x < 18446744073709551616.0 && std::floor(x) == x)) {
        return fail(seed_path, "must be a whole number >= 0, not " + format_number(x));
      }
      seed = static_cast<std::uint64_t>(x);
    } else {
      return fail(seed_path, expected("a whole number >= 0", *seed_v));
    }
  }

  std::vector<RackedBall> racked;
  try {
    racked = make_rack(game, s.table, default_ball(s.table).radius, seed);
  } catch (const std::exception& e) {
    return fail(path, e.what());
  }
  // make_rack lists the pool balls in rack order; the scenario lists them
  // by number, so a result reads "1", "2", ... whatever the rack. The
  // snooker rack is already in its order: red1 ... red15, then the colours
  // from yellow to black; the three-cushion one too: white, yellow, red.
  if (!snooker && !carom) {
    std::sort(racked.begin(), racked.end(), [](const RackedBall& a, const RackedBall& b) {
      return a.id.size() < b.id.size() || (a.id.size() == b.id.size() && a.id < b.id);
    });
  }

  // A given ball may not take an object ball's id: which of the two would
  // "3" in an event be?
  for (const RackedBall& rb : racked) {
    if (const auto it = index_of_.find(rb.id); it != index_of_.end()) {
      return fail(index_path("balls", static_cast<std::size_t>(it->second)) + ".id",
                  "the rack places a ball with the id '" + rb.id +
                      "'; give this ball another id");
    }
  }
  if (!carom && index_of_.find("cue") == index_of_.end()) {
    // Pool: the head spot; snooker: the break-off spot in the D. The
    // three-cushion rack has its own cue balls.
    add_placed_ball("cue", snooker ? snooker_break_off_spot() : s.table.head_spot, s);
  }
  for (RackedBall& rb : racked) add_placed_ball(std::move(rb.id), rb.position, s);

  // A given ball in the way of a placed one is the given ball's problem:
  // say so at its own path (validate() would name the placed ball).
  for (std::size_t i = 0; i < given_balls_; ++i) {
    for (std::size_t j = given_balls_; j < s.balls.size(); ++j) {
      const double reach = s.balls[i].radius + s.balls[j].radius - kTouchTolerance;
      if (norm(s.start[i].position - s.start[j].position) < reach) {
        return fail(index_path("balls", i) + ".position",
                    "ball '" + s.balls[i].id + "' overlaps ball '" + s.balls[j].id +
                        "' placed by the rack");
      }
    }
  }
  return true;
}

/// A ball placed by the rack: default radius, mass and wall restitution,
/// at rest.
void ScenarioReader::add_placed_ball(std::string id, Vec2 position, Scenario& s) {
  BallSpec spec = default_ball(s.table);
  spec.id = std::move(id);
  spec.wall_restitution = default_wall_restitution_;
  BallState state;
  state.position = position;
  state.state = MotionState::stationary;
  index_of_.emplace(spec.id, static_cast<std::int32_t>(s.balls.size()));
  s.balls.push_back(std::move(spec));
  s.start.push_back(state);
}

bool ScenarioReader::read_ball(const json& v, const std::string& path, Scenario& s) {
  if (!require_object(v, path)) return false;
  if (!known_fields(v, path,
                    {"id", "position", "velocity", "spin", "radius", "mass",
                     "wall_restitution"})) {
    return false;
  }
  BallSpec spec = default_ball(s.table);
  spec.wall_restitution = default_wall_restitution_;
  BallState state;

  const json* id = find(v, "id");
  const std::string id_path = member_path(path, "id");
  if (id == nullptr) return fail(id_path, "missing required field");
  if (!id->is_string()) return fail(id_path, expected("a string", *id));
  spec.id = id->get<std::string>();
  if (spec.id.empty()) return fail(id_path, "must not be empty");
  const auto index = static_cast<std::int32_t>(s.balls.size());
  if (const auto [it, inserted] = index_of_.emplace(spec.id, index); !inserted) {
    return fail(id_path, "duplicate id '" + spec.id + "' (also balls[" +
                             std::to_string(it->second) + "])");
  }

  const json* pos = find(v, "position");
  if (pos == nullptr) return fail(member_path(path, "position"), "missing required field");
  if (!vec2(*pos, member_path(path, "position"), state.position)) return false;
  if (const json* vel = find(v, "velocity")) {
    const std::string vpath = member_path(path, "velocity");
    if (vel->is_array() && vel->size() != 2 && vel->size() != 3 &&
        s.physics.model == Model::pool) {
      return fail(vpath, "expected an array of 2 numbers, or 3 with a vertical component, not an "
                         "array of " + std::to_string(vel->size()));
    }
    if (vel->is_array() && vel->size() == 3) {
      // Pool model: a vertical component (up positive).
      Vec3 v3;
      if (!vec3(*vel, vpath, v3)) return false;
      if (s.physics.model != Model::pool) {
        return fail(vpath, "a vertical component needs the pool model");
      }
      if (v3.z != 0.0 && !s.physics.airborne) {
        return fail(vpath, "a vertical component (" + format_number(v3.z) +
                               ") needs physics.airborne true");
      }
      state.velocity = {v3.x, v3.y};
      state.vz = v3.z;
    } else if (!vec2(*vel, vpath, state.velocity)) {
      return false;
    }
  }
  if (const json* spin = find(v, "spin")) {
    const std::string spin_path = member_path(path, "spin");
    if (!vec3(*spin, spin_path, state.spin)) return false;
    // Only the pool model has rotation; elsewhere a nonzero spin would be
    // silently dropped.
    if (state.spin != Vec3{} && s.physics.model != Model::pool) {
      return fail(spin_path, "spin needs the pool model");
    }
  }
  if (!optional_number(v, path, "radius", spec.radius) ||
      !positive(spec.radius, member_path(path, "radius"))) {
    return false;
  }
  if (!optional_number(v, path, "mass", spec.mass) ||
      !positive(spec.mass, member_path(path, "mass"))) {
    return false;
  }
  if (!optional_number(v, path, "wall_restitution", spec.wall_restitution) ||
      !restitution(spec.wall_restitution, member_path(path, "wall_restitution"))) {
    return false;
  }
  if (s.physics.model == Model::pool) {
    // The engine derives the state from the motion itself; this is the
    // same rule, so that the scenario says what the engine will do.
    const Vec2 slip{state.velocity.x - spec.radius * state.spin.y,
                    state.velocity.y + spec.radius * state.spin.x};
    if (state.vz > 0.0) {
      state.state = MotionState::airborne;
    } else if (slip != Vec2{}) {
      state.state = MotionState::sliding;
    } else if (state.velocity != Vec2{}) {
      state.state = MotionState::rolling;
    } else if (state.spin.z != 0.0) {
      state.state = MotionState::spinning;
    } else {
      state.state = MotionState::stationary;
    }
  } else {
    state.state = state.velocity == Vec2{} ? MotionState::stationary : MotionState::moving;
  }
  s.balls.push_back(std::move(spec));
  s.start.push_back(state);
  return true;
}

bool ScenarioReader::read_pairs(const json& doc, Scenario& s) {
  s.pair_restitution.clear();
  const json* ps = find(doc, "pair_restitution");
  if (ps == nullptr) return true;
  const std::string path = "pair_restitution";
  if (!ps->is_array()) return fail(path, expected("an array", *ps));
  // Key a * n + b with a < b, to find a pair listed twice.
  std::unordered_map<std::uint64_t, std::size_t> seen;
  const auto n = static_cast<std::uint64_t>(s.balls.size());
  for (std::size_t k = 0; k < ps->size(); ++k) {
    const json& entry = (*ps)[k];
    const std::string epath = index_path(path, k);
    if (!require_object(entry, epath)) return false;
    if (!known_fields(entry, epath, {"balls", "restitution"})) return false;

    const json* ids = find(entry, "balls");
    const std::string ids_path = member_path(epath, "balls");
    if (ids == nullptr) return fail(ids_path, "missing required field");
    if (!ids->is_array() || ids->size() != 2) {
      if (ids->is_array()) {
        return fail(ids_path, "expected 2 ball ids, not " + std::to_string(ids->size()));
      }
      return fail(ids_path, expected("an array of 2 ball ids", *ids));
    }
    std::int32_t idx[2] = {0, 0};
    for (std::size_t j = 0; j < 2; ++j) {
      const json& idv = (*ids)[j];
      const std::string jpath = index_path(ids_path, j);
      if (!idv.is_string()) return fail(jpath, expected("a ball id (a string)", idv));
      const auto it = index_of_.find(idv.get<std::string>());
      if (it == index_of_.end()) {
        return fail(jpath, "no ball has the id '" + idv.get<std::string>() + "'");
      }
      idx[j] = it->second;
    }
    if (idx[0] == idx[1]) return fail(ids_path, "the two balls must differ");

    const json* e = find(entry, "restitution");
    const std::string e_path = member_path(epath, "restitution");
    if (e == nullptr) return fail(e_path, "missing required field");
    PairRestitution pr;
    pr.a = std::min(idx[0], idx[1]);
    pr.b = std::max(idx[0], idx[1]);
    if (!number(*e, e_path, pr.restitution) || !restitution(pr.restitution, e_path)) {
      return false;
    }
    const std::uint64_t key = static_cast<std::uint64_t>(pr.a) * n + static_cast<std::uint64_t>(pr.b);
    if (const auto [it, inserted] = seen.emplace(key, k); !inserted) {
      return fail(ids_path, "the pair '" + s.balls[static_cast<std::size_t>(pr.a)].id +
                                "', '" + s.balls[static_cast<std::size_t>(pr.b)].id +
                                "' is already listed at pair_restitution[" +
                                std::to_string(it->second) + "]");
    }
    s.pair_restitution.push_back(pr);
  }
  return true;
}

/// "cue": the shot at t = 0 (pool model). An offset beyond the miscue
/// limit is not an error: the engine plays it as a miscue and says so in
/// the result.
bool ScenarioReader::read_cue(const json& doc, Scenario& s) {
  s.cue.reset();
  const json* c = find(doc, "cue");
  if (c == nullptr) return true;
  const std::string path = "cue";
  // A cue strike gives the ball spin, which only the pool model has.
  if (s.physics.model != Model::pool) return fail(path, "a cue strike needs the pool model");
  if (!require_object(*c, path)) return false;
  if (!known_fields(*c, path,
                    {"ball", "speed", "phi", "theta", "a", "b", "cue_mass",
                     "tip_restitution"})) {
    return false;
  }

  CueSpec cue;
  const std::string ball_path = "cue.ball";
  std::string id = "cue";
  const json* ball_v = find(*c, "ball");
  if (ball_v != nullptr) {
    if (!ball_v->is_string()) return fail(ball_path, expected("a ball id (a string)", *ball_v));
    id = ball_v->get<std::string>();
  }
  const auto it = index_of_.find(id);
  if (it == index_of_.end()) {
    return fail(ball_path, ball_v != nullptr
                               ? "no ball has the id '" + id + "'"
                               : "no ball has the id 'cue' (the default); name the ball struck");
  }
  cue.ball = it->second;
  const auto ub = static_cast<std::size_t>(cue.ball);
  // The strike sets the ball's velocity and spin: a motion given in the
  // file would be dropped without a word, so it is refused instead.
  if (s.start[ub].velocity != Vec2{} || s.start[ub].spin != Vec3{}) {
    return fail(ball_path, "ball '" + id +
                               "' has a velocity or spin; the ball a cue strikes must be at rest");
  }

  const json* speed = find(*c, "speed");
  const std::string speed_path = "cue.speed";
  if (speed == nullptr) return fail(speed_path, "missing required field");
  if (!number(*speed, speed_path, cue.strike.speed) ||
      !positive(cue.strike.speed, speed_path)) {
    return false;
  }
  if (!optional_number(*c, path, "phi", cue.strike.phi)) return false;
  const std::string theta_path = "cue.theta";
  if (!optional_number(*c, path, "theta", cue.strike.theta)) return false;
  if (!(cue.strike.theta >= 0.0 && cue.strike.theta < 90.0)) {
    return fail(theta_path, "the cue elevation must be in [0, 90) degrees, not " +
                                format_number(cue.strike.theta));
  }
  if (!optional_number(*c, path, "a", cue.strike.a) ||
      !optional_number(*c, path, "b", cue.strike.b)) {
    return false;
  }
  if (!optional_number(*c, path, "cue_mass", cue.params.mass) ||
      !positive(cue.params.mass, "cue.cue_mass")) {
    return false;
  }
  if (!optional_number(*c, path, "tip_restitution", cue.params.tip_restitution) ||
      !restitution(cue.params.tip_restitution, "cue.tip_restitution")) {
    return false;
  }
  s.cue = cue;
  return true;
}

}  // namespace breakshot::json_io
