// The event queue: each ball's earliest predicted event, and the balls in
// an indexed binary min-heap ordered by its time (DynamO's scheduler and
// sorter in one). Ties are broken by ball index, so that simultaneous
// events come out in a fixed order.
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

class EventQueue {
 public:
  // Room for n balls, in index order; their predictions are set next,
  // then build() orders them.
  void reset(std::size_t n);
  // Orders the heap once every ball's prediction is set (bottom-up).
  void build();

  bool empty() const { return heap_.empty(); }
  // The ball whose event comes first (the queue must not be empty).
  std::int32_t top() const { return heap_[0]; }

  const Prediction& next(std::int32_t i) const { return next_[static_cast<std::size_t>(i)]; }
  // Sets ball i's next event; fix(i) then restores the order.
  void set(std::int32_t i, const Prediction& p) { next_[static_cast<std::size_t>(i)] = p; }
  void fix(std::int32_t i);

 private:
  bool less(std::int32_t a, std::int32_t b) const {
    const double ta = next_[static_cast<std::size_t>(a)].time;
    const double tb = next_[static_cast<std::size_t>(b)].time;
    if (ta != tb) return ta < tb;
    return a < b;
  }
  void swap(std::size_t a, std::size_t b) {
    std::swap(heap_[a], heap_[b]);
    pos_[static_cast<std::size_t>(heap_[a])] = static_cast<std::int32_t>(a);
    pos_[static_cast<std::size_t>(heap_[b])] = static_cast<std::int32_t>(b);
  }
  void sift_down(std::size_t pos);

  std::vector<Prediction> next_;     // each ball's earliest event
  std::vector<std::int32_t> heap_;  // ball indices, min-heap on next_
  std::vector<std::int32_t> pos_;   // where each ball sits in heap_
};

}  // namespace breakshot::detail
