// Ball-ball impact with friction for the pool model: throw and spin
// transfer (Alciatore TP; the same impulse picture as
// pooltool's "frictional inelastic" ball-ball model).
//
// Notation. Ball i has centre p_i (on the table plane), velocity v_i,
// spin w_i (3-D, z up), mass m_i, radius r_i, moment of inertia
// I_i = 2/5 m_i r_i^2. n = (p2 - p1) / |p2 - p1| is the line of centres,
// taken horizontal (see "Limitations"). The contact point is r1 n from
// ball 1's centre and -r2 n from ball 2's.
//
// Ball 2 receives the impulse P = Jn n + Jt at the contact point, ball 1
// receives -P. Then, with d1 = r1 n and d2 = -r2 n the offsets of the
// contact point from the centres (torque = offset x force):
//
//   v1' = v1 - P / m1            w1' = w1 + d1 x (-P) / I1 = w1 - r1 (n x Jt) / I1
//   v2' = v2 + P / m2            w2' = w2 + d2 x   P  / I2 = w2 - r2 (n x Jt) / I2
//
// (n x n = 0: the normal impulse exerts no torque.) Both spins change by
// the same vector scaled by r_i / I_i: english on the cue ball gives the
// object ball spin the other way round (spin transfer).
//
// Normal impulse. The closing speed vn = (v1 - v2) . n does not depend on
// the spins (w x n is perpendicular to n), so as in the frictionless case
//   Jn = (1 + e) mu_red vn,   mu_red = m1 m2 / (m1 + m2),
// which gives vn' = -e vn.
//
// Slip. The velocity of ball 1's contact point relative to ball 2's is
//   u = (v1 + w1 x (r1 n)) - (v2 + w2 x (-r2 n)),
// and the slip is its part tangent to the contact, u_t = u - (u . n) n:
// a horizontal component along t = z x n (cut angle and sidespin) and a
// vertical component (follow or draw). An impulse Jt perpendicular to n
// changes it by
//   du_t = -Jt (1/m1 + r1^2/I1 + 1/m2 + r2^2/I2) = -Jt / M_t
// (for Jt perpendicular to n, (n x Jt) x n = Jt), and it does not touch
// the normal relative velocity: normal and tangential problems decouple.
// With I = 2/5 m r^2 each r^2/I is 5/(2m), so 1/M_t = 7/2 (1/m1 + 1/m2);
// for equal masses M_t = m/7, Alciatore's "1/7" (TP A-14).
//
// Friction impulse (Coulomb, with the slip direction fixed during the
// impact because M_t is the same in every tangent direction):
//   Jt = -j u_t / |u_t| on ball 1, +j u_t / |u_t| on ball 2,
//   j  = min(mu(|u_t|) Jn, M_t |u_t|).
// mu is BallFriction evaluated at the slip speed at the start of the
// impact. The second term is the impulse that stops the slip: beyond it
// the slip would reverse, which friction cannot do. So at the end of the
// impact u_t' = (1 - j / (M_t |u_t|)) u_t, same direction, never longer
// (counting the vertical velocities the impact gives before the cloth
// removes them, next paragraph).
//
// Vertical part. The vertical component of Jt changes the spins (the
// object ball gets a little draw from a follow shot, a little follow from
// a draw shot, TP A-14's spin transfer) and, as in TP A-14, it uses up
// part of the friction budget: mu Jn acts along the whole slip, so follow
// or draw reduce the horizontal throw. Its linear part (a vertical
// velocity of either ball) is dropped: the balls stay on the cloth, which
// takes the downward part; an upward part would make a hop of a fraction
// of a millimetre, which the model ignores. Dropping a velocity component
// only removes kinetic energy.
//
// Conservation, all exact up to rounding:
// - linear momentum on the table plane (the horizontal impulses are equal
//   and opposite);
// - angular momentum about a vertical axis: for each ball about the axis
//   through the contact point, for both balls together about any vertical
//   axis (the impulses act at the contact point; the cloth's is vertical);
// - spin about the line of centres (no impulse has a moment about n);
// - kinetic energy never increases: the normal impulse dissipates
//   (1 - e^2) mu_red vn^2 / 2 and the friction impulse does work
//   -j |u_t| (1 - j / (2 M_t |u_t|)) <= 0 because j <= M_t |u_t|;
//   dropping the vertical velocity only removes energy.
//
// Limitations.
// - With different radii the true line of centres is tilted (the centres
//   are at heights r1 and r2); here it is taken as the horizontal
//   direction between the centres, and the contact point is at r1 n from
//   ball 1's centre and -r2 n from ball 2's as if the balls touched at a
//   common height. Exact for equal radii.
// - Instantaneous impact; no cloth friction during it; the throw is
//   decided by the slip at the start (mu is not integrated along the
//   impact as the slip falls).
#include <algorithm>
#include <cmath>
#include <limits>

#include "breakshot/pool.hpp"
#include "physics/detmath.hpp"

namespace breakshot {

namespace {

constexpr double dot3(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

constexpr Vec3 cross3(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

constexpr Vec3 lift(Vec2 a) { return {a.x, a.y, 0.0}; }

constexpr Vec2 flat(Vec3 a) { return {a.x, a.y}; }

}  // namespace

double BallFriction::operator()(double slip) const {
  // Clamped at zero: a negative coefficient would feed energy in.
  return std::max(0.0, a + b * dm::exp(-c * std::abs(slip)));
}

BallImpact ball_ball_impact(Vec2 p1, Vec2 v1, Vec3 w1, double m1, double r1, Vec2 p2, Vec2 v2,
                            Vec3 w2, double m2, double r2, double restitution,
                            const BallFriction& friction) {
  BallImpact out{v1, v2, w1, w2};
  if (!(m1 > 0.0 && m2 > 0.0 && r1 > 0.0 && r2 > 0.0)) return out;  // callers validate

  const Vec2 d = p2 - p1;
  const double dist = norm(d);
  if (!(dist > 0.0)) return out;  // coincident centres: no line of centres
  const Vec2 n = d / dist;

  const double closing = dot(v1 - v2, n);
  if (!(closing > 0.0)) return out;  // separating or grazing: no impact

  // Normal impulse on ball 2 (ball 1 gets the opposite).
  const double mu_red = m1 * m2 / (m1 + m2);
  const double jn = (1.0 + restitution) * mu_red * closing;

  // Slip of ball 1's contact point relative to ball 2's, tangent part.
  const Vec3 n3 = lift(n);
  const Vec3 vc1 = lift(v1) + cross3(w1, n3 * r1);
  const Vec3 vc2 = lift(v2) + cross3(w2, n3 * (-r2));
  const Vec3 u = vc1 - vc2;
  const Vec3 ut = u - n3 * dot3(u, n3);
  const double slip = std::sqrt(dot3(ut, ut));

  // Friction impulse on ball 2, along the slip (ball 1 gets the opposite).
  Vec3 jt{};
  const double i1 = 0.4 * m1 * r1 * r1;
  const double i2 = 0.4 * m2 * r2 * r2;
  if (slip > 0.0) {
    const double inv_mt = 1.0 / m1 + 1.0 / m2 + r1 * r1 / i1 + r2 * r2 / i2;
    const double stop_slip = slip / inv_mt;
    const double j = std::min(friction(slip) * jn, stop_slip);
    jt = ut * (j / slip);
  }

  // Horizontal impulse on ball 2; the vertical part of jt acts on the spins
  // only (the cloth keeps the balls on the table).
  const Vec2 p_on_2 = n * jn + flat(jt);
  out.v1 = v1 - p_on_2 / m1;
  out.v2 = v2 + p_on_2 / m2;

  const Vec3 n_x_jt = cross3(n3, jt);
  out.w1 = w1 - n_x_jt * (r1 / i1);
  out.w2 = w2 - n_x_jt * (r2 / i2);
  return out;
}

// ---------------------------------------------------------------------------
// Mathavan, Jackson, Parkin 2014, "Numerical simulations of the frictional
// collisions of solid balls on a rough surface", Sports Eng. 17:227-237.
//
// The impact is followed through the normal impulse P instead of being
// solved in one step. At each increment dP (on ball 2 along n, on ball 1
// along -n), with the slips as they are at that moment:
//
// - friction at the ball-ball contact: mu_b dP along the contact slip u_t
//   (the same 3-D slip as above) on ball 2, the opposite on ball 1;
// - its vertical part presses one of the balls into the cloth (the ball it
//   pushes down): the cloth answers with the same vertical impulse N and a
//   friction mu_s N against that ball's slip on the cloth,
//   s = v + w x (-r z); the ball it pushes up stays on the cloth (gravity's
//   impulse during the impact is neglected, as in the paper: no hop);
// - each ball's velocity changes by its horizontal impulses / m and its spin
//   by the moments of the impulses about its centre / I (the normal impulse
//   and the cloth's vertical reaction have none).
//
// Restitution is Stronge's energetic one, as in the paper: the work of the
// normal force during compression (until the normal relative velocity
// turns from closing to separating) is W_c, and the impact ends when the
// total work reaches (1 + e^2) W_c. dP is the frictionless impulse
// (1 + e) m_red v_n / steps (the paper's eq. 14: about `steps` increments).
//
// mu_b is evaluated once, at the slip at the start (BallFriction, as in the
// friction model); mu_s is the cloth's sliding friction. Only sqrt and the
// four operations: the result is the same on every IEEE machine.
BallImpact ball_ball_impact_mathavan(Vec2 p1, Vec2 v1, Vec3 w1, double m1, double r1, Vec2 p2,
                                     Vec2 v2, Vec3 w2, double m2, double r2, double restitution,
                                     const BallFriction& friction, double cloth_friction,
                                     int steps) {
  BallImpact out{v1, v2, w1, w2};
  if (!(m1 > 0.0 && m2 > 0.0 && r1 > 0.0 && r2 > 0.0 && steps > 0)) return out;
  const Vec2 d = p2 - p1;
  const double dist = norm(d);
  if (!(dist > 0.0)) return out;
  const Vec2 n = d / dist;
  const double closing = dot(v1 - v2, n);
  if (!(closing > 0.0)) return out;

  const Vec3 n3 = lift(n);
  const Vec3 z{0.0, 0.0, 1.0};
  const double i1 = 0.4 * m1 * r1 * r1;
  const double i2 = 0.4 * m2 * r2 * r2;
  const double mu_red = m1 * m2 / (m1 + m2);
  const double dp = (1.0 + restitution) * mu_red * closing / static_cast<double>(steps);

  Vec3 a_v = lift(v1), b_v = lift(v2), a_w = w1, b_w = w2;
  auto contact_slip = [&] {
    const Vec3 u = (a_v + cross3(a_w, n3 * r1)) - (b_v + cross3(b_w, n3 * (-r2)));
    return u - n3 * dot3(u, n3);
  };
  const Vec3 ut0 = contact_slip();
  const double mu_b = friction(std::sqrt(dot3(ut0, ut0)));

  // Table friction on a ball pressed down by `down` (> 0) with slip s.
  auto cloth = [&](Vec3 v, Vec3 w, double r, double down) {
    if (!(down > 0.0)) return Vec3{};
    const Vec3 s = v + cross3(w, z * (-r));
    const Vec3 sh{s.x, s.y, 0.0};
    const double len = std::sqrt(dot3(sh, sh));
    if (!(len > 0.0)) return Vec3{};
    return sh * (-cloth_friction * down / len);
  };

  double vn = -closing;  // (v2 - v1) . n: < 0 while closing
  double work = 0.0;
  double work_end = std::numeric_limits<double>::infinity();
  bool compressed = false;
  const long limit = 100L * steps;  // the normal impulse alone ends it in ~steps
  for (long k = 0; k < limit && (vn < 0.0 || work < work_end); ++k) {
    const Vec3 ut = contact_slip();
    const double slip = std::sqrt(dot3(ut, ut));
    const Vec3 f = slip > 0.0 ? ut * (mu_b * dp / slip) : Vec3{};  // on ball 2
    // Vertical part: -f.z on ball 1, +f.z on ball 2; the one pushed down
    // is held by the cloth.
    const Vec3 t1 = cloth(a_v, a_w, r1, f.z);
    const Vec3 t2 = cloth(b_v, b_w, r2, -f.z);
    const Vec3 on1 = n3 * (-dp) - f + t1;
    const Vec3 on2 = n3 * dp + f + t2;
    a_v = a_v + Vec3{on1.x, on1.y, 0.0} * (1.0 / m1);
    b_v = b_v + Vec3{on2.x, on2.y, 0.0} * (1.0 / m2);
    a_w = a_w + (cross3(n3 * r1, f * -1.0) + cross3(z * (-r1), t1)) * (1.0 / i1);
    b_w = b_w + (cross3(n3 * (-r2), f) + cross3(z * (-r2), t2)) * (1.0 / i2);
    const double vn_before = vn;
    vn = dot3(b_v - a_v, n3);
    work += 0.5 * dp * std::abs(vn_before + vn);
    if (!compressed && vn > 0.0) {
      compressed = true;
      work_end = (1.0 + restitution * restitution) * work;
    }
  }
  out.v1 = flat(a_v);
  out.v2 = flat(b_v);
  out.w1 = a_w;
  out.w2 = b_w;
  return out;
}

}  // namespace breakshot
