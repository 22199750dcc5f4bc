// Simultaneous impacts on clusters of balls (cluster_impact.hpp).
//
// Pairwise, instantaneous impacts pass a blow through a chain of balls
// one contact at a time, as in Newton's cradle: a break shot then sends
// nearly all its energy into the rack's last balls and leaves the rest
// where they were racked. Real balls are in contact for about 0.2 ms,
// far longer than the cue ball takes to close a rack's tenths of a
// millimetre of gaps, so the contacts overlap in time and share the blow.
// Here the cluster's contacts are integrated together under Hertz's law
// (Johnson, Contact Mechanics, 1985, ch. 4), which is how a numerical
// study of the perfectly racked break obtained its ball speeds
// (docs/physics-core.md, "Clusters", compares them).
#include "physics/cluster_impact.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

#include "physics/detmath.hpp"

namespace breakshot {

namespace {

/// Two doubles in one register where the target has one (GCC's and
/// clang's vector extension; element-wise IEEE operations).
typedef double V2 __attribute__((vector_size(16)));
static_assert(sizeof(Vec2) == sizeof(V2));

/// Pairs whose surfaces start further apart than this (m) are not
/// watched: no ball moves that far during an impact.
constexpr double kWatchGap = 0.01;
/// Verlet steps per contact duration: 16 give the published break of
/// tests/test_cluster_impact.cpp to within 0.02 (cue ball at 10) of 64.
constexpr double kStepsPerContact = 16.0;
/// A pair closing from further than this many contact durations away is
/// left to the event loop (a separate, later impact).
constexpr double kHorizonContacts = 4.0;
/// Bound on the work of one impact (steps and free-flight jumps).
constexpr int kMaxSteps = 200000;



/// Duration of a Hertz contact closing at `speed` (Johnson, eq. 11.24):
/// 2.94 times the greatest compression over the speed.
double contact_duration(const ClusterPair& p, double speed) {
  const double compression =
      dm::pow(5.0 * p.reduced * speed * speed / (4.0 * p.stiffness), 0.4);
  return 2.9432 * compression / speed;
}

}  // namespace

void cluster_impact(const std::vector<ClusterBody>& bodies, const ClusterRestitution& restitution,
                    ClusterScratch& scratch, ClusterOutcome& out) {
  const int n = static_cast<int>(bodies.size());
  std::vector<Vec2>& p = scratch.position;
  std::vector<Vec2>& v = scratch.velocity;
  std::vector<ClusterPair>& pairs = scratch.pairs;
  std::vector<std::size_t>& pressed = scratch.pressed;
  p.clear();
  v.clear();
  pairs.clear();
  out.velocity.clear();
  out.touched.clear();
  out.steps = 0;
  for (const ClusterBody& b : bodies) {
    p.push_back(b.position);
    v.push_back(b.velocity);
    out.velocity.push_back(b.velocity);
  }

  const double e_star = kBallYoungModulus / (2.0 * (1.0 - kBallPoisson * kBallPoisson));
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      const ClusterBody& A = bodies[static_cast<std::size_t>(a)];
      const ClusterBody& B = bodies[static_cast<std::size_t>(b)];
      ClusterPair q;
      q.a = a;
      q.b = b;
      q.reach = A.radius + B.radius;
      q.reach2 = q.reach * q.reach;
      if (norm(B.position - A.position) - q.reach > kWatchGap) continue;
      const double r_star = A.radius * B.radius / q.reach;
      q.stiffness = 4.0 / 3.0 * e_star * std::sqrt(r_star);
      q.reduced = A.mass * B.mass / (A.mass + B.mass);
      pairs.push_back(q);
    }
  }

  // Raw views of the working memory: the loops below run hundreds of
  // times per impact, and the vectors' sizes do not change in them.
  Vec2* const P = p.data();
  Vec2* const V = v.data();
  ClusterPair* const Q = pairs.data();
  const std::size_t np = pairs.size();
  const std::size_t nb = p.size();

  // The step: from the fastest closing speed in the cluster, the shortest
  // contact there will be (slower contacts last longer).
  double fastest = 0.0;
  for (std::size_t k = 0; k < np; ++k) {
    const ClusterPair& q = Q[k];
    const Vec2 d = P[q.b] - P[q.a];
    const double len = norm(d);
    if (len > 0.0) fastest = std::max(fastest, -dot(V[q.b] - V[q.a], d) / len);
  }
  if (np == 0 || !(fastest > 0.0)) return;
  // Pairs of the same balls (all of them, in a rack) have the same
  // duration: it is computed once for each run of equal pairs.
  double shortest = std::numeric_limits<double>::infinity();
  double last_reduced = -1.0;
  double last_stiffness = -1.0;
  double last_duration = 0.0;
  for (std::size_t k = 0; k < np; ++k) {
    const ClusterPair& q = Q[k];
    if (q.reduced != last_reduced || q.stiffness != last_stiffness) {
      last_reduced = q.reduced;
      last_stiffness = q.stiffness;
      last_duration = contact_duration(q, fastest);
    }
    shortest = std::min(shortest, last_duration);
  }
  const double dt = shortest / kStepsPerContact;
  const double horizon = kHorizonContacts * shortest;

  // The pairs pressed together, in pair order (room for all of them, so
  // that adding one is a store).
  pressed.resize(np);
  std::size_t* const pressed_at = pressed.data();
  std::size_t n_pressed = 0;
  // Each body's mass, for the kicks.
  const ClusterBody* const body = bodies.data();

  // Forces at the current positions, and the pairs that have one (in
  // pair order, so that the kicks add up in the same order as over every
  // pair); true if any pair overlaps. A pair without a force keeps a
  // stale one, which nothing reads.
  const auto compute_forces = [&]() {
    bool any = false;
    n_pressed = 0;
    for (std::size_t k = 0; k < np; ++k) {
      ClusterPair& q = Q[k];
      // d = p_b - p_a and dd = d.x d.x + d.y d.y, the two lanes at once:
      // the same IEEE operations as Vec2's, so the same bits.
      V2 pa, pb;
      std::memcpy(&pa, &P[q.a], sizeof pa);
      std::memcpy(&pb, &P[q.b], sizeof pb);
      const V2 dv = pb - pa;
      const V2 sq = dv * dv;
      const double dd = sq[0] + sq[1];
      if (dd >= q.reach2) continue;  // apart: no force, and no square root
      const Vec2 d{dv[0], dv[1]};
      const double len = std::sqrt(dd);
      const double overlap = q.reach - len;
      if (overlap > 0.0 && len > 0.0) {
        q.force = d * (q.stiffness * overlap * std::sqrt(overlap) / len);
        any = true;
        if (q.force.x != 0.0 || q.force.y != 0.0) pressed_at[n_pressed++] = k;
      }
    }
    return any;
  };
  const auto kick = [&](double h) {
    for (std::size_t m = 0; m < n_pressed; ++m) {
      ClusterPair& q = Q[pressed_at[m]];
      const Vec2 j = q.force * h;
      q.impulse = q.impulse + j;
      V[q.a] = V[q.a] - j / body[q.a].mass;
      V[q.b] = V[q.b] + j / body[q.b].mass;
    }
  };

  bool touching = compute_forces();
  while (out.steps < kMaxSteps) {
    ++out.steps;
    if (!touching) {
      // Free flight: on to the next contact among the watched pairs, if it
      // comes within the horizon.
      double next = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < np; ++k) {
        const ClusterPair& q = Q[k];
        const Vec2 d = P[q.b] - P[q.a];
        const Vec2 w = V[q.b] - V[q.a];
        const double dw = dot(d, w);
        const double ww = dot(w, w);
        if (!(dw < 0.0) || !(ww > 0.0)) continue;
        const double gap2 = dot(d, d) - q.reach2;
        if (gap2 <= 0.0) {
          next = 0.0;
          break;
        }
        const double disc = dw * dw - ww * gap2;
        if (disc < 0.0) continue;
        next = std::min(next, (-dw - std::sqrt(disc)) / ww);
      }
      if (!(next <= horizon)) break;
      for (std::size_t k = 0; k < nb; ++k) P[k] = P[k] + V[k] * next;
    }
    kick(0.5 * dt);
    for (std::size_t k = 0; k < nb; ++k) P[k] = P[k] + V[k] * dt;
    touching = compute_forces();
    kick(0.5 * dt);
  }

  // Each pair's impulse, scaled for its restitution, from the velocities
  // before the impact.
  for (const ClusterPair& q : pairs) {
    if (q.impulse.x == 0.0 && q.impulse.y == 0.0) continue;
    const Vec2 j = q.impulse * (0.5 * (1.0 + restitution.at(q.a, q.b)));
    out.velocity[static_cast<std::size_t>(q.a)] =
        out.velocity[static_cast<std::size_t>(q.a)] - j / bodies[static_cast<std::size_t>(q.a)].mass;
    out.velocity[static_cast<std::size_t>(q.b)] =
        out.velocity[static_cast<std::size_t>(q.b)] + j / bodies[static_cast<std::size_t>(q.b)].mass;
    out.touched.emplace_back(q.a, q.b);
  }
}

}  // namespace breakshot
