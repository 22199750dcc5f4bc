// A recorded run read back (src/physics/run_record.hpp): Replay answers
// advance_to, time and balls exactly as a Simulation advanced through the
// same times does, without running the physics again.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "physics/run_record.hpp"

namespace test_run_record {

using namespace breakshot;

namespace {

BallState moving(Vec2 p, Vec2 v) {
  BallState s;
  s.position = p;
  s.velocity = v;
  s.state = (v.x != 0.0 || v.y != 0.0) ? MotionState::moving : MotionState::stationary;
  return s;
}

// A striker into a row of five touching balls: collisions at one instant,
// so that max_events can stop the run between two events at one time.
Scenario cradle() {
  Scenario s;
  s.physics.model = Model::ideal;
  s.table = make_rectangle({0.0, 0.0}, {2.0, 0.2});
  s.balls.push_back(BallSpec{"s", 0.02, 0.1, 1.0});
  s.start.push_back(moving({0.3, 0.1}, {1.0, 0.0}));
  for (int k = 0; k < 5; ++k) {
    s.balls.push_back(BallSpec{"r" + std::to_string(k), 0.02, 0.1, 1.0});
    s.start.push_back(moving({0.8 + 0.04 * k, 0.1}, {0.0, 0.0}));
  }
  s.until.rest = false;
  s.until.time = 3.0;
  return s;
}

// 60 balls: the grid of cells, with cell crossings between the events.
Scenario gas() {
  Scenario s;
  s.physics.model = Model::ideal;
  s.table = make_rectangle({0.0, 0.0}, {1.0, 1.0});
  for (int k = 0; k < 60; ++k) {
    s.balls.push_back(BallSpec{"g" + std::to_string(k), 0.02, 0.1, 1.0});
    s.start.push_back(moving({0.06 + 0.125 * (k % 8), 0.06 + 0.125 * (k / 8)},
                             {std::cos(1.3 * k), std::sin(1.7 * k)}));
  }
  s.until.rest = false;
  s.until.time = 1.0;
  return s;
}

// Every event time, the times between them, and the end.
std::vector<double> times_of(const RunResult& r, double end) {
  std::vector<double> t{0.0};
  for (const Event& e : r.events) {
    if (e.time > t.back()) t.push_back(0.5 * (t.back() + e.time));
    if (e.time >= t.back()) t.push_back(e.time);
  }
  if (end > t.back()) t.push_back(end);
  return t;
}

}  // namespace

TEST(RunRecord, ReplayGivesTheStatesOfTheSimulationAtAnyTimeOfTheRun) {
  std::vector<Scenario> scenarios{cradle(), gas(), make_break_scenario("eight_ball", "9ft", 1, 7.5)};
  for (const Scenario& base : scenarios) {
    for (std::uint64_t max_events : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3},
                                     std::uint64_t{50}, std::uint64_t{10000000}}) {
      Scenario s = base;
      s.max_events = max_events;
      SCOPED_TRACE(testing::Message() << s.balls.size() << " balls, max_events " << max_events);
      detail::RunRecord record;
      const RunResult result = detail::simulate_recorded(s, record);
      // Up to the end of the recorded run; after max_events stopped it,
      // any time.
      const double end = result.complete ? (s.until.rest ? result.final_time : s.until.time)
                                         : result.final_time + 1.0;
      Simulation sim(s);
      detail::Replay replay(record);
      for (double t : times_of(result, end)) {
        const StopReason want = sim.advance_to(t);
        ASSERT_EQ(replay.advance_to(t), want) << "t = " << t;
        ASSERT_EQ(replay.time(), sim.time()) << "t = " << t;
        const std::vector<BallState> a = replay.balls();
        const std::vector<BallState> b = sim.balls();
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
          EXPECT_EQ(a[i].position, b[i].position) << "t = " << t << ", ball " << i;
          EXPECT_EQ(a[i].velocity, b[i].velocity) << "t = " << t << ", ball " << i;
          EXPECT_EQ(a[i].spin, b[i].spin) << "t = " << t << ", ball " << i;
          EXPECT_EQ(a[i].state, b[i].state) << "t = " << t << ", ball " << i;
        }
      }
    }
  }
}

}  // namespace test_run_record
