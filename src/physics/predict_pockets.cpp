// Prediction of a fall into a pocket: a ball falls in when its centre
// comes within the pocket's radius of the pocket's centre (docs/physics.md,
// "Pockets").
#include <algorithm>
#include <cmath>

#include "physics/engine.hpp"
#include "physics/prediction.hpp"
#include "physics/roots.hpp"

namespace breakshot::detail {

void Engine::predict_pockets(const Kinematics& ki, Prediction& best) const {
  if (ki.still) return;
  const double t = origin_;
  const double window = within_best(best, t, std::max(0.0, ki.t_end - t));
  const auto& pockets = scenario_.table.pockets;
  for (std::size_t k = 0; k < pockets.size(); ++k) {
    const Vec2 centre = pockets[k].centre;
    const double pr = pockets[k].radius;
    if (centre.x - pr > ki.box_hi.x || ki.box_lo.x > centre.x + pr ||
        centre.y - pr > ki.box_hi.y || ki.box_lo.y > centre.y + pr) {
      continue;
    }
    const Vec2 d = ki.p - centre;
    const double rr = pockets[k].radius * pockets[k].radius;
    double tau = kInf;
    if (ki.a.x == 0.0 && ki.a.y == 0.0) {
      const double b = dot(d, ki.v);
      if (b >= 0.0) continue;
      tau = first_contact_quadratic(norm2(d) - rr, b, norm2(ki.v));
    } else {
      // Bounds on the distance that prove no fall (prediction.hpp).
      const double d2 = norm2(d);
      if (d2 > rr && stays_apart(d, ki.v, ki.a, std::sqrt(d2), pr, window)) continue;
      const double c[5] = {norm2(d) - rr, 2.0 * dot(d, ki.v), norm2(ki.v) + dot(d, ki.a),
                           dot(ki.v, ki.a), 0.25 * norm2(ki.a)};
      tau = first_contact(c, 4, window);
    }
    if (!(tau <= window)) continue;
    // In flight, a ball whose bottom is above the rail's top passes over
    // the hole (engine_airborne.cpp).
    if (ki.airborne && ki.z + ki.vz * tau - 0.5 * ki.g * tau * tau >= cushion_nose_height(scenario_.table.cushion, ki.radius)) continue;
    consider(best, t + tau, EventKind::pocket, static_cast<std::int32_t>(k), 0);
  }
}

}  // namespace breakshot::detail
