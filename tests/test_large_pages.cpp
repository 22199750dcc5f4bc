// Large pages for a large scene's arrays (src/physics/large_pages.hpp):
// a hint that must never change what the arrays hold or how they grow.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "physics/large_pages.hpp"

namespace test_large_pages {

namespace {

using breakshot::detail::advise_large_pages;
using breakshot::detail::kLargePageMinBytes;
using breakshot::detail::reserve_large;

TEST(LargePages, ReserveLargeGivesRoomAndKeepsIt) {
  const std::size_t n = 2 * kLargePageMinBytes / sizeof(double);  // past the threshold
  std::vector<double> v;
  reserve_large(v, n);
  ASSERT_GE(v.capacity(), n);
  const double* const before = v.data();
  v.resize(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<double>(i) * 0.5;
  // No reallocation: the room was taken before the memory was written.
  EXPECT_EQ(v.data(), before);
  // A smaller or equal request keeps the memory and the contents.
  reserve_large(v, n / 2);
  reserve_large(v, n);
  EXPECT_EQ(v.data(), before);
  for (std::size_t i = 0; i < n; i += 4099) EXPECT_EQ(v[i], static_cast<double>(i) * 0.5);
}

TEST(LargePages, SmallArraysAreReservedAsUsual) {
  std::vector<std::int32_t> v{1, 2, 3};
  reserve_large(v, 100);
  EXPECT_GE(v.capacity(), 100u);
  EXPECT_EQ(v, (std::vector<std::int32_t>{1, 2, 3}));  // reserve keeps what is there
}

TEST(LargePages, AdviceOnAnyRangeIsHarmless) {
  advise_large_pages(nullptr, 0);
  std::vector<char> small(100, 'x');
  advise_large_pages(small.data() + 1, 50);  // no whole large page inside: nothing asked
  EXPECT_EQ(small[1], 'x');
  std::vector<char> big(kLargePageMinBytes, 'y');
  advise_large_pages(big.data(), big.size());  // memory already written keeps its contents
  EXPECT_EQ(big[big.size() / 2], 'y');
  EXPECT_EQ(big.back(), 'y');
}

}  // namespace

}  // namespace test_large_pages
