// The shortlist (ai_player.hpp): which of shot generation's candidates
// are sampled, ranked by what their noiseless play promises.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "ai_player.hpp"

namespace breakshot::ai_detail {

namespace {

// What a missed pot is taken to cost when candidates are ranked before
// sampling: the opponent at an average table (shooter_value(0.5)).
constexpr double kMissCost = 0.325;

}  // namespace

/// What a pot's noiseless play promises, for ranking candidates before
/// they are sampled: the chance that it drops times the value of its
/// leave, against a miss that hands over an average table. Other shots:
/// their prior.
double promise(const CandidateShot& c) {
  if (c.target < 0 || c.leave < 0.0) return c.prior;
  return c.prior * shooter_value(c.leave) - (1.0 - c.prior) * kMissCost;
}

/// The candidates worth sampling, from `cands` sorted by prior: the
/// priors of safeties (how little they leave) and of pots (how likely
/// they drop) are not on one scale, and each line comes in several
/// speed and spin variants with nearly equal priors, so a plain cut by
/// prior could hold only safeties, or one line. So three quarters of the
/// places go to pots and a quarter to safeties (either filling in for
/// the other when short). Pots are ranked by their promise (the prior
/// times the value of the leave of their noiseless play), safeties by
/// prior, and the first pass takes the best variant of each line (kind,
/// balls, pocket) before any second variant.
std::vector<CandidateShot> AiPlayer::shortlist(std::vector<CandidateShot> cands, std::size_t n) {
  if (cands.size() <= n) return cands;
  std::vector<std::size_t> pots;
  std::vector<std::size_t> safes;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    (cands[i].kind == ShotKind::safety || cands[i].target < 0 ? safes : pots).push_back(i);
  }
  const auto same_line = [&](std::size_t a, std::size_t b) {
    const CandidateShot& x = cands[a];
    const CandidateShot& y = cands[b];
    return x.kind == y.kind && x.first == y.first && x.target == y.target && x.pocket == y.pocket;
  };
  // Lines first, then the other variants, each in prior order.
  const auto spread = [&](const std::vector<std::size_t>& in) {
    std::vector<std::size_t> firsts;
    std::vector<std::size_t> rest;
    for (std::size_t i : in) {
      const bool seen = std::any_of(firsts.begin(), firsts.end(),
                                    [&](std::size_t f) { return same_line(f, i); });
      (seen ? rest : firsts).push_back(i);
    }
    firsts.insert(firsts.end(), rest.begin(), rest.end());
    return firsts;
  };
  // Pots by what their noiseless play promises: the chance that they
  // drop times the value of the leave, against a miss that hands over
  // an average table. So the variants of a line that leave the cue ball
  // well are the ones sampled.
  std::stable_sort(pots.begin(), pots.end(), [&](std::size_t a, std::size_t b) {
    return promise(cands[a]) > promise(cands[b]);
  });
  pots = spread(pots);
  safes = spread(safes);
  std::size_t n_safe = std::min(safes.size(), std::max<std::size_t>(1, n / 4));
  std::size_t n_pot = std::min(pots.size(), n - n_safe);
  n_safe = std::min(safes.size(), n - n_pot);
  std::vector<std::size_t> keep(pots.begin(), pots.begin() + static_cast<std::ptrdiff_t>(n_pot));
  keep.insert(keep.end(), safes.begin(), safes.begin() + static_cast<std::ptrdiff_t>(n_safe));
  std::vector<CandidateShot> out;
  out.reserve(keep.size());
  for (std::size_t i : keep) out.push_back(cands[i]);
  return out;
}

}  // namespace breakshot::ai_detail
