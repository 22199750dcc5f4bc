// Fits the constants of the AI's fast pot estimate (src/ai/evaluate.hpp,
// EstimateConstants) to the engine, on the tables of recorded games
// (docs/ai.md, "The estimate, checked against the engine").
//
//   ai_estimate_fit FIT_RECORD.json... --check CHECK_RECORD.json...
//
// For every recorded table with a shot to play (as ai_estimate_check), the
// engine's chance of every direct pot shot generation finds there (each
// ball and pocket: the best of its first six candidates, 64 plays each
// under tournament noise) is measured once and kept. The search then
// varies the constants and asks the estimate itself for its pick and its
// chance on every table, which costs only the geometry. The error of a
// table is the estimate's chance less the engine's chance of the pot it
// picks (0 when the generator has no line for it); where it picks none,
// 0 less the engine's best pot on the table. Pool tables (8-, 9- and
// 10-ball) and snooker tables are fitted separately, each by coordinate
// descent on fixed grids (below, `fit`) from the AI's constants, to the
// least sum of squared errors. The records after --check (games of other
// seeds) are only measured, before and after. All the records must be of
// one physics. Prints the constants, the errors and ai_estimate_check's
// table per tenth of the estimate, for both sets.
// Deterministic: fixed noise seeds, one thread. About 4 minutes for the
// records of docs/ai.md on the 2-core machine.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <deque>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "ai/evaluate.hpp"
#include "breakshot/game.hpp"
#include "breakshot/record.hpp"
#include "estimate_tables.hpp"
#include "record_file.hpp"

namespace {

using namespace breakshot;
using ai_detail::EstimateConstants;
using ai_detail::PocketConstants;

/// The engine's chance of one ball into one pocket on a table.
struct PotChance {
  int ball;
  int pocket;
  double chance;
};

/// A table with a shot to play and the engine's chance of every direct pot
/// on it.
struct FitTable {
  const Rules* rules;
  GameState state;
  std::vector<PotChance> pots;
  double best;  // the best of them, 0 when there is none
};

/// The tables of one kind of game (pool or snooker) in a set of records.
struct Tables {
  std::vector<FitTable> tables;
  int records = 0;
};

/// The tables of a set of records, pool and snooker apart. The rules the
/// tables point to live in `rules` (a deque: they do not move).
struct TableSet {
  std::deque<Rules> rules;
  Tables pool;
  Tables snooker;
};

/// Reads the tables of `files` into `set`. Every record must have been
/// played on `physics` (the first record's, when not yet set): the AI's
/// constants, the starting point and the "before" of the fit, are those of
/// the physics (ai_detail::estimate_constants).
bool read_tables(const std::vector<const char*>& files, TableSet& set,
                 std::optional<GamePhysics>& physics) {
  for (const char* file : files) {
    const std::optional<GameRecord> rec = bench_tools::read_record_file("ai_estimate_fit", file);
    if (!rec) return false;
    if (rec->config.game == GameType::three_cushion) continue;  // no pockets
    if (!physics) physics = rec->config.physics;
    if (!(rec->config.physics == *physics)) {
      std::fprintf(stderr,
                   "ai_estimate_fit: %s: played on another physics than the records before it\n",
                   file);
      return false;
    }
    const Rules& rules = set.rules.emplace_back(rec->config);
    Tables& kind = rec->config.game == GameType::snooker ? set.snooker : set.pool;
    ++kind.records;
    for (const RecordedAction& a : rec->actions) {
      const GameState& s = a.after;
      if (!bench_tools::shot_to_play(s)) continue;
      FitTable t{&rules, s, {}, 0.0};
      const std::vector<CandidateShot> candidates = bench_tools::direct_candidates(rules, s);
      for (const CandidateShot& c : candidates) {
        const auto same = [&c](const PotChance& p) {
          return p.ball == c.target && p.pocket == c.pocket;
        };
        if (std::any_of(t.pots.begin(), t.pots.end(), same)) continue;
        const double chance = bench_tools::engine_chance(rules, s, candidates, c.target, c.pocket);
        t.pots.push_back(PotChance{c.target, c.pocket, chance});
        t.best = std::max(t.best, chance);
      }
      kind.tables.push_back(std::move(t));
    }
  }
  return true;
}

/// The engine's chance of `ball` into `pocket` on `t`; -1 for no line.
double chance_of(const FitTable& t, int ball, int pocket) {
  for (const PotChance& p : t.pots) {
    if (p.ball == ball && p.pocket == pocket) return p.chance;
  }
  return -1.0;
}

/// The estimate with `c` on `tables`: the sum of squared errors, the
/// tables where it picks no pot, and its bins (tables with a pick).
struct Score {
  double squared = 0.0;
  int no_pick = 0;
  double no_pick_best = 0.0;  // the sum of the engine's best pots there
  bench_tools::EstimateBins bins;
};

Score score(const std::vector<FitTable>& tables, const EstimateConstants& c) {
  Score out;
  for (const FitTable& t : tables) {
    int ball = -1;
    int pocket = -1;
    const double p = ai_detail::best_pot_estimate_from(
        *t.rules, t.state, t.state.position[0], t.state.kitchen_shot,
        bench_tools::kEstimateSigmaDeg, c, &ball, &pocket);
    if (ball < 0) {
      ++out.no_pick;
      out.no_pick_best += t.best;
      out.squared += t.best * t.best;
      continue;
    }
    const double e = chance_of(t, ball, pocket);
    const double d = p - std::max(e, 0.0);
    out.squared += d * d;
    out.bins.add(p, e);
  }
  return out;
}

/// One constant of PocketConstants and the grid it is searched on.
struct Knob {
  const char* name;
  double PocketConstants::*field;
  double lo;
  double step;
  int steps;  // grid values lo, lo + step, ..., lo + steps * step
};

constexpr Knob kKnobs[] = {
    {"corner_tolerance", &PocketConstants::corner_tolerance, 0.20, 0.01, 130},
    {"side_tolerance", &PocketConstants::side_tolerance, 0.20, 0.01, 130},
    {"corner_min_cos", &PocketConstants::corner_min_cos, 0.10, 0.01, 80},
    {"side_min_cos", &PocketConstants::side_min_cos, 0.10, 0.01, 80},
    {"distance_penalty", &PocketConstants::distance_penalty, 0.0, 0.005, 60},
};

/// Where the descent starts besides the AI's own constants: tolerances
/// narrow and no distance penalty, the middle of the grids, wide and a
/// large penalty (the fit's landscape is rough, and the tolerances and the
/// penalty trade along ridges).
constexpr PocketConstants kOtherStarts[] = {
    {0.5, 0.5, 0.5, 0.5, 0.0},
    {0.85, 0.85, 0.5, 0.5, 0.15},
    {1.2, 1.2, 0.3, 0.3, 0.3},
};

/// The five constants of `c`, in the order of kKnobs.
std::string knobs_text(const PocketConstants& c) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f %.3f %.2f %.2f %.3f", c.corner_tolerance, c.side_tolerance,
                c.corner_min_cos, c.side_min_cos, c.distance_penalty);
  return text;
}

/// Grid value i of knob k, and the grid index nearest to v.
double grid_value(const Knob& k, int i) { return k.lo + k.step * i; }
int grid_index(const Knob& k, double v) {
  return std::clamp(static_cast<int>(std::lround((v - k.lo) / k.step)), 0, k.steps);
}

/// Coordinate descent from `start` (its `which` part) on `tables`. Each
/// round sets every constant in turn to its best value over its whole
/// grid, then moves every pair of constants together to the best point
/// within kPairReach grid steps of each (the tolerances and the distance
/// penalty trade against each other along ridges that single moves cannot
/// follow). Only a strictly smaller sum of squared errors moves a
/// constant; the rounds end when none moves.
EstimateConstants fit(const std::vector<FitTable>& tables, EstimateConstants start,
                      PocketConstants EstimateConstants::*which) {
  constexpr int kMaxRounds = 30;
  constexpr int kPairReach = 4;
  EstimateConstants cur = start;
  double best = score(tables, cur).squared;
  const auto field = [&](EstimateConstants& c, const Knob& k) -> double& {
    return (c.*which).*(k.field);
  };
  for (int round = 0; round < kMaxRounds; ++round) {
    bool moved = false;
    for (const Knob& k : kKnobs) {
      for (int i = 0; i <= k.steps; ++i) {
        EstimateConstants trial = cur;
        field(trial, k) = grid_value(k, i);
        const double sq = score(tables, trial).squared;
        if (sq < best) {
          best = sq;
          field(cur, k) = grid_value(k, i);
          moved = true;
        }
      }
    }
    for (std::size_t a = 0; a < std::size(kKnobs); ++a) {
      for (std::size_t b = a + 1; b < std::size(kKnobs); ++b) {
        const Knob& ka = kKnobs[a];
        const Knob& kb = kKnobs[b];
        const EstimateConstants centre = cur;
        const int ia = grid_index(ka, field(cur, ka));
        const int ib = grid_index(kb, field(cur, kb));
        for (int da = -kPairReach; da <= kPairReach; ++da) {
          for (int db = -kPairReach; db <= kPairReach; ++db) {
            if (ia + da < 0 || ia + da > ka.steps || ib + db < 0 || ib + db > kb.steps) continue;
            EstimateConstants trial = centre;
            field(trial, ka) = grid_value(ka, ia + da);
            field(trial, kb) = grid_value(kb, ib + db);
            const double sq = score(tables, trial).squared;
            if (sq < best) {
              best = sq;
              cur = trial;
              moved = true;
            }
          }
        }
      }
    }
    std::fprintf(stderr, "round %d: squared error %.4f\n", round + 1, best);
    if (!moved) break;
  }
  return cur;
}

void report(const char* kind, const Tables& fit_set, const Tables& check_set,
            const EstimateConstants& before, PocketConstants EstimateConstants::*which) {
  const std::vector<FitTable>& fit_tables = fit_set.tables;
  const std::vector<FitTable>& check_tables = check_set.tables;
  if (fit_tables.empty()) return;
  std::printf("== %s: fit on %zu tables of %d records, checked on %zu tables of %d records\n\n",
              kind, fit_tables.size(), fit_set.records, check_tables.size(), check_set.records);
  // The descent from each start; the least sum of squares on the fit set
  // wins (the first of equals).
  std::printf("%-27s  %-27s  %6s  %8s\n", "start", "end", "fit sq", "check sq");
  std::vector<PocketConstants> starts{before.*which};
  starts.insert(starts.end(), std::begin(kOtherStarts), std::end(kOtherStarts));
  EstimateConstants after = before;
  double after_sq = 0.0;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    EstimateConstants start = before;
    start.*which = starts[i];
    const EstimateConstants end = fit(fit_tables, start, which);
    const double sq = score(fit_tables, end).squared;
    std::printf("%s  %s  %6.2f  %8.2f\n", knobs_text(start.*which).c_str(),
                knobs_text(end.*which).c_str(), sq, score(check_tables, end).squared);
    if (i == 0 || sq < after_sq) {
      after = end;
      after_sq = sq;
    }
  }
  std::printf("\n");
  std::printf("constant            before   after\n");
  for (const Knob& k : kKnobs) {
    std::printf("%-18s  %6.3f  %6.3f\n", k.name, (before.*which).*(k.field),
                (after.*which).*(k.field));
  }
  const Score sets[2][2] = {{score(fit_tables, before), score(fit_tables, after)},
                            {score(check_tables, before), score(check_tables, after)}};
  const std::size_t sizes[2] = {fit_tables.size(), check_tables.size()};
  std::printf("\n                          fit set          check set\n");
  std::printf("                       before   after   before   after\n");
  std::printf("rms error per table    ");
  for (int s = 0; s < 2; ++s) {
    for (int a = 0; a < 2; ++a) {
      std::printf(" %6.3f ",
                  sizes[s] ? std::sqrt(sets[s][a].squared / static_cast<double>(sizes[s])) : 0.0);
    }
  }
  std::printf("\nrms of bin means       ");
  for (int s = 0; s < 2; ++s) {
    for (int a = 0; a < 2; ++a) std::printf(" %6.3f ", sets[s][a].bins.rms_of_bin_means());
  }
  std::printf("\ntables with no pot     ");
  for (int s = 0; s < 2; ++s) {
    for (int a = 0; a < 2; ++a) std::printf(" %6d ", sets[s][a].no_pick);
  }
  std::printf("\n  their engine's best   ");
  for (int s = 0; s < 2; ++s) {
    for (int a = 0; a < 2; ++a) {
      const Score& sc = sets[s][a];
      std::printf(" %6.3f ", sc.no_pick ? sc.no_pick_best / sc.no_pick : 0.0);
    }
  }
  std::printf("\n");
  const char* names[2][2] = {{"fit set, before", "fit set, after"},
                             {"check set, before", "check set, after"}};
  for (int s = 0; s < 2; ++s) {
    for (int a = 0; a < 2; ++a) {
      std::printf("\n%s %s:\n", kind, names[s][a]);
      sets[s][a].bins.print();
    }
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<const char*> fit_files;
  std::vector<const char*> check_files;
  bool check = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--check") == 0) {
      check = true;
    } else {
      (check ? check_files : fit_files).push_back(argv[i]);
    }
  }
  if (fit_files.empty() || check_files.empty()) {
    std::fprintf(stderr,
                 "usage: ai_estimate_fit FIT_RECORD.json... --check CHECK_RECORD.json...\n");
    return 2;
  }
  TableSet fit_set;
  TableSet check_set;
  std::optional<GamePhysics> physics;
  if (!read_tables(fit_files, fit_set, physics) || !read_tables(check_files, check_set, physics)) {
    return 1;
  }
  const EstimateConstants ai = ai_detail::estimate_constants(physics.value_or(GamePhysics{}));
  std::fprintf(stderr, "engine chances measured: fit %zu + %zu tables, check %zu + %zu\n",
               fit_set.pool.tables.size(), fit_set.snooker.tables.size(),
               check_set.pool.tables.size(), check_set.snooker.tables.size());
  report("pool", fit_set.pool, check_set.pool, ai, &EstimateConstants::pool);
  report("snooker", fit_set.snooker, check_set.snooker, ai, &EstimateConstants::snooker);
  return 0;
}
