// The C API's status names, errors, strings, version and physics options
// (include/breakshot.h).

#include "capi.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

#include "breakshot.h"
#include "breakshot/ball.hpp"
#include "breakshot/game.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/players.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/version.hpp"

namespace capi {

std::string& thread_error() {
  thread_local std::string message;
  return message;
}

char* copy_out(const std::string& s) {
  char* p = static_cast<char*>(std::malloc(s.size() + 1));
  if (p == nullptr) throw std::bad_alloc();
  std::memcpy(p, s.c_str(), s.size() + 1);
  return p;
}

std::string text_arg(const char* text, std::size_t len, const char* what) {
  need(text, what);
  return std::string(text, len);
}

namespace {

int version_part(std::size_t k) {
  const std::string_view v = bs::kVersion;
  std::size_t start = 0;
  for (std::size_t i = 0; i < k; ++i) start = v.find('.', start) + 1;
  int n = 0;
  for (std::size_t i = start; i < v.size() && v[i] != '.'; ++i) n = n * 10 + (v[i] - '0');
  return n;
}

nlohmann::ordered_json defaults_json(bs::Model m) {
  const bs::PhysicsParams p = bs::default_physics(m);
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  j["model"] = std::string(bs::to_string(p.model));
  j["ball_ball_model"] = std::string(bs::to_string(p.ball_ball_model));
  j["ball_ball_restitution"] = p.ball_ball_restitution;
  j["ball_ball_friction_fit"] = p.ball_ball_friction_fit;
  j["ball_clusters"] = p.ball_clusters;
  j["ball_ball_friction"] = p.ball_ball_friction;
  j["friction_curve"] = {p.ball_ball_friction_curve.a, p.ball_ball_friction_curve.b,
                         p.ball_ball_friction_curve.c};
  j["gravity"] = p.gravity;
  j["deceleration"] = p.deceleration;
  j["sliding_friction"] = p.sliding_friction;
  j["rolling_friction"] = p.rolling_friction;
  j["spinning_friction"] = p.spinning_friction;
  j["collapse_speed"] = p.collapse_speed;
  j["airborne"] = p.airborne;
  j["slate_restitution"] = p.slate_restitution;
  j["min_bounce_height"] = p.min_bounce_height;
  return j;
}

}  // namespace

}  // namespace capi

using namespace capi;

extern "C" {

const char* bs_status_name(BsStatus status) {
  const long long value = raw(status);
  if (value < BS_OK || value > BS_ERROR_INTERNAL) return "BS_UNKNOWN_STATUS";
  switch (static_cast<BsStatus>(value)) {
    case BS_OK:
      return "BS_OK";
    case BS_ERROR_NULL:
      return "BS_ERROR_NULL";
    case BS_ERROR_BAD_HANDLE:
      return "BS_ERROR_BAD_HANDLE";
    case BS_ERROR_BAD_JSON:
      return "BS_ERROR_BAD_JSON";
    case BS_ERROR_OUT_OF_RANGE:
      return "BS_ERROR_OUT_OF_RANGE";
    case BS_ERROR_INVALID:
      return "BS_ERROR_INVALID";
    case BS_ERROR_ILLEGAL:
      return "BS_ERROR_ILLEGAL";
    case BS_ERROR_STATE:
      return "BS_ERROR_STATE";
    case BS_ERROR_NO_MEMORY:
      return "BS_ERROR_NO_MEMORY";
    case BS_ERROR_INTERNAL:
      return "BS_ERROR_INTERNAL";
  }
  return "BS_UNKNOWN_STATUS";
}

const char* bs_error_message(const void* handle) {
  if (handle == nullptr) return thread_error().c_str();
  const auto* h = static_cast<const Handle*>(handle);
  switch (h->tag) {
    case kScenarioTag:
    case kSimulationTag:
    case kGameTag:
    case kPlayerTag:
    case kPlaybackTag:
      return h->error.c_str();
    default:
      return "bs_error_message: not a live handle of this API";
  }
}

void bs_string_free(char* text) { std::free(text); }

BsStatus bs_version(BsVersion* out) {
  return on_thread([&] {
    need(out, "out");
    out->major = version_part(0);
    out->minor = version_part(1);
    out->patch = version_part(2);
    out->api = BS_API_VERSION;
    static const std::string text(bs::kVersion);
    out->text = text.c_str();
  });
}

BsStatus bs_physics_options_json(char** out) {
  return on_thread([&] {
    need(out, "out");
    *out = nullptr;
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    j["version"] = std::string(bs::kVersion);
    j["api"] = BS_API_VERSION;
    j["models"] = {"ideal", "friction", "pool"};
    nlohmann::ordered_json cushions = nlohmann::ordered_json::array();
    for (const bs::CushionModel m : bs::kCushionModels) {
      cushions.push_back(std::string(bs::cushion_model_name(m)));
    }
    j["cushion_models"] = cushions;
    j["ball_ball_models"] = {std::string(bs::to_string(bs::BallBallModel::friction)),
                             std::string(bs::to_string(bs::BallBallModel::mathavan_2014))};
    j["table_shapes"] = {"rectangle", "polygon", "pool", "snooker", "carom"};
    j["pool_table_sizes"] = {"7ft", "8ft", "9ft"};
    j["games"] = bs::game_type_names();
    j["players"] = bs::player_names();
    nlohmann::ordered_json d = nlohmann::ordered_json::object();
    for (const bs::Model m : {bs::Model::ideal, bs::Model::friction, bs::Model::pool}) {
      d[std::string(bs::to_string(m))] = defaults_json(m);
    }
    j["defaults"] = d;
    // What a ball's NaN radius, mass and wall restitution take, and a pool
    // table's cushion restitution.
    nlohmann::ordered_json ball = nlohmann::ordered_json::object();
    ball["radius"] = bs::kPoolBallRadius;
    ball["mass"] = bs::kPoolBallMass;
    ball["wall_restitution"] = bs::BallSpec{}.wall_restitution;
    j["ball"] = ball;
    j["pool_cushion_restitution"] = bs::CushionParams{}.restitution;
    *out = copy_out(j.dump());
  });
}

}  // extern "C"
