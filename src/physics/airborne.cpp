// Impulses in three dimensions (src/physics/airborne.hpp), derived
// here from impulse-momentum for solid spheres (I = 2/5 m R^2).
//
// A fixed contact. The ball (velocity v, spin w, radius R) touches
// something immovable at r = -R n from its centre, n the unit normal from
// the contact to the centre. The contact point moves at
//   u = v + w x r.
// Its normal part is u.n = v.n (w x r is perpendicular to r), negative
// while the ball moves into the contact. An impulse per unit mass p at r
// changes
//   dv = p,   dw = (r x p) / (2/5 R^2) = -(5 / 2R) (n x p).
// Normal: Newton's restitution on v.n gives p_n = -(1 + e) v.n along n,
// which has no lever arm. Tangential: the slip u_t = u - (u.n) n changes
// under a tangential impulse f by
//   du_t = f + dw x r = f + (5/2) (n x f) x n = (7/2) f,
// so the direction of the slip never turns, and Coulomb friction is one
// impulse: f = -min(mu p_n, (2/7) |u_t|) u_t / |u_t| (the cap stops the
// slip exactly: the ball leaves the contact rolling on it). The normal
// impulse loses (1 - e^2) of the normal kinetic energy; a tangential
// impulse of a fraction k <= 1 of the stopping one changes the energy by
// -(7/2) (k - k^2 / 2) |f_stop|^2 <= 0. So energy never rises.
//
// The slate is the case n = z: the ball lands with v_z < 0 and leaves
// with -e v_z, its slip on the cloth shortened by the cloth's friction
// during the landing (physics.sliding_friction).
//
// Two balls. Centres c1, c2, n = (c2 - c1) / |c2 - c1|, contact points
// r1 = R1 n and r2 = -R2 n. Relative velocity of the contact points
// u = (v1 + w1 x r1) - (v2 + w2 x r2); approach speed u.n = (v1 - v2).n.
// Normal impulse on ball 2 (ball 1 takes the opposite):
//   J = (1 + e) (v1 - v2).n / (1/m1 + 1/m2).
// A tangential impulse F on ball 2 (-F on ball 1) changes ball k's
// contact point velocity by (7/2) F / m_k (as above), so the relative
// slip by -(7/2) (1/m1 + 1/m2) F, and the impulse that stops the slip is
// |u_t| / ((7/2) (1/m1 + 1/m2)), capped at mu J with mu evaluated at the
// slip at the start (the ball-ball friction curve). Spins:
//   dw1 = (r1 x (-P)) / I1 = -(5 / (2 m1 R1)) (n x F),
//   dw2 = (r2 x P) / I2 = -(5 / (2 m2 R2)) (n x F),
// with P = J n + F (the normal part has no lever arm). The same energy
// argument holds for the pair's reduced mass.
//
// Only arithmetic, sqrt and the project's exp are used: results are
// bit-identical wherever IEEE doubles are.
#include "physics/airborne.hpp"

#include <algorithm>
#include <cmath>

namespace breakshot {

namespace {

double dot3(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross3(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace

Motion3 fixed_contact_impact(const Motion3& in, Vec3 n, double radius, double restitution,
                             double friction) {
  const double vn = dot3(in.velocity, n);
  if (!(vn < 0.0)) return in;
  const double pn = -(1.0 + restitution) * vn;
  const Vec3 r = n * -radius;
  const Vec3 u = in.velocity + cross3(in.spin, r);
  const Vec3 ut = u - n * dot3(u, n);
  const double slip = std::sqrt(dot3(ut, ut));
  Vec3 f;
  if (slip > 0.0) {
    const double size = std::min(friction * pn, 2.0 / 7.0 * slip);
    f = ut * (-size / slip);
  }
  Motion3 out;
  out.velocity = in.velocity + n * pn + f;
  out.spin = in.spin - cross3(n, f) * (2.5 / radius);
  return out;
}

Impact3 ball_ball_impact_3d(Vec3 c1, const Motion3& m1, double mass1, double r1, Vec3 c2,
                            const Motion3& m2, double mass2, double r2, double restitution,
                            const BallFriction& friction) {
  Impact3 out{m1, m2};
  Vec3 n = c2 - c1;
  const double len = std::sqrt(dot3(n, n));
  if (!(len > 0.0)) return out;
  n = n * (1.0 / len);
  const double closing = dot3(m1.velocity - m2.velocity, n);
  if (!(closing > 0.0)) return out;
  const double inv = 1.0 / mass1 + 1.0 / mass2;
  const double J = (1.0 + restitution) * closing / inv;
  const Vec3 u = (m1.velocity + cross3(m1.spin, n * r1)) - (m2.velocity + cross3(m2.spin, n * -r2));
  const Vec3 ut = u - n * dot3(u, n);
  const double slip = std::sqrt(dot3(ut, ut));
  Vec3 F;
  if (slip > 0.0) {
    const double size = std::min(friction(slip) * J, slip / (3.5 * inv));
    F = ut * (size / slip);  // on ball 2, along the slip of ball 1 against ball 2
  }
  const Vec3 P = n * J + F;
  out.a.velocity = m1.velocity - P * (1.0 / mass1);
  out.b.velocity = m2.velocity + P * (1.0 / mass2);
  const Vec3 nf = cross3(n, F);
  out.a.spin = m1.spin - nf * (2.5 / (mass1 * r1));
  out.b.spin = m2.spin - nf * (2.5 / (mass2 * r2));
  return out;
}

}  // namespace breakshot
