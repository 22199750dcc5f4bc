// The AI's pot estimate (src/ai/evaluate.hpp) against the engine, on the
// tables of recorded games, for the measuring tools of bench/ (not part of
// the library): which tables count, the engine's chance of a pot on one,
// and the table of the two per tenth of the estimate that
// ai_estimate_check and ai_estimate_fit print (docs/ai.md, "The estimate,
// checked against the engine").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"

namespace bench_tools {

/// The aim noise the estimate is given (tournament, degrees).
inline constexpr double kEstimateSigmaDeg = 0.125;

/// A recorded state with a shot to play: the cue ball on the table and not
/// in hand.
inline bool shot_to_play(const breakshot::GameState& s) {
  return s.phase == breakshot::Phase::shot && s.ball_in_hand == breakshot::BallInHand::none &&
         s.on_table[0];
}

/// The direct pots shot generation finds on `s` (no banks, kicks,
/// combinations or safeties), in its order.
inline std::vector<breakshot::CandidateShot> direct_candidates(const breakshot::Rules& rules,
                                                               const breakshot::GameState& s) {
  breakshot::ShotGenOptions gen;
  gen.banks = false;
  gen.kicks = false;
  gen.combinations = false;
  gen.safeties = false;
  gen.max_candidates = 400;
  std::vector<breakshot::CandidateShot> out;
  for (breakshot::CandidateShot& c : breakshot::generate_shots(rules, s, gen)) {
    if (c.kind == breakshot::ShotKind::direct) out.push_back(std::move(c));
  }
  return out;
}

/// The engine's chance of `ball` into `pocket` on `s`: the best, over the
/// first six of `candidates` (direct_candidates of `s`) for that ball and
/// pocket, of the share of 64 plays under tournament noise (fixed seeds)
/// that pocket the ball there without a foul; -1 when there is no such
/// candidate ("no line").
inline double engine_chance(const breakshot::Rules& rules, const breakshot::GameState& s,
                            const std::vector<breakshot::CandidateShot>& candidates, int ball,
                            int pocket) {
  constexpr int kSamples = 64;
  constexpr int kVariants = 6;
  constexpr std::uint64_t kSeed = 99;
  const breakshot::NoiseModel noise = breakshot::parse_noise("tournament");
  double best = -1.0;
  int tried = 0;
  for (const breakshot::CandidateShot& c : candidates) {
    if (c.target != ball || c.pocket != pocket) continue;
    if (++tried > kVariants) break;
    int made = 0;
    for (int k = 0; k < kSamples; ++k) {
      breakshot::Shoot sh = c.shot;
      sh.strike = breakshot::perturb(c.shot.strike, noise, rules.config().ball_radius,
                                     breakshot::mix_seed(kSeed, static_cast<std::uint64_t>(k)));
      const breakshot::Outcome o = rules.apply(s, breakshot::Action{sh});
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

/// Tables binned by tenths of the estimate: how many, the mean estimate,
/// the mean engine chance ("no line" counted as 0) and how many had no line.
class EstimateBins {
 public:
  /// One table: the estimate's chance and the engine's (-1: no line).
  void add(double estimate, double engine) {
    Bin& b = bins_[static_cast<std::size_t>(std::min(9, static_cast<int>(estimate * 10.0)))];
    ++b.tables;
    b.estimate += estimate;
    b.engine += std::max(engine, 0.0);
    b.no_line += engine < 0.0 ? 1 : 0;
    ++tables_;
  }

  int tables() const { return tables_; }

  /// The root of the mean, over tables, of the squared difference between
  /// its bin's mean estimate and mean engine chance.
  double rms_of_bin_means() const {
    double sq = 0.0;
    for (const Bin& b : bins_) {
      if (!b.tables) continue;
      const double me = b.estimate / b.tables;
      const double mg = b.engine / b.tables;
      sq += b.tables * (me - mg) * (me - mg);
    }
    return tables_ ? std::sqrt(sq / tables_) : 0.0;
  }

  void print() const {
    std::printf("estimate  tables  mean estimate  mean engine  no line\n");
    for (std::size_t k = 0; k < bins_.size(); ++k) {
      const Bin& b = bins_[k];
      if (!b.tables) continue;
      std::printf("%.1f-%.1f  %6d  %13.3f  %11.3f  %7d\n", static_cast<double>(k) / 10.0,
                  static_cast<double>(k + 1) / 10.0, b.tables, b.estimate / b.tables,
                  b.engine / b.tables, b.no_line);
    }
    std::printf("tables %d, rms difference of bin means %.3f\n", tables_, rms_of_bin_means());
  }

 private:
  struct Bin {
    int tables = 0;
    int no_line = 0;
    double estimate = 0.0;
    double engine = 0.0;
  };
  std::array<Bin, 10> bins_{};
  int tables_ = 0;
};

}  // namespace bench_tools
