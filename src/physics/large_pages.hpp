// Room for a large scene's per-ball arrays in the processor's large pages.
//
// An event of a large gas reads a ball, its neighbours and its place in
// the queue, all at random in hundreds of megabytes: with 4 KiB pages
// such reads miss the address translation cache as well as the data
// caches. Linux backs memory with 2 MiB pages where a program asks for
// them (madvise MADV_HUGEPAGE; under the setting "madvise", that of
// Debian's kernels, no one else gets them), which cuts those misses: 10^6
// disks of the ideal gas ran 1.10x as many events a second
// (docs/performance.md). The results do not change: only where the
// memory lies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace breakshot::detail {

// Smaller arrays gained nothing measurable (docs/experiments.md,
// 2026-11-26: no difference from 10^4 to 3x10^5 disks).
inline constexpr std::size_t kLargePageMinBytes = std::size_t{8} << 20;

// Asks for large pages over the 2 MiB-aligned part of [data, data + bytes)
// (a hint: nothing happens where the system has none, or outside Linux).
void advise_large_pages(void* data, std::size_t bytes);

// v.reserve(n), asking for large pages before the memory is first written
// when the array is large; then resize or assign it as usual.
template <class T>
void reserve_large(std::vector<T>& v, std::size_t n) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  if (n * sizeof(T) >= kLargePageMinBytes) advise_large_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace breakshot::detail
