// Simulating a shot allocates no memory once the Simulation is set up:
// the AI will simulate thousands of shots per decision. Global operator
// new is replaced in this test binary to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

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

namespace {

/// Simulates `s` to rest and returns the allocations made after set-up.
long allocations_to_rest(const Scenario& s, std::uint64_t* events) {
  Simulation sim(s);
  const long before = g_allocations.load();
  sim.advance_to_rest();
  const long during = g_allocations.load() - before;
  *events = sim.event_count();
  return during;
}

}  // namespace

TEST(NoAllocation, PoolBreakAfterSetUp) {
  std::uint64_t events = 0;
  const long during = allocations_to_rest(make_break_scenario("nine_ball", "9ft", 3, 7.0), &events);
  EXPECT_GT(events, 20u);
  EXPECT_EQ(during, 0) << "allocations while simulating the break";
}

TEST(NoAllocation, HardEightBallBreakWithClusterImpacts) {
  const Scenario s = make_break_scenario("eight_ball", "9ft", 5, 11.0);
  ASSERT_TRUE(s.physics.ball_clusters);
  std::uint64_t events = 0;
  const long during = allocations_to_rest(s, &events);
  EXPECT_GT(events, 20u);
  EXPECT_EQ(during, 0) << "allocations while simulating the break";
}

// Re-arming one simulation for shot after shot (Simulation::reset) touches
// the heap no more once it has held the largest of the shots: the AI's
// rollouts and batch shots rely on it.
TEST(NoAllocation, ResetForShotAfterShot) {
  std::vector<Scenario> shots;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    shots.push_back(make_break_scenario(seed % 2 ? "eight_ball" : "nine_ball", "9ft", seed,
                                        5.0 + 0.25 * static_cast<double>(seed)));
  }
  Simulation sim(shots.front());
  sim.advance_to_rest();
  const long before = g_allocations.load();
  std::uint64_t events = 0;
  for (const Scenario& s : shots) {
    sim.reset(s);
    sim.advance_to_rest();
    events += sim.event_count();
  }
  EXPECT_GT(events, 24u * 50u);
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations while re-arming and simulating";
}
