// The event queue (src/physics/event_queue.hpp): the 4-ary heap and the
// calendar of time buckets must put the same ball on top after every
// change, the earliest by (time, ball index), which a plain scan finds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "physics/event_queue.hpp"

namespace test_event_queue {

namespace {

using breakshot::detail::EventKind;
using breakshot::detail::EventQueue;
using breakshot::detail::kBucketBalls;
using breakshot::detail::kBucketMaxBalls;
using breakshot::detail::Prediction;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The earliest ball by (time, index): what any queue must put on top.
std::int32_t scan_top(const std::vector<double>& t) {
  std::int32_t best = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] < t[static_cast<std::size_t>(best)]) best = static_cast<std::int32_t>(i);
  }
  return best;
}

// Plays an event loop on n balls: the ball on top takes its event and gets
// a later time (sometimes never), a partner is moved too, and now and then
// a ball's time is set to the present (a contact at once) or ties another
// ball's exactly. Checks the top against a scan after every change.
void play(std::size_t n, std::uint64_t seed, int steps) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  EventQueue q;
  q.reset(n);
  std::vector<double> t(n);
  const auto put = [&](std::size_t i, double time) {
    t[i] = time;
    Prediction p;
    p.time = time;
    p.kind = std::isfinite(time) ? EventKind::wall : EventKind::none;
    q.set(static_cast<std::int32_t>(i), p);
  };
  for (std::size_t i = 0; i < n; ++i) put(i, i % 7 == 3 ? kInf : u(g) * 2.0);
  q.build();
  double now = 0.0;
  for (int s = 0; s < steps; ++s) {
    const std::int32_t top = q.top();
    ASSERT_EQ(top, scan_top(t)) << "n " << n << " step " << s;
    const auto ui = static_cast<std::size_t>(top);
    if (!std::isfinite(t[ui])) {
      // Nothing left to happen: start some balls again.
      for (std::size_t k = 0; k < n; k += 3) {
        put(k, now + u(g));
        q.fix(static_cast<std::int32_t>(k));
      }
      continue;
    }
    now = t[ui];
    const double r = u(g);
    put(ui, r < 0.05 ? kInf : now + u(g) * (r < 0.5 ? 0.01 : 3.0));
    q.fix(top);
    const auto other = static_cast<std::size_t>(g() % n);
    const double r2 = u(g);
    if (r2 < 0.1) {
      put(other, now);  // at once
    } else if (r2 < 0.2) {
      put(other, t[static_cast<std::size_t>(g() % n)]);  // a tie
    } else if (r2 < 0.25) {
      put(other, kInf);
    } else {
      put(other, now + u(g));
    }
    q.fix(static_cast<std::int32_t>(other));
  }
}

TEST(EventQueue, HeapPutsTheEarliestOnTop) { play(kBucketBalls - 1, 1, 20000); }

TEST(EventQueue, CalendarPutsTheEarliestOnTop) {
  play(kBucketBalls, 2, 20000);
  play(3 * kBucketBalls + 5, 3, 20000);
}

TEST(EventQueue, CalendarWithEveryBallNeverOrAtOnce) {
  // Only infinite times, then every ball at the same instant.
  const std::size_t n = kBucketBalls + 1;
  EventQueue q;
  q.reset(n);
  for (std::size_t i = 0; i < n; ++i) q.set(static_cast<std::int32_t>(i), Prediction{kInf, EventKind::none, -1, 0});
  q.build();
  EXPECT_EQ(q.top(), 0);
  for (std::size_t i = n; i-- > 0;) {
    q.set(static_cast<std::int32_t>(i), Prediction{1.5, EventKind::wall, -1, 0});
    q.fix(static_cast<std::int32_t>(i));
    EXPECT_EQ(q.top(), static_cast<std::int32_t>(i));  // the lowest index of the tied ones
  }
}

TEST(EventQueue, LargeSceneUsesTheHeapAgain) {
  EXPECT_LT(kBucketBalls, kBucketMaxBalls);
  play(kBucketMaxBalls, 4, 300);
}

}  // namespace

}  // namespace test_event_queue
