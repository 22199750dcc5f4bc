// The cell grid (src/physics/cell_grid.hpp): a cell gives its balls with
// the one filed last first, and taking a ball out keeps the others'
// order. Ties between partners are settled by index, but the order in
// which partners are examined narrows each later root search's window
// (within_best), and a root found in another window may differ in its
// last bits: the order is part of the results, and a new way of keeping
// the cells must keep it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <list>
#include <random>
#include <vector>

#include "physics/cell_grid.hpp"

namespace test_cell_grid {

namespace {

using breakshot::Vec2;
using breakshot::detail::CellGrid;

std::vector<std::int32_t> members(const CellGrid& g, std::int32_t cell) {
  std::vector<std::int32_t> out;
  for (std::int32_t j = g.first(cell); j >= 0; j = g.next(j)) out.push_back(j);
  return out;
}

// Random filings and removals among few cells, so that some cells hold
// many balls, checked against lists after every change.
TEST(CellGrid, CellsKeepTheOrderOfAListWithTheNewestInFront) {
  constexpr std::size_t kBalls = 40;
  CellGrid g;
  // A 0.1 m square for 40 balls of 1 cm: 3 x 3 cells of 3.3 cm.
  ASSERT_TRUE(g.build(Vec2{0.0, 0.0}, Vec2{0.1, 0.1}, kBalls, 0.01));
  const std::int32_t cells = g.nx() * g.ny();
  ASSERT_GE(cells, 2);
  std::vector<std::list<std::int32_t>> ref(static_cast<std::size_t>(cells));
  std::vector<std::int32_t> where(kBalls, -1);
  std::mt19937_64 rng(7);
  std::size_t most = 0;
  for (int step = 0; step < 20000; ++step) {
    const auto i = static_cast<std::int32_t>(rng() % kBalls);
    const auto ui = static_cast<std::size_t>(i);
    if (where[ui] >= 0 && rng() % 4 != 0) {
      g.unlink(i);
      ref[static_cast<std::size_t>(where[ui])].remove(i);
      where[ui] = -1;
      EXPECT_EQ(g.cell_of(i), -1);
    } else if (where[ui] < 0) {
      // Skewed towards the first cells, so that they hold many balls.
      const auto c = static_cast<std::int32_t>(
          std::min<std::uint64_t>(rng() % 4, rng() % static_cast<std::uint64_t>(cells)));
      g.link(i, c);
      ref[static_cast<std::size_t>(c)].push_front(i);
      where[ui] = c;
      EXPECT_EQ(g.cell_of(i), c);
    }
    for (std::int32_t c = 0; c < cells; ++c) {
      const std::list<std::int32_t>& r = ref[static_cast<std::size_t>(c)];
      most = std::max(most, r.size());
      ASSERT_EQ(members(g, c), std::vector<std::int32_t>(r.begin(), r.end()))
          << "cell " << c << " after step " << step;
    }
  }
  EXPECT_GE(most, 10u);  // long lists were exercised
}

}  // namespace

}  // namespace test_cell_grid
