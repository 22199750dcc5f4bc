// Cluster impacts (physics.ball_clusters; docs/physics-core.md,
// "Clusters"): a ball striking balls within kClusterGap of each other
// gathers the whole cluster, and cluster_impact() (cluster_impact.cpp)
// shares the blow among all its contacts at once.
#include <algorithm>
#include <cmath>

#include "physics/engine.hpp"

namespace breakshot::detail {

void Engine::reserve_cluster_work() {
  const std::size_t n = scenario_.balls.size();
  if (!scenario_.physics.ball_clusters || n > kClusterReserveBalls) return;
  // A cluster holds at most every ball; each impact on one adds an
  // event per pair that touched (about three per ball in a rack), and
  // the events of a spread rack come on top: reserve_events() counts
  // those.
  const std::size_t pairs = n * (n - 1) / 2;
  cluster_.group.reserve(n);
  cluster_.place.reserve(n);
  cluster_.member.reserve(n);
  cluster_.near.reserve(n);
  cluster_.bodies.reserve(n);
  cluster_.scratch.position.reserve(n);
  cluster_.scratch.velocity.reserve(n);
  cluster_.scratch.pairs.reserve(pairs);
  cluster_.scratch.pressed.reserve(pairs);
  cluster_.out.velocity.reserve(n);
  cluster_.out.touched.reserve(pairs);
}

// The cluster of an impact of i on j at t: i, j, then every ball whose
// place at t is within kClusterGap of a member's, in a chain, each moved
// to t as it joins. Members are taken in order and, for each, the
// candidates in increasing index, so the group (and so the result) is the
// same whether every ball is a candidate or only those of the cells
// nearby.
void Engine::gather_cluster(std::int32_t i, std::int32_t j, double t) {
  std::vector<std::int32_t>& group = cluster_.group;
  group.clear();
  group.push_back(i);
  group.push_back(j);
  const auto n = static_cast<std::int32_t>(traj_.size());
  const auto join = [&](std::size_t ug, Vec2 pg, std::int32_t k, Vec2 pk) {
    const auto uk = static_cast<std::size_t>(k);
    if (norm(pk - pg) - radius_[uk] - radius_[ug] < kClusterGap &&
        std::find(group.begin(), group.end(), k) == group.end()) {
      move_to(traj_[uk], t);
      group.push_back(k);
    }
  };
  if (grid_.used()) {
    // Only the balls of the cells within reach: a large scene pays for
    // the balls near the impact, not for all of them.
    const std::int32_t reach = cluster_.reach;
    std::vector<std::int32_t>& near = cluster_.near;
    for (std::size_t g = 0; g < group.size(); ++g) {
      const auto ug = static_cast<std::size_t>(group[g]);
      const Vec2 pg = traj_[ug].p0;
      const std::int32_t cx = grid_.cell_of(group[g]) % grid_.nx();
      const std::int32_t cy = grid_.cell_of(group[g]) / grid_.nx();
      near.clear();
      for (std::int32_t y = std::max(0, cy - reach); y <= std::min(grid_.ny() - 1, cy + reach);
           ++y) {
        for (std::int32_t x = std::max(0, cx - reach); x <= std::min(grid_.nx() - 1, cx + reach);
             ++x) {
          for (std::int32_t k = grid_.first(y * grid_.nx() + x); k >= 0; k = grid_.next(k)) {
            const MotionState sk = traj_[static_cast<std::size_t>(k)].state;
            if (!out_of_play(sk) && sk != MotionState::airborne) {
              near.push_back(k);
            }
          }
        }
      }
      std::sort(near.begin(), near.end());
      for (std::int32_t k : near) {
        join(ug, pg, k, position_at(traj_[static_cast<std::size_t>(k)], t));
      }
    }
  } else {
    // Every ball's place at t, once (balls out of play or in flight are
    // never gathered).
    std::vector<Vec2>& at = cluster_.place;
    std::vector<std::uint8_t>& member = cluster_.member;
    at.clear();
    member.assign(static_cast<std::size_t>(n), 0);
    for (std::int32_t k = 0; k < n; ++k) {
      const Trajectory& tk = traj_[static_cast<std::size_t>(k)];
      const bool gathered = !out_of_play(tk.state) && tk.state != MotionState::airborne;
      at.push_back(out_of_play(tk.state) ? Vec2{} : position_at(tk, t));
      // Balls never gathered count as members: nothing is tested for them.
      member[static_cast<std::size_t>(k)] = gathered ? 0 : 1;
    }
    member[static_cast<std::size_t>(i)] = 1;
    member[static_cast<std::size_t>(j)] = 1;
    for (std::size_t g = 0; g < group.size(); ++g) {
      const auto ug = static_cast<std::size_t>(group[g]);
      const Vec2 pg = traj_[ug].p0;
      for (std::int32_t k = 0; k < n; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        if (member[uk]) continue;  // in the group already, or never gathered
        // join's test, norm(d) - r_k - r_g < kClusterGap, cannot hold when
        // the squared distance is beyond (kClusterGap + r_k + r_g)^2 by far
        // more than rounding: the square root is skipped.
        const Vec2 d = at[uk] - pg;
        const double reach = kClusterGap + radius_[uk] + radius_[ug];
        if (norm2(d) > reach * reach * (1.0 + 1e-9)) continue;
        const std::size_t before = group.size();
        join(ug, pg, k, at[uk]);
        if (group.size() > before) member[uk] = 1;
      }
    }
  }
}

// An impact of i on j (both moved to t) when more balls lie within
// kClusterGap of them, or of each other, in a chain: the whole cluster is
// resolved at once (cluster_impact.hpp). Returns false, doing nothing,
// for a lone pair or a contact slower than collapse_speed; else applies
// the new velocities (spins unchanged; the pairwise impact on top when
// i and j still close), records a ball_ball event for
// (i, j) and then one for every other pair that exchanged an impulse, and
// predicts again for every ball of the cluster.
bool Engine::collide_cluster(std::int32_t i, std::int32_t j, double t) {
  const Trajectory& A = traj_[static_cast<std::size_t>(i)];
  const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  const Vec2 d = B.p0 - A.p0;
  const double len = norm(d);
  if (!(len > 0.0) || dot(A.v0 - B.v0, d) / len < scenario_.physics.collapse_speed) return false;
  gather_cluster(i, j, t);
  const std::vector<std::int32_t>& group = cluster_.group;
  if (group.size() < 3) return false;
  std::vector<ClusterBody>& bodies = cluster_.bodies;
  bodies.clear();
  for (std::int32_t k : group) {
    const auto uk = static_cast<std::size_t>(k);
    bodies.push_back({traj_[uk].p0, traj_[uk].v0, radius_[uk], scenario_.balls[uk].mass});
  }
  struct Restitution final : ClusterRestitution {
    const Engine* sim;
    const std::vector<std::int32_t>* ids;
    Restitution(const Engine* s, const std::vector<std::int32_t>* g) : sim(s), ids(g) {}
    double at(int a, int b) const override {
      return sim->pair_restitution((*ids)[static_cast<std::size_t>(a)], (*ids)[static_cast<std::size_t>(b)]);
    }
  };
  const Restitution restitution(this, &group);
  ClusterOutcome& r = cluster_.out;
  cluster_impact(bodies, restitution, cluster_.scratch, r);
  for (std::size_t g = 0; g < group.size(); ++g) {
    const std::int32_t k = group[g];
    if (scenario_.physics.model == Model::pool) {
      set_motion(k, r.velocity[g], traj_[static_cast<std::size_t>(k)].w0);
    } else {
      set_velocity(k, r.velocity[g]);
    }
    ++counter_[static_cast<std::size_t>(k)];
  }
  // A grazing contact (closing far slower than the balls slide past each
  // other) can leave the cluster's contacts with next to no impulse while
  // the pair, frozen where it touched, still closes: the pairwise impact
  // then settles that pair, so the same contact never comes up again.
  if (dot(traj_[static_cast<std::size_t>(j)].v0 - traj_[static_cast<std::size_t>(i)].v0, d) < 0.0) {
    collide_balls(i, j);
  }
  const Event ev = ball_ball_event(t, i, j);
  add_event(ev);
  for (const auto& [a, b] : r.touched) {
    const std::int32_t x = group[static_cast<std::size_t>(a)];
    const std::int32_t y = group[static_cast<std::size_t>(b)];
    if (std::min(x, y) == ev.ball && std::max(x, y) == ev.other) continue;
    add_event(ball_ball_event(t, x, y));
  }
  for (std::int32_t k : group) {
    note_change(k, t);
    predict(k);
    queue_.fix(k);
  }
  return true;
}

}  // namespace breakshot::detail
