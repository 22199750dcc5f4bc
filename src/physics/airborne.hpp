// Impulses in three dimensions, for balls that leave the cloth
// (physics.airborne): a ball landing on the slate, a ball meeting a fixed
// edge (a cushion's nose from above, a rail's face in flight), and two
// balls meeting with a line of centres that is not level. Equations and
// their derivation: src/physics/airborne.cpp and docs/physics.md,
// "Airborne balls".
#pragma once

#include "breakshot/pool.hpp"
#include "breakshot/vec.hpp"

namespace breakshot {

/// A ball's velocity (3-D: x, y along the cloth, z up) and spin.
struct Motion3 {
  Vec3 velocity;
  Vec3 spin;
};

/// A ball meets something that does not move at the contact point
/// c - R n, where n is the unit contact normal pointing from the contact
/// to the ball's centre: Newton's restitution e on the normal, Coulomb
/// friction mu at the contact, capped at the impulse that stops the
/// contact point's slip. A ball not moving into the contact (v.n >= 0)
/// is returned unchanged. Kinetic energy never rises.
Motion3 fixed_contact_impact(const Motion3& in, Vec3 n, double radius, double restitution,
                             double friction);

/// Two balls touching, centres c1 and c2 (3-D), restitution e, friction
/// mu(slip at the start) capped at the impulse that stops the slip, no
/// cloth. Balls not approaching along c2 - c1 are returned unchanged.
struct Impact3 {
  Motion3 a, b;
};
Impact3 ball_ball_impact_3d(Vec3 c1, const Motion3& m1, double mass1, double r1, Vec3 c2,
                            const Motion3& m2, double mass2, double r2, double restitution,
                            const BallFriction& friction);

}  // namespace breakshot
