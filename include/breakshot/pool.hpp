// The pool model's impact laws: cue strike, ball-ball with friction, and
// the cushion. Each is a pure function of the states just before the
// impact, tested on its own against published figures; the simulation
// calls them at events.
#pragma once

#include <cstdint>
#include <string_view>

#include "breakshot/physics.hpp"
#include "breakshot/vec.hpp"

namespace breakshot {

// ---------------------------------------------------------------------------
// Cue strike (Leckie & Greenspan 2005 eq. 1-3; Alciatore TP ).

struct CueParams {
  double mass = 0.567;          ///< cue stick mass M (kg), a 20 oz cue
  double tip_restitution = 0.75;  ///< Alciatore's property constants: 0.71-0.75
  /// Effective end mass m_e of the shaft for squirt (kg); 0 turns squirt
  /// off. TP A-31: tan(squirt) = 5/2 a sqrt(1 - a^2) / (1 + m/m_e +
  /// 5/2 (1 - a^2)). 10 g (m/m_e = 17) gives 1.7 degrees at a = 0.25.
  double end_mass = 0.010;
  /// Largest tip offset sqrt(a^2 + b^2) (fraction of the radius) that
  /// does not miscue. Alciatore: about half the radius.
  double miscue_limit = 0.5;
};

/// What the cue stick does: `speed` m/s, aimed `phi` degrees
/// counter-clockwise from +x, elevated `theta` degrees (0 <= theta < 90),
/// tip offset `a` (right english > 0) and `b` (follow > 0) as fractions of
/// the radius. The offsets are measured perpendicular to the cue axis, as
/// seen sighting along the cue (not the contact point's height on the
/// ball): a and b are the same whatever the elevation.
struct CueStrike {
  double speed = 0.0;
  double phi = 0.0;
  double theta = 0.0;
  double a = 0.0;
  double b = 0.0;
  bool operator==(const CueStrike&) const = default;
};

struct StrikeResult {
  Vec2 velocity;   ///< of the ball centre, on the table plane
  Vec3 spin;       ///< rad/s; right english gives spin.z > 0 (counter-clockwise from above)
  /// Degrees from phi to the ball's direction, counter-clockwise positive:
  /// right english squirts the ball to the left, a positive angle.
  double squirt = 0.0;
  bool miscue = false;  ///< offset beyond CueParams::miscue_limit: not played
  /// The vertical part of the ball's velocity as the tip leaves it (m/s,
  /// -(J/m) sin theta: down, into the slate; 0 for a level cue).
  double vertical = 0.0;
};

/// The ball's velocity and spin just after the tip leaves it. A centre
/// hit (a = b = 0, theta = 0) gives speed (1 + e) V / (1 + m/M) for tip
/// restitution e (Leckie & Greenspan's 2 V / (1 + m/M) when e = 1) and no
/// spin. A miscue returns miscue = true and a zero velocity and spin; an
/// offset of a whole radius or more is always a miscue. The ball stays on
/// the cloth (no jumps): the vertical part of the velocity is dropped.
/// Strokes outside the model (speed not > 0, theta outside [0, 90),
/// non-finite values, masses or radius not > 0, tip restitution outside
/// [0, 1], negative end mass) leave the ball at rest with miscue = false:
/// callers validate; the result is never NaN. See src/physics/cue.cpp.
StrikeResult strike(const CueStrike& cue, double ball_mass, double ball_radius,
                    const CueParams& params);

// ---------------------------------------------------------------------------
// Ball-ball impact with friction (Alciatore TP ).

struct BallImpact {
  Vec2 v1, v2;  ///< velocities after
  Vec3 w1, w2;  ///< spins after
};

/// Friction coefficient between balls as a function of the sliding speed
/// of the contact points (m/s): mu(v) = a + b exp(-c |v|), clamped at 0.
/// BallFriction{} is Alciatore's fit to Marlow's data (TP;
/// pooltool's default; kThrowFitTPA28), the legacy curve: the simulation
/// does not use these initial values but builds its BallFriction from
/// the scenario's physics (default_physics(pool): TP B-3, kThrowFitTPB3).
/// BallFriction{0, 0, 0} is frictionless.
struct BallFriction {
  double a = kThrowFitTPA28.a;
  double b = kThrowFitTPA28.b;
  double c = kThrowFitTPA28.c;
  double operator()(double slip) const;
};

/// Impact of ball 1 (at p1) and ball 2 (at p2), touching, with restitution
/// e in [0, 1]. The normal impulse gives the restitution; the tangential
/// impulse opposes the slip of the contact points (horizontal and
/// vertical), at most mu(slip at the start) times the normal impulse and
/// no more than what stops the slip. It changes both balls' velocities
/// (throw) and spins (spin transfer, including a little draw or follow for
/// the object ball); its vertical linear part is taken by the cloth.
/// Momentum on the table plane and angular momentum about vertical axes
/// are conserved; energy never increases. The line of centres is taken
/// horizontal, exact for equal radii. Balls not approaching along the line
/// of centres, coincident centres, or masses or radii not > 0 leave the
/// state unchanged. See src/physics/ball_impact.cpp.
BallImpact ball_ball_impact(Vec2 p1, Vec2 v1, Vec3 w1, double m1, double r1, Vec2 p2, Vec2 v2,
                            Vec3 w2, double m2, double r2, double restitution,
                            const BallFriction& friction);

/// Mathavan, Jackson, Parkin 2014's ball-ball impact (Sports Eng. 17): the
/// impact followed through the normal impulse in `steps` increments, with
/// Coulomb friction mu (BallFriction at the slip at the start) at the
/// contact and `cloth_friction` where the contact's vertical friction
/// presses a ball into the cloth, and Stronge's energetic restitution e.
/// The balls stay on the cloth. Same arguments and degenerate cases as
/// ball_ball_impact (and steps not > 0). See src/physics/ball_impact.cpp.
BallImpact ball_ball_impact_mathavan(Vec2 p1, Vec2 v1, Vec3 w1, double m1, double r1, Vec2 p2,
                                     Vec2 v2, Vec3 w2, double m2, double r2, double restitution,
                                     const BallFriction& friction, double cloth_friction,
                                     int steps = 1000);

// ---------------------------------------------------------------------------
// Cushion impact with the rail nose above the ball's centre.

/// The cushion laws a scenario can choose (`table.cushion_model`).
/// Equations, sources and assumptions: src/physics/cushion.cpp and
/// docs/physics.md, "Cushions".
enum class CushionModel : std::uint8_t {
  /// "han_2005_v0": Han 2005 as breakshot 0.1 implemented it. The impulse
  /// at the nose is computed as if the ball were free to leave the cloth
  /// and its vertical part is then dropped, so the rail keeps less than
  /// its restitution says (0.854 of the speed straight in with e = 1 and
  /// no friction, nose 63.5 %). breakshot 0.1's law (part of the legacy
  /// physics, kLegacyGamePhysics), kept so that every output made with it
  /// can be made again; not the default.
  han_2005_v0,
  /// "han_2005": Han's impulse law with the slate taking the vertical part
  /// of the rail's impulse (the ball stays on the cloth): Newton's
  /// restitution on the nose's normal, Coulomb friction at the nose. The
  /// default (CushionParams::model).
  han_2005,
  /// "mathavan_2010": Mathavan, Jackson and Parkin 2010, rigid cushion,
  /// slip at the nose and at the cloth, integrated over the impulse.
  mathavan_2010,
  /// "impulse_frictional": one frictional impulse at the nose against the
  /// half-space of the tilted contact normal, the slate holding the ball
  /// on the cloth: Newton's restitution on the final normal velocity
  /// (the ball leaves at -e times its normal velocity, whatever its spin),
  /// Coulomb friction capped by the impulse that stops the slip, and the
  /// friction never doing positive work.
  impulse_frictional,
  /// "stronge_compliant": Stronge's compliant contact at the nose, the
  /// slate holding the ball on the cloth: a normal spring that unloads
  /// stiffer than it loads (energetic restitution e) and a tangential
  /// spring in series with a Coulomb slider (stiffness ratio
  /// CushionParams::compliance_ratio), followed through the impact in time
  /// steps. The tangential spring lets the slip reverse.
  stronge_compliant,
};

/// Every cushion model, in the order messages and help texts list them.
inline constexpr CushionModel kCushionModels[] = {CushionModel::han_2005_v0, CushionModel::han_2005,
                                                  CushionModel::mathavan_2010,
                                                  CushionModel::impulse_frictional,
                                                  CushionModel::stronge_compliant};

/// Whether m is one of kCushionModels (an enum can hold other values).
constexpr bool is_cushion_model(CushionModel m) {
  for (const CushionModel k : kCushionModels) {
    if (k == m) return true;
  }
  return false;
}

/// The scenario name of a cushion model ("han_2005_v0", ...).
std::string_view cushion_model_name(CushionModel m);

/// The model of a scenario name; false for an unknown name.
bool parse_cushion_model(std::string_view name, CushionModel& out);

/// pooltool's default ball-cushion restitution (BallParams.e_c = 0.85),
/// the default restitution of the stronge_compliant model.
inline constexpr double kStrongeRestitution = 0.85;
/// The default ratio eta^2 of the nose's tangential to its normal
/// compliance (normal over tangential stiffness) for stronge_compliant:
/// pooltool's default frequency ratio omega_t / omega_n = 1.8 for a sphere
/// on a half-space, whose tangential-to-normal inverse-mass ratio is 7/2,
/// so eta^2 = (7/2) / 1.8^2 = 1.0802 (Poisson's ratio 0.14 by
/// eta^2 = (2 - nu) / (2 (1 - nu))).
inline constexpr double kStrongeComplianceRatio = 3.5 / (1.8 * 1.8);
/// The range of CushionParams::compliance_ratio a scenario may give: the
/// law's time step resolves tangential frequencies up to sqrt(350) times
/// the normal one (docs/physics.md, "Cushions").
inline constexpr double kMinComplianceRatio = 0.01;
inline constexpr double kMaxComplianceRatio = 100.0;

/// Each cushion law's default restitution (`table.cushion_restitution`
/// when not given; docs/physics.md, "Cushions"): han_2005_v0 keeps
/// breakshot 0.1's 0.75; han_2005's 0.84 and impulse_frictional's 0.914
/// make a rolling ball driven straight in come back at 0.914 of its
/// speed, as Mathavan et al. 2010's model does with its own fitted
/// constants; mathavan_2010 takes those constants, e = 0.98;
/// stronge_compliant takes pooltool's default cushion restitution, 0.85.
constexpr double default_cushion_restitution(CushionModel m) {
  switch (m) {
    case CushionModel::han_2005_v0:
      return 0.75;
    case CushionModel::han_2005:
      return 0.84;
    case CushionModel::mathavan_2010:
      return 0.98;
    case CushionModel::impulse_frictional:
      return 0.914;
    case CushionModel::stronge_compliant:
      return kStrongeRestitution;
  }
  return 0.75;
}

struct CushionParams {
  /// The cushion law (see CushionModel). The default, han_2005, is Han's
  /// law with the slate's reaction at the restitution that matches
  /// Mathavan et al. 2010's measurement-fitted model (docs/physics.md).
  CushionModel model = CushionModel::han_2005;
  /// Height of the nose contact above the cloth as a fraction of the
  /// ball's diameter (WPA: about 63.5 %). The contact normal is tilted
  /// t = asin(2 nose_height - 1) above the horizontal (15.7 degrees here).
  /// 0.5 puts the nose at the centre's height. Meaningful in (0, 1).
  double nose_height = 0.635;
  /// Height of the nose contact above the cloth in metres
  /// (`table.cushion_height`); 0 when not given. When > 0 it wins over
  /// nose_height for every ball: sin t = (height - R) / R for a ball of
  /// radius R, so balls of different sizes meet the same rail at their
  /// own angles. Must lie in (R, 2R) for every ball.
  double height = 0.0;
  /// Newton restitution along the tilted contact normal, in [0, 1]. It is
  /// not the ratio of rebound to incident speed: with the nose above the
  /// centre and friction, a rolling ball hitting straight on comes back at
  /// 0.914 of its speed under han_2005 at 0.84, and at (1 + e) cos t
  /// (cos t + mu sin t) - 1 (0.686 at 0.75) under han_2005_v0. Mathavan's
  /// fitted 0.98 belongs to his own model (mathavan_2010, whose default
  /// it is). Each law's default: default_cushion_restitution.
  double restitution = default_cushion_restitution(CushionModel::han_2005);
  /// Ball-rail sliding friction, >= 0: Mathavan et al. 2010 (Proc. IMechE
  /// C 224) fitted 0.14 together with e = 0.98 in their own model.
  double friction = 0.14;
  /// Ball-cloth sliding friction during the impact (mathavan_2010 only).
  /// The simulation sets it to physics.sliding_friction, the same cloth's
  /// friction; Mathavan et al. measured 0.212 on their snooker cloth.
  double cloth_friction = 0.212;
  /// The ratio eta^2 of the nose's tangential to its normal compliance
  /// (its normal over its tangential stiffness), stronge_compliant only
  /// (`table.cushion_compliance_ratio`). In [0.01, 100]; elastic bodies
  /// have 1 to 1.5 (Poisson's ratio 0 to 0.5).
  double compliance_ratio = kStrongeComplianceRatio;
};

/// The nose's height above the cloth (m) for a ball of `radius`: the
/// cushion height when given, else nose_height times the diameter. The
/// height a ball in flight must clear (docs/physics.md, "Airborne balls").
constexpr double cushion_nose_height(const CushionParams& c, double radius) {
  return c.height > 0.0 ? c.height : 2.0 * radius * c.nose_height;
}

/// Mathavan et al. 2010's contact height, h = 7R/5 ("cushion height in
/// both snooker and pool"), as a fraction of the diameter: the default
/// nose_height of the mathavan_2010 model.
inline constexpr double kMathavanNoseHeight = 0.7;
/// Mathavan et al. 2010's fitted ball-cushion restitution: the default
/// cushion restitution of the mathavan_2010 model.
inline constexpr double kMathavanRestitution = 0.98;

struct CushionImpact {
  Vec2 velocity;
  Vec3 spin;
};

/// A ball moving with velocity v and spin w hits a straight cushion whose
/// normal n (nonzero; normalized here) points into the table. Returns the
/// velocity and spin just after, by the law params.model. Every law acts
/// at the nose contact (height from params.height if > 0, else
/// params.nose_height), changes velocity and spin together and keeps the
/// ball on the cloth (no hop). The result never moves into the cushion
/// (v.n >= 0 up to rounding) and never has more kinetic energy (for
/// mathavan_2010 and stronge_compliant up to the integration's error). A ball not moving
/// into the cushion (v.n >= 0) is returned unchanged. The mass cancels
/// out. Only arithmetic and sqrt are used: results are bit-identical
/// wherever IEEE doubles are. Equations and their derivation:
/// src/physics/cushion.cpp.
CushionImpact cushion_impact(Vec2 v, Vec3 w, Vec2 n, double mass, double radius,
                             const CushionParams& params);

}  // namespace breakshot
