// A decision's allowance (internal): the AI level's simulation budget,
// which keeps a decision deterministic, and its time budget, which does
// not (docs/ai.md, "Budget, threads and determinism").
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>

namespace breakshot::ai_detail {

/// A decision's remaining allowance: simulations (deterministic) and wall
/// time (not).
class Budget {
 public:
  Budget(std::int64_t simulations, double seconds)
      : left_(simulations > 0 ? simulations : -1),
        seconds_(seconds),
        start_(std::chrono::steady_clock::now()) {}

  /// Up to n simulations (all of them without a simulation budget).
  std::int64_t take(std::int64_t n) {
    if (left_ < 0) return n;
    const std::int64_t got = std::min(n, left_);
    left_ -= got;
    return got;
  }
  std::int64_t left() const { return left_ < 0 ? std::numeric_limits<std::int64_t>::max() : left_; }
  /// True once `fraction` of the time budget is spent (never without one).
  bool past(double fraction) const {
    if (seconds_ <= 0.0) return false;
    const std::chrono::duration<double> used = std::chrono::steady_clock::now() - start_;
    return used.count() >= fraction * seconds_;
  }

 private:
  std::int64_t left_;
  double seconds_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace breakshot::ai_detail
