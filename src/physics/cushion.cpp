// Cushion rebound for the pool model: the rail's nose touches the ball
// above its centre (H. Han, "Dynamics in carom and three cushion
// billiards", J. Mech. Sci. Tech. 19 (2005)). Every step below is derived
// here from impulse-momentum for a solid sphere (I = 2/5 m R^2) rather
// than copied from the paper, whose intermediate equations have typos.
//
// Frame. The rail's unit normal n points into the table. We work in a
// right-handed local frame with
//   x = -n        (horizontal, from the ball towards the rail),
//   y = z cross x (horizontal, along the rail),
//   z             (up).
// The ball moves into the rail: v_x > 0. Its velocity is horizontal
// (v_z = 0) and its spin w = (w_x, w_y, w_z) is arbitrary.
//
// Geometry. The nose touches the ball at height h = nose_height * 2R above
// the cloth, i.e. h - R above the centre, so the contact point is
//   r = R (cos t, 0, sin t),   sin t = h/R - 1 = 2 nose_height - 1,
// and the contact normal (unit, from the rail into the ball) is
//   N = -(cos t, 0, sin t).
// WPA's 63.5 % nose gives sin t = 0.27, t = 15.7 degrees.
//
// Velocity of the ball's surface at the contact: u = v + w x r, with
//   w x r = R (w_y sin t, w_z cos t - w_x sin t, -w_y cos t).
// Normal part: u . N = v . N = -v_x cos t (w x r is perpendicular to r),
// so the approach speed along the contact normal is
//   c = v_x cos t                                          (Han's c)
// and it does not depend on the spin. Tangent plane basis
//   t1 = (0, 1, 0),   t2 = (-sin t, 0, cos t)   (t2 points up the ball)
// gives the slip components
//   u1 = u . t1 = v_y + R (w_z cos t - w_x sin t),
//   u2 = u . t2 = -(v_x sin t + R w_y).
// (Han's s_x and s_y are -u2 and -u1.)
//
// Impulse. The rail gives the impulse P = m p at r, with the impulse per
// unit mass p = p_N N + p1 t1 + p2 t2. Then
//   dv = p,   dw = (r x P) / I = 5/(2R^2) (r x p).
// With p_x = -p_N cos t - p2 sin t, p_y = p1, p_z = -p_N sin t + p2 cos t:
//   r x p = R (-p1 sin t, p_x sin t - p_z cos t, p1 cos t)
//         = R (-p1 sin t, -p2, p1 cos t),
// so (the normal part has no lever arm, only friction turns the ball)
//   dw_x = -(5 / 2R) p1 sin t,   dw_y = -(5 / 2R) p2,   dw_z = (5 / 2R) p1 cos t.
// The slip changes by
//   du1 = p1 + R (dw_z cos t - dw_x sin t) = 7/2 p1,
//   du2 = -(dv_x sin t - dv_z cos t) - R dw_y = 7/2 p2,
// and the approach speed by d(u . N) = p_N. For a sphere the normal and
// the tangential problems decouple, and the tangential one is isotropic:
// a friction impulse only shortens the slip, never turns it, so the slip
// direction stays fixed during the impact and the two cases below are
// exact for Coulomb friction (no need to integrate over the impact as
// Mathavan et al. 2010 do, whose table contact couples the directions).
//
// Normal impulse (Newton's restitution e on the contact normal):
//   p_N = (1 + e) c                                         (Han's P_zE / m)
// Friction: the impulse that stops the slip is -(2/7) u_t, of size
// (2/7) |u_t| (Han's P_zS / m). Coulomb's law caps it at mu p_N:
//   stick, if (2/7) |u_t| <= mu p_N:  (p1, p2) = -(2/7) (u1, u2)
//   slide, otherwise:                 (p1, p2) = -mu p_N (u1, u2) / |u_t|
// (Han's condition compares P_zS with mu P_zE; some write-ups of the
// model drop the mu.) After a stick the contact point rolls on the nose;
// after a slide the slip has kept its direction and shrunk by
// (7/2) mu p_N.
//
// New state, in the local frame:
//   v_x' = v_x - p_N cos t - p2 sin t,   v_y' = v_y + p1,
//   w_x' = w_x - (5/2R) p1 sin t,  w_y' = w_y - (5/2R) p2,  w_z' = w_z + (5/2R) p1 cos t.
// The vertical velocity v_z' = -p_N sin t + p2 cos t is dropped: the ball
// stays on the cloth. When it points down (always so when mu < tan t, as
// with the defaults: friction cannot tip the impulse upwards) the cloth
// takes it with an impulse through the ball's lowest point, which has no
// lever arm about the centre, so the spin is unchanged. When it points up
// (friction beyond tan t with strong topspin) the ball would hop, which
// the model ignores. Han's model has no cloth friction during the impact.
//
// Last guard. The tilted impulse stops the motion along N only: with a
// very low restitution, a high nose or strong draw meeting high friction,
// v_x' can stay positive (into the rail). A ball cannot pass the rail and
// the cloth together, so v_x' is then set to 0 (an extra horizontal
// impulse through the centre; it only removes energy). Since p2 >= -mu p_N,
//   v_x' <= v_x (1 - (1 + e) cos t (cos t - mu sin t)),
// so with the default nose and friction it cannot trigger for e >= 0.13.
//
// Checks (tests/test_cushion.cpp): nose at the centre height (t = 0) with
// no friction gives plain reflection v_x' = -e v_x; kinetic energy never
// increases (the normal impulse loses (1 - e^2) of the normal energy,
// friction removes slip energy, dropping v_z and the guard only remove
// energy); the angular momentum about the contact point keeps its x and z
// components (every impulse of the rail acts at r; v_z does not enter
// those two components).
//
// The mass cancels: every impulse is proportional to it. Only sqrt is
// used, so results are bit-identical wherever IEEE doubles are.
#include "breakshot/pool.hpp"

#include <cmath>

namespace breakshot {

CushionImpact cushion_impact(Vec2 v, Vec3 w, Vec2 n, double mass, double radius,
                             const CushionParams& params) {
  static_cast<void>(mass);  // cancels out, see above
  const Vec2 ex = -(n / norm(n));  // towards the rail
  const Vec2 ey = perp(ex);        // along the rail; (ex, ey, z) right-handed

  const double vx = dot(v, ex);
  if (!(vx > 0.0)) return {v, w};  // not moving into the rail: no impact
  const double vy = dot(v, ey);
  const Vec2 wh{w.x, w.y};
  const double wx = dot(wh, ex);
  const double wy = dot(wh, ey);
  const double wz = w.z;

  const double R = radius;
  const double e = params.restitution;
  const double mu = params.friction;
  const double s = 2.0 * params.nose_height - 1.0;  // sin t
  const double c = std::sqrt(1.0 - s * s);          // cos t

  // Normal impulse per unit mass.
  const double pn = (1.0 + e) * vx * c;

  // Slip of the contact point in the tangent plane (t1, t2).
  const double u1 = vy + R * (wz * c - wx * s);
  const double u2 = -(vx * s + R * wy);
  const double slip = std::sqrt(u1 * u1 + u2 * u2);

  double p1 = 0.0;
  double p2 = 0.0;
  const double limit = mu * pn;
  if (2.0 / 7.0 * slip <= limit) {  // the slip stops: sticking
    p1 = -2.0 / 7.0 * u1;
    p2 = -2.0 / 7.0 * u2;
  } else {  // sliding throughout, along the initial slip direction
    const double k = limit / slip;
    p1 = -k * u1;
    p2 = -k * u2;
  }

  double vx2 = vx - pn * c - p2 * s;
  const double vy2 = vy + p1;
  if (vx2 > 0.0) vx2 = 0.0;  // the rail and the cloth together stop it

  const double q = 2.5 / R;
  const double wx2 = wx - q * s * p1;
  const double wy2 = wy - q * p2;
  const double wz2 = wz + q * c * p1;

  CushionImpact out;
  out.velocity = ex * vx2 + ey * vy2;
  const Vec2 wh2 = ex * wx2 + ey * wy2;
  out.spin = {wh2.x, wh2.y, wz2};
  return out;
}

}  // namespace breakshot
