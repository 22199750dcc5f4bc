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
  Scenario s;
  s.physics.model = Model::pool;
  s.physics.ball_ball_restitution = 0.95;
  s.physics.ball_ball_friction_fit = true;
  s.physics.collapse_speed = kPoolCollapseSpeed;
  s.table = make_pool_table("9ft");
  const double r = 0.028575;
  s.balls.push_back({"cue", r, 0.17, 0.75});
  BallState cue;
  cue.position = s.table.head_spot;
  s.start.push_back(cue);
  for (const RackedBall& b : make_rack("nine_ball", s.table, r, 3)) {
    s.balls.push_back({b.id, r, 0.17, 0.75});
    BallState st;
    st.position = b.position;
    s.start.push_back(st);
  }
  CueSpec c;
  c.ball = 0;
  c.strike.speed = 7.0;
  s.cue = c;
  Simulation sim(s);
  const long before = g_allocations.load();
  sim.advance_to_rest();
  const long during = g_allocations.load() - before;
  EXPECT_GT(sim.event_count(), 20u);
  EXPECT_EQ(during, 0) << "allocations while simulating the break";
}
