// The balls ordered by their next event's time: an indexed 4-ary heap,
// or for many balls a calendar of time buckets (event_queue.hpp).
#include "physics/event_queue.hpp"

#include <algorithm>
#include <cmath>

#include "physics/large_pages.hpp"

namespace breakshot::detail {

void EventQueue::reset(std::size_t n) {
  reserve_large(next_, n);
  next_.resize(n);
  buckets_ = n >= kBucketBalls && n < kBucketMaxBalls;
  top_ = -1;
  if (buckets_) {
    heap_.clear();
    pos_.clear();
    // As many buckets as balls: rebuild() sizes them so that a few balls
    // fall in each.
    reserve_large(head_, n);
    reserve_large(bucket_of_, n);
    reserve_large(prev_, n);
    reserve_large(after_, n);
    head_.assign(n, -1);
    bucket_of_.assign(n, kOverflow);
    prev_.assign(n, -1);
    after_.assign(n, -1);
    spread_.reserve(n);
    overflow_ = -1;
    cur_ = 0;
    return;
  }
  reserve_large(heap_, n);
  reserve_large(pos_, n);
  heap_.resize(n);
  pos_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    heap_[i] = {0.0, static_cast<std::int32_t>(i)};
    pos_[i] = static_cast<std::int32_t>(i);
  }
}

void EventQueue::build() {
  if (buckets_) {
    // Every ball into the overflow list, then spread over the buckets.
    overflow_ = -1;
    for (std::size_t i = next_.size(); i-- > 0;) link(static_cast<std::int32_t>(i), kOverflow);
    rebuild();
    return;
  }
  const std::size_t n = heap_.size();
  if (n < 2) return;
  for (std::size_t k = (n - 2) / 4 + 1; k-- > 0;) sift_down(k);
}

// The bucket of a time: kOverflow beyond the last bucket (and for an
// infinite time), never one before cur_ (a time earlier than cur_'s start
// goes into cur_, which is searched whole; past the last bucket, into the
// overflow list, laid out again when it is reached). floor((t - base) / width) is
// non-decreasing in t, so a later time is never in an earlier bucket.
std::int32_t EventQueue::bucket_for(double t) const {
  const double q = (t - base_) / width_;
  if (!(q < static_cast<double>(head_.size()))) return kOverflow;
  std::int32_t k = q > 0.0 ? static_cast<std::int32_t>(q) : 0;
  if (k < cur_) k = cur_;
  return k < static_cast<std::int32_t>(head_.size()) ? k : kOverflow;
}

void EventQueue::link(std::int32_t i, std::int32_t bucket) {
  const auto ui = static_cast<std::size_t>(i);
  std::int32_t& head = bucket == kOverflow ? overflow_ : head_[static_cast<std::size_t>(bucket)];
  bucket_of_[ui] = bucket;
  prev_[ui] = -1;
  after_[ui] = head;
  if (head >= 0) prev_[static_cast<std::size_t>(head)] = i;
  head = i;
}

void EventQueue::unlink(std::int32_t i) {
  const auto ui = static_cast<std::size_t>(i);
  const std::int32_t p = prev_[ui];
  const std::int32_t a = after_[ui];
  if (p >= 0) {
    after_[static_cast<std::size_t>(p)] = a;
  } else if (bucket_of_[ui] == kOverflow) {
    overflow_ = a;
  } else {
    head_[static_cast<std::size_t>(bucket_of_[ui])] = a;
  }
  if (a >= 0) prev_[static_cast<std::size_t>(a)] = p;
}

// The earliest ball of the first bucket that holds any. When every
// bucket is empty (so every ball is in the overflow list) the calendar is
// laid out again; if no ball has a finite time, the earliest of the
// overflow list (by ball index) is on top.
void EventQueue::find_top() {
  const auto nb = static_cast<std::int32_t>(head_.size());
  while (cur_ < nb && head_[static_cast<std::size_t>(cur_)] < 0) ++cur_;
  if (cur_ == nb) {
    rebuild();
    while (cur_ < nb && head_[static_cast<std::size_t>(cur_)] < 0) ++cur_;
  }
  std::int32_t best = cur_ < nb ? head_[static_cast<std::size_t>(cur_)] : overflow_;
  for (std::int32_t j = after_[static_cast<std::size_t>(best)]; j >= 0;
       j = after_[static_cast<std::size_t>(j)]) {
    const Node a{next_[static_cast<std::size_t>(j)].time, j};
    const Node b{next_[static_cast<std::size_t>(best)].time, best};
    if (less(a, b)) best = j;
  }
  top_ = best;
}

// Lays the calendar out again from the balls of the overflow list (all of
// them, when called): its start is the earliest finite time, and its
// buckets as wide as six times the median distance of the finite times
// from it over the number of buckets (so a few balls to a bucket, and the
// calendar reaching past most balls' times). The median, not the mean: a
// ball whose next event is ages away must not widen every bucket. With no
// finite time, every ball stays in the overflow list and cur_ past the
// last bucket.
void EventQueue::rebuild() {
  const auto nb = static_cast<std::int32_t>(head_.size());
  double lo = INFINITY;
  for (std::int32_t j = overflow_; j >= 0; j = after_[static_cast<std::size_t>(j)]) {
    const double t = next_[static_cast<std::size_t>(j)].time;
    if (std::isfinite(t)) lo = std::min(lo, t);
  }
  if (!std::isfinite(lo)) {
    cur_ = nb;
    return;
  }
  spread_.clear();
  for (std::int32_t j = overflow_; j >= 0; j = after_[static_cast<std::size_t>(j)]) {
    const double t = next_[static_cast<std::size_t>(j)].time;
    if (std::isfinite(t)) spread_.push_back(t - lo);
  }
  const auto mid = spread_.begin() + static_cast<std::ptrdiff_t>(spread_.size() / 2);
  std::nth_element(spread_.begin(), mid, spread_.end());
  base_ = lo;
  width_ = 6.0 * *mid / static_cast<double>(nb);
  if (!(width_ > 0.0) || !std::isfinite(width_)) width_ = 1.0;
  cur_ = 0;
  std::int32_t j = overflow_;
  overflow_ = -1;
  while (j >= 0) {
    const std::int32_t a = after_[static_cast<std::size_t>(j)];
    link(j, bucket_for(next_[static_cast<std::size_t>(j)].time));
    j = a;
  }
}

void EventQueue::fix(std::int32_t i) {
  if (buckets_) {
    top_ = -1;
    unlink(i);
    link(i, bucket_for(next_[static_cast<std::size_t>(i)].time));
    return;
  }
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
