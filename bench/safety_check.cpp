// Were a player's safeties forced? (docs/ai.md, "What limits the
// champion"). For each safety the player chose in recorded games, a
// brute-force search looks for a direct pot that shot generation may
// have missed, and both are played under tournament noise.
//
//   breakshot match --game eight_ball --players champion,baseline --games 40
//       --seed 7 --noise tournament --records /tmp/records   (one line)
//   safety_check [--player NAME] [--min P] /tmp/records/game-*.json
//
// A safety here is a shot the player (default: champion) played with no
// call from a table with the cue ball on it and no ball in hand (the AI
// calls every pot it attempts, in 9-ball too; docs/ai.md). On each such
// table, for every legal target ball:
//
//   - the sweep: the cue ball is struck at the centre at 1.5, 2.5 and
//     4 m/s, at every aim 0.02 degrees apart across the range in which it
//     can meet that ball directly, without noise. For each pocket and
//     speed the widest run of neighbouring aims that drop the ball in that
//     pocket is found, and its middle aim is played 48 times under
//     tournament noise;
//   - the generator: generate_shots with the player's own options (the
//     champion's, for an AI level; the defaults otherwise); each pot it
//     returns that hits that ball first and drops it in that pocket
//     (direct, bank or kick) is played 48 times the same way.
//
// An aim of the sweep, or a noisy play, counts when the cue ball hits
// that ball first and the ball drops in that pocket with no foul; a noisy
// play must also leave the shooter at the table (or the winner). Printed:
// one line per table with a pot the sweep makes at least --min (default
// 0.8) of the time, its best share from the sweep and from the generator
// (or "none" when it returned no such pot), and a summary. Deterministic:
// fixed noise seeds, one thread.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "record_file.hpp"

namespace {

using namespace breakshot;

constexpr int kSamples = 48;
constexpr std::uint64_t kSeed = 4242;
constexpr double kStepDeg = 0.02;
constexpr double kPi = 3.14159265358979323846;

/// The pocket `ball` dropped in when the cue ball hit it first and `o`
/// had no foul and did not lose the game for `player`, else -1. The sweep
/// plays without a call, which an 8-ball pot needs to keep the table; the
/// noisy plays carry it.
int dropped_in(const Outcome& o, int ball, int player) {
  if (o.facts.first_hit != ball || !o.ruling.fouls.empty()) return -1;
  if (o.state.phase == Phase::game_over && o.state.winner != player) return -1;
  for (std::size_t i = 0; i < o.facts.pocketed.size(); ++i) {
    if (o.facts.pocketed[i] == ball) return o.facts.pocket_of[i];
  }
  return -1;
}

/// Whether `o` dropped `ball` in `pocket` as dropped_in counts it and left
/// `player` at the table (or the winner).
bool pot_kept(const Outcome& o, int ball, int pocket, int player) {
  if (dropped_in(o, ball, player) != pocket) return false;
  return o.state.phase == Phase::game_over ? o.state.winner == player : o.state.player == player;
}

/// Share of kSamples noisy plays of `shot` that pot `ball` in `pocket`.
double success(const Rules& rules, const GameState& s, const Shoot& shot, int ball, int pocket,
               const NoiseModel& noise) {
  int made = 0;
  for (int k = 0; k < kSamples; ++k) {
    Shoot x = shot;
    x.strike = perturb(shot.strike, noise, rules.config().ball_radius,
                       mix_seed(kSeed, static_cast<std::uint64_t>(k)));
    made += pot_kept(rules.apply(s, Action{x}), ball, pocket, s.player) ? 1 : 0;
  }
  return static_cast<double>(made) / kSamples;
}

/// The shot for `ball` into `pocket`, with the call when the rules take
/// one (8-ball needs it; 9-ball accepts it as information).
Shoot make_shot(const Rules& rules, const GameState& s, const CueStrike& strike, int ball,
                int pocket) {
  Shoot sh;
  sh.strike = strike;
  sh.call = Call{ball, pocket};
  if (rules.check(s, Action{sh})) sh.call.reset();
  return sh;
}

struct Found {
  int ball = -1;
  int pocket = -1;
  double sweep = 0.0;      ///< best share over the speeds
  double speed = 0.0;      ///< m/s of that best
  double width = 0.0;      ///< degrees of noiseless aims that pot it, at that speed
  double generator = -1.0;  ///< best share of the generator's pots; -1: none
  int generated = 0;        ///< how many pots of this ball and pocket it returned
};

struct Options {
  std::string player = "champion";
  double min = 0.8;
  std::vector<const char*> files;
};

std::optional<Options> parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--player" || arg == "--min") {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "safety_check: %s needs a value\n", argv[i]);
        return std::nullopt;
      }
      const std::string_view v = argv[++i];
      if (arg == "--player") {
        o.player = v;
      } else {
        double m = -1.0;
        const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), m);
        if (ec != std::errc() || end != v.data() + v.size() || !(m >= 0.0 && m <= 1.0)) {
          std::fprintf(stderr, "safety_check: --min must be a number in [0, 1], not '%s'\n",
                       argv[i]);
          return std::nullopt;
        }
        o.min = m;
      }
    } else if (arg.rfind("--", 0) == 0) {
      std::fprintf(stderr, "safety_check: unknown option %s\n", argv[i]);
      return std::nullopt;
    } else {
      o.files.push_back(argv[i]);
    }
  }
  if (o.files.empty()) {
    std::fprintf(stderr, "usage: safety_check [--player NAME] [--min P] RECORD.json...\n");
    return std::nullopt;
  }
  return o;
}

/// The sweep and the generator on one table: every (ball, pocket) whose
/// sweep share is at least `min`.
std::vector<Found> examine(const Rules& rules, const GameState& s, const ShotGenOptions& gen,
                           const NoiseModel& noise, double min) {
  const int pockets = static_cast<int>(rules.table().pockets.size());
  const double R = rules.config().ball_radius;
  const Vec2 cue = s.position[0];
  std::vector<Found> found;
  std::vector<CandidateShot> cands;
  bool generated = false;
  for (int ball : rules.legal_actions(s).targets) {
    const Vec2 to = s.position[static_cast<std::size_t>(ball)] - cue;
    const double dist = norm(to);
    if (dist <= 2.0 * R) continue;
    const double centre = std::atan2(to.y, to.x) * 180.0 / kPi;
    const double half = std::asin(std::min(1.0, 2.0 * R / dist)) * 180.0 / kPi;
    const int steps = static_cast<int>(2.0 * half / kStepDeg);
    std::vector<Found> best(static_cast<std::size_t>(pockets));
    for (double speed : {1.5, 2.5, 4.0}) {
      // Which pocket each aim drops the ball in (-1: none).
      std::vector<int> in(static_cast<std::size_t>(steps + 1), -1);
      for (int k = 0; k <= steps; ++k) {
        CueStrike st;
        st.speed = speed;
        st.phi = centre - half + k * kStepDeg;
        Shoot sh;
        sh.strike = st;
        in[static_cast<std::size_t>(k)] = dropped_in(rules.apply(s, Action{sh}), ball, s.player);
      }
      for (int p = 0; p < pockets; ++p) {
        int lo = -1;
        int n = 0;
        for (int k = 0; k <= steps;) {
          if (in[static_cast<std::size_t>(k)] != p) {
            ++k;
            continue;
          }
          int j = k;
          while (j <= steps && in[static_cast<std::size_t>(j)] == p) ++j;
          if (j - k > n) {
            lo = k;
            n = j - k;
          }
          k = j;
        }
        if (n == 0) continue;
        CueStrike st;
        st.speed = speed;
        st.phi = centre - half + (lo + 0.5 * (n - 1)) * kStepDeg;
        const double share = success(rules, s, make_shot(rules, s, st, ball, p), ball, p, noise);
        Found& f = best[static_cast<std::size_t>(p)];
        if (share > f.sweep || f.ball < 0) {
          f = Found{ball, p, share, speed, n * kStepDeg, -1.0, 0};
        }
      }
    }
    for (Found& f : best) {
      if (f.ball < 0 || f.sweep < min) continue;
      if (!generated) {
        cands = generate_shots(rules, s, gen);
        generated = true;
      }
      for (const CandidateShot& c : cands) {
        if (c.first != f.ball || c.target != f.ball || c.pocket != f.pocket) continue;
        ++f.generated;
        f.generator = std::max(f.generator, success(rules, s, c.shot, f.ball, f.pocket, noise));
      }
      found.push_back(f);
    }
  }
  return found;
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<Options> opt = parse(argc, argv);
  if (!opt) return 2;
  ShotGenOptions gen;
  try {
    gen = ai_level(opt->player).generation;
  } catch (const std::exception&) {
    // Not an AI level (the baseline): the generator's defaults.
  }
  const NoiseModel noise = parse_noise("tournament");

  int safeties = 0;
  int with_pot = 0;      // tables where the sweep makes some pot >= min
  int none = 0;          // ... and the generator returned no pot for the best pair
  int lower = 0;         // ... or its best was 0.2 or more below the sweep's
  int seated = 0;        // records in which the player played
  for (const char* file : opt->files) {
    const std::optional<GameRecord> read = bench_tools::read_record_file("safety_check", file);
    if (!read) return 1;
    const GameRecord& rec = *read;
    int seat = -1;
    for (int p = 0; p < 2; ++p) {
      if (rec.players[static_cast<std::size_t>(p)] == opt->player) seat = p;
    }
    if (seat < 0) continue;
    ++seated;
    const Rules rules(rec.config);
    GameState before = rec.start;
    int index = 0;
    for (const RecordedAction& a : rec.actions) {
      const auto* shot = std::get_if<Shoot>(&a.action);
      const bool counted = a.player == seat && shot && !shot->call &&
                           before.phase == Phase::shot && before.on_table[0] &&
                           before.ball_in_hand == BallInHand::none;
      if (counted) {
        ++safeties;
        std::vector<Found> found = examine(rules, before, gen, noise, opt->min);
        if (!found.empty()) {
          std::stable_sort(found.begin(), found.end(),
                           [](const Found& x, const Found& y) { return x.sweep > y.sweep; });
          const Found& f = found.front();
          ++with_pot;
          if (f.generated == 0) {
            ++none;
          } else if (f.generator < f.sweep - 0.2) {
            ++lower;
          }
          const Vec2 b = before.position[static_cast<std::size_t>(f.ball)];
          std::printf("%s action %d: ball %d at (%.3f, %.3f) into pocket %d: sweep %.2f (%.1f m/s, "
                      "%.2f deg wide), generator ",
                      file, index, f.ball, b.x, b.y, f.pocket, f.sweep, f.speed, f.width);
          if (f.generated == 0) {
            std::printf("none\n");
          } else {
            std::printf("%.2f (%d pots)\n", f.generator, f.generated);
          }
        }
      }
      before = a.after;
      ++index;
    }
  }
  if (seated == 0) {
    std::fprintf(stderr, "safety_check: no record has a player named %s\n", opt->player.c_str());
    return 1;
  }
  std::printf("safeties by %s from a table with the cue ball on it: %d\n", opt->player.c_str(),
              safeties);
  std::printf("with a direct pot the sweep makes >= %.2f of the time: %d\n", opt->min, with_pot);
  std::printf("  the generator had no pot of that ball into that pocket: %d\n", none);
  std::printf("  the generator's best was 0.2 or more below the sweep's: %d\n", lower);
  return 0;
}
