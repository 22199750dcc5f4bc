// How a player's runs from its own break end (docs/ai.md, "What limits
// the champion"): the break-and-run rate on three times the breaks of a
// 200-game match, in less time than the match, and how the runs end.
//
//   run_probe [--game eight_ball|nine_ball] [--player NAME] [--racks N]
//             [--seed S] [--noise SPEC] [--break-only]
//
// Each rack is broken by the player (seat 0, rack and decision seeds
// fixed by S and the rack's index) and played by it for as long as it
// keeps the table; the opponent never shoots, so the opponent does not
// matter. The player shoots with its own noise (make_player(NAME)->noise(),
// else SPEC, default tournament). A run ends in one of:
//
//   - won: the rack is won without the opponent taking a shot (a
//     break-and-run);
//   - break: the break passes the table (dry, or a foul);
//   - missed pot: a called pot (8-ball) or a 9-ball shot with a call (the
//     AI calls what it attempts, docs/ai.md) that passes the table;
//   - safety: a declared 8-ball safety, or a shot with no call, that
//     passes the table without a foul;
//   - foul: any other shot that fouls (a pot that scratches counts here);
//   - lost: the player loses the rack at the table (an 8 early, a scratch
//     on the 8).
//
// Printed: the count of each, the break-and-run share of all racks and of
// the racks whose break kept the table, and how many balls the player had
// potted after the break when each run ended. With --break-only each rack
// ends after its break (the break's own figures, in a tenth of the time):
// the breaks that kept the table, those that won the rack (the 9 on a
// 9-ball break) and the balls they potted. Deterministic for a given
// seed: the AI's decisions depend only on their seeds.
#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <variant>

#include "breakshot/players.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/player.hpp"

namespace {

using namespace breakshot;

constexpr std::uint64_t kRackStream = 0x7261636bULL;      // "rack"
constexpr std::uint64_t kDecideStream = 0x646563696465ULL;  // "decide"
constexpr std::uint64_t kNoiseStream = 0x6e6f697365ULL;     // "noise"

enum class End { won, break_lost, missed_pot, safety, foul, lost, shot_limit, break_kept };

constexpr std::array<const char*, 8> kEndNames{"won (break-and-run)", "break passed the table",
                                               "missed pot", "safety", "foul", "lost at the table",
                                               "shot limit", "break kept the table"};

struct Run {
  End end = End::shot_limit;
  int potted = 0;  ///< object balls pocketed after the break
};

int balls_on(const GameState& s) {
  int n = 0;
  for (std::size_t b = 1; b < s.on_table.size(); ++b) n += s.on_table[b];
  return n;
}

Run play_rack(const Rules& rules, Player& player, const NoiseModel& noise, std::uint64_t seed,
              int rack, bool break_only) {
  const std::uint64_t rack_seed =
      mix_seed(mix_seed(seed, kRackStream), static_cast<std::uint64_t>(rack));
  GameState state = rules.start(rack_seed, 0);
  const double radius = rules.config().ball_radius;
  Run run;
  int after_break = -1;  // balls on the table after the break (-1 before it)
  const int racked = balls_on(state);
  for (int i = 0; i < rules.config().max_shots; ++i) {
    const bool breaking = state.phase == Phase::break_shot;
    Action a = player.decide(rules, state, mix_seed(mix_seed(rack_seed, kDecideStream),
                                                    static_cast<std::uint64_t>(i)));
    bool called = false;
    bool declared_safe = false;
    if (auto* shoot = std::get_if<Shoot>(&a)) {
      called = shoot->call.has_value();
      declared_safe = shoot->safety;
      const std::uint64_t noise_seed =
          mix_seed(mix_seed(rack_seed, kNoiseStream), static_cast<std::uint64_t>(i));
      shoot->strike = perturb(shoot->strike, noise, radius, noise_seed);
    }
    const Outcome out = rules.apply(state, a);
    const bool shot = std::holds_alternative<Shoot>(a);
    state = out.state;
    if (shot && breaking) after_break = balls_on(state);
    if (after_break >= 0) run.potted = after_break - balls_on(state);
    if (break_only && shot && breaking) {
      // The balls the break potted, and whether it kept the table or won.
      run.potted = racked - balls_on(state);
      if (state.phase == Phase::game_over) {
        run.end = state.winner == 0 ? End::won : End::lost;
      } else {
        run.end = state.player == 0 ? End::break_kept : End::break_lost;
      }
      return run;
    }
    if (state.phase == Phase::game_over) {
      run.end = state.winner == 0 ? End::won : End::lost;
      return run;
    }
    if (state.player == 0) continue;
    if (breaking) {
      run.end = End::break_lost;
    } else if (!out.ruling.fouls.empty()) {
      run.end = End::foul;
    } else if (called && !declared_safe) {
      run.end = End::missed_pot;
    } else {
      run.end = End::safety;
    }
    return run;
  }
  return run;
}

bool parse_int(std::string_view s, long long* out) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), *out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

int usage() {
  std::fprintf(stderr,
               "usage: run_probe [--game eight_ball|nine_ball] [--player NAME] [--racks N] "
               "[--seed S] [--noise SPEC] [--break-only]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  GameConfig config;
  std::string name = "champion";
  long long racks = 300;
  long long seed = 7;
  std::string noise_spec = "tournament";
  bool break_only = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--break-only") {
      break_only = true;
      continue;
    }
    if (i + 1 >= argc) return usage();
    const std::string_view val = argv[++i];
    if (arg == "--game") {
      if (val == "eight_ball") {
        config.game = GameType::eight_ball;
      } else if (val == "nine_ball") {
        config.game = GameType::nine_ball;
      } else {
        std::fprintf(stderr, "run_probe: unknown game \"%.*s\" (eight_ball or nine_ball)\n",
                     static_cast<int>(val.size()), val.data());
        return 2;
      }
    } else if (arg == "--player") {
      name = std::string(val);
    } else if (arg == "--racks") {
      if (!parse_int(val, &racks) || racks < 1 || racks > 1000000) {
        std::fprintf(stderr, "run_probe: --racks takes a whole number from 1 to 1000000\n");
        return 2;
      }
    } else if (arg == "--seed") {
      if (!parse_int(val, &seed) || seed < 0) {
        std::fprintf(stderr, "run_probe: --seed takes a whole number from 0\n");
        return 2;
      }
    } else if (arg == "--noise") {
      noise_spec = std::string(val);
    } else {
      return usage();
    }
  }
  try {
    const Rules rules(config);
    const std::unique_ptr<Player> player = make_player(name);
    const NoiseModel noise = player->noise().value_or(parse_noise(noise_spec));
    std::array<int, kEndNames.size()> ends{};
    std::map<int, std::array<int, kEndNames.size()>> by_potted;
    for (long long r = 0; r < racks; ++r) {
      const Run run = play_rack(rules, *player, noise, static_cast<std::uint64_t>(seed),
                                static_cast<int>(r), break_only);
      ++ends[static_cast<std::size_t>(run.end)];
      if (break_only || run.end != End::break_lost) {
        ++by_potted[run.potted][static_cast<std::size_t>(run.end)];
      }
    }
    if (break_only) {
      const auto count = [&](End e) { return ends[static_cast<std::size_t>(e)]; };
      const int kept = count(End::break_kept) + count(End::won);
      long long balls = 0;
      for (const auto& [potted, e] : by_potted) {
        for (const int n : e) balls += static_cast<long long>(potted) * n;
      }
      std::printf("%s, %s, %lld breaks, seed %lld\n", name.c_str(),
                  config.game == GameType::eight_ball ? "eight_ball" : "nine_ball", racks, seed);
      std::printf("  kept the table %d (%.1f %%), of them won the rack %d; passed it %d; lost %d\n",
                  kept, 100.0 * kept / static_cast<double>(racks), count(End::won),
                  count(End::break_lost), count(End::lost));
      std::printf("  balls potted per break %.2f\n", static_cast<double>(balls) /
                                                           static_cast<double>(racks));
      std::printf("breaks by balls potted (kept/won/passed/lost):\n");
      for (const auto& [potted, e] : by_potted) {
        std::printf("  %2d: %4d %4d %4d %4d\n", potted, e[static_cast<std::size_t>(End::break_kept)],
                    e[static_cast<std::size_t>(End::won)],
                    e[static_cast<std::size_t>(End::break_lost)],
                    e[static_cast<std::size_t>(End::lost)]);
      }
      return 0;
    }
    const int kept = static_cast<int>(racks) - ends[static_cast<std::size_t>(End::break_lost)];
    const int won = ends[static_cast<std::size_t>(End::won)];
    std::printf("%s, %s, %lld racks, seed %lld\n", name.c_str(),
                config.game == GameType::eight_ball ? "eight_ball" : "nine_ball", racks, seed);
    for (std::size_t k = 0; k < kEndNames.size(); ++k) {
      if (ends[k] > 0 || k <= static_cast<std::size_t>(End::safety)) {
        std::printf("  %-24s %5d\n", kEndNames[k], ends[k]);
      }
    }
    std::printf("break-and-runs: %d of %lld racks (%.1f %%), %d of the %d kept breaks (%.1f %%)\n",
                won, racks, 100.0 * won / static_cast<double>(racks), won, kept,
                kept > 0 ? 100.0 * won / kept : 0.0);
    std::printf(
        "runs by balls potted after the break when they ended "
        "(won/missed/safety/foul/lost):\n");
    for (const auto& [potted, e] : by_potted) {
      std::printf("  %2d: %4d %4d %4d %4d %4d\n", potted, e[static_cast<std::size_t>(End::won)],
                  e[static_cast<std::size_t>(End::missed_pot)],
                  e[static_cast<std::size_t>(End::safety)], e[static_cast<std::size_t>(End::foul)],
                  e[static_cast<std::size_t>(End::lost)]);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "run_probe: %s\n", e.what());
    return 1;
  }
  return 0;
}
