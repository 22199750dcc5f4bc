// Every field of PhysicsParams (physics.hpp), by the name the web facade's
// defaults reply (bs_version) gives it, for tests that compare physics
// field by field. A field added to PhysicsParams and not listed here
// fails to compile (the static_assert below counts the struct's fields),
// so no comparison can leave one out.
#pragma once

#include <cstddef>
#include <iterator>
#include <variant>

#include "breakshot/physics.hpp"

namespace physics_fields {

using breakshot::PhysicsParams;

/// Converts to any field's type: counts an aggregate's fields.
struct AnyField {
  template <class T>
  constexpr operator T() const {  // NOLINT(google-explicit-constructor)
    return T{};
  }
};

/// The number of fields of aggregate T: the most AnyFields T{...} takes.
template <class T, class... A>
constexpr std::size_t field_count() {
  if constexpr (requires { T{A{}..., AnyField{}}; }) {
    return field_count<T, A..., AnyField>();
  } else {
    return sizeof...(A);
  }
}

using Member =
    std::variant<double PhysicsParams::*, bool PhysicsParams::*, breakshot::Model PhysicsParams::*,
                 breakshot::BallBallModel PhysicsParams::*,
                 breakshot::FrictionCurve PhysicsParams::*>;

struct Field {
  const char* name;
  Member member;
};

/// PhysicsParams's fields in declaration order.
inline constexpr Field kFields[] = {
    {"model", &PhysicsParams::model},
    {"ball_ball_restitution", &PhysicsParams::ball_ball_restitution},
    {"ball_ball_friction", &PhysicsParams::ball_ball_friction},
    {"ball_ball_friction_fit", &PhysicsParams::ball_ball_friction_fit},
    {"ball_ball_friction_curve", &PhysicsParams::ball_ball_friction_curve},
    {"ball_ball_model", &PhysicsParams::ball_ball_model},
    {"gravity", &PhysicsParams::gravity},
    {"deceleration", &PhysicsParams::deceleration},
    {"sliding_friction", &PhysicsParams::sliding_friction},
    {"rolling_friction", &PhysicsParams::rolling_friction},
    {"spinning_friction", &PhysicsParams::spinning_friction},
    {"collapse_speed", &PhysicsParams::collapse_speed},
    {"ball_clusters", &PhysicsParams::ball_clusters},
    {"airborne", &PhysicsParams::airborne},
    {"slate_restitution", &PhysicsParams::slate_restitution},
    {"min_bounce_height", &PhysicsParams::min_bounce_height},
};

static_assert(field_count<PhysicsParams>() == 16,
              "PhysicsParams has a field kFields does not list: add it");
static_assert(std::size(kFields) == 16);

}  // namespace physics_fields
