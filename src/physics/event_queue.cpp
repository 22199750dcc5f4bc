// The indexed 4-ary heap of balls, ordered by their next event's time.
#include "physics/event_queue.hpp"

namespace breakshot::detail {

void EventQueue::reset(std::size_t n) {
  next_.resize(n);
  heap_.resize(n);
  pos_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    heap_[i] = {0.0, static_cast<std::int32_t>(i)};
    pos_[i] = static_cast<std::int32_t>(i);
  }
}

void EventQueue::build() {
  const std::size_t n = heap_.size();
  if (n < 2) return;
  for (std::size_t k = (n - 2) / 4 + 1; k-- > 0;) sift_down(k);
}

void EventQueue::fix(std::int32_t i) {
  const auto pos = static_cast<std::size_t>(pos_[static_cast<std::size_t>(i)]);
  if (pos > 0 && less(heap_[pos], heap_[(pos - 1) / 4])) {
    sift_up(pos);
  } else {
    sift_down(pos);
  }
}

// The node at pos moves up past every parent later than it; the parents
// move down into the hole.
void EventQueue::sift_up(std::size_t pos) {
  const Node x = heap_[pos];
  while (pos > 0) {
    const std::size_t parent = (pos - 1) / 4;
    if (!less(x, heap_[parent])) break;
    place(pos, heap_[parent]);
    pos = parent;
  }
  place(pos, x);
}

// The node at pos moves down past every child earlier than it; the
// earliest child moves up into the hole at each level.
void EventQueue::sift_down(std::size_t pos) {
  const std::size_t n = heap_.size();
  const Node x = heap_[pos];
  for (;;) {
    const std::size_t first = 4 * pos + 1;
    if (first >= n) break;
    std::size_t m = first;
    if (first + 4 <= n) {
      // Four children: the earlier of each pair, then of the two.
      const std::size_t a = less(heap_[first + 1], heap_[first]) ? first + 1 : first;
      const std::size_t b = less(heap_[first + 3], heap_[first + 2]) ? first + 3 : first + 2;
      m = less(heap_[b], heap_[a]) ? b : a;
    } else {
      for (std::size_t c = first + 1; c < n; ++c) {
        if (less(heap_[c], heap_[m])) m = c;
      }
    }
    if (!less(heap_[m], x)) break;
    place(pos, heap_[m]);
    pos = m;
  }
  place(pos, x);
}

}  // namespace breakshot::detail
