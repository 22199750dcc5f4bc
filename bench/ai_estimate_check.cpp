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
// Deterministic: fixed noise seeds, one thread. bench/ai_estimate_fit
// fits the estimate's constants on the same comparison.
#include <cstdio>
#include <optional>

#include "ai/evaluate.hpp"
#include "breakshot/game.hpp"
#include "breakshot/record.hpp"
#include "estimate_tables.hpp"
#include "record_file.hpp"

int main(int argc, char** argv) {
  using namespace breakshot;
  if (argc < 2) {
    std::fprintf(stderr, "usage: ai_estimate_check RECORD.json...\n");
    return 2;
  }
  bench_tools::EstimateBins bins;
  for (int i = 1; i < argc; ++i) {
    const std::optional<GameRecord> read =
        bench_tools::read_record_file("ai_estimate_check", argv[i]);
    if (!read) return 1;
    const GameRecord& rec = *read;
    const Rules rules(rec.config);
    for (const RecordedAction& a : rec.actions) {
      const GameState& s = a.after;
      if (!bench_tools::shot_to_play(s)) continue;
      int ball = -1;
      int pocket = -1;
      const double p = ai_detail::best_pot_estimate_from(
          rules, s, s.position[0], s.kitchen_shot, bench_tools::kEstimateSigmaDeg, &ball, &pocket);
      if (ball < 0) continue;
      bins.add(p, bench_tools::engine_chance(rules, s, bench_tools::direct_candidates(rules, s),
                                             ball, pocket));
    }
  }
  bins.print();
  return 0;
}
