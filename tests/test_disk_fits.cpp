// disk_fits (table.hpp) gives wall_clearance(...) >= 0 sooner: the two must
// agree everywhere, most of all near the cushions, the jaws and outside.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "breakshot/carom.hpp"
#include "breakshot/snooker.hpp"
#include "breakshot/table.hpp"

namespace test_disk_fits {

using namespace breakshot;

namespace {

// Points over the table's box and a margin beyond it, half of them drawn
// near a wall (on either side of it), with radii from nothing to a ball's.
void agree_on(const Table& t, const std::string& name, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int near = 0;
  int fits = 0;
  for (int k = 0; k < 40000; ++k) {
    Vec2 p;
    if (k % 2 == 0) {
      p = {t.min.x - 0.1 + u(g) * (t.max.x - t.min.x + 0.2),
           t.min.y - 0.1 + u(g) * (t.max.y - t.min.y + 0.2)};
    } else {
      const Wall& w = t.walls[static_cast<std::size_t>(g() % t.walls.size())];
      const Vec2 on = w.kind == WallKind::segment ? w.a + (w.b - w.a) * u(g) : w.a;
      p = on + Vec2{(u(g) - 0.5) * 0.08, (u(g) - 0.5) * 0.08};
      ++near;
    }
    const double r = k % 5 == 0 ? 0.0 : u(g) * 0.03;
    const bool expected = wall_clearance(t, p, r) >= 0.0;
    ASSERT_EQ(disk_fits(t, p, r), expected)
        << name << ": p = (" << p.x << ", " << p.y << "), r = " << r;
    fits += expected ? 1 : 0;
  }
  // Both answers occur often, so the agreement says something.
  EXPECT_GT(fits, 4000) << name;
  EXPECT_LT(fits, 36000) << name;
  EXPECT_EQ(near, 20000);
}

TEST(DiskFits, AgreesWithWallClearanceOnEveryTable) {
  agree_on(make_pool_table("7ft"), "7ft", 1);
  agree_on(make_pool_table("9ft"), "9ft", 2);
  agree_on(make_snooker_table(), "snooker", 3);
  agree_on(make_carom_table(), "carom", 4);
  agree_on(make_rectangle({0.0, 0.0}, {1.0, 0.5}), "rectangle", 5);
  agree_on(make_polygon({{0, 0}, {1, 0}, {1, 1}, {0.5, 0.4}, {0, 1}}), "polygon with a reflex corner", 6);
}

}  // namespace

}  // namespace test_disk_fits
