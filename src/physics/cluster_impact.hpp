// Impacts on clusters of (nearly) touching balls, resolved as one
// simultaneous collision with Hertzian contacts (docs/physics-core.md,
// "Clusters"). The simulation uses it when PhysicsParams::ball_clusters is
// set; it can also be called on its own.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "breakshot/vec.hpp"

namespace breakshot {

/// One ball of a cluster at the instant of the impact.
struct ClusterBody {
  Vec2 position;
  Vec2 velocity;
  double radius = 0.0;
  double mass = 0.0;
};

/// The restitution of each pair of a cluster (indices into the bodies).
class ClusterRestitution {
 public:
  virtual ~ClusterRestitution() = default;
  virtual double at(int a, int b) const = 0;
};

/// The outcome: each body's velocity after the impact, and the pairs
/// (indices into the bodies, a < b) that exchanged an impulse, in order.
struct ClusterOutcome {
  std::vector<Vec2> velocity;
  std::vector<std::pair<int, int>> touched;
  int steps = 0;  ///< integration steps taken
};

/// A pair of bodies watched during an impact (working state).
struct ClusterPair {
  int a = 0;
  int b = 0;
  double reach = 0.0;      ///< sum of the radii
  double reach2 = 0.0;     ///< reach * reach
  double stiffness = 0.0;  ///< k in F = k d^(3/2)
  double reduced = 0.0;    ///< reduced mass
  Vec2 force;              ///< on b at the current positions (minus on a)
  Vec2 impulse;            ///< on b, accumulated (minus on a)
};

/// Working memory of cluster_impact, kept between calls so that an impact
/// allocates nothing once the vectors have grown to the cluster's size.
struct ClusterScratch {
  std::vector<Vec2> position;
  std::vector<Vec2> velocity;
  std::vector<ClusterPair> pairs;
  /// The pairs pressed together at the current positions (a nonzero
  /// force), in pair order: the kicks go through these alone.
  std::vector<std::size_t> pressed;
};

/// Young's modulus (Pa) and Poisson ratio of a phenolic resin ball: the
/// contact stiffness sets how long a contact lasts against the time it
/// takes to close a gap. Assumed values for cast phenolic resin; for
/// gaps much smaller than the compression (a tight rack) the outcome does
/// not depend on them, as the equations scale.
inline constexpr double kBallYoungModulus = 5.0e9;
inline constexpr double kBallPoisson = 0.35;

/// Balls nearer than this (m, surface to surface) to a ball of the cluster
/// belong to it.
inline constexpr double kClusterGap = 0.5e-3;

/// Resolves an impact on `bodies`, which are where they are at the instant
/// of the impact (no friction with the cloth or between the balls during
/// the contact, which lasts a fraction of a millisecond): the bodies move
/// under the Hertz contact forces F = k d^(3/2) (d the overlap,
/// k = 4/3 E* sqrt(R*)) by velocity Verlet steps of 1/16 of the shortest
/// contact's duration, jumping over free flight, until no pair overlaps
/// and none closes on another sooner than four contact durations. Each
/// pair's impulse is then scaled by (1 + e) / 2 with e its restitution,
/// which for two bodies gives exactly the restitution law; momentum is
/// conserved in every case. Positions are not changed: the impact is
/// instantaneous for the caller. Deterministic: plain arithmetic, sqrt and
/// breakshot::dm only.
void cluster_impact(const std::vector<ClusterBody>& bodies, const ClusterRestitution& restitution,
                    ClusterScratch& scratch, ClusterOutcome& out);

}  // namespace breakshot
