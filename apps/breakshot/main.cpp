// The breakshot command: simulate a scenario file and write the result.
//
//   breakshot simulate FILE|- [-o PATH] [--plot PREFIX]
//
// Exit status (shared/contract/scenario-format.md): 0 the run is
// complete, 2 the scenario is invalid (nothing simulated), 3 max_events
// stopped the run (the partial result is written), 1 anything else.

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <new>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "breakshot/lab.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"

#ifndef BREAKSHOT_VERSION
#define BREAKSHOT_VERSION "0.1.0"
#endif

namespace {

namespace bs = breakshot;

constexpr int kExitOk = 0;
constexpr int kExitOther = 1;
constexpr int kExitInvalid = 2;
constexpr int kExitEventLimit = 3;

/// Thrown for the failures that end the command with exit status 1; the
/// message is what the user sees after "breakshot: ".
struct Failure {
  std::string message;
};

std::string read_input(const std::string& file) {
  if (file == "-") {
    std::ostringstream text;
    text << std::cin.rdbuf();
    if (std::cin.bad()) throw Failure{"cannot read standard input"};
    return text.str();
  }
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw Failure{"cannot read " + file + ": it is a directory"};
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Failure{"cannot read " + file + ": " + std::strerror(errno)};
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw Failure{"cannot read " + file + ": read error"};
  return text;
}

void write_output(const std::string& path, const std::string& text) {
  if (path.empty() || path == "-") {
    std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
    std::cout.flush();
    if (!std::cout) throw Failure{"cannot write the result to standard output"};
    return;
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw Failure{"cannot write " + path + ": " + std::strerror(errno)};
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw Failure{"cannot write " + path + ": write error"};
}

bool finite(bs::Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(bs::Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const bs::BallState& b) {
  return finite(b.position) && finite(b.velocity) && finite(b.spin);
}

/// A result with an infinity or NaN in it is a bug in the engine, not an
/// answer; JSON cannot carry those values, so say so instead of writing
/// nulls that a reader would take for data.
void check_finite(const bs::RunResult& r) {
  bool ok = std::isfinite(r.final_time);
  for (const auto& b : r.final_balls) ok = ok && finite(b);
  for (const auto& e : r.events) ok = ok && std::isfinite(e.time);
  for (const auto& s : r.samples) {
    ok = ok && std::isfinite(s.time);
    for (const auto& b : s.balls) ok = ok && finite(b);
  }
  if (!ok) throw Failure{"the simulation produced a non-finite number (an engine bug)"};
}

struct SimulateOptions {
  std::string input;
  std::string output;
  std::string plot_prefix;
};

int run_simulate(const SimulateOptions& opt) {
  const std::string text = read_input(opt.input);
  auto parsed = bs::read_scenario(text);
  if (const auto* err = std::get_if<bs::ScenarioError>(&parsed)) {
    if (err->unsupported) {
      std::cerr << "breakshot: not supported yet: " << err->path << ": " << err->reason << '\n';
      return kExitOther;
    }
    std::cerr << "breakshot: invalid scenario: " << err->path << ": " << err->reason << '\n';
    return kExitInvalid;
  }
  const bs::Scenario& scenario = std::get<bs::Scenario>(parsed);

  const bs::RunResult result = bs::simulate(scenario);
  check_finite(result);
  write_output(opt.output, bs::write_result(scenario, result));
  if (!result.complete) {
    std::cerr << "breakshot: stopped after max_events = " << scenario.max_events
              << " events; the result is incomplete\n";
  }

  if (!opt.plot_prefix.empty()) {
    const std::vector<bs::Sample> frames = bs::trace(scenario);
    try {
      for (const std::string& path : bs::write_plots(scenario, frames, opt.plot_prefix)) {
        std::cerr << "breakshot: wrote " << path << '\n';
      }
    } catch (const std::runtime_error& e) {
      throw Failure{e.what()};
    }
  }
  return result.complete ? kExitOk : kExitEventLimit;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"breakshot: an event-driven billiards physics engine", "breakshot"};
  app.set_version_flag("--version", std::string("breakshot ") + BREAKSHOT_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Run 'breakshot simulate --help' for the scenario file and exit status.\n"
      "The scenario and result file formats are described in docs/scenario.md.");

  SimulateOptions opt;
  CLI::App* sim = app.add_subcommand(
      "simulate", "Simulate a scenario (JSON) and write the result (JSON)");
  sim->add_option("FILE", opt.input, "Scenario file, or - for standard input")->required();
  sim->add_option("-o,--output", opt.output, "Write the result to PATH instead of standard output")
      ->type_name("PATH");
  sim->add_option("--plot", opt.plot_prefix,
                  "Also write PREFIX-trajectories.svg, PREFIX-energy.svg and PREFIX-momentum.svg")
      ->type_name("PREFIX");
  sim->footer(
      "Exit status:\n"
      "  0  simulated; the result has \"complete\": true\n"
      "  2  invalid scenario: nothing simulated; standard error names the field\n"
      "  3  the max_events guard stopped the run; the result so far is written\n"
      "     with \"complete\": false\n"
      "  1  anything else (unreadable file, unsupported feature, cannot write)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with status 0; usage errors print
    // their message and map to the contract's "anything else".
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitOther;
  }

  try {
    return run_simulate(opt);
  } catch (const Failure& f) {
    std::cerr << "breakshot: " << f.message << '\n';
  } catch (const std::bad_alloc&) {
    std::cerr << "breakshot: out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << "breakshot: error: " << e.what() << '\n';
  }
  return kExitOther;
}
