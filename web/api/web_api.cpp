// The facade of the browser version (web/api/web_api.hpp, docs/web.md):
// the C API's entry points, each a call into the parts (facade.hpp), and
// bs_version with the engine's defaults. bs_simulate returns the engine's
// own result text (write_result).

#include "web_api.hpp"

#include "facade.hpp"

#include <cstdlib>
#include <memory>
#include <string>

#include "breakshot/ai.hpp"
#include "breakshot/ball.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/version.hpp"

using namespace facade;

// ---------------------------------------------------------------------------
// Defaults: the page's blank fields show them, and its balls take them.

namespace {

ojson friction_curve_json(const bs::FrictionCurve& k) {
  ojson j = ojson::object();
  j["a"] = k.a;
  j["b"] = k.b;
  j["c"] = k.c;
  return j;
}

/// default_physics(model), every field of PhysicsParams by its name, in
/// the struct's order (tests/physics_fields.hpp lists them; the facade's
/// test compares this reply with it).
ojson physics_defaults_json(bs::Model model) {
  const bs::PhysicsParams p = bs::default_physics(model);
  ojson j = ojson::object();
  j["model"] = std::string(bs::to_string(p.model));
  j["ball_ball_restitution"] = p.ball_ball_restitution;
  j["ball_ball_friction"] = p.ball_ball_friction;
  j["ball_ball_friction_fit"] = p.ball_ball_friction_fit;
  j["ball_ball_friction_curve"] = friction_curve_json(p.ball_ball_friction_curve);
  j["ball_ball_model"] = std::string(bs::to_string(p.ball_ball_model));
  j["gravity"] = p.gravity;
  j["deceleration"] = p.deceleration;
  j["sliding_friction"] = p.sliding_friction;
  j["rolling_friction"] = p.rolling_friction;
  j["spinning_friction"] = p.spinning_friction;
  j["collapse_speed"] = p.collapse_speed;
  j["ball_clusters"] = p.ball_clusters;
  j["airborne"] = p.airborne;
  j["slate_restitution"] = p.slate_restitution;
  j["min_bounce_height"] = p.min_bounce_height;
  return j;
}

/// default_physics for every model, the default ball and the pool
/// cushion's restitution (a pool ball's default wall restitution).
ojson defaults_json() {
  ojson j = ojson::object();
  ojson ball = ojson::object();
  ball["radius"] = bs::kPoolBallRadius;
  ball["mass"] = bs::kPoolBallMass;
  ball["wall_restitution"] = bs::BallSpec{}.wall_restitution;
  j["ball"] = ball;
  j["pool_cushion_restitution"] = bs::CushionParams{}.restitution;
  ojson physics = ojson::object();
  for (const bs::Model m : {bs::Model::ideal, bs::Model::friction, bs::Model::pool}) {
    physics[std::string(bs::to_string(m))] = physics_defaults_json(m);
  }
  j["physics"] = physics;
  return j;
}

}  // namespace

// ---------------------------------------------------------------------------
// The C API

extern "C" {

const char* bs_version(void) {
  static const std::string reply = [] {
    ojson j = ojson::object();
    j["version"] = std::string(bs::kVersion);
    ojson levels = ojson::array();
    ojson budgets = ojson::object();
    for (const std::string& l : bs::ai_level_names()) {
      levels.push_back(l);
      budgets[l] = web_budget(l);
    }
    j["levels"] = levels;
    j["ai_budgets"] = budgets;
    // The computer players of a snooker seat (facade::computer_players).
    ojson snooker = ojson::array();
    for (const std::string& p : computer_players(bs::GameType::snooker)) snooker.push_back(p);
    j["snooker_players"] = snooker;
    j["defaults"] = defaults_json();
    return j.dump();
  }();
  return reply.c_str();
}

const char* bs_game_players(const char* game) {
  static thread_local std::string reply;
  return keep(reply, guarded([&] { return players_json(game); }));
}

char* bs_simulate(const char* scenario_json) {
  return copy_out(guarded([&] {
    const bs::Scenario s = scenario_from(scenario_json);
    return bs::write_result(s, bs::simulate(s));
  }));
}

void bs_free(char* p) { std::free(p); }

BsPlayback* bs_playback_new(const char* scenario_json) {
  return guarded_new<BsPlayback>(
      [&] { return std::make_unique<BsPlayback>(scenario_from(scenario_json)); });
}

const char* bs_playback_frame(BsPlayback* pb, double t) {
  if (pb == nullptr) return null_handle();
  return keep(pb->reply, guarded([&] { return frame_json(*pb, t); }));
}

const double* bs_playback_frame_data(BsPlayback* pb, double t) {
  return guarded_ptr<const double>([&] {
    if (pb == nullptr) bad("handle", "a null handle");
    return frame_data(*pb, t);
  });
}

const double* bs_playback_spins(BsPlayback* pb) {
  return guarded_ptr<const double>([&] {
    if (pb == nullptr) bad("handle", "a null handle");
    return spins_data(*pb);
  });
}

const char* bs_playback_events(BsPlayback* pb, int from) {
  if (pb == nullptr) return null_handle();
  return keep(pb->reply, guarded([&] { return events_json(*pb, from); }));
}

const char* bs_playback_carom_count(BsPlayback* pb) {
  if (pb == nullptr) return null_handle();
  return keep(pb->reply, guarded([&] { return carom_count_json(*pb); }));
}

void bs_playback_free(BsPlayback* pb) { delete pb; }

BsGame* bs_game_new(const char* config_json) {
  return guarded_new<BsGame>([&] { return make_game(read_config(parse_text(config_json, "config"))); });
}

BsGame* bs_game_from_link(const char* link) {
  return guarded_new<BsGame>([&] { return game_from_link(link); });
}

const char* bs_game_table(BsGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return table_json(*g).dump(); }));
}

const char* bs_game_state(BsGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return state_json(*g).dump(); }));
}

const char* bs_game_check_placement(BsGame* g, double x, double y) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return check_placement_json(*g, x, y); }));
}

const char* bs_game_act(BsGame* g, const char* action_json_text) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return act_json(*g, action_json_text); }));
}

const char* bs_game_ai_action(BsGame* g, const char* level_or_null) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return ai_action_json(*g, level_or_null); }));
}

BsPlayback* bs_game_shot_playback(BsGame* g, int index) {
  return guarded_new<BsPlayback>([&] {
    if (g == nullptr) bad("handle", "a null handle");
    return shot_playback(*g, index);
  });
}

const char* bs_game_link(BsGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return link_json(*g); }));
}

const char* bs_game_record(BsGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return bs::write_record(g->record()); }));
}

const char* bs_game_turns(BsGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return turns_json(*g); }));
}

const char* bs_game_undo_to(BsGame* g, int n) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return undo_to_json(*g, n); }));
}

void bs_game_free(BsGame* g) { delete g; }

const char* bs_last_error(void) { return last_error(); }

}  // extern "C"
