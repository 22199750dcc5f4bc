// Large pages for large arrays (large_pages.hpp).
#include "physics/large_pages.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace breakshot::detail {

void advise_large_pages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kPage = std::uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t lo = (begin + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t hi = (begin + bytes) & ~(kPage - 1);
  if (hi > lo) {
    // A hint: where it is refused (no transparent huge pages), the
    // memory stays in small pages and works the same.
    (void)madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
  }
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace breakshot::detail
