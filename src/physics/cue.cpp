// The cue strike of the pool model: the ball's velocity and spin just after
// the tip leaves it.
//
// Sources: W. Leckie, M. Greenspan, "An event-based pool physics
// simulator" (2005), eq. 1-3; D. Alciatore, technical proofs TP A-30 (cue
// tip impact) and TP A-31 (squirt). The derivation below is our own; it
// reproduces those results (see tests/test_cue.cpp, which also checks it
// against the Leckie-Greenspan equations written in their own frame).
//
// Frame of the shot. f is the aim direction on the table (phi degrees
// counter-clockwise from +x), l = z x f points to the shooter's left, z is
// up. The cue is elevated by theta, so it moves along
//   d = cos(theta) f - sin(theta) z.
// The tip offsets are measured in the plane perpendicular to the cue, as a
// player sighting along the cue sees them: a to the right (along -l) and b
// "up" along u = sin(theta) f + cos(theta) z, both as fractions of R. The
// contact point relative to the ball's centre is
//   Q = R (-a l + b u - k d),   k = sqrt(1 - a^2 - b^2).
// (Leckie and Greenspan give a and b as coordinates of the contact point on
// the ball in a level frame with +x to the shooter's left; their a is our
// -a and their b is our b cos(theta) + k sin(theta). With that substitution
// their eq. 1-3 become the equations here.)
//
// Impulse. Tip and ball are modelled as a point impact along d with no
// tangential impulse (the tip does not slip): the impulse on the ball is
// J d. Then
//   v = (J/m) d,   w = Q x (J d) / I,   I = 2/5 m R^2,
// and with s = -l (right), s x d = u and u x d = l, so
//   Q x d = R (a u + b l),   |Q x d|^2 = R^2 (a^2 + b^2).
// The velocity of the ball's contact point along d after the impact is
// J/m + J |Q x d|^2 / I = (J/m)(1 + 5/2 (a^2 + b^2)); the cue (a rigid mass
// M) slows to V - J/M. Tip restitution e along the cue axis,
//   (ball point) - (cue) = e V,
// gives
//   J/m = (1 + e) V / (1 + m/M + 5/2 (a^2 + b^2)).
// Leckie and Greenspan's factor 2 is the case e = 1 (a perfectly elastic
// tip); TP A-30 uses (1 + e) in the same way. We use (1 + e) with the tip
// restitution of CueParams, so a centre hit gives (1 + e) V / (1 + m/M).
// In the shot frame the spin is
//   w = (5/2) (J/m) / R (a sin(theta) f + b l + a cos(theta) z),
// so b > 0 (follow) spins the ball forward (rolling when b = 2/5 and the cue
// is level: w = v/R), b < 0 spins it backward (draw), and a > 0 (right
// english) gives w_z > 0: counter-clockwise seen from above. (Pushing the
// ball's right side forward turns it counter-clockwise; such a ball
// rebounds to the shooter's right from a cushion hit straight on.) The
// f component a sin(theta) is the tilt of the spin axis that makes an
// elevated english shot curve (masse) once the ball slides on the cloth.
//
// The ball stays on the cloth. The downward part -(J/m) sin(theta) of the
// velocity is dropped: the cloth takes it with a vertical impulse through
// the contact point with the cloth, which has no lever arm and so leaves
// the spin alone. Jumps (and the cloth's friction during the impact) are
// not modelled; the cue's impulse is computed as if the cloth were not
// there.
//
// Squirt (TP A-31). With english the ball leaves at an angle to the cue.
// During the brief contact the tip end of the shaft behaves like a free
// mass m_e sideways (the "effective end mass"); it sticks to the ball's
// contact point sideways. For a level cue with side offset a (fraction of
// R), lateral impulse P_y and forward impulse P_x on the ball:
//   ball:  v_y = P_y/m,  w_z R = (5/2)(a P_x - sqrt(1 - a^2) P_y)/m
//   shaft: lateral velocity -P_y/m_e
//   contact point moves sideways with the shaft:
//     v_y - w_z R sqrt(1 - a^2) = -P_y/m_e,
// so
//   tan(squirt) = P_y/P_x
//               = (5/2) a sqrt(1 - a^2) / (1 + m/m_e + (5/2)(1 - a^2)).
// Right english (a > 0) pushes the ball to the left of the aim line, which
// is counter-clockwise: a positive squirt angle. We rotate the ball's
// velocity by this angle and leave the spin as computed from the cue axis
// (as pooltool does). The angle does not depend on speed, cue mass or tip
// restitution; we use the side offset a whatever the elevation and b.
// End mass 0 means no squirt.
#include "breakshot/pool.hpp"

#include <cmath>

#include "physics/detmath.hpp"

namespace breakshot {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

bool finite(double x) { return std::isfinite(x); }

// The inputs for which the equations make sense. Anything else returns a
// ball that does not move (never NaN); scenario validation is expected to
// reject such strokes before they get here.
bool valid(const CueStrike& cue, double ball_mass, double ball_radius, const CueParams& p) {
  return finite(cue.speed) && cue.speed > 0.0 && finite(cue.phi) && finite(cue.theta) &&
         cue.theta >= 0.0 && cue.theta < 90.0 && finite(cue.a) && finite(cue.b) &&
         finite(ball_mass) && ball_mass > 0.0 && finite(ball_radius) && ball_radius > 0.0 &&
         p.mass > 0.0 &&  // +inf allowed: an immovable cue
         p.tip_restitution >= 0.0 && p.tip_restitution <= 1.0 &&
         p.end_mass >= 0.0;  // +inf allowed
}

// TP A-31 squirt angle in radians for side offset a (|a| < 1, fraction of
// the radius); positive (counter-clockwise) for a > 0.
double squirt_angle(double a, double ball_mass, double end_mass) {
  if (end_mass <= 0.0 || a == 0.0) return 0.0;
  const double q = 1.0 - a * a;
  return dm::atan2(2.5 * a * std::sqrt(q), 1.0 + ball_mass / end_mass + 2.5 * q);
}

}  // namespace

StrikeResult strike(const CueStrike& cue, double ball_mass, double ball_radius,
                    const CueParams& params) {
  StrikeResult out;
  if (!valid(cue, ball_mass, ball_radius, params)) return out;

  const double a = cue.a;
  const double b = cue.b;
  const double offset2 = a * a + b * b;
  // Beyond the limit the tip slides off; at a whole radius it misses.
  const double offset = std::sqrt(offset2);
  if (offset > params.miscue_limit || offset >= 1.0) {
    out.miscue = true;
    return out;
  }

  // Speed of the ball along the cue axis, J/m.
  const double e = params.tip_restitution;
  const double along =
      (1.0 + e) * cue.speed / (1.0 + ball_mass / params.mass + 2.5 * offset2);

  const double theta = cue.theta * kDegree;
  double st = 0.0;
  double ct = 0.0;
  dm::sincos(theta, st, ct);

  // Spin in the shot frame (f, l, z).
  const double k = 2.5 * along / ball_radius;
  const double w_f = k * a * st;
  const double w_l = k * b;
  const double w_z = k * a * ct;

  const double phi = cue.phi * kDegree;
  Vec2 f;
  dm::sincos(phi, f.y, f.x);
  const Vec2 l = perp(f);
  const Vec2 w_xy = w_f * f + w_l * l;
  out.spin = Vec3{w_xy.x, w_xy.y, w_z};

  const double alpha = squirt_angle(a, ball_mass, params.end_mass);
  const double dir = phi + alpha;
  Vec2 heading;
  dm::sincos(dir, heading.y, heading.x);
  out.velocity = heading * (along * ct);
  out.vertical = -along * st;
  out.squirt = alpha / kDegree;
  // Overflow with absurd magnitudes (a speed near DBL_MAX, a radius near
  // zero) would give inf or NaN: such a stroke is outside the model too.
  if (!finite(out.velocity.x) || !finite(out.velocity.y) || !finite(out.spin.x) ||
      !finite(out.spin.y) || !finite(out.spin.z)) {
    return StrikeResult{};
  }
  return out;
}

}  // namespace breakshot
