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

// The balls in a 4-ary min-heap whose nodes hold the time with the ball,
// so that sifting reads one array (four children share a cache line or
// two) instead of reaching through each ball's prediction. The keys
// (time, ball index) are all different, so the ball on top is the one
// that any correct queue would give: the order of events does not depend
// on the heap's shape.
class EventQueue {
 public:
  // Room for n balls, in index order; their predictions are set next,
  // then build() orders them.
  void reset(std::size_t n);
  // Orders the heap once every ball's prediction is set (bottom-up).
  void build();

  bool empty() const { return heap_.empty(); }
  // The ball whose event comes first (the queue must not be empty).
  std::int32_t top() const { return heap_[0].ball; }

  const Prediction& next(std::int32_t i) const { return next_[static_cast<std::size_t>(i)]; }
  // Sets ball i's next event; fix(i) then restores the order.
  void set(std::int32_t i, const Prediction& p) {
    next_[static_cast<std::size_t>(i)] = p;
    heap_[static_cast<std::size_t>(pos_[static_cast<std::size_t>(i)])].time = p.time;
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

  std::vector<Prediction> next_;   // each ball's earliest event
  std::vector<Node> heap_;         // 4-ary min-heap: children of k at 4k+1 .. 4k+4
  std::vector<std::int32_t> pos_;  // where each ball sits in heap_
};

}  // namespace breakshot::detail
