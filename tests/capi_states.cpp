// The C API's states at any time (bs_simulation_states_at) against the
// run's record taken during the run itself (simulate_recorded and Replay,
// src/physics/run_record.hpp): a BsSimulation records its trajectories
// only when first asked for states, by running the scenario again, and
// those states are bit for bit the ones the record of the first run
// gives, whichever call comes first and whether the run came from
// bs_simulate or bs_simulate_batch. Its own binary: it links the C API's
// static library.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "breakshot.h"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "physics/run_record.hpp"

namespace bs = breakshot;

namespace {

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The scenarios: every examples/pool/ file, and 8-ball breaks, each also
// stopped by max_events after 1 and 40 events.
std::vector<std::string> scenario_texts() {
  std::vector<std::string> out;
  const std::filesystem::path dir = std::filesystem::path(BREAKSHOT_SOURCE_DIR) / "examples/pool";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) out.push_back(read_text(f));
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    for (std::uint64_t max_events : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{40}}) {
      BsScenario* s = nullptr;
      EXPECT_EQ(bs_scenario_new(&s), BS_OK);
      BsPhysics p;
      EXPECT_EQ(bs_physics_default(BS_MODEL_POOL, &p), BS_OK);
      p.ball_clusters = 1;
      EXPECT_EQ(bs_scenario_set_physics(s, &p), BS_OK);
      BsTable t;
      EXPECT_EQ(bs_table_default(BS_TABLE_POOL, &t), BS_OK);
      EXPECT_EQ(bs_scenario_set_table(s, &t), BS_OK);
      EXPECT_EQ(bs_scenario_set_rack(s, "eight_ball", seed), BS_OK);
      const BsStrike k{7.5, 0.01 * static_cast<double>(seed), 0.0, 0.0, 0.1};
      EXPECT_EQ(bs_scenario_strike(s, "cue", &k), BS_OK);
      if (max_events > 0) {
        EXPECT_EQ(bs_scenario_set_max_events(s, max_events), BS_OK);
      }
      char* text = nullptr;
      EXPECT_EQ(bs_scenario_to_json(s, &text), BS_OK);
      out.emplace_back(text);
      bs_string_free(text);
      bs_scenario_free(s);
    }
  }
  return out;
}

// Every event time, the times between them, and the end.
std::vector<double> times_of(const bs::RunResult& r) {
  std::vector<double> t{0.0};
  for (const bs::Event& e : r.events) {
    if (e.time > t.back()) t.push_back(0.5 * (t.back() + e.time));
    if (e.time >= t.back()) t.push_back(e.time);
  }
  if (r.final_time > t.back()) t.push_back(r.final_time);
  return t;
}

void expect_states(const BsSimulation* sim, const bs::Scenario& scenario) {
  bs::detail::RunRecord record;
  const bs::RunResult result = bs::detail::simulate_recorded(scenario, record);
  bs::detail::Replay replay(record);
  std::vector<BsBallState> got(result.final_balls.size());
  for (double t : times_of(result)) {
    replay.advance_to(t);
    const std::vector<bs::BallState> want = replay.balls();
    ASSERT_EQ(bs_simulation_states_at(sim, t, got.data(), got.size()), BS_OK) << "t = " << t;
    for (std::size_t i = 0; i < want.size(); ++i) {
      const BsBallState& g = got[i];
      const bs::BallState& w = want[i];
      EXPECT_EQ(g.position[0], w.position.x) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.position[1], w.position.y) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.velocity[0], w.velocity.x) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.velocity[1], w.velocity.y) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.spin[0], w.spin.x) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.spin[1], w.spin.y) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.spin[2], w.spin.z) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.z, w.z) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.vz, w.vz) << "t = " << t << ", ball " << i;
      EXPECT_EQ(g.motion, static_cast<std::int32_t>(w.state)) << "t = " << t << ", ball " << i;
    }
  }
}

}  // namespace

TEST(CApiStates, TheRecordMadeOnTheFirstQueryGivesTheStatesOfTheRecordedRun) {
  const std::vector<std::string> texts = scenario_texts();
  ASSERT_GT(texts.size(), 9u);
  std::vector<BsScenario*> c(texts.size(), nullptr);
  for (std::size_t k = 0; k < texts.size(); ++k) {
    ASSERT_EQ(bs_scenario_from_json(texts[k].data(), texts[k].size(), &c[k]), BS_OK)
        << bs_error_message(nullptr);
  }
  std::vector<BsSimulation*> batch(texts.size(), nullptr);
  ASSERT_EQ(bs_simulate_batch(c.data(), c.size(), 2, batch.data()), BS_OK);
  for (std::size_t k = 0; k < texts.size(); ++k) {
    SCOPED_TRACE(testing::Message() << "scenario " << k);
    auto read = bs::read_scenario(texts[k]);
    ASSERT_TRUE(std::holds_alternative<bs::Scenario>(read));
    const bs::Scenario& scenario = std::get<bs::Scenario>(read);
    // States first, then the result file; the result file first, then
    // the states (a run from the batch).
    BsSimulation* sim = nullptr;
    ASSERT_EQ(bs_simulate(c[k], &sim), BS_OK);
    expect_states(sim, scenario);
    for (BsSimulation* s : {sim, batch[k]}) {
      char* text = nullptr;
      ASSERT_EQ(bs_simulation_result_json(s, &text), BS_OK);
      EXPECT_EQ(std::string(text), bs::write_result(scenario, bs::simulate(scenario)));
      bs_string_free(text);
    }
    expect_states(batch[k], scenario);
    // A wrong n is refused before anything is recorded, and a later
    // query still gives the states.
    BsBallState one;
    BsSimulation* fresh = nullptr;
    ASSERT_EQ(bs_simulate(c[k], &fresh), BS_OK);
    EXPECT_EQ(bs_simulation_states_at(fresh, 0.0, &one, 0), BS_ERROR_OUT_OF_RANGE);
    expect_states(fresh, scenario);
    bs_simulation_free(fresh);
    bs_simulation_free(sim);
    bs_simulation_free(batch[k]);
    bs_scenario_free(c[k]);
  }
}
