// The AI levels (include/breakshot/ai.hpp, docs/ai.md): what each of the
// five shoots with and searches, and how deep its lookahead reads.
#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/noise.hpp"
#include "policy.hpp"

namespace breakshot {

namespace {

/// The five levels: each shoots with less noise and searches more than the
/// one below it.
AiLevel make_level(std::string_view name) {
  AiLevel l;
  l.name = std::string(name);
  if (name == "beginner") {
    // Four times tournament noise, no sampling: the best prior, at once.
    l.noise = parse_noise("4x");
    l.generation.banks = false;
    l.generation.combinations = false;
    l.generation.speed_factors = {1.6};
    l.generation.spins = {0.0};
    l.generation.refine_iterations = 1;
    l.generation.max_candidates = 30;
    l.candidates = 1;
    l.samples = 0;
    l.threads = 1;
  } else if (name == "amateur") {
    l.noise = parse_noise("2.5x");
    l.generation.combinations = false;
    l.generation.speed_factors = {1.2, 2.0};
    l.generation.spins = {0.0};
    l.generation.refine_iterations = 2;
    l.generation.max_candidates = 40;
    l.candidates = 6;
    l.samples = 6;
  } else if (name == "club") {
    l.noise = parse_noise("1.6x");
    l.generation.refine_iterations = 3;
    l.generation.max_candidates = 60;
    l.candidates = 12;
    l.samples = 12;
  } else if (name == "expert") {
    // A little more noise than the champion's, so that the two differ in
    // more than the depth of their search (with the same noise the
    // champion won only 55 of 100 9-ball games).
    l.noise = parse_noise("1.25x");
    l.generation.jumps = true;
    l.candidates = 24;
    l.samples = 24;
  } else if (name == "champion") {
    l.noise = parse_noise("tournament");
    // Twice the samples of the first version and twice the candidates
    // read a shot deeper. Five speeds, five tip heights and two side
    // offsets per line: the shortlist ranks them by the leave of their
    // noiseless play, so the variants sampled are the ones that play
    // position (docs/ai.md).
    l.generation.speed_factors = {1.0, 1.35, 1.8, 2.4, 3.2};
    l.generation.spins = {-0.45, -0.25, 0.0, 0.25, 0.45};
    l.generation.sides = {-0.35, 0.35};
    l.generation.max_candidates = 400;
    l.generation.safety_turns = {0.0, 12.0, 25.0, 38.0, 50.0, 62.0};
    l.generation.safety_speeds = {0.8, 1.2, 1.7, 2.4, 3.4};
    l.generation.safety_spins = {-0.4, 0.0, 0.4};
    l.generation.jumps = true;
    // Snooker: eight speeds, eight tip heights and four side offsets per
    // line, and room for them all in the shortlist. On 80 open tables
    // (bench/snooker_probe) the mean break rose from 14.6 to 17.9 and the
    // pots made from 79 % to 83 % of those attempted (docs/ai.md).
    ShotGenOptions sn = l.generation;
    sn.speed_factors = {1.0, 1.2, 1.4, 1.7, 2.0, 2.4, 2.9, 3.5};
    sn.spins = {-0.55, -0.4, -0.25, -0.1, 0.0, 0.15, 0.3, 0.45};
    sn.sides = {-0.35, -0.2, 0.2, 0.35};
    sn.max_candidates = 1000;
    l.snooker_generation = sn;
    l.candidates = 60;
    l.samples = 128;
    l.lookahead = true;
    l.lookahead_candidates = 10;
    l.lookahead_candidates_nine = 16;
    l.lookahead_states_nine = 12;
    l.centre_aim = true;
  }
  return l;
}

constexpr std::array<std::string_view, 5> kLevelNames{"beginner", "amateur", "club", "expert",
                                                      "champion"};

}  // namespace

LookaheadDepth lookahead_depth(const AiLevel& level, GameType game) {
  const bool nine = ai_detail::game_policy(game).rotation;
  LookaheadDepth d;
  d.candidates = nine && level.lookahead_candidates_nine > 0 ? level.lookahead_candidates_nine
                                                             : level.lookahead_candidates;
  d.states = nine && level.lookahead_states_nine > 0 ? level.lookahead_states_nine
                                                     : level.lookahead_states;
  if (d.states <= 0) d.states = level.samples >= 48 ? 8 : 4;
  return d;
}

AiLevel ai_level(std::string_view name) {
  if (std::find(kLevelNames.begin(), kLevelNames.end(), name) == kLevelNames.end()) {
    std::string known;
    for (std::string_view n : kLevelNames) known += (known.empty() ? "" : ", ") + std::string(n);
    throw std::invalid_argument("unknown AI level \"" + std::string(name) +
                                "\" (known levels: " + known + ")");
  }
  return make_level(name);
}

std::vector<std::string> ai_level_names() {
  return std::vector<std::string>(kLevelNames.begin(), kLevelNames.end());
}

}  // namespace breakshot
