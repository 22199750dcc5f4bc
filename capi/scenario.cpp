// Scenarios (BsScenario): a document in the scenario format, built by
// calls or read from text, and read by the scenario reader (io) when it is
// simulated, so that every default, check and message is the format's own.
// The scenario read is kept until the document changes.

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <variant>

#include "breakshot.h"
#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "capi.hpp"
#include "io/json_read.hpp"
#include "io/scenario_json.hpp"

namespace capi {

namespace {

void finite(double x, const std::string& path) {
  if (!std::isfinite(x)) fail(BS_ERROR_OUT_OF_RANGE, path + ": not a finite number");
}

bs::Model model_of(std::int32_t m, const std::string& path) {
  if (m < BS_MODEL_IDEAL || m > BS_MODEL_POOL) {
    fail(BS_ERROR_OUT_OF_RANGE,
         path + ": not a BsModel (0 ideal, 1 friction, 2 pool), but " + std::to_string(m));
  }
  return static_cast<bs::Model>(m);
}

void flag(std::int32_t v, const std::string& path) {
  if (v != 0 && v != 1) {
    fail(BS_ERROR_OUT_OF_RANGE, path + ": must be 0 or 1, not " + std::to_string(v));
  }
}

/// The physics as the scenario format's "physics" object.
json physics_doc(const BsPhysics& p) {
  const bs::Model model = model_of(p.model, "physics.model");
  if (p.ball_ball_model != BS_BALL_BALL_FRICTION &&
      p.ball_ball_model != BS_BALL_BALL_MATHAVAN_2014) {
    fail(BS_ERROR_OUT_OF_RANGE,
         "physics.ball_ball_model: not a BsBallBallModel (0 friction, 1 mathavan_2014), but " +
             std::to_string(p.ball_ball_model));
  }
  flag(p.ball_ball_friction_fit, "physics.ball_ball_friction_fit");
  flag(p.ball_clusters, "physics.ball_clusters");
  flag(p.airborne, "physics.airborne");
  const std::pair<const char*, double> numbers[] = {
      {"ball_ball_restitution", p.ball_ball_restitution},
      {"ball_ball_friction", p.ball_ball_friction},
      {"friction_curve[0]", p.friction_curve[0]},
      {"friction_curve[1]", p.friction_curve[1]},
      {"friction_curve[2]", p.friction_curve[2]},
      {"gravity", p.gravity},
      {"deceleration", p.deceleration},
      {"sliding_friction", p.sliding_friction},
      {"rolling_friction", p.rolling_friction},
      {"spinning_friction", p.spinning_friction},
      {"collapse_speed", p.collapse_speed},
      {"slate_restitution", p.slate_restitution},
      {"min_bounce_height", p.min_bounce_height}};
  for (const auto& [name, value] : numbers) finite(value, std::string("physics.") + name);

  json j = json::object();
  j["model"] = std::string(bs::to_string(model));
  j["ball_ball_restitution"] = p.ball_ball_restitution;
  if (p.ball_ball_friction_fit != 0) {
    j["ball_ball_friction"] = {
        {"a", p.friction_curve[0]}, {"b", p.friction_curve[1]}, {"c", p.friction_curve[2]}};
  } else {
    j["ball_ball_friction"] = p.ball_ball_friction;
  }
  j["gravity"] = p.gravity;
  j["deceleration"] = p.deceleration;
  j["sliding_friction"] = p.sliding_friction;
  j["rolling_friction"] = p.rolling_friction;
  j["spinning_friction"] = p.spinning_friction;
  j["collapse_speed"] = p.collapse_speed;
  j["ball_clusters"] = p.ball_clusters != 0;
  j["ball_ball_model"] = p.ball_ball_model == BS_BALL_BALL_FRICTION ? "friction" : "mathavan_2014";
  j["airborne"] = p.airborne != 0;
  // The format takes these only with airborne balls.
  if (p.airborne != 0) {
    j["slate_restitution"] = p.slate_restitution;
    j["min_bounce_height"] = p.min_bounce_height;
  }
  return j;
}

/// The table as the scenario format's "table" object.
json table_doc(const BsTable& t) {
  json j = json::object();
  switch (t.shape) {
    case BS_TABLE_RECTANGLE:
      for (int k = 0; k < 2; ++k) {
        finite(t.min[k], "table.min[" + std::to_string(k) + "]");
        finite(t.max[k], "table.max[" + std::to_string(k) + "]");
      }
      j["shape"] = "rectangle";
      j["min"] = {t.min[0], t.min[1]};
      j["max"] = {t.max[0], t.max[1]};
      break;
    case BS_TABLE_POLYGON: {
      if (t.vertex_count > 0) need(t.vertices, "table.vertices");
      if (t.vertex_count > 1'000'000) {
        fail(BS_ERROR_OUT_OF_RANGE,
             "table.vertex_count: at most 1000000, not " + std::to_string(t.vertex_count));
      }
      json v = json::array();
      for (std::size_t k = 0; k < t.vertex_count; ++k) {
        finite(t.vertices[2 * k], "table.vertices[" + std::to_string(k) + "][0]");
        finite(t.vertices[2 * k + 1], "table.vertices[" + std::to_string(k) + "][1]");
        v.push_back({t.vertices[2 * k], t.vertices[2 * k + 1]});
      }
      j["shape"] = "polygon";
      j["vertices"] = std::move(v);
      break;
    }
    case BS_TABLE_POOL:
      j["shape"] = "pool";
      j["size"] = t.size == nullptr ? "9ft" : t.size;
      break;
    case BS_TABLE_SNOOKER:
      j["shape"] = "snooker";
      break;
    case BS_TABLE_CAROM:
      j["shape"] = "carom";
      break;
    default:
      fail(BS_ERROR_OUT_OF_RANGE,
           "table.shape: not a BsTableShape (0 rectangle, 1 polygon, 2 pool, 3 snooker, 4 "
           "carom), but " +
               std::to_string(t.shape));
  }
  if (t.cushion_model != BS_CUSHION_DEFAULT) {
    bs::CushionModel m{};
    if (t.cushion_model < 0 || t.cushion_model > BS_CUSHION_STRONGE_COMPLIANT ||
        !bs::is_cushion_model(m = static_cast<bs::CushionModel>(t.cushion_model))) {
      fail(BS_ERROR_OUT_OF_RANGE, "table.cushion_model: not a BsCushionModel (-1 to 4), but " +
                                      std::to_string(t.cushion_model));
    }
    j["cushion_model"] = std::string(bs::cushion_model_name(m));
  }
  // NaN: the format's default (the field is left out).
  const std::pair<const char*, double> options[] = {
      {"cushion_restitution", t.cushion_restitution},
      {"cushion_friction", t.cushion_friction},
      {"nose_height", t.nose_height},
      {"cushion_height", t.cushion_height},
      {"cushion_compliance_ratio", t.cushion_compliance_ratio}};
  for (const auto& [name, value] : options) {
    if (std::isnan(value)) continue;
    finite(value, std::string("table.") + name);
    j[name] = value;
  }
  return j;
}

/// Reads `doc`; a problem at a path that starts with `part` ("physics",
/// "table") is thrown as BS_ERROR_OUT_OF_RANGE, any other ignored: how a
/// setter checks its part before the rest of the scenario exists.
void check_part(const json& doc, const std::string& part) {
  auto read = bs::json_io::read_scenario_tree(doc);
  if (const auto* e = std::get_if<bs::ScenarioError>(&read)) {
    if (e->path.compare(0, part.size(), part) == 0) {
      fail(BS_ERROR_OUT_OF_RANGE, e->path + ": " + e->reason);
    }
  }
}

/// A probe scenario: `physics` and `table`, no balls, a run to a time.
json probe(const json& physics, const json& table) {
  json doc = json::object();
  doc["physics"] = physics;
  doc["table"] = table;
  doc["balls"] = json::array();
  doc["until"] = {{"time", 1.0}};
  return doc;
}

json default_physics_doc() {
  BsPhysics p;
  (void)bs_physics_default(BS_MODEL_IDEAL, &p);
  return physics_doc(p);
}

json default_table_doc() {
  return {{"shape", "rectangle"}, {"min", {-1.0, -1.0}}, {"max", {1.0, 1.0}}};
}

/// The document changed: the scenario read from it is stale.
json& edit(BsScenario& s) {
  s.read.reset();
  return s.doc;
}

void ball_state_fields(const BsBall& b, json& j) {
  finite(b.position[0], "ball.position[0]");
  finite(b.position[1], "ball.position[1]");
  for (int k = 0; k < 3; ++k) {
    finite(b.velocity[k], "ball.velocity[" + std::to_string(k) + "]");
    finite(b.spin[k], "ball.spin[" + std::to_string(k) + "]");
  }
  j["position"] = {b.position[0], b.position[1]};
  if (b.velocity[2] != 0.0) {
    j["velocity"] = {b.velocity[0], b.velocity[1], b.velocity[2]};
  } else {
    j["velocity"] = {b.velocity[0], b.velocity[1]};
  }
  if (b.spin[0] != 0.0 || b.spin[1] != 0.0 || b.spin[2] != 0.0) {
    j["spin"] = {b.spin[0], b.spin[1], b.spin[2]};
  }
}

}  // namespace

std::shared_ptr<const bs::Scenario> shared_scenario_of(const BsScenario& s) {
  if (!s.read) {
    auto read = bs::json_io::read_scenario_tree(s.doc);
    if (auto* e = std::get_if<bs::ScenarioError>(&read)) {
      fail(BS_ERROR_INVALID,
           e->path + ": " + (e->unsupported ? "not supported: " : "") + e->reason);
    }
    s.read = std::make_shared<const bs::Scenario>(std::get<bs::Scenario>(std::move(read)));
  }
  return s.read;
}

const bs::Scenario& scenario_of(const BsScenario& s) { return *shared_scenario_of(s); }

}  // namespace capi

using namespace capi;

extern "C" {

BsStatus bs_physics_default(BsModel model, BsPhysics* out) {
  return on_thread([&] {
    need(out, "out");
    const bs::PhysicsParams p =
        bs::default_physics(model_of(static_cast<std::int32_t>(raw(model)), "model"));
    *out = BsPhysics{};
    out->model = static_cast<std::int32_t>(p.model);
    out->ball_ball_model = static_cast<std::int32_t>(p.ball_ball_model);
    out->ball_ball_restitution = p.ball_ball_restitution;
    out->ball_ball_friction_fit = p.ball_ball_friction_fit ? 1 : 0;
    out->ball_clusters = p.ball_clusters ? 1 : 0;
    out->ball_ball_friction = p.ball_ball_friction;
    out->friction_curve[0] = p.ball_ball_friction_curve.a;
    out->friction_curve[1] = p.ball_ball_friction_curve.b;
    out->friction_curve[2] = p.ball_ball_friction_curve.c;
    out->gravity = p.gravity;
    out->deceleration = p.deceleration;
    out->sliding_friction = p.sliding_friction;
    out->rolling_friction = p.rolling_friction;
    out->spinning_friction = p.spinning_friction;
    out->collapse_speed = p.collapse_speed;
    out->airborne = p.airborne ? 1 : 0;
    out->slate_restitution = p.slate_restitution;
    out->min_bounce_height = p.min_bounce_height;
  });
}

BsStatus bs_table_default(BsTableShape shape, BsTable* out) {
  return on_thread([&] {
    need(out, "out");
    if (raw(shape) < BS_TABLE_RECTANGLE || raw(shape) > BS_TABLE_CAROM) {
      fail(BS_ERROR_OUT_OF_RANGE,
           "shape: not a BsTableShape (0 to 4), but " + std::to_string(raw(shape)));
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    *out = BsTable{};
    out->shape = shape;
    out->cushion_model = BS_CUSHION_DEFAULT;
    out->min[0] = out->min[1] = -1.0;
    out->max[0] = out->max[1] = 1.0;
    out->vertices = nullptr;
    out->vertex_count = 0;
    out->size = shape == BS_TABLE_POOL ? "9ft" : nullptr;
    out->cushion_restitution = nan;
    out->cushion_friction = nan;
    out->nose_height = nan;
    out->cushion_height = nan;
    out->cushion_compliance_ratio = nan;
  });
}

BsStatus bs_ball_default(BsBall* out) {
  return on_thread([&] {
    need(out, "out");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    *out = BsBall{};
    out->id = nullptr;
    out->radius = nan;
    out->mass = nan;
    out->wall_restitution = nan;
  });
}

BsStatus bs_scenario_new(BsScenario** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    auto s = std::make_unique<BsScenario>();
    s->doc["physics"] = default_physics_doc();
    *out = s.release();
  });
}

BsStatus bs_scenario_from_json(const char* text, std::size_t len, BsScenario** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    const std::string t = text_arg(text, len, "text");
    auto s = std::make_unique<BsScenario>();
    bs::json_io::ParseOptions options;
    options.free_key = "extra";
    if (auto problem = bs::json_io::parse_strict(t, s->doc, options)) {
      fail(problem->syntax ? BS_ERROR_BAD_JSON : BS_ERROR_INVALID,
           problem->error.path + ": " + problem->error.reason);
    }
    (void)scenario_of(*s);
    *out = s.release();
  });
}

BsStatus bs_scenario_clone(const BsScenario* scenario, BsScenario** out) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](const BsScenario& s) {
    need(out, "out");
    *out = nullptr;
    auto c = std::make_unique<BsScenario>();
    c->doc = s.doc;
    c->read = s.read;
    *out = c.release();
  });
}

void bs_scenario_free(BsScenario* scenario) {
  if (scenario == nullptr || scenario->tag != kScenarioTag) return;
  scenario->tag = kFreed;
  delete scenario;
}

BsStatus bs_scenario_set_physics(BsScenario* scenario, const BsPhysics* physics) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](BsScenario& s) {
    need(physics, "physics");
    json p = physics_doc(*physics);
    const json* table = bs::json_io::Reader::find(s.doc, "table");
    check_part(probe(p, table != nullptr ? *table : default_table_doc()), "physics");
    edit(s)["physics"] = std::move(p);
  });
}

BsStatus bs_scenario_set_table(BsScenario* scenario, const BsTable* table) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](BsScenario& s) {
    need(table, "table");
    json t = table_doc(*table);
    const json* physics = bs::json_io::Reader::find(s.doc, "physics");
    check_part(probe(physics != nullptr ? *physics : default_physics_doc(), t), "table");
    edit(s)["table"] = std::move(t);
  });
}

BsStatus bs_scenario_add_ball(BsScenario* scenario, const BsBall* ball, std::size_t* index) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](BsScenario& s) {
    need(ball, "ball");
    need(ball->id, "ball.id");
    json b = json::object();
    b["id"] = ball->id;
    ball_state_fields(*ball, b);
    const std::pair<const char*, double> options[] = {{"radius", ball->radius},
                                                      {"mass", ball->mass},
                                                      {"wall_restitution", ball->wall_restitution}};
    for (const auto& [name, value] : options) {
      if (std::isnan(value)) continue;
      finite(value, std::string("ball.") + name);
      b[name] = value;
    }
    json& balls = edit(s)["balls"];
    if (!balls.is_array()) balls = json::array();
    if (index != nullptr) *index = balls.size();
    balls.push_back(std::move(b));
  });
}

BsStatus bs_scenario_set_rack(BsScenario* scenario, const char* game, std::uint64_t seed) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](BsScenario& s) {
    if (game == nullptr) {
      edit(s).erase("rack");
      return;
    }
    edit(s)["rack"] = {{"game", game}, {"seed", seed}};
  });
}

BsStatus bs_scenario_set_pair_restitution(BsScenario* scenario, const char* ball_a,
                                          const char* ball_b, double restitution) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](BsScenario& s) {
    need(ball_a, "ball_a");
    need(ball_b, "ball_b");
    finite(restitution, "restitution");
    json& pairs = edit(s)["pair_restitution"];
    if (!pairs.is_array()) pairs = json::array();
    pairs.push_back({{"balls", {ball_a, ball_b}}, {"restitution", restitution}});
  });
}

BsStatus bs_scenario_set_until_time(BsScenario* scenario, double t) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](BsScenario& s) {
    finite(t, "t");
    edit(s)["until"] = {{"time", t}};
  });
}

BsStatus bs_scenario_set_until_rest(BsScenario* scenario) {
  return on_handle(scenario, kScenarioTag, "scenario",
                   [&](BsScenario& s) { edit(s)["until"] = "rest"; });
}

BsStatus bs_scenario_set_max_events(BsScenario* scenario, std::uint64_t max_events) {
  return on_handle(scenario, kScenarioTag, "scenario",
                   [&](BsScenario& s) { edit(s)["max_events"] = max_events; });
}

BsStatus bs_scenario_strike(BsScenario* scenario, const char* ball_id, const BsStrike* strike) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](BsScenario& s) {
    if (strike == nullptr) {
      edit(s).erase("cue");
      return;
    }
    need(ball_id, "ball_id");
    finite(strike->speed, "strike.speed");
    finite(strike->phi, "strike.phi");
    finite(strike->theta, "strike.theta");
    finite(strike->a, "strike.a");
    finite(strike->b, "strike.b");
    edit(s)["cue"] = {{"ball", ball_id},        {"speed", strike->speed}, {"phi", strike->phi},
                      {"theta", strike->theta}, {"a", strike->a},         {"b", strike->b}};
  });
}

BsStatus bs_scenario_validate(const BsScenario* scenario) {
  return on_handle(scenario, kScenarioTag, "scenario",
                   [&](const BsScenario& s) { (void)scenario_of(s); });
}

BsStatus bs_scenario_ball_count(const BsScenario* scenario, std::size_t* out) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](const BsScenario& s) {
    need(out, "out");
    *out = scenario_of(s).balls.size();
  });
}

BsStatus bs_scenario_to_json(const BsScenario* scenario, char** out) {
  return on_handle(scenario, kScenarioTag, "scenario", [&](const BsScenario& s) {
    need(out, "out");
    *out = nullptr;
    *out = copy_out(s.doc.dump());
  });
}

}  // extern "C"
