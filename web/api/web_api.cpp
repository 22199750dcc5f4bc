// The facade of the browser version (web/api/web_api.hpp, docs/web.md):
// each entry point calls the C API (include/breakshot.h) and adapts its
// reply to the page's calling convention: JSON text, {"error"} for a
// failed call, and the last error of a call that returns NULL.

#include "web_api.hpp"

#include "facade.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace facade;

namespace {

// ---------------------------------------------------------------------------
// Version and defaults: the page's blank fields show them, and its balls
// take them.

/// A model's defaults as bs_physics_options_json gives them, in the
/// page's form: every field of PhysicsParams by its name, in the struct's
/// order (tests/physics_fields.hpp lists them; the facade's test compares
/// this reply with it), the friction curve as {"a", "b", "c"}.
ojson physics_defaults_json(const ojson& d) {
  ojson j = ojson::object();
  j["model"] = d.at("model");
  j["ball_ball_restitution"] = d.at("ball_ball_restitution");
  j["ball_ball_friction"] = d.at("ball_ball_friction");
  j["ball_ball_friction_fit"] = d.at("ball_ball_friction_fit");
  const ojson& curve = d.at("friction_curve");
  ojson k = ojson::object();
  k["a"] = curve.at(0);
  k["b"] = curve.at(1);
  k["c"] = curve.at(2);
  j["ball_ball_friction_curve"] = k;
  j["ball_ball_model"] = d.at("ball_ball_model");
  for (const char* f : {"gravity", "deceleration", "sliding_friction", "rolling_friction",
                        "spinning_friction", "collapse_speed", "ball_clusters", "airborne",
                        "slate_restitution", "min_bounce_height"}) {
    j[f] = d.at(f);
  }
  return j;
}

std::string version_json() {
  BsVersion v;
  check(bs_version(&v), nullptr);
  char* text = nullptr;
  check(bs_ai_levels_json(&text), nullptr);
  const ojson levels = ojson::parse(take(text));
  check(bs_game_players_json("snooker", &text), nullptr);
  const ojson snooker = ojson::parse(take(text));
  check(bs_physics_options_json(&text), nullptr);
  const ojson options = ojson::parse(take(text));
  ojson j = ojson::object();
  j["version"] = std::string(v.text);
  j["levels"] = levels.at("levels");
  j["ai_budgets"] = levels.at("budgets");
  // The computer players of a snooker seat.
  j["snooker_players"] = snooker.at("players");
  ojson defaults = ojson::object();
  defaults["ball"] = options.at("ball");
  defaults["pool_cushion_restitution"] = options.at("pool_cushion_restitution");
  ojson physics = ojson::object();
  for (const char* m : {"ideal", "friction", "pool"}) {
    physics[m] = physics_defaults_json(options.at("defaults").at(m));
  }
  defaults["physics"] = physics;
  j["defaults"] = defaults;
  return j.dump();
}

// ---------------------------------------------------------------------------
// Scenarios and playbacks

/// A scenario handle from the page's text (owned by the unique_ptr).
struct ScenarioFree {
  void operator()(BsScenario* s) const { bs_scenario_free(s); }
};
using ScenarioPtr = std::unique_ptr<BsScenario, ScenarioFree>;

ScenarioPtr scenario_from(const char* scenario_json) {
  if (scenario_json == nullptr) error("scenario: missing (a null pointer)");
  BsScenario* s = nullptr;
  check(bs_scenario_from_json(scenario_json, std::strlen(scenario_json), &s), nullptr);
  return ScenarioPtr(s);
}

std::string simulate_json(const char* scenario_json) {
  const ScenarioPtr s = scenario_from(scenario_json);
  char* text = nullptr;
  check(bs_simulate_result_json(s.get(), &text), s.get());
  return take(text);
}

const double* frame_data(BsWebPlayback& pb, double t) {
  const double* d = nullptr;
  std::size_t n = 0;
  check(bs_playback_frame(pb.pb, t, &d, &n), pb.pb);
  return d;
}

/// bs_web_playback_frame's reply: the frame's doubles as JSON.
std::string frame_json(BsWebPlayback& pb, double t) {
  const double* d = frame_data(pb, t);
  const auto n = static_cast<std::size_t>(d[7]);
  const std::size_t flight_at = BS_FRAME_HEADER + BS_FRAME_STRIDE * n;
  ojson j = ojson::object();
  j["t"] = d[0];
  const bool flight = d[flight_at] != 0.0;
  ojson balls = ojson::array();
  for (std::size_t i = 0; i < n; ++i) {
    const double* b = d + BS_FRAME_HEADER + BS_FRAME_STRIDE * i;
    ojson ball = ojson::array({b[0], b[1], b[2] != 0.0 ? 1 : 0, b[3], b[4], b[5], b[6], b[7]});
    if (flight) {
      const double* f = d + flight_at + 1 + BS_FLIGHT_STRIDE * i;
      ball.push_back(f[0]);
      ball.push_back(static_cast<int>(f[1]));
    }
    balls.push_back(std::move(ball));
  }
  j["balls"] = balls;
  j["energy"] = d[4];
  j["momentum"] = ojson::array({d[5], d[6]});
  j["events"] = static_cast<std::size_t>(d[1]);
  j["at_rest"] = d[2] != 0.0;
  j["complete"] = d[3] != 0.0;
  return j.dump();
}

/// The balls' states at the playback's time, into pb.states.
void read_states(BsWebPlayback& pb) {
  BsPlaybackInfo info;
  check(bs_playback_info(pb.pb, &info), pb.pb);
  pb.states.resize(info.balls);
  check(bs_playback_states(pb.pb, pb.states.data(), info.balls), pb.pb);
}

const double* spins_data(BsWebPlayback& pb) {
  read_states(pb);
  const std::size_t n = pb.states.size();
  pb.values.assign(3 * n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 3; ++k) pb.values[3 * i + k] = pb.states[i].spin[k];
  }
  return pb.values.data();
}

const double* motions_data(BsWebPlayback& pb) {
  read_states(pb);
  const std::size_t n = pb.states.size();
  pb.values.assign(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) pb.values[i] = static_cast<double>(pb.states[i].motion);
  return pb.values.data();
}

std::string events_json(BsWebPlayback& pb, int from) {
  if (from < 0) {
    BsPlaybackInfo info;
    check(bs_playback_info(pb.pb, &info), pb.pb);
    error("from: must be in [0, " + std::to_string(info.events) + "], not " +
          std::to_string(from));
  }
  char* text = nullptr;
  check(bs_playback_events_json(pb.pb, static_cast<std::size_t>(from), &text), pb.pb);
  return take(text);
}

std::string carom_count_json(BsWebPlayback& pb) {
  char* text = nullptr;
  check(bs_playback_carom_count_json(pb.pb, &text), pb.pb);
  return take(text);
}

// ---------------------------------------------------------------------------
// Games

/// A reply of the C API on the game (a char** call).
template <class F>
std::string game_text(const BsWebGame& g, F&& call) {
  char* text = nullptr;
  check(call(g.game, &text), g.game);
  return take(text);
}

/// The page's state: the state as records write it, then the seats, the
/// number of actions, what the rules allow next and the game's figures.
std::string state_json(const BsWebGame& g) {
  std::string s = game_text(g, bs_game_state_json);
  BsGameInfo info;
  check(bs_game_info(g.game, &info), g.game);
  const char* seats[2] = {nullptr, nullptr};
  for (std::int32_t k = 0; k < 2; ++k) check(bs_game_seat(g.game, k, &seats[k]), g.game);
  s.pop_back();  // the object's '}': the page's fields follow
  s += ",\"players\":" + ojson::array({seats[0], seats[1]}).dump();
  s += ",\"actions\":" + std::to_string(info.actions);
  s += ",\"legal\":" + game_text(g, bs_game_legal_actions_json);
  // The figures of the game's kind; another game's call says BS_ERROR_STATE.
  char* text = nullptr;
  BsStatus st = bs_game_snooker_figures_json(g.game, &text);
  if (st == BS_OK) s += ",\"snooker_figures\":" + take(text);
  if (st != BS_OK && st != BS_ERROR_STATE) check(st, g.game);
  st = bs_game_carom_figures_json(g.game, &text);
  if (st == BS_OK) s += ",\"carom_figures\":" + take(text);
  if (st != BS_OK && st != BS_ERROR_STATE) check(st, g.game);
  s += '}';
  return s;
}

std::string check_placement_json(const BsWebGame& g, double x, double y) {
  const BsStatus st = bs_game_check_placement(g.game, x, y);
  ojson j = ojson::object();
  if (st == BS_OK) {
    j["ok"] = true;
  } else if (st == BS_ERROR_ILLEGAL) {
    j["ok"] = false;
    j["reason"] = std::string(bs_error_message(g.game));
  } else {
    check(st, g.game);
  }
  return j.dump();
}

std::string act_json(const BsWebGame& g, const char* action) {
  char* text = nullptr;
  check(bs_game_act_json(g.game, action, action == nullptr ? 0 : std::strlen(action), &text),
        g.game);
  std::string s = take(text);
  s.pop_back();
  s += ",\"state\":" + state_json(g) + '}';
  return s;
}

std::string ai_action_json(const BsWebGame& g, const char* level) {
  BsPlayer* p = nullptr;
  check(bs_player_new_for_game(g.game, level, &p), g.game);
  char* text = nullptr;
  const BsStatus st = bs_player_decide_json(p, g.game, &text);
  if (st != BS_OK) {
    const std::string message = bs_error_message(p);
    bs_player_free(p);
    error(message);
  }
  bs_player_free(p);
  return "{\"action\":" + take(text) + "}";
}

BsWebPlayback* shot_playback(const BsWebGame& g, int index) {
  if (index < 0) {
    BsGameInfo info;
    check(bs_game_info(g.game, &info), g.game);
    error("index: must be in [0, " + std::to_string(info.actions) + "), not " +
          std::to_string(index));
  }
  BsPlayback* pb = nullptr;
  check(bs_game_shot_playback(g.game, static_cast<std::size_t>(index), &pb), g.game);
  return new BsWebPlayback(pb);
}

std::string link_json(const BsWebGame& g) {
  ojson j = ojson::object();
  j["link"] = game_text(g, bs_game_link);
  return j.dump();
}

std::string undo_to_json(const BsWebGame& g, int n) {
  if (n < 0) {
    BsGameInfo info;
    check(bs_game_info(g.game, &info), g.game);
    error("n: must be in [0, " + std::to_string(info.actions) + "], not " + std::to_string(n));
  }
  check(bs_game_undo_to(g.game, static_cast<std::size_t>(n)), g.game);
  return state_json(g);
}

BsWebGame* new_game(BsStatus status, BsGame* game) {
  check(status, nullptr);
  return new BsWebGame(game);
}

}  // namespace

// ---------------------------------------------------------------------------
// The entry points

extern "C" {

const char* bs_web_version(void) {
  static const std::string reply = guarded(version_json);
  return reply.c_str();
}

const char* bs_web_game_players(const char* game) {
  static thread_local std::string reply;
  return keep(reply, guarded([&] {
                char* text = nullptr;
                check(bs_game_players_json(game, &text), nullptr);
                return take(text);
              }));
}

char* bs_web_simulate(const char* scenario_json) {
  return copy_out(guarded([&] { return simulate_json(scenario_json); }));
}

void bs_web_free(char* p) { std::free(p); }

BsWebPlayback* bs_web_playback_new(const char* scenario_json) {
  return guarded_ptr<BsWebPlayback>([&] {
    const ScenarioPtr s = scenario_from(scenario_json);
    BsPlayback* pb = nullptr;
    check(bs_playback_new(s.get(), &pb), s.get());
    return new BsWebPlayback(pb);
  });
}

const char* bs_web_playback_frame(BsWebPlayback* pb, double t) {
  if (pb == nullptr) return null_handle();
  return keep(pb->reply, guarded([&] { return frame_json(*pb, t); }));
}

const double* bs_web_playback_frame_data(BsWebPlayback* pb, double t) {
  return guarded_ptr<const double>([&] {
    if (pb == nullptr) error("handle: a null handle");
    return frame_data(*pb, t);
  });
}

const double* bs_web_playback_spins(BsWebPlayback* pb) {
  return guarded_ptr<const double>([&] {
    if (pb == nullptr) error("handle: a null handle");
    return spins_data(*pb);
  });
}

const double* bs_web_playback_motions(BsWebPlayback* pb) {
  return guarded_ptr<const double>([&] {
    if (pb == nullptr) error("handle: a null handle");
    return motions_data(*pb);
  });
}

const char* bs_web_playback_events(BsWebPlayback* pb, int from) {
  if (pb == nullptr) return null_handle();
  return keep(pb->reply, guarded([&] { return events_json(*pb, from); }));
}

const char* bs_web_playback_carom_count(BsWebPlayback* pb) {
  if (pb == nullptr) return null_handle();
  return keep(pb->reply, guarded([&] { return carom_count_json(*pb); }));
}

void bs_web_playback_free(BsWebPlayback* pb) { delete pb; }

BsWebGame* bs_web_game_new(const char* config_json) {
  return guarded_ptr<BsWebGame>([&] {
    BsGame* g = nullptr;
    const BsStatus st = bs_game_new_json(
        config_json, config_json == nullptr ? 0 : std::strlen(config_json), &g);
    return new_game(st, g);
  });
}

BsWebGame* bs_web_game_from_link(const char* link) {
  return guarded_ptr<BsWebGame>([&] {
    BsGame* g = nullptr;
    const BsStatus st = bs_game_from_link(link, link == nullptr ? 0 : std::strlen(link), &g);
    return new_game(st, g);
  });
}

const char* bs_web_game_table(BsWebGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return game_text(*g, bs_game_table_json); }));
}

const char* bs_web_game_state(BsWebGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return state_json(*g); }));
}

const char* bs_web_game_check_placement(BsWebGame* g, double x, double y) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return check_placement_json(*g, x, y); }));
}

const char* bs_web_game_act(BsWebGame* g, const char* action_json) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return act_json(*g, action_json); }));
}

const char* bs_web_game_ai_action(BsWebGame* g, const char* level_or_null) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return ai_action_json(*g, level_or_null); }));
}

BsWebPlayback* bs_web_game_shot_playback(BsWebGame* g, int index) {
  return guarded_ptr<BsWebPlayback>([&] {
    if (g == nullptr) error("handle: a null handle");
    return shot_playback(*g, index);
  });
}

const char* bs_web_game_link(BsWebGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return link_json(*g); }));
}

const char* bs_web_game_record(BsWebGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return game_text(*g, bs_game_record_json); }));
}

const char* bs_web_game_turns(BsWebGame* g) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return game_text(*g, bs_game_turns_json); }));
}

const char* bs_web_game_undo_to(BsWebGame* g, int n) {
  if (g == nullptr) return null_handle();
  return keep(g->reply, guarded([&] { return undo_to_json(*g, n); }));
}

void bs_web_game_free(BsWebGame* g) { delete g; }

const char* bs_web_last_error(void) { return last_error(); }

}  // extern "C"
