// Batch shots (breakshot/batch.hpp): the same arrays for any thread count,
// each shot exactly a simulate() run with that cue, noise from the seed
// and the shot's index only, and refusals naming the strike and field.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/batch.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/rack.hpp"
#include "breakshot/simulation.hpp"

namespace test_batch {

using namespace breakshot;

namespace {

/// The 9-ball rack with the cue ball on the head spot, no strike.
Scenario rack_scene() {
  Scenario s = make_break_scenario("nine_ball", "9ft", 3, 7.5);
  s.cue.reset();
  return s;
}

/// A spread of strikes: the break itself, soft and hard shots in many
/// directions, spin, elevation, and a miscue (offset beyond 0.5 R).
std::vector<CueStrike> strikes() {
  std::vector<CueStrike> out;
  out.push_back({7.5, 0.0, 0.0, 0.0, 0.0});  // filled in below: toward the apex
  for (int k = 0; k < 14; ++k) {
    const double kd = static_cast<double>(k);
    // Even k toward the rack (within 7 degrees of the apex), odd k anywhere.
    const double phi = k % 2 == 0 ? kd - 7.0 : 25.0 * kd - 40.0;
    out.push_back({0.5 + 0.4 * kd, phi, kd < 7 ? 0.0 : 12.0, 0.02 * kd - 0.14, 0.3 - 0.04 * kd});
  }
  out.push_back({3.0, 10.0, 0.0, 0.5, 0.3});  // miscue
  return out;
}

void expect_same(const ShotBatch& x, const ShotBatch& y) {
  ASSERT_EQ(x.shots, y.shots);
  ASSERT_EQ(x.balls, y.balls);
  for (std::size_t i = 0; i < x.final_positions.size(); ++i) {
    EXPECT_EQ(x.final_positions[i].x, y.final_positions[i].x) << i;
    EXPECT_EQ(x.final_positions[i].y, y.final_positions[i].y) << i;
  }
  EXPECT_EQ(x.pockets, y.pockets);
  EXPECT_EQ(x.cushions, y.cushions);
  EXPECT_EQ(x.cue_index, y.cue_index);
  EXPECT_EQ(x.first_hit, y.first_hit);
  EXPECT_EQ(x.cushions_before_hit, y.cushions_before_hit);
  EXPECT_EQ(x.event_counts, y.event_counts);
  EXPECT_EQ(x.final_times, y.final_times);
  EXPECT_EQ(x.complete, y.complete);
  EXPECT_EQ(x.miscue, y.miscue);
  EXPECT_EQ(x.played, y.played);
}

std::string refusal(const Scenario& s, const std::vector<CueStrike>& k) {
  try {
    play_shots(s, k);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST(Batch, SameArraysForAnyThreadCount) {
  const Scenario s = rack_scene();
  const std::vector<CueStrike> k = strikes();
  ShotBatchOptions one;
  one.threads = 1;
  const ShotBatch a = play_shots(s, k, one);
  for (unsigned t : {2u, 3u, 0u}) {
    ShotBatchOptions o;
    o.threads = t;
    expect_same(a, play_shots(s, k, o));
  }
}

TEST(Batch, EachShotIsSimulateWithThatCue) {
  const Scenario base = rack_scene();
  std::vector<CueStrike> k = strikes();
  k[0] = make_break_scenario("nine_ball", "9ft", 3, 7.5).cue->strike;  // the break
  ShotBatchOptions o;
  o.threads = 2;
  const ShotBatch b = play_shots(base, k, o);
  ASSERT_EQ(b.shots, k.size());
  ASSERT_EQ(b.balls, base.balls.size());
  int pocketed = 0;
  int hits = 0;
  for (std::size_t j = 0; j < k.size(); ++j) {
    Scenario s = base;
    s.cue = CueSpec{0, k[j], CueParams{}};
    ASSERT_EQ(s.balls[0].id, "cue");
    const RunResult r = simulate(s);
    EXPECT_EQ(b.played[j], k[j]);
    EXPECT_EQ(b.cue_index[j], 0);
    EXPECT_EQ(b.complete[j], r.complete ? 1 : 0);
    EXPECT_EQ(b.event_counts[j], r.events.size()) << j;
    EXPECT_EQ(b.final_times[j], r.final_time) << j;
    EXPECT_EQ(b.miscue[j], r.cue && r.cue->miscue ? 1 : 0);
    std::int32_t first = -1;
    for (const Event& e : r.events) {
      if (e.type == EventType::ball_ball && (e.ball == 0 || e.other == 0)) {
        first = e.ball == 0 ? e.other : e.ball;
        break;
      }
    }
    EXPECT_EQ(b.first_hit[j], first) << j;
    hits += first >= 0;
    for (std::size_t i = 0; i < b.balls; ++i) {
      const Vec2 p = b.final_positions[j * b.balls + i];
      EXPECT_EQ(p.x, r.final_balls[i].position.x) << j << ' ' << i;
      EXPECT_EQ(p.y, r.final_balls[i].position.y) << j << ' ' << i;
      const bool in_pocket = r.final_balls[i].state == MotionState::pocketed;
      EXPECT_EQ(b.pockets[j * b.balls + i] >= 0, in_pocket) << j << ' ' << i;
      pocketed += in_pocket;
      int cushions = 0;
      for (const Event& e : r.events) {
        cushions += e.type == EventType::ball_cushion && e.ball == static_cast<std::int32_t>(i);
      }
      EXPECT_EQ(b.cushions[j * b.balls + i], cushions);
    }
  }
  // The batch covers what it claims to: hits, pockets and a miscue.
  EXPECT_GT(hits, 3);
  EXPECT_GT(pocketed, 0);
  EXPECT_EQ(b.miscue.back(), 1);
  EXPECT_EQ(b.event_counts.back(), 0u);
  EXPECT_EQ(b.first_hit.back(), -1);
}

TEST(Batch, OneScenarioPerStrikeEqualsSeparateBatches) {
  // Different layouts (rack seeds) in one batch, one strike each.
  std::vector<Scenario> scenes;
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    Scenario s = make_break_scenario("eight_ball", "9ft", seed, 7.5);
    s.cue.reset();
    scenes.push_back(s);
  }
  const std::vector<CueStrike> k = {
      {7.5, 0.0, 0.0, 0.0, 0.0}, {5.0, 1.0, 0.0, 0.1, -0.2}, {2.0, 170.0, 5.0, 0.0, 0.0},
      {8.0, -1.0, 0.0, -0.1, 0.1}};
  std::vector<const Scenario*> ptrs;
  for (const Scenario& s : scenes) ptrs.push_back(&s);
  ShotBatchOptions o;
  o.threads = 2;
  const ShotBatch b = play_shots(ptrs, k, o);
  for (std::size_t j = 0; j < k.size(); ++j) {
    const ShotBatch single = play_shots(scenes[j], std::vector<CueStrike>{k[j]});
    for (std::size_t i = 0; i < b.balls; ++i) {
      EXPECT_EQ(b.final_positions[j * b.balls + i], single.final_positions[i]);
      EXPECT_EQ(b.pockets[j * b.balls + i], single.pockets[i]);
    }
    EXPECT_EQ(b.event_counts[j], single.event_counts[0]);
  }
}

TEST(Batch, NoiseDependsOnSeedAndIndexOnly) {
  const Scenario s = rack_scene();
  const std::vector<CueStrike> k(6, CueStrike{4.0, 3.0, 0.0, 0.0, 0.0});
  ShotBatchOptions o;
  o.noise = parse_noise("tournament");
  o.seed = 11;
  o.threads = 1;
  const ShotBatch a = play_shots(s, k, o);
  o.threads = 2;
  expect_same(a, play_shots(s, k, o));
  for (std::size_t j = 0; j < k.size(); ++j) {
    EXPECT_EQ(a.played[j], perturb(k[j], o.noise, s.balls[0].radius, mix_seed(11, j)));
    EXPECT_NE(a.played[j], k[j]);
  }
  // The same strike six times, six different executions.
  EXPECT_NE(a.played[0], a.played[1]);
  o.seed = 12;
  const ShotBatch c = play_shots(s, k, o);
  EXPECT_NE(c.played[0], a.played[0]);
  EXPECT_NE(c.final_positions, a.final_positions);
}

TEST(Batch, RefusalsNameTheStrikeAndField) {
  const Scenario s = rack_scene();
  std::vector<CueStrike> k = {{2.0, 0.0, 0.0, 0.0, 0.0}, {2.0, 0.0, 90.0, 0.0, 0.0}};
  EXPECT_EQ(refusal(s, k).rfind("strikes[1].theta: ", 0), 0u) << refusal(s, k);
  k[1] = {-1.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(refusal(s, k).rfind("strikes[1].speed: ", 0), 0u) << refusal(s, k);
  k[1] = {1.0, 0.0, 0.0, 0.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_EQ(refusal(s, k).rfind("strikes[1].b: ", 0), 0u) << refusal(s, k);
  k[1] = k[0];

  const Scenario with_cue = make_break_scenario("nine_ball", "9ft", 3, 7.5);
  EXPECT_EQ(refusal(with_cue, k).rfind("cue: ", 0), 0u) << refusal(with_cue, k);
  Scenario no_cue_ball = s;
  no_cue_ball.balls[0].id = "white";
  EXPECT_EQ(refusal(no_cue_ball, k).rfind("balls: ", 0), 0u);
  Scenario moving = s;
  moving.start[0].velocity = {0.1, 0.0};
  EXPECT_EQ(refusal(moving, k).rfind("balls[0]: ", 0), 0u) << refusal(moving, k);
  Scenario frictionless = s;
  frictionless.physics.rolling_friction = 0.0;
  EXPECT_EQ(refusal(frictionless, k).rfind("physics.rolling_friction: ", 0), 0u);

  // No strikes is an empty batch, not an error.
  const ShotBatch empty = play_shots(s, std::vector<CueStrike>{});
  EXPECT_EQ(empty.shots, 0u);
  EXPECT_EQ(empty.balls, s.balls.size());
}

}  // namespace test_batch
