// The breakshot command: simulate a scenario file and write the result;
// play matches between computer players; replay game records.
//
//   breakshot simulate FILE|- [-o PATH] [--plot PREFIX]
//   breakshot match --game eight_ball|nine_ball|ten_ball|snooker|three_cushion --players A,B
//                   --games N
//                   --seed S --noise LEVEL [--table 7ft|8ft|9ft|12ft|10ft] [--records DIR]
//                   [--timing]
//                   [--target N] [--innings-limit N] [--equalizing-inning on|off] (three-cushion)
//                   [--first-game N] [--jobs N] [--cushion-model NAME] [--ball-ball-model NAME]
//                   [--ball-ball-friction tpa28|tpb3|A,B,C|MU] [--airborne on|off]
//                   [--spinning-friction measured|legacy|MU]
//   breakshot match-sum SUMMARY...
//     (--noise is the noise of players without one of their own; AI levels
//     shoot with their level's noise)
//   breakshot replay RECORD|-
//
// Exit status of simulate (docs/contract.md): 0 the run
// is complete, 2 the scenario is invalid (nothing simulated), 3
// max_events stopped the run (the partial result is written), 1 anything
// else. match: 0 played (the summary JSON on standard output), 2 a bad
// argument (named on standard error), 1 anything else. replay: 0 the
// record replays identical, 4 it differs (what and where on standard
// output), 2 the record cannot be read or is invalid (standard error
// names the JSON path), 1 anything else. match-sum: 0 summed (the summary
// on standard output), 2 a summary cannot be read, is invalid or is not of
// the same match as the others (standard error names the file and the
// problem), 1 anything else.

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "breakshot/game.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/match.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/plot.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/record.hpp"
#include "breakshot/players.hpp"
#include "breakshot/match_io.hpp"
#include "breakshot/record_io.hpp"
#include "breakshot/scenario_io.hpp"
#include "web/serve.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/version.hpp"

#include <csignal>

#include "build_commit.hpp"  // BREAKSHOT_COMMIT (cmake/build_commit.cmake)

namespace {

namespace bs = breakshot;

constexpr int kExitOk = 0;
constexpr int kExitOther = 1;
constexpr int kExitInvalid = 2;
constexpr int kExitEventLimit = 3;
constexpr int kExitReplayDiffers = 4;

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

  // With --plot, one run gives both the result and the plots' frames.
  bs::RunResult result;
  std::vector<bs::Sample> frames;
  if (opt.plot_prefix.empty()) {
    result = bs::simulate(scenario);
  } else {
    bs::TracedRun traced = bs::simulate_traced(scenario);
    result = std::move(traced.result);
    frames = std::move(traced.frames);
  }
  check_finite(result);
  write_output(opt.output, bs::write_result(scenario, result));
  if (!result.complete) {
    std::cerr << "breakshot: stopped after max_events = " << scenario.max_events
              << " events; the result is incomplete\n";
  }

  if (!opt.plot_prefix.empty()) {
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

/// A bad command-line value: exit status 2, the message after "breakshot: ".
struct BadArgument {
  std::string message;
};

/// Options of `match` as typed: numbers and names are checked here, not
/// by CLI11, so that a bad value is exit status 2 with a message naming
/// the option (CLI11's own errors are usage errors, status 1).
struct MatchArgs {
  std::string game;
  std::string players;
  std::string games;
  std::string seed;
  std::string noise;
  std::string table;  // empty: 9ft, snooker 12ft, three-cushion 10ft
  std::string records;
  std::string first_game = "0";
  std::string jobs;  // empty: every core, or 1 with --timing
  bool timing = false;
  std::string physics;             // a preset ("default", "legacy"); empty: "default"
  std::string cushion_model;       // empty: the preset's
  std::string ball_ball_model;     // empty: the default
  std::string ball_ball_friction;  // empty: the default
  std::string airborne;            // "on", "off"; empty: the default
  std::string spinning_friction;   // "measured", "legacy" or a number; empty: the default
  std::string target;              // three-cushion; empty: the default
  std::string innings_limit;       // three-cushion; empty: the default
  std::string equalizing_inning;   // three-cushion: "on", "off"; empty: the default
};

template <class T>
bool parse_whole(const std::string& text, T& out) {
  const char* last = text.data() + text.size();
  const auto r = std::from_chars(text.data(), last, out);
  return !text.empty() && r.ec == std::errc() && r.ptr == last;
}

/// --ball-ball-friction: "tpa28", "tpb3", "A,B,C" (the curve a + b exp(-c v))
/// or one number (a constant).
void parse_ball_ball_friction(const std::string& text, bs::GamePhysics& p) {
  const std::string option = "--ball-ball-friction: ";
  if (text == "tpa28" || text == "tpb3") {
    p.ball_ball_friction_fit = true;
    p.ball_ball_friction_curve = text == "tpa28" ? bs::kThrowFitTPA28 : bs::kThrowFitTPB3;
    p.ball_ball_friction = 0.0;
    return;
  }
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos
                                                                           : comma - start);
    double x = 0.0;
    if (!parse_whole(part, x) || !std::isfinite(x)) {
      throw BadArgument{option + "expected tpa28, tpb3, a curve A,B,C or a constant friction, "
                        "not '" + text + "'"};
    }
    values.push_back(x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() == 3) {
    p.ball_ball_friction_fit = true;
    p.ball_ball_friction_curve = {values[0], values[1], values[2]};
    p.ball_ball_friction = 0.0;
    if (auto bad = bs::check_friction_curve(p.ball_ball_friction_curve)) {
      throw BadArgument{option + std::string(1, bad->member) + ": " + bad->reason};
    }
  } else if (values.size() == 1) {
    if (values[0] < 0.0) {
      throw BadArgument{option + "a constant friction must be >= 0, not '" + text + "'"};
    }
    p.ball_ball_friction_fit = false;
    p.ball_ball_friction_curve = bs::FrictionCurve{};
    p.ball_ball_friction = values[0];
  } else {
    throw BadArgument{option + "expected one number (a constant) or three (a curve A,B,C), not '" +
                      text + "'"};
  }
}

/// The cushion models' names, "han_2005_v0, ... or impulse_frictional".
std::string cushion_model_list() {
  std::string out;
  const std::size_t n = std::size(bs::kCushionModels);
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) out += k + 1 == n ? " or " : ", ";
    out += bs::cushion_model_name(bs::kCushionModels[k]);
  }
  return out;
}

/// The physics presets' names, "default or legacy".
std::string physics_preset_list() {
  std::string out;
  const std::size_t n = std::size(bs::kGamePhysicsPresets);
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0) out += k + 1 == n ? " or " : ", ";
    out += bs::kGamePhysicsPresets[k];
  }
  return out;
}

/// The physics options of `match`: the preset's physics (--physics, the
/// engine's defaults when not given), each option given explicitly
/// winning over the preset's value for it.
bs::GamePhysics match_physics(const MatchArgs& a) {
  bs::GamePhysics p;
  if (!a.physics.empty()) {
    const auto preset = bs::game_physics_preset(a.physics);
    if (!preset) {
      throw BadArgument{"--physics: unknown physics preset '" + a.physics + "' (" +
                        physics_preset_list() + ")"};
    }
    p = *preset;
  }
  if (!a.cushion_model.empty() && !bs::parse_cushion_model(a.cushion_model, p.cushion_model)) {
    throw BadArgument{"--cushion-model: unknown cushion model '" + a.cushion_model + "' (" +
                      cushion_model_list() + ")"};
  }
  if (!a.ball_ball_model.empty() &&
      !bs::parse_ball_ball_model(a.ball_ball_model, p.ball_ball_model)) {
    throw BadArgument{"--ball-ball-model: unknown ball-ball model '" + a.ball_ball_model +
                      "' (friction or mathavan_2014)"};
  }
  if (!a.ball_ball_friction.empty()) parse_ball_ball_friction(a.ball_ball_friction, p);
  if (a.airborne == "on" || a.airborne == "off") {
    p.airborne = a.airborne == "on";
  } else if (!a.airborne.empty()) {
    throw BadArgument{"--airborne: expected on or off, not '" + a.airborne + "'"};
  }
  if (a.spinning_friction == "measured") {
    p.spinning_friction = bs::kSpinningFriction;
  } else if (a.spinning_friction == "legacy") {
    p.spinning_friction = bs::kLegacySpinningFriction;
  } else if (!a.spinning_friction.empty()) {
    double mu = 0.0;
    if (!parse_whole(a.spinning_friction, mu) || !std::isfinite(mu) || !(mu > 0.0)) {
      throw BadArgument{"--spinning-friction: expected measured, legacy or a number > 0, not '" +
                        a.spinning_friction + "'"};
    }
    p.spinning_friction = mu;
  }
  return p;
}

bs::MatchOptions match_options(const MatchArgs& a) {
  bs::MatchOptions opt;
  const auto game = bs::parse_game_type(a.game);
  if (!game) {
    throw BadArgument{"--game: unknown game '" + a.game +
                      "' (eight_ball, nine_ball, ten_ball, snooker or three_cushion)"};
  }
  opt.game = *game;

  const std::size_t comma = a.players.find(',');
  if (comma == std::string::npos || a.players.find(',', comma + 1) != std::string::npos ||
      comma == 0 || comma + 1 == a.players.size()) {
    throw BadArgument{"--players: expected two player names separated by a comma (like "
                      "baseline,baseline), not '" + a.players + "'"};
  }
  opt.players = {a.players.substr(0, comma), a.players.substr(comma + 1)};
  for (const std::string& name : opt.players) {
    if (auto why = bs::check_player(name, opt.game)) throw BadArgument{"--players: " + *why};
  }

  if (!parse_whole(a.games, opt.games) || opt.games < 1) {
    throw BadArgument{"--games: expected a whole number of games >= 1, not '" + a.games + "'"};
  }
  if (!parse_whole(a.first_game, opt.first_game) || opt.first_game < 0) {
    throw BadArgument{"--first-game: expected a whole number >= 0, not '" + a.first_game + "'"};
  }
  if (opt.first_game > std::numeric_limits<int>::max() - opt.games) {
    throw BadArgument{"--first-game: --first-game + --games must be at most " +
                      std::to_string(std::numeric_limits<int>::max()) + ", not " +
                      a.first_game + " + " + a.games};
  }
  if (!a.jobs.empty()) {
    if (!parse_whole(a.jobs, opt.jobs) || opt.jobs < 0) {
      throw BadArgument{"--jobs: expected a whole number >= 0 (0: one per core), not '" + a.jobs +
                        "'"};
    }
  } else {
    // Decision times are each decision's own only when games do not
    // share the cores.
    opt.jobs = a.timing ? 1 : 0;
  }
  if (!parse_whole(a.seed, opt.seed)) {
    throw BadArgument{"--seed: expected a whole number in [0, 2^64), not '" + a.seed + "'"};
  }
  try {
    opt.noise = bs::parse_noise(a.noise);
  } catch (const std::invalid_argument& e) {
    std::string_view why = e.what();
    if (why.substr(0, 7) == "noise: ") why.remove_prefix(7);
    throw BadArgument{"--noise: " + std::string(why)};
  }
  if (opt.game == bs::GameType::snooker) {
    if (!a.table.empty() && a.table != "12ft") {
      throw BadArgument{"--table: snooker is played on the 12ft table, not '" + a.table + "'"};
    }
    opt.table_size = "12ft";
  } else if (opt.game == bs::GameType::three_cushion) {
    if (!a.table.empty() && a.table != "10ft") {
      throw BadArgument{"--table: three_cushion is played on the 10ft carom table, not '" +
                        a.table + "'"};
    }
    opt.table_size = "10ft";
  } else {
    const std::string table = a.table.empty() ? "9ft" : a.table;
    if (table != "7ft" && table != "8ft" && table != "9ft") {
      throw BadArgument{"--table: unknown table size '" + table + "' (7ft, 8ft or 9ft)"};
    }
    opt.table_size = table;
  }
  const bool carom = opt.game == bs::GameType::three_cushion;
  for (const auto& [given, option] :
       {std::pair{&a.target, "--target"}, std::pair{&a.innings_limit, "--innings-limit"},
        std::pair{&a.equalizing_inning, "--equalizing-inning"}}) {
    if (!given->empty() && !carom) {
      throw BadArgument{std::string(option) + ": only three_cushion has this option, not " +
                        a.game};
    }
  }
  if (!a.target.empty() && (!parse_whole(a.target, opt.carom.target) || opt.carom.target < 1)) {
    throw BadArgument{"--target: expected a whole number of points >= 1, not '" + a.target + "'"};
  }
  if (!a.innings_limit.empty() &&
      (!parse_whole(a.innings_limit, opt.carom.innings_limit) || opt.carom.innings_limit < 0)) {
    throw BadArgument{"--innings-limit: expected a whole number >= 0 (0: no limit), not '" +
                      a.innings_limit + "'"};
  }
  if (a.equalizing_inning == "on" || a.equalizing_inning == "off") {
    opt.carom.equalizing_inning = a.equalizing_inning == "on";
  } else if (!a.equalizing_inning.empty()) {
    throw BadArgument{"--equalizing-inning: expected on or off, not '" + a.equalizing_inning + "'"};
  }
  opt.physics = match_physics(a);
  opt.timing = a.timing;
  return opt;
}

int run_match(const MatchArgs& args) {
  bs::MatchOptions opt;
  try {
    opt = match_options(args);
  } catch (const BadArgument& bad) {
    std::cerr << "breakshot: " << bad.message << '\n';
    return kExitInvalid;
  }
  try {
    const bs::RecordSink records =
        args.records.empty() ? bs::RecordSink{} : bs::record_files(args.records);
    write_output("", bs::match_summary_json(bs::play_match(opt, records)));
  } catch (const std::runtime_error& e) {
    // A record that cannot be written: the message names the path.
    throw Failure{e.what()};
  }
  return kExitOk;
}

/// `match-sum`: the summaries of chunks of one match added together.
int run_match_sum(const std::vector<std::string>& files) {
  bs::MatchSummary sum;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string& file = files[i];
    std::string text;
    try {
      text = read_input(file);
    } catch (const Failure& f) {
      std::cerr << "breakshot: " << f.message << '\n';
      return kExitInvalid;
    }
    const std::string name = file == "-" ? "standard input" : file;
    bs::MatchSummary part;
    try {
      part = bs::read_match_summary(text);
    } catch (const std::invalid_argument& e) {
      std::cerr << "breakshot: invalid summary " << name << ": " << e.what() << '\n';
      return kExitInvalid;
    }
    if (i == 0) {
      sum = std::move(part);
      continue;
    }
    try {
      bs::add_summary(sum, part);
    } catch (const std::invalid_argument& e) {
      std::cerr << "breakshot: cannot add " << name << " to "
                << (i == 1 ? files[0] : "the summaries before it") << ": " << e.what() << '\n';
      return kExitInvalid;
    }
  }
  write_output("", bs::match_summary_json(sum));
  return kExitOk;
}

int run_replay(const std::string& file) {
  std::string text;
  try {
    text = read_input(file);
  } catch (const Failure& f) {
    std::cerr << "breakshot: " << f.message << '\n';
    return kExitInvalid;
  }
  auto parsed = bs::read_record(text);
  if (const auto* err = std::get_if<bs::RecordError>(&parsed)) {
    std::cerr << "breakshot: invalid record: " << err->path << ": " << err->reason << '\n';
    return kExitInvalid;
  }
  const bs::GameRecord& record = std::get<bs::GameRecord>(parsed);
  const bs::ReplayReport report = bs::replay(record);
  std::ostringstream out;
  if (!report.identical) {
    out << "replayed " << report.actions_identical << " of " << record.actions.size()
        << " actions identical, then: " << report.message << '\n';
    write_output("", out.str());
    return kExitReplayDiffers;
  }
  out << "replayed " << record.actions.size() << " actions: identical\n";
  const bs::GameState& end = report.final_state;
  if (record.ending) {
    // A game the rules did not end: online play's forfeit.
    const bs::GameEnding& e = *record.ending;
    if (e.winner < 0) {
      out << bs::to_string(e.kind) << ": " << e.text << '\n';
    } else {
      out << bs::to_string(e.kind) << ": winner Player " << e.winner + 1 << " ("
          << record.players[static_cast<std::size_t>(e.winner)] << "): " << e.text << '\n';
    }
  } else if (end.phase != bs::Phase::game_over) {
    out << "the game is not over (phase " << bs::to_string(end.phase) << ")\n";
  } else if (end.winner < 0) {
    out << "draw: " << end.result << '\n';
  } else {
    // Numbered from 1, as the rulings' texts number the players.
    out << "winner: Player " << end.winner + 1 << " ("
        << record.players[static_cast<std::size_t>(end.winner)] << "): " << end.result << '\n';
  }
  write_output("", out.str());
  return kExitOk;
}

struct ServeArgs {
  std::string root;  // empty: the first of default_page_roots() that holds a page
  std::string host = "127.0.0.1";
  int port = 8000;
  std::string records;
  double seat_timeout = 120;
  bool quiet = false;
};

// Set by SIGINT/SIGTERM so that `serve` returns and the process exits 0.
std::atomic<bool> g_stop_serving{false};
extern "C" void on_stop_signal(int) { g_stop_serving.store(true); }

/// Where `serve` looks for the page without --root, in order: the
/// installed page beside the command (`cmake --install` puts
/// build/web/dist's files in DATADIR/breakshot/web, BINDIR/../share/
/// breakshot/web), then, for the command of the build tree only,
/// scripts/web.sh's build/web/dist.
std::vector<std::filesystem::path> default_page_roots() {
  namespace fs = std::filesystem;
  std::vector<fs::path> out;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return out;
  const fs::path bin = exe.parent_path();
#ifdef BREAKSHOT_WEB_INSTALLED
  out.push_back((bin / BREAKSHOT_WEB_INSTALLED).lexically_normal());
#endif
#if defined(BREAKSHOT_WEB_DIST) && defined(BREAKSHOT_BINARY_DIR)
  if (fs::equivalent(bin, fs::path(BREAKSHOT_BINARY_DIR), ec)) {
    out.push_back(fs::path(BREAKSHOT_WEB_DIST));
  }
#endif
  return out;
}

/// The page's folder: --root, else the first default that holds an
/// index.html; nullopt (after saying where it looked) when there is none.
std::optional<std::string> page_root(const ServeArgs& args) {
  if (!args.root.empty()) return args.root;
  const std::vector<std::filesystem::path> roots = default_page_roots();
  std::string looked;
  for (const std::filesystem::path& r : roots) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(r / "index.html", ec)) return r.string();
    looked += (looked.empty() ? "" : ", ") + r.string();
  }
  std::cerr << "breakshot: no page found: no index.html in "
            << (looked.empty() ? std::string("(no place to look: the command's own folder is "
                                             "unknown)")
                               : looked)
            << ". Build the page with scripts/web.sh (then `cmake --install` installs it beside "
               "the command), or give --root DIR.\n";
  return std::nullopt;
}

int run_serve(const ServeArgs& args) {
  const std::optional<std::string> root = page_root(args);
  if (!root) return kExitOther;
  breakshot::ServeOptions o;
  o.root = *root;
  o.host = args.host;
  o.port = args.port;
  o.records = args.records;
  o.rooms.seat_timeout = args.seat_timeout;
  o.stop = &g_stop_serving;
  o.on_ready = [&](int port) {
    std::cout << "breakshot: serving " << o.root << "\n";
    if (!args.records.empty()) {
      std::cout << "breakshot: the records of online games go to " << args.records << "\n";
    }
    if (breakshot::is_loopback(args.host)) {
      std::cout << "breakshot: open http://" << args.host << ":" << port
                << "/ (Ctrl-C stops)" << std::endl;
    } else {
      std::cout << "breakshot: WARNING: listening on " << args.host << ":" << port
                << ", reachable from the network.\n"
                << "breakshot: WARNING: it speaks plain HTTP and WebSocket, without TLS:\n"
                << "breakshot: WARNING: put it behind a reverse proxy that adds TLS "
                   "(docs/web.md, \"Online play\").\n"
                << "breakshot: (Ctrl-C stops)" << std::endl;
    }
  };
  if (!args.quiet) {
    o.log = [](const std::string& line) { std::cerr << line << '\n'; };
  }
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  try {
    breakshot::serve(o);
  } catch (const std::runtime_error& e) {
    throw Failure{e.what()};
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"breakshot: an event-driven billiards physics engine", "breakshot"};
  app.set_version_flag("--version", "breakshot " + std::string(bs::kVersion) + " (commit " +
                                        BREAKSHOT_COMMIT + ")");
  app.require_subcommand(1);
  app.footer(
      "Run 'breakshot simulate --help' for the scenario file and exit status,\n"
      "'breakshot match --help', 'breakshot match-sum --help' and\n"
      "'breakshot replay --help' for games,\n"
      "'breakshot serve --help' for the browser game and lab.\n"
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

  MatchArgs match_args;
  CLI::App* match = app.add_subcommand(
      "match", "Play games between computer players and print a summary (JSON)");
  match->add_option("--game", match_args.game,
                    "eight_ball, nine_ball, ten_ball, snooker or three_cushion")
      ->type_name("GAME")
      ->required();
  match->add_option("--players", match_args.players,
                    "The two players, by name, comma separated (e.g. baseline,baseline); "
                    "NAME@NOISE plays that player at a noise of its own (e.g. champion@0.5x)")
      ->type_name("A,B")
      ->required();
  match->add_option("--games", match_args.games, "Number of games (>= 1); breaks alternate")
      ->type_name("N")
      ->required();
  match->add_option("--seed", match_args.seed, "Match seed (0 to 2^64 - 1): same seed, same match")
      ->type_name("S")
      ->required();
  match->add_option("--noise", match_args.noise,
                    "Shot noise of players without a noise of their own (the baseline): "
                    "none, tournament, <k>x (k times tournament) or "
                    "custom:phi=..,theta=..,speed=..,a=..,b=..")
      ->type_name("LEVEL")
      ->required();
  match
      ->add_option("--table", match_args.table,
                   "Table size: 7ft, 8ft or 9ft (default 9ft); snooker: 12ft (the default); "
                   "three_cushion: 10ft (the default, the 2840 x 1420 mm carom table)")
      ->type_name("SIZE");
  match
      ->add_option("--target", match_args.target,
                   "three_cushion: the points that win a game (default 40)")
      ->type_name("N");
  match
      ->add_option("--innings-limit", match_args.innings_limit,
                   "three_cushion: the game ends after this many innings each, the higher "
                   "score winning (default 50; 0: no limit)")
      ->type_name("N");
  match
      ->add_option("--equalizing-inning", match_args.equalizing_inning,
                   "three_cushion: on (default): when the breaker reaches the target, the "
                   "other player has one more inning; off: the game ends at once")
      ->type_name("on|off");
  match->add_option("--records", match_args.records,
                    "Write each game's record to DIR/game-0001.json, ... (DIR is created)")
      ->type_name("DIR");
  match->add_option("--first-game", match_args.first_game,
                    "Play games N .. N + games - 1 of the match (default 0): each game is played "
                    "as in one long match, so chunks of a match can be summed (match-sum)")
      ->type_name("N");
  match->add_option("--jobs", match_args.jobs,
                    "Games played at once (0: one per core; the default, or 1 with --timing); "
                    "the summary and the records are the same for any N")
      ->type_name("N");
  match->add_option("--physics", match_args.physics,
                    "Physics preset: " + physics_preset_list() +
                        " (default: the engine's; legacy: breakshot 0.1's, the four options "
                        "below); an option below given with it wins over the preset's value")
      ->type_name("NAME");
  match->add_option("--cushion-model", match_args.cushion_model,
                    "Cushion law: " + cushion_model_list() +
                        " (default han_2005; han_2005_v0 is the legacy law; docs/physics.md)")
      ->type_name("NAME");
  match->add_option("--ball-ball-model", match_args.ball_ball_model,
                    "Ball-ball impact law: friction (default) or mathavan_2014")
      ->type_name("NAME");
  match->add_option("--ball-ball-friction", match_args.ball_ball_friction,
                    "Ball-ball friction: tpb3 (default: Alciatore's refit to the measured throw, "
                    "TP B-3), tpa28 (TP A-28's curve, the legacy one), a curve A,B,C "
                    "(mu = a + b exp(-c v)) or a constant")
      ->type_name("SPEC");
  match->add_option("--airborne", match_args.airborne,
                    "on (default): balls may leave the cloth (jumps, hops, balls off the "
                    "table); off: they stay on it, as in the legacy physics")
      ->type_name("on|off");
  match->add_option("--spinning-friction", match_args.spinning_friction,
                    "Spinning friction mu_sp (side spin decays at 5 mu_sp g / 2R): measured "
                    "(default, 0.0117: 10 rad/s^2 on a pool ball), legacy (0.044, FastFiz's, "
                    "as in the legacy physics) or a number > 0")
      ->type_name("SPEC");
  match->add_flag("--timing", match_args.timing,
                  "Add each player's decision times (median, p90, max seconds) to the summary; "
                  "they vary from run to run");
  match->footer(
      "--noise is the baseline noise: AI levels shoot with their level's own noise\n"
      "(docs/ai.md), whatever --noise says. The summary gives each player's noise.\n"
      "\n"
      "Exit status:\n"
      "  0  played; the summary JSON is on standard output\n"
      "  2  a bad argument (unknown game, player or table, games < 1, bad seed,\n"
      "     noise, first game or physics): standard error names it\n"
      "  1  anything else (a record cannot be written, a missing option)\n"
      "\n"
      "A long match can be played in chunks: --first-game N --games K plays games\n"
      "N .. N+K-1 exactly as one match from game 0 plays them (records are\n"
      "numbered game-(N+1).json, ...), and its summary says \"first_game\": N.\n"
      "'breakshot match-sum' adds the chunks' summaries into the match's.\n"
      "\n"
      "The physics options choose the pool model's laws (the scenario fields\n"
      "table.cushion_model, physics.ball_ball_model, physics.ball_ball_friction,\n"
      "physics.airborne and physics.spinning_friction, docs/scenario.md). --physics\n"
      "legacy is the legacy physics, the same as --cushion-model han_2005_v0\n"
      "--ball-ball-friction tpa28 --airborne off --spinning-friction legacy; an option\n"
      "given with a preset wins over the preset's value for it (--physics legacy\n"
      "--airborne on: the legacy physics with airborne balls). Records always carry\n"
      "the physics; the summary shows it (\"physics\") only when it is not the default.");

  std::vector<std::string> sum_files;
  CLI::App* msum = app.add_subcommand(
      "match-sum", "Add the summaries of chunks of one match (match --first-game) together");
  msum->add_option("SUMMARY", sum_files,
                   "Summary files (JSON, as 'breakshot match' prints them), or - for standard "
                   "input")
      ->required();
  msum->footer(
      "Prints the summary of all the games the files cover, exactly the bytes\n"
      "that one 'breakshot match' over those games prints when they are games\n"
      "0 .. N-1 (with \"first_game\" or \"game_ranges\" otherwise). The files\n"
      "must be of one match (game, table, physics, seed, noise and players) and cover\n"
      "different games; any order. --timing summaries cannot be summed.\n"
      "\n"
      "Exit status:\n"
      "  0  summed; the summary JSON is on standard output\n"
      "  2  a file cannot be read, is not a summary, or does not belong with the\n"
      "     others (another match, or games already covered): standard error\n"
      "     names the file and the field\n"
      "  1  anything else");

  std::string record_file;
  CLI::App* rep = app.add_subcommand(
      "replay", "Replay a game record and check that it comes out identical");
  rep->add_option("RECORD", record_file, "Game record (JSON), or - for standard input")
      ->required();
  rep->footer(
      "Exit status:\n"
      "  0  the record replays identical (the winner is printed)\n"
      "  4  the replay differs: standard output names the first action and field\n"
      "  2  the record cannot be read or is invalid: standard error names the\n"
      "     JSON path (a record of a physics or a record version this build\n"
      "     does not have: also the record's version and the engine that made it)\n"
      "  1  anything else\n"
      "\n"
      "Records of version 1 (written before the engine and the physics were\n"
      "recorded) replay on the legacy physics they were played with.");

  ServeArgs serve_args;
  CLI::App* srv = app.add_subcommand(
      "serve", "Serve the browser game, lab and online play (built by scripts/web.sh)");
  srv->add_option("--port", serve_args.port, "TCP port (default 8000; 0 picks a free one)")
      ->type_name("P");
  srv->add_option("--host", serve_args.host,
                  "IPv4 address to listen on (default 127.0.0.1; another is reachable from "
                  "the network)")
      ->type_name("ADDR");
  srv->add_option("--root", serve_args.root,
                  "Folder of the built page (default: the installed page, "
                  "BINDIR/../share/breakshot/web beside the command; for the command of the "
                  "build tree, build/web/dist, where scripts/web.sh builds it)")
      ->type_name("DIR");
  srv->add_option("--records", serve_args.records,
                  "Folder (existing) to write the records of online games to")
      ->type_name("DIR");
  srv->add_option("--seat-timeout", serve_args.seat_timeout,
                  "Seconds an online player may be away before forfeiting (default 120)")
      ->type_name("S")
      ->check(CLI::Range(1.0, 86400.0));
  srv->add_flag("--quiet", serve_args.quiet, "Do not log requests on standard error");
  srv->footer(
      "Serves the page and online play (a WebSocket at /ws, docs/web.md) on one\n"
      "port, on 127.0.0.1 unless --host says otherwise; serves nothing outside\n"
      "DIR; the page loads nothing from elsewhere. Online games' records are\n"
      "written into --records under names the server makes; `breakshot replay`\n"
      "replays them. It speaks plain HTTP: off the loopback interface, TLS\n"
      "belongs to a reverse proxy. Ctrl-C (or SIGTERM) stops it.\n"
      "\n"
      "Exit status:\n"
      "  0  stopped by a signal\n"
      "  1  the page is not built, the port is in use, or another error");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with status 0; usage errors print
    // their message and map to the contract's "anything else".
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitOther;
  }

  try {
    if (match->parsed()) return run_match(match_args);
    if (msum->parsed()) return run_match_sum(sum_files);
    if (rep->parsed()) return run_replay(record_file);
    if (srv->parsed()) return run_serve(serve_args);
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
