// Checks the AI's fast pot estimate (src/ai/evaluate.hpp) against the
// engine, on the tables of recorded games (docs/ai.md, "The estimate,
// checked against the engine").
//
//   breakshot match --game eight_ball --players champion,baseline --games 20
//       --seed 7 --noise tournament --records /tmp/records   (one line)
//   ai_estimate_check /tmp/records/game-*.json
//
// For every recorded table with a shot to play (the cue ball on the table,
// no ball in hand), the estimate picks its best pot (ball and pocket) and
// gives its chance. The engine's chance for that pot is the best, over the
// first six direct candidates that shot generation finds for that ball and
// pocket, of the share of 64 plays under tournament noise that pocket the
// ball without a foul (0 when there is no such candidate: "no line").
// Prints, per tenth of the estimate, the tables, the mean estimate, the
// mean engine chance and how many had no line, and the rms difference.
// Deterministic: fixed noise seeds, one thread.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "ai/evaluate.hpp"
#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"
#include "record_file.hpp"

namespace {

using namespace breakshot;

constexpr int kSamples = 64;
constexpr int kVariants = 6;
constexpr std::uint64_t kSeed = 99;

struct Bin {
  int tables = 0;
  int no_line = 0;
  double estimate = 0.0;
  double engine = 0.0;
};

/// The engine's chance of the best of the first kVariants direct
/// candidates for `ball` into `pocket`; -1 when there is none.
double engine_chance(const Rules& rules, const GameState& s, int ball, int pocket) {
  ShotGenOptions gen;
  gen.banks = false;
  gen.kicks = false;
  gen.combinations = false;
  gen.safeties = false;
  gen.max_candidates = 400;
  const NoiseModel noise = parse_noise("tournament");
  double best = -1.0;
  int tried = 0;
  for (const CandidateShot& c : generate_shots(rules, s, gen)) {
    if (c.kind != ShotKind::direct || c.target != ball || c.pocket != pocket) continue;
    if (++tried > kVariants) break;
    int made = 0;
    for (int k = 0; k < kSamples; ++k) {
      Shoot sh = c.shot;
      sh.strike = perturb(c.shot.strike, noise, rules.config().ball_radius,
                          mix_seed(kSeed, static_cast<std::uint64_t>(k)));
      const Outcome o = rules.apply(s, Action{sh});
      bool in = false;
      for (std::size_t i = 0; i < o.facts.pocketed.size(); ++i) {
        in = in || (o.facts.pocketed[i] == ball && o.facts.pocket_of[i] == pocket);
      }
      made += in && o.ruling.fouls.empty() ? 1 : 0;
    }
    best = std::max(best, static_cast<double>(made) / kSamples);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: ai_estimate_check RECORD.json...\n");
    return 2;
  }
  std::array<Bin, 10> bins{};
  int tables = 0;
  for (int i = 1; i < argc; ++i) {
    const std::optional<GameRecord> read = bench_tools::read_record_file("ai_estimate_check", argv[i]);
    if (!read) return 1;
    const GameRecord& rec = *read;
    const Rules rules(rec.config);
    for (const RecordedAction& a : rec.actions) {
      const GameState& s = a.after;
      if (s.phase != Phase::shot || s.ball_in_hand != BallInHand::none || !s.on_table[0]) continue;
      int ball = -1;
      int pocket = -1;
      const double p = ai_detail::best_pot_estimate_from(rules, s, s.position[0], s.kitchen_shot,
                                                         0.125, &ball, &pocket);
      if (ball < 0) continue;
      const double e = engine_chance(rules, s, ball, pocket);
      Bin& b = bins[static_cast<std::size_t>(std::min(9, static_cast<int>(p * 10.0)))];
      ++b.tables;
      b.estimate += p;
      b.engine += std::max(e, 0.0);
      b.no_line += e < 0.0 ? 1 : 0;
      ++tables;
    }
  }
  std::printf("estimate  tables  mean estimate  mean engine  no line\n");
  double sq = 0.0;
  for (std::size_t k = 0; k < bins.size(); ++k) {
    const Bin& b = bins[k];
    if (!b.tables) continue;
    const double me = b.estimate / b.tables;
    const double mg = b.engine / b.tables;
    sq += b.tables * (me - mg) * (me - mg);
    std::printf("%.1f-%.1f  %6d  %13.3f  %11.3f  %7d\n", static_cast<double>(k) / 10.0,
                static_cast<double>(k + 1) / 10.0, b.tables, me, mg, b.no_line);
  }
  std::printf("tables %d, rms difference of bin means %.3f\n", tables,
              tables ? std::sqrt(sq / tables) : 0.0);
  return 0;
}
