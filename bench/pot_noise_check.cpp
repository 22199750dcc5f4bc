// Where a player's pots are lost under noise, on the pots of recorded
// games (docs/ai.md, "Where pots are lost").
//
//   breakshot match --game nine_ball --players champion,baseline --games 200
//       --seed 7 --noise tournament --records /tmp/records   (one line)
//   pot_noise_check [--player NAME] /tmp/records/game-*.json
//
// For every called pot the player (default: champion) shot from a table
// with the cue ball on it, the strike it chose (before noise) is played
// again 48 times under tournament noise, each time from the recorded
// table, with fixed noise seeds. A play succeeds when the call is made
// and the shooter keeps the table (or wins). Printed, as the mean share
// of successful plays over the pots:
//
//   - made in the games: what the recorded noisy shots did;
//   - chosen aim: the chosen strike under the full noise;
//   - centred aim: the same with phi moved to the middle of the aims
//     that make the pot without noise (ai_detail::centre_aim);
//   - one noise at a time: only the aim error (phi), only the speed
//     error, or only the tip offsets and the elevation, at the chosen aim.
//
// And how far the chosen aim sat from the middle of its window, in units
// of the tournament aim noise (0.125 degrees). Deterministic: fixed noise
// seeds, one thread.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ai/evaluate.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "record_file.hpp"

namespace {

using namespace breakshot;

constexpr int kSamples = 48;
constexpr std::uint64_t kSeed = 777;

/// Share of kSamples plays of `shot` from `s` under `noise` that make the
/// call and keep the table for `player`.
double success(const Rules& rules, const GameState& s, const Shoot& shot, const NoiseModel& noise,
               int player) {
  int made = 0;
  for (int k = 0; k < kSamples; ++k) {
    Shoot x = shot;
    x.strike = perturb(shot.strike, noise, rules.config().ball_radius,
                       mix_seed(kSeed, static_cast<std::uint64_t>(k)));
    const Outcome o = rules.apply(s, Action{x});
    if (!o.ruling.call_made) continue;
    const bool keeps = o.state.phase == Phase::game_over ? o.state.winner == player
                                                         : o.state.player == player;
    made += keeps ? 1 : 0;
  }
  return static_cast<double>(made) / kSamples;
}

}  // namespace

int main(int argc, char** argv) {
  std::string who = "champion";
  int first = 1;
  if (argc >= 3 && std::strcmp(argv[1], "--player") == 0) {
    who = argv[2];
    first = 3;
  }
  if (first >= argc) {
    std::fprintf(stderr, "usage: pot_noise_check [--player NAME] RECORD.json...\n");
    return 2;
  }
  const NoiseModel full = parse_noise("tournament");
  NoiseModel aim_only;
  aim_only.phi = full.phi;
  NoiseModel speed_only;
  speed_only.speed = full.speed;
  NoiseModel tip_only;
  tip_only.theta = full.theta;
  tip_only.a = full.a;
  tip_only.b = full.b;

  int pots = 0;
  double made = 0.0;
  std::array<double, 5> sum{};  // chosen, centred, aim only, speed only, tip only
  std::array<int, 5> offsets{};  // |chosen - middle| in quarters of sigma, the last open
  for (int i = first; i < argc; ++i) {
    const std::optional<GameRecord> read = bench_tools::read_record_file("pot_noise_check", argv[i]);
    if (!read) return 1;
    const GameRecord& rec = *read;
    int seat = -1;
    for (int p = 0; p < 2; ++p) {
      if (rec.players[static_cast<std::size_t>(p)] == who) seat = p;
    }
    if (seat < 0) continue;
    const Rules rules(rec.config);
    GameState before = rec.start;
    for (const RecordedAction& a : rec.actions) {
      const auto* shot = std::get_if<Shoot>(&a.action);
      const bool counted = a.player == seat && shot && shot->call && a.intended &&
                           before.phase == Phase::shot && before.on_table[0] &&
                           before.ball_in_hand == BallInHand::none;
      if (counted) {
        Shoot chosen = *shot;
        chosen.strike = *a.intended;
        const Shoot centred = ai_detail::centre_aim(rules, before, chosen);
        ++pots;
        made += a.ruling.call_made ? 1.0 : 0.0;
        sum[0] += success(rules, before, chosen, full, seat);
        sum[1] += success(rules, before, centred, full, seat);
        sum[2] += success(rules, before, chosen, aim_only, seat);
        sum[3] += success(rules, before, chosen, speed_only, seat);
        sum[4] += success(rules, before, chosen, tip_only, seat);
        const double off = std::abs(chosen.strike.phi - centred.strike.phi) / full.phi;
        ++offsets[static_cast<std::size_t>(std::min(4, static_cast<int>(off / 0.25)))];
      }
      before = a.after;
    }
  }
  if (pots == 0) {
    std::printf("no called pots by %s from a table with the cue ball on it\n", who.c_str());
    return 0;
  }
  std::printf("called pots by %s: %d\n", who.c_str(), pots);
  std::printf("made in the games          %.3f\n", made / pots);
  std::printf("chosen aim, full noise     %.3f\n", sum[0] / pots);
  std::printf("centred aim, full noise    %.3f\n", sum[1] / pots);
  std::printf("chosen aim, aim noise only %.3f\n", sum[2] / pots);
  std::printf("chosen aim, speed only     %.3f\n", sum[3] / pots);
  std::printf("chosen aim, tip and elevation only %.3f\n", sum[4] / pots);
  std::printf("chosen aim off the middle of its window (sigma = %.3f deg):\n", full.phi);
  const std::array<const char*, 5> bins{"< 0.25", "0.25-0.5", "0.5-0.75", "0.75-1", ">= 1"};
  for (std::size_t k = 0; k < bins.size(); ++k) {
    std::printf("  %-9s sigma  %d\n", bins[k], offsets[k]);
  }
  return 0;
}
