// How a player's snooker breaks go (docs/ai.md, "Snooker"): visits from
// open tables, many more of them than frames give, in less time.
//
//   snooker_probe [--player NAME] [--tables N] [--from T] [--reds K]
//                 [--seed S] [--noise SPEC] [--shoot-noise SPEC] [--verbose]
//
// Each table has K reds (default 15) placed at random, uniformly over the
// bed, clear of each other, of the colour spots and of the pocket mouths,
// the colours on their spots and the cue ball at random: an open table,
// the kind a break is built on, with the player on a red at 0-0. The
// player (seat 0, with its own noise, else SPEC, default tournament)
// plays until its visit ends; the opponent never shoots. --shoot-noise
// gives an AI level another noise to shoot with and to plan for (its
// searches then estimate their pots with it), to see what the noise costs.
// A visit ends:
//
//   - cleared: the table is cleared (the frame is over);
//   - missed pot: a shot that passes the table without a foul whose
//     noiseless play would have potted a ball on;
//   - safety: any other shot that passes the table without a foul;
//   - foul: a shot that fouls.
//
// Printed: how the visits ended, the mean break (docs/ai.md: over the
// visits scoring at least one point), breaks of 50+ and 100+, the highest,
// the share of pot attempts that potted, and the breaks in bands.
// Deterministic for a given seed. --verbose prints each visit and each
// shot; --from T starts at table T (tables are numbered from 0).
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"
#include "breakshot/players.hpp"
#include "breakshot/snooker.hpp"

namespace {

using namespace breakshot;

constexpr std::uint64_t kTableStream = 0x7461626c65ULL;     // "table"
constexpr std::uint64_t kDecideStream = 0x646563696465ULL;  // "decide"
constexpr std::uint64_t kNoiseStream = 0x6e6f697365ULL;     // "noise"

enum class End { cleared, missed_pot, safety, foul, shot_limit };
constexpr std::array<const char*, 5> kEndNames{"cleared", "missed pot", "safety", "foul",
                                               "shot limit"};

double uniform(std::uint64_t seed, std::uint64_t k) {
  return static_cast<double>(mix_seed(seed, k) >> 11) * 0x1.0p-53;
}

/// An open table: `reds` reds and the cue ball at random, the colours on
/// their spots, player 0 on a red at 0-0.
GameState open_table(const Rules& rules, int reds, std::uint64_t seed) {
  GameState s = rules.start(seed, 0);
  const Table& t = rules.table();
  const double r = rules.config().ball_radius;
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  for (int c = 16; c <= 21; ++c) s.on_table[static_cast<std::size_t>(c)] = 1;
  const SnookerMarks m = snooker_marks();
  const std::array<Vec2, 6> spots{m.yellow, m.green, m.brown, m.blue, m.pink, m.black};
  for (int c = 0; c < 6; ++c)
    s.position[static_cast<std::size_t>(16 + c)] = spots[static_cast<std::size_t>(c)];
  std::vector<int> balls;
  for (int b = 1; b <= reds; ++b) balls.push_back(b);
  balls.push_back(0);
  std::uint64_t k = 0;
  for (const int b : balls) {
    for (;;) {
      const Vec2 p{r + 1e-3 + uniform(seed, k++) * (t.length - 2 * r - 2e-3),
                   r + 1e-3 + uniform(seed, k++) * (t.width - 2 * r - 2e-3)};
      bool ok = true;
      for (const Pocket& pk : t.pockets) ok = ok && norm(p - pk.centre) > pk.radius + 3 * r;
      for (std::size_t o = 0; o < s.on_table.size() && ok; ++o) {
        if (s.on_table[o]) ok = norm(p - s.position[o]) > 2 * r + 1e-3;
      }
      if (!ok) continue;
      s.position[static_cast<std::size_t>(b)] = p;
      s.on_table[static_cast<std::size_t>(b)] = 1;
      break;
    }
  }
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.player = 0;
  s.shots = 1;
  s.snooker = SnookerState{};
  return s;
}

bool pots_ball_on(const Rules& rules, const GameState& state, const Action& a) {
  const Outcome out = rules.apply(state, a);
  return out.ruling.fouls.empty() && out.state.snooker &&
         out.state.snooker->score[0] > state.snooker->score[0];
}

struct Visit {
  End end = End::shot_limit;
  int points = 0;
  int attempts = 0;  ///< shots whose noiseless play pots a ball on
  int pots = 0;      ///< shots that potted a ball on
};

/// Of `n` plays of `a` under `noise`, how many pot a ball on (verbose).
int pot_share(const Rules& rules, const GameState& state, const Action& a, const NoiseModel& noise,
              int n) {
  int k = 0;
  for (int i = 0; i < n; ++i) {
    Action b = a;
    auto& shoot = std::get<Shoot>(b);
    shoot.strike = perturb(shoot.strike, noise, rules.config().ball_radius,
                           mix_seed(0x5eedULL, static_cast<std::uint64_t>(i)));
    k += pots_ball_on(rules, state, b) ? 1 : 0;
  }
  return k;
}

/// The ball a noiseless play pots first, and the cue ball's and its
/// travel lengths before: printed per shot with --verbose.
void describe(const Rules& rules, const GameState& state, const Action& a,
              const NoiseModel& noise) {
  const Outcome out = rules.apply(state, a);
  int ball = -1;
  for (const int b : out.facts.pocketed) {
    if (b > 0) {
      ball = b;
      break;
    }
  }
  const auto& sh = std::get<Shoot>(a);
  if (ball < 0) {
    std::printf("    no pot: speed %.2f\n", sh.strike.speed);
    return;
  }
  const Vec2 cue = state.position[0];
  const Vec2 obj = state.position[static_cast<std::size_t>(ball)];
  double pocket = 1e9;
  for (const Pocket& pk : rules.table().pockets) pocket = std::min(pocket, norm(obj - pk.centre));
  std::printf("    ball %d: cue %.2f m, pocket %.2f m, speed %.2f, tip %.1f/%.1f mm, %d/32\n", ball,
              norm(obj - cue), pocket, sh.strike.speed, sh.strike.a * 1e3, sh.strike.b * 1e3,
              pot_share(rules, state, a, noise, 32));
}

Visit play_visit(const Rules& rules, Player& player, const NoiseModel& noise, GameState state,
                 std::uint64_t seed, bool verbose) {
  const double radius = rules.config().ball_radius;
  Visit v;
  for (int i = 0; i < 200; ++i) {
    Action a = player.decide(
        rules, state, mix_seed(mix_seed(seed, kDecideStream), static_cast<std::uint64_t>(i)));
    const bool shot = std::holds_alternative<Shoot>(a);
    const bool attempt = shot && pots_ball_on(rules, state, a);
    if (verbose && shot) describe(rules, state, a, noise);
    if (auto* shoot = std::get_if<Shoot>(&a)) {
      const std::uint64_t noise_seed =
          mix_seed(mix_seed(seed, kNoiseStream), static_cast<std::uint64_t>(i));
      shoot->strike = perturb(shoot->strike, noise, radius, noise_seed);
    }
    const int before = state.snooker->score[0];
    const Outcome out = rules.apply(state, a);
    state = out.state;
    v.attempts += attempt ? 1 : 0;
    const bool scored =
        state.snooker && state.snooker->score[0] > before && out.ruling.fouls.empty();
    v.pots += shot && scored ? 1 : 0;
    v.points = state.snooker->score[0];
    if (state.phase == Phase::game_over) {
      v.end = End::cleared;
      return v;
    }
    if (state.player == 0) continue;
    v.end = !out.ruling.fouls.empty() ? End::foul : attempt ? End::missed_pot : End::safety;
    return v;
  }
  return v;
}

bool parse_int(std::string_view s, long long* out) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), *out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

int usage() {
  std::fprintf(stderr,
               "usage: snooker_probe [--player NAME] [--tables N] [--from T] [--reds K] [--seed S] "
               "[--noise SPEC] [--shoot-noise SPEC] [--verbose]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string name = "champion";
  long long tables = 40;
  long long reds = 15;
  long long from = 0;
  long long seed = 7;
  bool verbose = false;
  std::string noise_spec = "tournament";
  std::string shoot_noise;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--verbose") {
      verbose = true;
      continue;
    }
    if (i + 1 >= argc) return usage();
    const std::string_view val = argv[++i];
    if (arg == "--player") {
      name = std::string(val);
    } else if (arg == "--tables") {
      if (!parse_int(val, &tables) || tables < 1 || tables > 1000000) {
        std::fprintf(stderr, "snooker_probe: --tables takes a whole number from 1 to 1000000\n");
        return 2;
      }
    } else if (arg == "--from") {
      if (!parse_int(val, &from) || from < 0) {
        std::fprintf(stderr, "snooker_probe: --from takes a whole number from 0\n");
        return 2;
      }
    } else if (arg == "--reds") {
      if (!parse_int(val, &reds) || reds < 0 || reds > 15) {
        std::fprintf(stderr, "snooker_probe: --reds takes a whole number from 0 to 15\n");
        return 2;
      }
    } else if (arg == "--seed") {
      if (!parse_int(val, &seed) || seed < 0) {
        std::fprintf(stderr, "snooker_probe: --seed takes a whole number from 0\n");
        return 2;
      }
    } else if (arg == "--noise") {
      noise_spec = std::string(val);
    } else if (arg == "--shoot-noise") {
      shoot_noise = std::string(val);
    } else {
      return usage();
    }
  }
  try {
    const Rules rules(snooker_config());
    std::unique_ptr<Player> player;
    if (shoot_noise.empty()) {
      player = make_player(name);
    } else {
      const std::vector<std::string> levels = ai_level_names();
      if (std::find(levels.begin(), levels.end(), name) == levels.end()) {
        std::fprintf(stderr, "snooker_probe: --shoot-noise is for the AI levels, not \"%s\"\n",
                     name.c_str());
        return 2;
      }
      AiLevel level = ai_level(name);
      level.noise = parse_noise(shoot_noise);
      player = make_ai_player(level);
    }
    const NoiseModel noise = player->noise().value_or(parse_noise(noise_spec));
    std::array<int, kEndNames.size()> ends{};
    std::vector<int> breaks;
    int attempts = 0;
    int pots = 0;
    for (long long t = from; t < from + tables; ++t) {
      const std::uint64_t table_seed = mix_seed(
          mix_seed(static_cast<std::uint64_t>(seed), kTableStream), static_cast<std::uint64_t>(t));
      const GameState start = open_table(rules, static_cast<int>(reds), table_seed);
      const Visit v = play_visit(rules, *player, noise, start, table_seed, verbose);
      ++ends[static_cast<std::size_t>(v.end)];
      breaks.push_back(v.points);
      attempts += v.attempts;
      pots += v.pots;
      if (verbose) {
        std::printf("table %lld: %d points, %d of %d attempts, %s\n", t, v.points, v.pots,
                    v.attempts, kEndNames[static_cast<std::size_t>(v.end)]);
        std::fflush(stdout);
      }
    }
    int scoring = 0;
    long long sum = 0;
    int fifty = 0;
    int hundred = 0;
    for (const int b : breaks) {
      scoring += b > 0 ? 1 : 0;
      sum += b;
      fifty += b >= 50 ? 1 : 0;
      hundred += b >= 100 ? 1 : 0;
    }
    std::printf("%s, %lld tables of %lld reds, seed %lld%s%s\n", name.c_str(), tables, reds, seed,
                shoot_noise.empty() ? "" : ", shooting with ", shoot_noise.c_str());
    for (std::size_t k = 0; k < kEndNames.size(); ++k) {
      if (ends[k] > 0 || k < 4) std::printf("  %-12s %5d\n", kEndNames[k], ends[k]);
    }
    std::printf("mean break %.1f over %d scoring visits (%.1f over all)\n",
                scoring > 0 ? static_cast<double>(sum) / scoring : 0.0, scoring,
                static_cast<double>(sum) / static_cast<double>(tables));
    std::printf("highest %d, 50+ %d, 100+ %d\n", *std::max_element(breaks.begin(), breaks.end()),
                fifty, hundred);
    std::printf("pot attempts %d, potted %d (%.1f %%)\n", attempts, pots,
                attempts > 0 ? 100.0 * pots / attempts : 0.0);
    std::array<int, 6> bands{};
    for (const int b : breaks) ++bands[static_cast<std::size_t>(std::min(5, b / 20))];
    std::printf("breaks 0-19 %d, 20-39 %d, 40-59 %d, 60-79 %d, 80-99 %d, 100+ %d\n", bands[0],
                bands[1], bands[2], bands[3], bands[4], bands[5]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snooker_probe: %s\n", e.what());
    return 1;
  }
  return 0;
}
