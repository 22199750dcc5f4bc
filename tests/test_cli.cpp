// The breakshot command as a user runs it: exit status, standard error
// and the result it writes (docs/contract.md, "Command
// line and exit status").

#include <gtest/gtest.h>

#ifdef BREAKSHOT_CLI

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "breakshot/version.hpp"

namespace test_cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// A fresh directory per test, removed afterwards.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("breakshot-cli-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  struct Run {
    int status = -1;
    std::string out;
    std::string err;
  };

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  static std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
      if (c == '\'') {
        q += "'\\''";
      } else {
        q += c;
      }
    }
    return q + "'";
  }

  /// Runs `breakshot ARGS` through the shell, with `stdin_file` as
  /// standard input if given.
  Run run(const std::string& args, const std::string& stdin_file = "") const {
    const fs::path out = dir_ / "stdout.txt";
    const fs::path err = dir_ / "stderr.txt";
    std::string cmd = quote(BREAKSHOT_CLI) + " " + args + " >" + quote(out.string()) + " 2>" +
                      quote(err.string());
    if (!stdin_file.empty()) cmd += " <" + quote(stdin_file);
    const int raw = std::system(cmd.c_str());
    Run r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  fs::path dir_;
};

json good_scenario() {
  return json::parse(R"({
    "physics": {"model": "ideal"},
    "table": {"shape": "rectangle", "min": [-1.0, -0.5], "max": [1.0, 0.5]},
    "balls": [
      {"id": "white", "position": [-0.5, 0.0], "velocity": [1.0, 0.1]},
      {"id": "black", "position": [0.3, 0.0]}
    ],
    "until": {"time": 3.0},
    "samples": {"dt": 0.5}
  })");
}

TEST_F(Cli, GoodScenarioExitsZeroWithJsonOnStdout) {
  const Run r = run("simulate " + quote(write("s.json", good_scenario().dump())));
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out["complete"], true);
  EXPECT_FALSE(out["events"].empty());
  EXPECT_EQ(out["final"]["time"].get<double>(), 3.0);
  ASSERT_EQ(out["final"]["balls"].size(), 2u);
  EXPECT_EQ(out["final"]["balls"][0]["id"], "white");
  EXPECT_EQ(out["samples"].size(), 7u);  // 0, 0.5, ..., 3 (end included)
}

TEST_F(Cli, SameScenarioSameBytes) {
  const std::string file = quote(write("s.json", good_scenario().dump()));
  const Run a = run("simulate " + file);
  const Run b = run("simulate " + file);
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
}

TEST_F(Cli, StandardInput) {
  const std::string file = write("s.json", good_scenario().dump());
  const Run from_stdin = run("simulate -", file);
  ASSERT_EQ(from_stdin.status, 0) << from_stdin.err;
  const Run from_file = run("simulate " + quote(file));
  EXPECT_EQ(from_stdin.out, from_file.out);
}

TEST_F(Cli, OutputFile) {
  const std::string result = (dir_ / "result.json").string();
  const Run r = run("simulate " + quote(write("s.json", good_scenario().dump())) + " -o " +
                    quote(result));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(json::parse(slurp(result))["complete"], true);
}

TEST_F(Cli, EventLimitExitsThreeWithIncompleteResult) {
  json doc = good_scenario();
  doc["max_events"] = 5;
  doc["until"]["time"] = 100.0;
  const Run r = run("simulate " + quote(write("s.json", doc.dump())));
  ASSERT_EQ(r.status, 3) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out["complete"], false);
  EXPECT_LE(out["events"].size(), 5u);
  EXPECT_NE(r.err.find("max_events"), std::string::npos);
}

TEST_F(Cli, InvalidScenariosExitTwoAndNameTheField) {
  struct Case {
    const char* name;
    json doc;
    const char* path;
  };
  json overlap = good_scenario();
  overlap["balls"][1]["position"] = {-0.48, 0.0};
  json wall = good_scenario();
  wall["balls"][0]["position"] = {-0.99, 0.0};
  json radius = good_scenario();
  radius["balls"][1]["radius"] = -0.1;
  json mass = good_scenario();
  mass["balls"][0]["mass"] = 0;
  json restitution = good_scenario();
  restitution["balls"][1]["wall_restitution"] = 1.2;
  json unknown = good_scenario();
  unknown["balls"][1]["colour"] = "black";
  json missing = good_scenario();
  missing["physics"].erase("model");
  json type = good_scenario();
  type["balls"][1]["radius"] = "big";
  json duplicate = good_scenario();
  duplicate["balls"][1]["id"] = "white";
  json polygon = good_scenario();
  polygon["table"] = {{"shape", "polygon"}, {"vertices", {{-1, -1}, {1, 1}, {1, -1}, {-1, 2}}}};
  const Case cases[] = {
      {"overlap", overlap, "balls[1].position"},
      {"wall", wall, "balls[0].position"},
      {"radius", radius, "balls[1].radius"},
      {"mass", mass, "balls[0].mass"},
      {"restitution", restitution, "balls[1].wall_restitution"},
      {"unknown", unknown, "balls[1].colour"},
      {"missing", missing, "physics.model"},
      {"type", type, "balls[1].radius"},
      {"duplicate", duplicate, "balls[1].id"},
      {"polygon", polygon, "table.vertices"},
  };
  for (const Case& c : cases) {
    const Run r = run("simulate " + quote(write(std::string(c.name) + ".json", c.doc.dump())));
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(std::string("breakshot: invalid scenario: ") + c.path + ": "),
              std::string::npos)
        << c.name << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.name;
  }
}

TEST_F(Cli, NotJsonExitsTwo) {
  const Run r = run("simulate " + quote(write("bad.json", "{\"physics\": NaN}")));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("invalid scenario"), std::string::npos) << r.err;
}

TEST_F(Cli, CaromBreakRunsToRest) {
  const json doc = json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "carom"},
    "rack": {"game": "three_cushion", "seed": 1},
    "cue": {"ball": "white", "speed": 4.0, "phi": 30.0}
  })");
  const Run r = run("simulate " + quote(write("carom.json", doc.dump())));
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out["complete"], true);
  ASSERT_EQ(out["final"]["balls"].size(), 3u);
  EXPECT_EQ(out["final"]["balls"][0]["id"], "white");
  EXPECT_EQ(out["final"]["balls"][1]["id"], "yellow");
  EXPECT_EQ(out["final"]["balls"][2]["id"], "red");
  bool cushion = false;
  for (const json& e : out["events"]) {
    cushion = cushion || (e["type"] == "ball_cushion" && e["cushion"] == "rail_top");
  }
  EXPECT_TRUE(cushion);

  // The carom rack on a pool table is an invalid scenario.
  json bad = doc;
  bad["table"] = {{"shape", "pool"}, {"size", "9ft"}};
  const Run r2 = run("simulate " + quote(write("carom_bad.json", bad.dump())));
  EXPECT_EQ(r2.status, 2) << r2.err;
  EXPECT_NE(r2.err.find("rack.game: the three_cushion rack needs the carom table"),
            std::string::npos)
      << r2.err;
}

TEST_F(Cli, PoolBreakRunsToRest) {
  const json doc = json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "pool", "size": "9ft"},
    "rack": {"game": "eight_ball", "seed": 1},
    "cue": {"speed": 8.0}
  })");
  const std::string file = quote(write("break.json", doc.dump()));
  const Run r = run("simulate " + file);
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out["complete"], true);
  ASSERT_FALSE(out["events"].empty());
  EXPECT_EQ(out["events"][0]["type"], "cue_strike");
  EXPECT_EQ(out["events"][0]["balls"], json({"cue"}));
  EXPECT_EQ(out["cue"]["miscue"], false);
  ASSERT_EQ(out["final"]["balls"].size(), 16u);
  EXPECT_EQ(out["final"]["balls"][0]["id"], "cue");
  for (const json& b : out["final"]["balls"]) {
    const std::string state = b["state"].get<std::string>();
    EXPECT_TRUE(state == "stationary" || state == "pocketed") << b.dump();
  }
  EXPECT_EQ(run("simulate " + file).out, r.out);  // the same bytes again
}

TEST_F(Cli, PoolScenarioErrorsExitTwo) {
  json doc = json::parse(R"({
    "physics": {"model": "pool"},
    "table": {"shape": "pool", "size": "10ft"},
    "rack": {"game": "eight_ball"}
  })");
  Run r = run("simulate " + quote(write("size.json", doc.dump())));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("invalid scenario: table.size: "), std::string::npos) << r.err;
  doc["table"]["size"] = "9ft";
  doc["cue"] = {{"speed", 3.0}, {"theta", 90.0}};
  r = run("simulate " + quote(write("theta.json", doc.dump())));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("invalid scenario: cue.theta: "), std::string::npos) << r.err;
}

TEST_F(Cli, OtherFailuresExitOne) {
  Run r = run("simulate " + quote((dir_ / "no-such-file.json").string()));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no-such-file.json"), std::string::npos) << r.err;

  r = run("simulate " + quote(dir_.string()));
  EXPECT_EQ(r.status, 1) << r.err;

  const std::string file = quote(write("s.json", good_scenario().dump()));
  r = run("simulate " + file + " -o " + quote((dir_ / "missing-dir" / "out.json").string()));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;

  r = run("simulate");  // no file
  EXPECT_EQ(r.status, 1);
  r = run("");  // no subcommand
  EXPECT_EQ(r.status, 1);
  r = run("frobnicate");
  EXPECT_EQ(r.status, 1);
  r = run("simulate " + file + " --no-such-option");
  EXPECT_EQ(r.status, 1);
}

TEST_F(Cli, HelpAndVersion) {
  Run r = run("--version");
  EXPECT_EQ(r.status, 0);
  // The library's version (version.hpp) and the commit it was built from.
  EXPECT_EQ(r.out.rfind("breakshot " + std::string(breakshot::kVersion) + " (commit ", 0), 0u)
      << r.out;
  r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("simulate"), std::string::npos);
  r = run("simulate --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("Exit status"), std::string::npos);
}

}  // namespace

#endif  // BREAKSHOT_CLI

}  // namespace test_cli
