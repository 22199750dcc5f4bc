// Break statistics per break option, under tournament noise (docs/experiments.md,
// "richer safeties; 9-ball calls on expected pots"): which placements, aims, speeds and
// tip heights keep the table, break dry or foul.
//
//   break_probe [--game eight_ball|nine_ball] [--racks N]
//
// Each option is the one the AI's break search can play: the cue ball on
// the head string, `dy` metres from the head spot across the table, aimed
// `off` ball radii to one side of the head ball's centre (the apex ball;
// the 1 in 9-ball), at `speed` m/s with tip height `b` (fractions of R,
// draw < 0). Every option breaks the same N racks (rack seeds and noise
// seeds fixed), played through the rules: "keep" is a break after which
// the breaker shoots again or has won, "dry" one that passes the turn
// without a foul, "foul" one with a foul. Prints every option, then the
// mean keep and foul shares for each value of each factor, then the best
// five options by keep. Deterministic, one thread.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "physics/detmath.hpp"

namespace {

using namespace breakshot;

constexpr std::uint64_t kRackSeed = 777;
constexpr std::uint64_t kNoiseSeed = 555;
constexpr double kPi = 3.14159265358979323846;

struct Option {
  double dy = 0.0;
  double off = 0.0;
  double speed = 0.0;
  double b = 0.0;
};

struct Tally {
  int keep = 0;
  int dry = 0;
  int foul = 0;
  int n = 0;
};

int usage(const char* why) {
  std::fprintf(stderr, "break_probe: %s\nusage: break_probe [--game eight_ball|nine_ball] [--racks N]\n",
               why);
  return 2;
}

Tally probe(const Rules& rules, const NoiseModel& noise, const Option& o, int racks) {
  const double R = rules.config().ball_radius;
  const Table& table = rules.table();
  Tally t;
  for (int r = 0; r < racks; ++r) {
    GameState s = rules.start(mix_seed(kRackSeed, static_cast<std::uint64_t>(r)), 0);
    int apex = -1;
    if (s.game == GameType::nine_ball) {
      apex = rules.legal_actions(s).targets.front();
    } else {
      for (std::size_t k = 1; k < s.on_table.size(); ++k) {
        if (s.on_table[k] && (apex < 0 || s.position[k].x < s.position[static_cast<std::size_t>(apex)].x)) {
          apex = static_cast<int>(k);
        }
      }
    }
    const Vec2 target = s.position[static_cast<std::size_t>(apex)];
    const Vec2 p{rules.head_string(), table.head_spot.y + o.dy};
    s.position[0] = p;
    s.on_table[0] = 1;
    const Vec2 d = (target - p) / norm(target - p);
    const Vec2 aim = target + perp(d) * (o.off * R);
    Shoot shot;
    shot.strike.speed = o.speed;
    shot.strike.b = o.b;
    shot.strike.phi = dm::atan2(aim.y - p.y, aim.x - p.x) * 180.0 / kPi;
    shot.strike = perturb(shot.strike, noise, R, mix_seed(kNoiseSeed, static_cast<std::uint64_t>(r)));
    const Outcome out = rules.apply(s, Action{shot});
    ++t.n;
    if (!out.ruling.fouls.empty()) {
      ++t.foul;
    } else if (out.ruling.turn_continues || out.ruling.winner == 0) {
      ++t.keep;
    } else {
      ++t.dry;
    }
  }
  return t;
}

double share(int k, int n) { return n > 0 ? static_cast<double>(k) / n : 0.0; }

}  // namespace

int main(int argc, char** argv) {
  GameConfig config;
  config.game = GameType::nine_ball;
  int racks = 1000;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--game" && i + 1 < argc) {
      const std::string_view g = argv[++i];
      if (g == "eight_ball") {
        config.game = GameType::eight_ball;
      } else if (g == "nine_ball") {
        config.game = GameType::nine_ball;
      } else {
        return usage("--game must be eight_ball or nine_ball");
      }
    } else if (arg == "--racks" && i + 1 < argc) {
      const std::string_view n = argv[++i];
      const auto [end, ec] = std::from_chars(n.data(), n.data() + n.size(), racks);
      if (ec != std::errc{} || end != n.data() + n.size() || racks < 1 || racks > 1000000) {
        return usage("--racks must be a whole number from 1 to 1000000");
      }
    } else {
      return usage(("unknown or incomplete argument '" + std::string(arg) + "'").c_str());
    }
  }
  const Rules rules(config);
  const NoiseModel noise = parse_noise("tournament");

  std::vector<Option> options;
  for (double dy : {-0.45, -0.35, -0.25, 0.25, 0.35, 0.45}) {
    for (double off : {-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3}) {
      for (double speed : {11.0, 12.0}) {
        for (double b : {-0.2, 0.0, 0.2}) options.push_back(Option{dy, off, speed, b});
      }
    }
  }
  std::printf("%s, %d racks a option, tournament noise\n",
              config.game == GameType::nine_ball ? "nine_ball" : "eight_ball", racks);
  std::printf("   dy    off  speed     b    keep    dry   foul\n");
  std::vector<Tally> tallies;
  for (const Option& o : options) {
    const Tally t = probe(rules, noise, o, racks);
    tallies.push_back(t);
    std::printf("%+5.2f  %+5.1f  %5.1f  %+4.1f   %.3f  %.3f  %.3f\n", o.dy, o.off, o.speed, o.b,
                share(t.keep, t.n), share(t.dry, t.n), share(t.foul, t.n));
  }

  // Mean shares for each value of each factor (|dy|: the two sides).
  struct Sum {
    double keep = 0.0;
    double foul = 0.0;
    int n = 0;
  };
  std::map<std::string, Sum> by;
  char key[64];
  for (std::size_t i = 0; i < options.size(); ++i) {
    const Option& o = options[i];
    const Tally& t = tallies[i];
    const auto add = [&](const char* k) {
      Sum& s = by[k];
      s.keep += share(t.keep, t.n);
      s.foul += share(t.foul, t.n);
      ++s.n;
    };
    std::snprintf(key, sizeof key, "|dy| %.2f", o.dy < 0 ? -o.dy : o.dy);
    add(key);
    std::snprintf(key, sizeof key, "speed %.1f", o.speed);
    add(key);
    std::snprintf(key, sizeof key, "b %+.1f", o.b);
    add(key);
  }
  std::printf("\nmean over the options with\n");
  for (const auto& [k, s] : by) {
    std::printf("  %-10s  keep %.3f  foul %.3f\n", k.c_str(), s.keep / s.n, s.foul / s.n);
  }

  std::vector<std::size_t> order(options.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return tallies[a].keep > tallies[b].keep; });
  std::printf("\nbest by keep\n");
  for (std::size_t k = 0; k < 5 && k < order.size(); ++k) {
    const Option& o = options[order[k]];
    const Tally& t = tallies[order[k]];
    std::printf("  dy %+5.2f off %+4.1f speed %4.1f b %+4.1f: keep %.3f, dry %.3f, foul %.3f\n", o.dy,
                o.off, o.speed, o.b, share(t.keep, t.n), share(t.dry, t.n), share(t.foul, t.n));
  }
  return 0;
}
