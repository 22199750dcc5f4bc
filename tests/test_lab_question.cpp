// docs/lab.md asks: can a moving ball A stop dead after hitting a
// stationary ball B (different radii, restitution 1)? Only with equal
// masses and a head-on hit. These tests hold the answer to the engine.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <variant>

#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"

namespace test_lab_question {

using namespace breakshot;

namespace {

Scenario load(const char* name) {
  std::ifstream in(std::string(BREAKSHOT_SOURCE_DIR) + "/examples/lab/" + name);
  std::stringstream text;
  text << in.rdbuf();
  auto parsed = read_scenario(text.str());
  if (auto* err = std::get_if<ScenarioError>(&parsed)) {
    ADD_FAILURE() << err->path << ": " << err->reason;
    return {};
  }
  return std::get<Scenario>(parsed);
}

}  // namespace

TEST(Lab, StopAfterImpact) {
  const Scenario s = load("stop_after_impact.json");
  ASSERT_EQ(s.balls.size(), 2u);
  ASSERT_NE(s.balls[0].radius, s.balls[1].radius);
  ASSERT_EQ(s.balls[0].mass, s.balls[1].mass);
  const RunResult r = simulate(s);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].type, EventType::ball_ball);
  EXPECT_NEAR(r.events[0].time, (0.6 - 0.15 - 0.055) / 0.5, 1e-15);
  EXPECT_EQ(r.final_balls[0].velocity.x, 0.0);
  EXPECT_EQ(r.final_balls[0].velocity.y, 0.0);
  EXPECT_EQ(r.final_balls[0].state, MotionState::stationary);
  EXPECT_NEAR(r.final_balls[1].velocity.x, 0.5, 1e-15);
}

TEST(Lab, UnequalMassesNeverStopTheStriker) {
  Scenario s = load("stop_after_impact.json");
  s.balls[1].mass = 0.13;
  const RunResult r = simulate(s);
  ASSERT_GE(r.events.size(), 1u);
  // (m_A - m_B) / (m_A + m_B) * 0.5 = -0.02 m/s: A rebounds.
  EXPECT_NEAR(r.final_balls[0].velocity.x, (0.12 - 0.13) / 0.25 * 0.5, 1e-15);
}

TEST(Lab, OffCentreHitKeepsTheTangentialVelocity) {
  Scenario s = load("stop_after_impact.json");
  s.start[0].position.y += 0.02;  // impact parameter 2 cm
  const RunResult r = simulate(s);
  ASSERT_GE(r.events.size(), 1u);
  EXPECT_GT(std::hypot(r.final_balls[0].velocity.x, r.final_balls[0].velocity.y), 0.05);
}

TEST(Lab, LowerRestitutionStopsALighterStriker) {
  // m_A = e m_B: the striker stops, and energy is lost.
  Scenario s = load("stop_after_impact.json");
  s.physics.ball_ball_restitution = 0.8;
  s.balls[1].mass = s.balls[0].mass / 0.8;
  const RunResult r = simulate(s);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_NEAR(r.final_balls[0].velocity.x, 0.0, 1e-15);
}

}  // namespace test_lab_question
