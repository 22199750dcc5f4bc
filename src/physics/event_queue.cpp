// The indexed heap of balls, ordered by their next event's time.
#include "physics/event_queue.hpp"

namespace breakshot::detail {

void EventQueue::reset(std::size_t n) {
  next_.resize(n);
  heap_.resize(n);
  pos_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    heap_[i] = static_cast<std::int32_t>(i);
    pos_[i] = static_cast<std::int32_t>(i);
  }
}

void EventQueue::build() {
  for (std::size_t k = heap_.size() / 2; k-- > 0;) sift_down(k);
}

void EventQueue::fix(std::int32_t i) {
  auto pos = static_cast<std::size_t>(pos_[static_cast<std::size_t>(i)]);
  while (pos > 0) {
    const std::size_t parent = (pos - 1) / 2;
    if (!less(heap_[pos], heap_[parent])) break;
    swap(pos, parent);
    pos = parent;
  }
  sift_down(pos);
}

void EventQueue::sift_down(std::size_t pos) {
  const std::size_t n = heap_.size();
  for (;;) {
    const std::size_t l = 2 * pos + 1;
    const std::size_t r = l + 1;
    std::size_t m = pos;
    if (l < n && less(heap_[l], heap_[m])) m = l;
    if (r < n && less(heap_[r], heap_[m])) m = r;
    if (m == pos) break;
    swap(pos, m);
    pos = m;
  }
}

}  // namespace breakshot::detail
