// Simulating a shot allocates no memory once the Simulation is set up:
// the AI will simulate thousands of shots per decision. Global operator
// new is replaced in this test binary to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace breakshot;

TEST(NoAllocation, PoolBreakAfterSetUp) {
  Scenario s = make_break_scenario("nine_ball", "9ft", 3, 7.0);
  Simulation sim(s);
  const long before = g_allocations.load();
  sim.advance_to_rest();
  const long during = g_allocations.load() - before;
  EXPECT_GT(sim.event_count(), 20u);
  EXPECT_EQ(during, 0) << "allocations while simulating the break";
}

TEST(NoAllocation, HardEightBallBreakWithClusterImpacts) {
  Scenario s = make_break_scenario("eight_ball", "9ft", 5, 11.0);
  ASSERT_TRUE(s.physics.ball_clusters);
  Simulation sim(s);
  const long before = g_allocations.load();
  sim.advance_to_rest();
  const long during = g_allocations.load() - before;
  EXPECT_GT(sim.event_count(), 20u);
  EXPECT_EQ(during, 0) << "allocations while simulating the break";
}
