// Prediction against the other balls, the part inlined where partners are
// searched (predict.cpp, predict_balls.cpp): a pair of balls, written out
// for the ideal model, and the choice between every other ball and the
// cells around the ball's own. The rest is in predict_balls.cpp.
#pragma once

#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "physics/engine.hpp"
#include "physics/prediction.hpp"

namespace breakshot::detail {

// Inlined into the neighbour loops: it is most of the cost of an event.
// In the ideal model no ball ever accelerates: the quadratic case,
// written out.
[[gnu::always_inline]] inline void Engine::predict_ideal_pair(const Kinematics& ki,
                                                               std::int32_t j,
                                                               Prediction& best) const {
  const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  const double t = origin_;
  const double dt = t - B.t0;
  const Vec2 dp = B.p0 + B.v0 * dt - ki.p;
  const Vec2 dv = B.v0 - ki.v;
  const double b = dot(dp, dv);
  if (b >= 0.0) return;  // not approaching
  const double sigma = ki.radius + radius_[static_cast<std::size_t>(j)];
  const double c = norm2(dp) - sigma * sigma;
  // The root c / (-b + sqrt(b^2 - a c)) is at least c / (-2 b): skip
  // the square root when even that is later than the best so far.
  if (c > 0.0 && c > (best.time - t) * (-2.0 * b)) return;
  // first_contact_quadratic, inlined.
  double tau = 0.0;
  if (c > 0.0) {
    const double disc = b * b - norm2(dv) * c;
    if (disc < 0.0) return;
    tau = c / (-b + std::sqrt(disc));
  }
  consider(best, t + tau, EventKind::ball, j, counter_[static_cast<std::size_t>(j)]);
}

// The other models. `need` is kTranslating for a ball in place (it meets
// only balls that move), else kInPlay.
[[gnu::always_inline]] inline void Engine::predict_moving_pair(const Kinematics& ki,
                                                                std::int32_t j, std::uint32_t need,
                                                                Prediction& best) const {
  // The cheap rejections inline (most pairs end here), the rest out of
  // line in predict_accelerating_pair. A ball out of play meets nothing,
  // and a ball in place only balls that move; then the boxes.
  const Sweep& S = sweep_[static_cast<std::size_t>(j)];
  // Debug builds (the sanitizer run of the tests) check the copy.
  [[maybe_unused]] const Trajectory& B = traj_[static_cast<std::size_t>(j)];
  assert(S.lo == B.box_lo && S.hi == B.box_hi &&
         S.radius[0] == radius_[static_cast<std::size_t>(j)] &&
         ((S.flags & kInPlay) != 0) == !out_of_play(B.state) &&
         ((S.flags & kTranslating) != 0) == translating(B.state));
  if (!(S.flags & need)) return;
  const double sigma = ki.radius + S.radius[0];
  if (S.lo.x - ki.box_hi.x > sigma || ki.box_lo.x - S.hi.x > sigma ||
      S.lo.y - ki.box_hi.y > sigma || ki.box_lo.y - S.hi.y > sigma) {
    return;  // their paths never come within reach
  }
  predict_accelerating_pair(ki, j, best);
}

inline void Engine::predict_ball_pair(const Kinematics& ki, std::int32_t j,
                                      Prediction& best) const {
  if (ideal_) {
    predict_ideal_pair(ki, j, best);
  } else {
    predict_moving_pair(ki, j, ki.still ? kTranslating : kInPlay, best);
  }
}

// Every other ball, or with the grid those of the 3 x 3 cells around.
inline void Engine::predict_partners(std::int32_t i, const Kinematics& ki, Prediction& best) const {
  if (grid_.used()) {
    const std::int32_t cell = grid_.cell_of(i);
    const std::int32_t cx = cell % grid_.nx();
    const std::int32_t cy = cell / grid_.nx();
    predict_cells(i, ki, cx - 1, cx + 1, cy - 1, cy + 1, best);
  } else {
    // The balls before i, then those after it: the order of a loop over
    // every other ball, and the model's test chosen once.
    const auto n = static_cast<std::int32_t>(traj_.size());
    if (ideal_) {
      for (std::int32_t j = 0; j < i; ++j) predict_ideal_pair(ki, j, best);
      for (std::int32_t j = i + 1; j < n; ++j) predict_ideal_pair(ki, j, best);
    } else if (n <= 32) {
      // The cheap rejections of predict_moving_pair for every ball at
      // once, without a branch (which way each goes is as good as random,
      // and a mispredicted branch costs more than the tests): two bits
      // per ball (one per axis), set where the boxes stay apart. Then the
      // balls left, in index order.
#ifndef NDEBUG
      for (std::int32_t j = 0; j < n; ++j) {  // debug builds check the copies
        const auto uj = static_cast<std::size_t>(j);
        const Trajectory& B = traj_[uj];
        const Sweep& S = sweep_[uj];
        assert(S.lo == B.box_lo && S.hi == B.box_hi && S.radius[0] == radius_[uj] &&
               S.radius[1] == radius_[uj]);
        assert(((in_play_bits_ >> (2 * j)) & 1) == (out_of_play(B.state) ? 0u : 1u));
        assert(((translating_bits_ >> (2 * j)) & 1) == (translating(B.state) ? 1u : 0u));
      }
#endif
      std::uint64_t apart = 0;
#if defined(__SSE2__)
      // Both axes at once: the same subtractions and comparisons.
      const __m128d k_lo = _mm_set_pd(ki.box_lo.y, ki.box_lo.x);
      const __m128d k_hi = _mm_set_pd(ki.box_hi.y, ki.box_hi.x);
      const __m128d k_r = _mm_set1_pd(ki.radius);
      for (std::int32_t j = 0; j < n; ++j) {
        const Sweep& S = sweep_[static_cast<std::size_t>(j)];
        const __m128d reach = _mm_add_pd(k_r, _mm_loadu_pd(S.radius));
        const __m128d far = _mm_or_pd(_mm_cmpgt_pd(_mm_sub_pd(_mm_loadu_pd(&S.lo.x), k_hi), reach),
                                      _mm_cmpgt_pd(_mm_sub_pd(k_lo, _mm_loadu_pd(&S.hi.x)), reach));
        apart |= static_cast<std::uint64_t>(_mm_movemask_pd(far)) << (2 * j);
      }
#else
      for (std::int32_t j = 0; j < n; ++j) {
        const Sweep& S = sweep_[static_cast<std::size_t>(j)];
        const double sigma = ki.radius + S.radius[0];
        const auto x = static_cast<std::uint64_t>((S.lo.x - ki.box_hi.x > sigma) |
                                                  (ki.box_lo.x - S.hi.x > sigma));
        const auto y = static_cast<std::uint64_t>((S.lo.y - ki.box_hi.y > sigma) |
                                                  (ki.box_lo.y - S.hi.y > sigma));
        apart |= (x | (y << 1)) << (2 * j);
      }
#endif
      // A ball out of play meets nothing, a ball in place only balls that
      // move; and i is not its own partner.
      std::uint64_t near = ~(apart | (apart >> 1)) & (ki.still ? translating_bits_ : in_play_bits_);
      near &= ~(std::uint64_t{1} << (2 * i));
      while (near != 0) {
        const int j = std::countr_zero(near) / 2;
        near &= near - 1;
        predict_accelerating_pair(ki, j, best);
      }
    } else {
      const std::uint32_t need = ki.still ? kTranslating : kInPlay;
      for (std::int32_t j = 0; j < i; ++j) predict_moving_pair(ki, j, need, best);
      for (std::int32_t j = i + 1; j < n; ++j) predict_moving_pair(ki, j, need, best);
    }
  }
}

}  // namespace breakshot::detail
