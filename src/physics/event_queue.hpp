// The event queue: each ball's earliest predicted event, and the balls in
// an indexed min-heap ordered by its time (DynamO's scheduler and sorter
// in one). Ties are broken by ball index, so that simultaneous events
// come out in a fixed order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace breakshot::detail {

// What a ball's next event is. Kinds in the order simultaneous events of
// one ball are taken.
enum class EventKind : std::uint8_t { ball, wall, pocket, off, stop, cell, none };

// A ball's earliest predicted event. Ball-ball predictions remember the
// partner's event counter so that one made stale by the partner's own
// later event is recognised when it comes up, instead of being searched
// for and removed (the DynamO way).
struct Prediction {
  double time = 0.0;
  EventKind kind = EventKind::none;
  std::int32_t other = -1;          // ball, wall, pocket, or cell direction
  std::uint64_t other_counter = 0;  // partner's counter at prediction
};

// Few balls (a game of pool) and very many sit in a 4-ary min-heap whose
// nodes hold the time with the ball, so that sifting reads one array
// instead of reaching through each ball's prediction. From kBucketBalls
// up to kBucketMaxBalls they sit in a calendar of time buckets (DynamO's
// bounded queue, simplified): the ball on top is the earliest of the
// first bucket that holds any, and moving a ball is taking it out of one
// list and into another, where a heap pays for several unpredictable
// comparisons a level (in an ideal gas, 10-25 % more events a second from
// 200 to 10^4 balls). Beyond about 3x10^5 balls the lists' links are
// cache misses and the heap is faster again (docs/experiments.md,
// 2026-11-26). Either way the keys (time, ball index) are all different,
// so the ball on top is the one that any correct queue would give: the
// order of events does not depend on how the queue is kept.
inline constexpr std::size_t kBucketBalls = 128;
inline constexpr std::size_t kBucketMaxBalls = 262144;

class EventQueue {
 public:
  // Room for n balls, in index order; their predictions are set next,
  // then build() orders them.
  void reset(std::size_t n);
  // Orders the queue once every ball's prediction is set.
  void build();

  bool empty() const { return next_.empty(); }
  // The ball whose event comes first (the queue must not be empty).
  std::int32_t top() {
    if (!buckets_) return heap_[0].ball;
    if (top_ < 0) find_top();
    return top_;
  }

  const Prediction& next(std::int32_t i) const { return next_[static_cast<std::size_t>(i)]; }
  // Sets ball i's next event; fix(i) then restores the order.
  void set(std::int32_t i, const Prediction& p) {
    next_[static_cast<std::size_t>(i)] = p;
    if (buckets_) {
      top_ = -1;
    } else {
      heap_[static_cast<std::size_t>(pos_[static_cast<std::size_t>(i)])].time = p.time;
    }
  }
  void fix(std::int32_t i);

 private:
  struct Node {
    double time;
    std::int32_t ball;
  };
  // Earlier time first, ties by ball index.
  static bool less(const Node& a, const Node& b) {
    if (a.time != b.time) return a.time < b.time;
    return a.ball < b.ball;
  }
  void place(std::size_t at, const Node& x) {
    heap_[at] = x;
    pos_[static_cast<std::size_t>(x.ball)] = static_cast<std::int32_t>(at);
  }
  void sift_down(std::size_t pos);
  void sift_up(std::size_t pos);

  // The calendar: bucket k holds the balls whose time t has
  // floor((t - base_) / width_) = k, for k below the number of buckets;
  // the others (later, or never) are in the overflow list. Every ball is
  // in one doubly linked list.
  static constexpr std::int32_t kOverflow = -1;
  std::int32_t bucket_for(double t) const;
  void link(std::int32_t i, std::int32_t bucket);
  void unlink(std::int32_t i);
  void find_top();
  void rebuild();

  std::vector<Prediction> next_;   // each ball's earliest event
  bool buckets_ = false;           // the calendar (else the heap)
  std::vector<Node> heap_;         // 4-ary min-heap: children of k at 4k+1 .. 4k+4
  std::vector<std::int32_t> pos_;  // where each ball sits in heap_
  std::vector<std::int32_t> head_;       // first ball of each bucket, or -1
  std::vector<std::int32_t> bucket_of_;  // each ball's bucket, or kOverflow
  std::vector<std::int32_t> prev_;       // neighbours in the ball's list, or -1
  std::vector<std::int32_t> after_;
  std::vector<double> spread_;  // rebuild()'s working memory
  std::int32_t overflow_ = -1;  // first ball of the overflow list
  double base_ = 0.0;
  double width_ = 1.0;
  std::int32_t cur_ = 0;   // no ball is in a bucket before this one
  std::int32_t top_ = -1;  // the ball on top, if known
};

}  // namespace breakshot::detail
