// The physics lab: energy and momentum against closed forms, traces of
// runs built in code, and the SVG plots written from them.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "expect_states.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/plot.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"

namespace breakshot::test_lab {
namespace {

BallState moving(Vec2 p, Vec2 v) {
  BallState s;
  s.position = p;
  s.velocity = v;
  s.state = (v.x != 0.0 || v.y != 0.0) ? MotionState::moving : MotionState::stationary;
  return s;
}

// Two balls of different mass on a 4 m x 4 m ideal table: a hits b
// obliquely at t = 0.905 s and then nothing reaches a wall before 1.5 s
// (light leaves the contact at x = 0.4 at speed <= 1 m/s, 1.55 m from
// the nearest wall; heavy at speed <= 0.5 m/s, 1.45 m from it). So momentum is
// exactly conserved over the whole run.
Scenario two_ball_collision() {
  Scenario s;
  s.physics.model = Model::ideal;
  s.table = make_rectangle({-2.0, -2.0}, {2.0, 2.0});
  s.balls = {BallSpec{"light", 0.05, 0.1, 1.0}, BallSpec{"heavy", 0.05, 0.3, 1.0}};
  s.start = {moving({-0.5, 0.0}, {1.0, 0.0}), moving({0.5, 0.03}, {0.0, 0.0})};
  s.until.rest = false;
  s.until.time = 1.5;
  return s;
}

// Three balls of different radius and mass bouncing in a small box for
// a long time: many ball-ball and wall events.
Scenario box_of_three(double restitution) {
  Scenario s;
  s.physics.model = Model::ideal;
  s.physics.ball_ball_restitution = restitution;
  s.table = make_rectangle({-0.1, -0.1}, {0.1, 0.1});
  s.balls = {BallSpec{"white", 0.012, 0.02, restitution},
             BallSpec{"black", 0.02, 0.05, restitution},
             BallSpec{"red", 0.015, 0.03, restitution}};
  s.start = {moving({-0.05, 0.0}, {0.3, 0.05}), moving({0.05, 0.01}, {0.0, 0.0}),
             moving({0.0, 0.06}, {-0.1, -0.2})};
  s.until.rest = false;
  s.until.time = 5.0;
  return s;
}

Vec2 total_momentum(const Scenario& s, const Sample& f) {
  Vec2 p;
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    p += momentum(s.balls[i], f.balls[i]);
  }
  return p;
}

double total_energy(const Scenario& s, const Sample& f) {
  double e = 0.0;
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    e += kinetic_energy(s.balls[i], f.balls[i]);
  }
  return e;
}

// The distinct event times of a straight run to the end.
std::vector<double> event_times(const Scenario& s) {
  Simulation sim(s);
  if (s.until.rest) {
    sim.advance_to_rest();
  } else {
    sim.advance_to(s.until.time);
  }
  std::vector<double> t;
  for (const Event& e : sim.events()) {
    t.push_back(e.time);
  }
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

bool contains_time(const std::vector<Sample>& frames, double t) {
  return std::any_of(frames.begin(), frames.end(),
                     [t](const Sample& f) { return f.time == t; });
}

void expect_strictly_increasing(const std::vector<Sample>& frames) {
  for (std::size_t k = 1; k < frames.size(); ++k) {
    ASSERT_LT(frames[k - 1].time, frames[k].time) << "frame " << k;
  }
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A fresh empty directory under the system temp directory.
std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("breakshot_test_lab_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// ---------------------------------------------------------------------------

TEST(Lab, KineticEnergyIsTranslationalPlusSolidSphereRotation) {
  const BallSpec spec{"b", 0.03, 0.2, 1.0};
  BallState st;
  st.velocity = {3.0, -4.0};
  EXPECT_DOUBLE_EQ(kinetic_energy(spec, st), 0.5 * 0.2 * 25.0);

  st.spin = {10.0, -20.0, 20.0};  // |w|^2 = 900
  const double inertia = 2.0 / 5.0 * 0.2 * 0.03 * 0.03;
  EXPECT_NEAR(kinetic_energy(spec, st), 2.5 + 0.5 * inertia * 900.0, 1e-15);

  st.velocity = {};
  EXPECT_NEAR(kinetic_energy(spec, st), 0.5 * inertia * 900.0, 1e-15);
  EXPECT_EQ(kinetic_energy(spec, BallState{}), 0.0);
}

TEST(Lab, MomentumIsMassTimesVelocity) {
  const BallSpec spec{"b", 0.03, 0.17, 1.0};
  BallState st;
  st.velocity = {2.0, -0.5};
  st.spin = {5.0, 5.0, 5.0};  // spin carries no linear momentum
  const Vec2 p = momentum(spec, st);
  EXPECT_DOUBLE_EQ(p.x, 0.34);
  EXPECT_DOUBLE_EQ(p.y, -0.085);
}

TEST(Lab, TraceFramesAreSortedAndIncludeStartEndAndEveryEvent) {
  const Scenario s = box_of_three(1.0);
  ASSERT_FALSE(validate(s).has_value());
  const std::vector<Sample> frames = trace(s, 101);
  const std::vector<double> events = event_times(s);
  ASSERT_GT(events.size(), 10u) << "the scenario should be eventful";

  ASSERT_FALSE(frames.empty());
  expect_strictly_increasing(frames);
  EXPECT_EQ(frames.front().time, 0.0);
  EXPECT_EQ(frames.back().time, 5.0);
  for (double t : events) {
    EXPECT_TRUE(contains_time(frames, t)) << "no frame at event time " << t;
  }
  for (int k = 0; k <= 100; ++k) {
    EXPECT_TRUE(contains_time(frames, 5.0 * k / 100.0)) << "no grid frame " << k;
  }
  EXPECT_LE(frames.size(), 101 + events.size());
  for (const Sample& f : frames) {
    ASSERT_EQ(f.balls.size(), 3u);
  }
}

TEST(Lab, TraceDoesNotChangeTheRun) {
  const Scenario s = box_of_three(0.9);
  const std::vector<Sample> frames = trace(s, 333);
  Simulation sim(s);
  sim.advance_to(s.until.time);
  const std::vector<BallState> end = sim.balls();
  ASSERT_EQ(frames.back().balls.size(), end.size());
  for (std::size_t i = 0; i < end.size(); ++i) {
    EXPECT_EQ(frames.back().balls[i].position, end[i].position) << i;
    EXPECT_EQ(frames.back().balls[i].velocity, end[i].velocity) << i;
  }
}

TEST(Lab, TwoBallCollisionConservesMomentumAndEnergy) {
  const Scenario s = two_ball_collision();
  ASSERT_FALSE(validate(s).has_value());
  const std::vector<Sample> frames = trace(s, 50);

  // The one event is the collision: the centres are 0.1 m apart when
  // light is sqrt(0.1^2 - 0.03^2) m short of heavy's x, at 1 m/s.
  const std::vector<double> events = event_times(s);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0], 1.0 - std::sqrt(0.0091), 1e-12);
  EXPECT_TRUE(contains_time(frames, events[0]));

  const Vec2 p0 = total_momentum(s, frames.front());
  const double e0 = total_energy(s, frames.front());
  EXPECT_DOUBLE_EQ(p0.x, 0.1);
  EXPECT_DOUBLE_EQ(e0, 0.05);
  for (const Sample& f : frames) {
    const Vec2 p = total_momentum(s, f);
    EXPECT_NEAR(p.x, p0.x, 1e-14) << "t = " << f.time;
    EXPECT_NEAR(p.y, p0.y, 1e-14) << "t = " << f.time;
    EXPECT_NEAR(total_energy(s, f), e0, 1e-14) << "t = " << f.time;
  }
  // And the collision did happen: the heavy ball moves at the end.
  EXPECT_GT(norm(frames.back().balls[1].velocity), 0.1);
}

TEST(Lab, ElasticBoxConservesEnergyThroughWallsAndCollisions) {
  const Scenario s = box_of_three(1.0);
  const std::vector<Sample> frames = trace(s, 200);
  const double e0 = total_energy(s, frames.front());
  for (const Sample& f : frames) {
    EXPECT_NEAR(total_energy(s, f), e0, 1e-12 * e0) << "t = " << f.time;
  }
}

TEST(Lab, TraceRespectsMaxFramesByThinningEvents) {
  const Scenario s = box_of_three(1.0);
  const std::vector<double> events = event_times(s);
  ASSERT_GT(events.size(), 25u);
  // 10 grid frames and 15 of the event times.
  const std::vector<Sample> frames = trace(s, 10, 25);
  EXPECT_LE(frames.size(), 25u);
  EXPECT_GT(frames.size(), 20u);  // the budget is used, not wasted
  expect_strictly_increasing(frames);
  EXPECT_EQ(frames.front().time, 0.0);
  EXPECT_EQ(frames.back().time, 5.0);
  // Thinned evenly: the first and the last event are kept.
  EXPECT_TRUE(contains_time(frames, events.front()));
  EXPECT_TRUE(contains_time(frames, events.back()));

  // A budget smaller than the grid: the grid shrinks, ends stay.
  const std::vector<Sample> few = trace(s, 1000, 5);
  EXPECT_LE(few.size(), 5u);
  EXPECT_EQ(few.front().time, 0.0);
  EXPECT_EQ(few.back().time, 5.0);
}

TEST(Lab, TraceStopsAtTheEventLimit) {
  Scenario s = box_of_three(1.0);
  s.max_events = 7;
  Simulation sim(s);
  ASSERT_EQ(sim.advance_to(s.until.time), StopReason::event_limit);
  const double stop = sim.time();

  const std::vector<Sample> frames = trace(s, 100);
  expect_strictly_increasing(frames);
  EXPECT_EQ(frames.back().time, stop);
  EXPECT_LT(frames.back().time, s.until.time);
}

TEST(Lab, TraceToRestEndsWhenEverythingStops) {
  Scenario s = box_of_three(0.8);
  s.physics.model = Model::friction;
  s.physics.deceleration = 0.2;
  s.until.rest = true;
  Simulation sim(s);
  sim.advance_to_rest();
  const double rest = sim.time();
  ASSERT_GT(rest, 0.0);

  const std::vector<Sample> frames = trace(s, 64);
  EXPECT_EQ(frames.front().time, 0.0);
  EXPECT_EQ(frames.back().time, rest);
  for (const BallState& b : frames.back().balls) {
    EXPECT_EQ(b.velocity, Vec2{});
  }
}

// trace() and simulate_traced() run the shot once and read the frames
// from a record of it. The frames are exactly those of the way trace()
// used to work: a run to the end for the end time and the event times,
// then a second run advanced through the frame times.
std::vector<Sample> trace_in_two_runs(const Scenario& scenario, std::size_t points,
                                      std::size_t max_frames) {
  const Simulation start(scenario);
  Simulation probe = start;
  if (scenario.until.rest) {
    probe.advance_to_rest();
  } else {
    probe.advance_to(scenario.until.time);
  }
  const double end = probe.time();
  std::vector<double> event_times;
  for (const Event& e : probe.events()) {
    if (event_times.empty() || e.time != event_times.back()) event_times.push_back(e.time);
  }
  std::size_t budget = std::max<std::size_t>(max_frames, 2);
  const std::size_t n_balls = std::max<std::size_t>(start.ball_count(), 1);
  budget = std::min(budget, std::max<std::size_t>((std::size_t{1} << 22) / n_balls, 2));
  const std::size_t grid_points = std::min(std::max<std::size_t>(points, 2), budget);
  std::vector<double> times;
  for (std::size_t k = 0; k + 1 < grid_points; ++k) {
    times.push_back(end * static_cast<double>(k) / static_cast<double>(grid_points - 1));
  }
  times.push_back(end);
  const std::size_t event_budget = budget - grid_points;
  if (event_times.size() <= event_budget) {
    times.insert(times.end(), event_times.begin(), event_times.end());
  } else if (event_budget == 1) {
    times.push_back(event_times.back());
  } else if (event_budget > 1) {
    const std::size_t n = event_times.size();
    for (std::size_t k = 0; k < event_budget; ++k) {
      times.push_back(event_times[k * (n - 1) / (event_budget - 1)]);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::vector<Sample> frames;
  Simulation sim = start;
  for (double t : times) {
    const StopReason reason = sim.advance_to(t);
    Sample f{sim.time(), sim.balls()};
    if (!frames.empty() && frames.back().time >= f.time) {
      frames.back() = std::move(f);
    } else {
      frames.push_back(std::move(f));
    }
    if (reason == StopReason::event_limit) break;
  }
  return frames;
}

TEST(Lab, OneRunGivesTheResultAndTheFramesOfSeparateRuns) {
  std::vector<Scenario> scenarios = {two_ball_collision(), box_of_three(1.0), box_of_three(0.3)};
  Scenario friction = box_of_three(0.8);
  friction.physics.model = Model::friction;
  friction.physics.deceleration = 0.2;
  friction.until.rest = true;
  scenarios.push_back(friction);
  scenarios.push_back(make_break_scenario("eight_ball", "9ft", 1, 7.5));
  Scenario spinning = make_break_scenario("nine_ball", "9ft", 3, 6.0);
  spinning.physics.spinning_friction = 0.0;  // balls may spin forever
  scenarios.push_back(spinning);
  // A gas of 60 balls: the grid of cells, and cell crossings between
  // events.
  Scenario gas;
  gas.physics.model = Model::ideal;
  gas.table = make_rectangle({0.0, 0.0}, {1.0, 1.0});
  for (int k = 0; k < 60; ++k) {
    gas.balls.push_back(BallSpec{"g" + std::to_string(k), 0.02, 0.1, 1.0});
    gas.start.push_back(moving({0.06 + 0.125 * (k % 8), 0.06 + 0.125 * (k / 8)},
                               {std::cos(1.3 * k), std::sin(1.7 * k)}));
  }
  gas.until.rest = false;
  gas.until.time = 2.0;
  scenarios.push_back(gas);
  // A Newton's cradle: collisions at one instant, so that max_events can
  // stop the run between two events at the same time.
  Scenario cradle;
  cradle.physics.model = Model::ideal;
  cradle.table = make_rectangle({0.0, 0.0}, {2.0, 0.2});
  cradle.balls.push_back(BallSpec{"s", 0.02, 0.1, 1.0});
  cradle.start.push_back(moving({0.3, 0.1}, {1.0, 0.0}));
  for (int k = 0; k < 5; ++k) {
    cradle.balls.push_back(BallSpec{"r" + std::to_string(k), 0.02, 0.1, 1.0});
    cradle.start.push_back(moving({0.8 + 0.04 * k, 0.1}, {0.0, 0.0}));
  }
  cradle.until.rest = false;
  cradle.until.time = 1.0;
  scenarios.push_back(cradle);
  for (Scenario s : scenarios) {
    for (std::uint64_t max_events : {std::uint64_t{1}, std::uint64_t{3}, std::uint64_t{9},
                                     std::uint64_t{100}, std::uint64_t{10000000}}) {
      for (const std::optional<double> dt : {std::optional<double>{}, std::optional<double>{0.25}}) {
        s.max_events = max_events;
        s.sample_dt = dt;
        for (const auto& [points, max_frames] :
             {std::pair<std::size_t, std::size_t>{2000, 200000}, {50, 80}, {10, 12}}) {
          SCOPED_TRACE(testing::Message() << s.balls.size() << " balls, max_events " << max_events
                                          << ", points " << points << ", max_frames " << max_frames
                                          << (dt ? ", samples" : ""));
          const TracedRun run = simulate_traced(s, points, max_frames);
          const RunResult want = simulate(s);
          EXPECT_EQ(run.result.complete, want.complete);
          EXPECT_EQ(run.result.events, want.events);
          EXPECT_EQ(run.result.final_time, want.final_time);
          expect_same_states(run.result.final_balls, want.final_balls);
          ASSERT_EQ(run.result.samples.size(), want.samples.size());
          for (std::size_t k = 0; k < want.samples.size(); ++k) {
            EXPECT_EQ(run.result.samples[k].time, want.samples[k].time);
            expect_same_states(run.result.samples[k].balls, want.samples[k].balls);
          }
          const std::vector<Sample> frames = trace_in_two_runs(s, points, max_frames);
          ASSERT_EQ(run.frames.size(), frames.size());
          for (std::size_t k = 0; k < frames.size(); ++k) {
            EXPECT_EQ(run.frames[k].time, frames[k].time) << "frame " << k;
            expect_same_states(run.frames[k].balls, frames[k].balls);
          }
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------

TEST(Plots, WritesThreeSvgFilesWithLegends) {
  const Scenario s = box_of_three(1.0);
  const std::vector<Sample> frames = trace(s, 200);
  const auto dir = scratch_dir("three");
  const std::string prefix = (dir / "run").string();
  const std::vector<std::string> paths = write_plots(s, frames, prefix);
  ASSERT_EQ(paths.size(), 3u);
  EXPECT_EQ(paths[0], prefix + "-trajectories.svg");
  EXPECT_EQ(paths[1], prefix + "-energy.svg");
  EXPECT_EQ(paths[2], prefix + "-momentum.svg");
  for (const std::string& p : paths) {
    const std::string svg = read_all(p);
    EXPECT_NE(svg.find("<svg"), std::string::npos) << p;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << p;
    EXPECT_GT(svg.find("</svg>"), svg.find("<svg")) << p;
    for (const BallSpec& b : s.balls) {
      EXPECT_NE(svg.find(">" + b.id + "<"), std::string::npos) << p << " lacks " << b.id;
    }
    EXPECT_NE(svg.find("ideal model, 3 balls"), std::string::npos) << p;
  }
  EXPECT_NE(read_all(paths[0]).find("x (m)"), std::string::npos);
  EXPECT_NE(read_all(paths[1]).find("kinetic energy ("), std::string::npos);
  EXPECT_NE(read_all(paths[1]).find("time (s)"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Plots, OutputIsDeterministic) {
  const Scenario s = box_of_three(0.95);
  const auto dir = scratch_dir("determinism");
  const auto a = write_plots(s, trace(s, 300), (dir / "a").string());
  const auto b = write_plots(s, trace(s, 300), (dir / "b").string());
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(read_all(a[k]), read_all(b[k])) << a[k];
  }
  std::filesystem::remove_all(dir);
}

TEST(Plots, IdsAreEscaped) {
  Scenario s = two_ball_collision();
  s.balls[0].id = "a<&>\"b";
  const auto dir = scratch_dir("escape");
  const auto paths = write_plots(s, trace(s, 20), (dir / "x").string());
  const std::string svg = read_all(paths[0]);
  EXPECT_NE(svg.find("a&lt;&amp;&gt;&quot;b"), std::string::npos);
  EXPECT_EQ(svg.find("a<&"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Plots, ManyBallsDrawSomePathsAndSaySo) {
  // 15 x 10 grid of small balls: more than the 12-series and 20-path
  // limits.
  Scenario s;
  s.physics.model = Model::ideal;
  s.table = make_rectangle({0.0, 0.0}, {1.6, 1.1});
  for (int i = 0; i < 150; ++i) {
    const double x = 0.1 + 0.1 * (i % 15);
    const double y = 0.1 + 0.1 * (i / 15);
    s.balls.push_back(BallSpec{"b" + std::to_string(i), 0.02, 0.1, 1.0});
    s.start.push_back(moving({x, y}, {0.3 * std::cos(i), 0.3 * std::sin(i)}));
  }
  s.until.rest = false;
  s.until.time = 2.0;
  ASSERT_FALSE(validate(s).has_value());
  const auto dir = scratch_dir("many");
  const auto paths = write_plots(s, trace(s, 500), (dir / "gas").string());
  const std::string traj = read_all(paths[0]);
  EXPECT_NE(traj.find("first 20 of 150 balls"), std::string::npos);
  EXPECT_NE(traj.find(">b19<"), std::string::npos);
  EXPECT_EQ(traj.find(">b20<"), std::string::npos);
  // Every ball's end position is drawn: 150 end + 20 start circles.
  std::size_t circles = 0;
  for (std::size_t at = traj.find("<circle"); at != std::string::npos;
       at = traj.find("<circle", at + 1)) {
    ++circles;
  }
  EXPECT_GE(circles, 170u);
  const std::string energy = read_all(paths[1]);
  EXPECT_NE(energy.find("first 10 of 150 balls"), std::string::npos);
  EXPECT_NE(energy.find(">b9<"), std::string::npos);
  EXPECT_EQ(energy.find(">b10<"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Plots, ConstantAndEmptyDataStillMakeFiles) {
  // Nothing moves: every series is flat at zero.
  Scenario s = two_ball_collision();
  s.start[0].velocity = {};
  s.start[0].state = MotionState::stationary;
  const auto dir = scratch_dir("flat");
  const auto paths = write_plots(s, trace(s, 10), (dir / "still").string());
  for (const std::string& p : paths) {
    const std::string svg = read_all(p);
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << p;
    EXPECT_EQ(svg.find("nan"), std::string::npos) << p;
    EXPECT_EQ(svg.find("inf"), std::string::npos) << p;
  }
  // No frames at all.
  const auto empty = write_plots(s, {}, (dir / "empty").string());
  EXPECT_NE(read_all(empty[1]).find("</svg>"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Plots, UnwritablePrefixThrowsNamingTheFile) {
  const Scenario s = two_ball_collision();
  const std::vector<Sample> frames = trace(s, 10);
  const auto dir = scratch_dir("missing");
  const std::string prefix = (dir / "no_such_dir" / "run").string();
  try {
    write_plots(s, frames, prefix);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(prefix + "-trajectories.svg"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace breakshot::test_lab
