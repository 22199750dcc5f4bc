// How often the pots a snooker break is made of go in under a noise
// (docs/ai.md, "Snooker"): the colours from their spots, and an object
// ball at set distances from a corner pocket, with the cue ball placed
// at a set distance behind the ghost ball, straight or at a cut.
//
//   snooker_pots [--noise SPEC] [--samples N]
//
// Each pot is the best, by its share of N plays (default 256, fixed noise
// seeds) under SPEC (default tournament), of the first three direct
// candidates that the AI's shot generation finds for that ball and pocket
// (centre ball, 1.35 times the least speed that reaches the pocket). A
// play succeeds when it pots the ball without a foul. With the cue ball
// placed as well as it can be, this is the ceiling of a player at that
// noise: a break of 100 needs about 13 colours in a row, each from its
// spot while reds remain.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"
#include "breakshot/snooker.hpp"

namespace {

using namespace breakshot;

/// The pocket whose centre is nearest `p`.
int nearest_pocket(const Table& t, Vec2 p) {
  int best = 0;
  for (std::size_t k = 1; k < t.pockets.size(); ++k) {
    if (norm(t.pockets[k].centre - p) <
        norm(t.pockets[static_cast<std::size_t>(best)].centre - p)) {
      best = static_cast<int>(k);
    }
  }
  return best;
}

/// Share of `samples` plays that pot ball 1 (a red) from `obj` into
/// `pocket` with the cue ball `d1` behind the ghost ball, the cue ball's
/// path turned `cut_deg` from the object ball's; -1 when the cue ball
/// would be off the bed or no candidate is found.
double pot_share(const Rules& rules, Vec2 obj, int pocket, double d1, double cut_deg,
                 const NoiseModel& noise, int samples) {
  const Table& t = rules.table();
  const double R = rules.config().ball_radius;
  const Vec2 pc = t.pockets[static_cast<std::size_t>(pocket)].centre;
  const Vec2 u = (pc - obj) / norm(pc - obj);
  const double c = cut_deg * 3.14159265358979323846 / 180.0;
  const Vec2 dir{u.x * std::cos(c) - u.y * std::sin(c), u.x * std::sin(c) + u.y * std::cos(c)};
  const Vec2 cue = obj - u * (2.0 * R) - dir * d1;
  if (cue.x < R || cue.y < R || cue.x > t.length - R || cue.y > t.width - R) return -1.0;
  GameState s = rules.start(1, 0);
  std::fill(s.on_table.begin(), s.on_table.end(), std::uint8_t{0});
  s.on_table[0] = 1;
  s.position[0] = cue;
  s.on_table[1] = 1;
  s.position[1] = obj;
  s.phase = Phase::shot;
  s.ball_in_hand = BallInHand::none;
  s.shots = 1;
  s.snooker = SnookerState{};
  ShotGenOptions gen;
  gen.banks = false;
  gen.kicks = false;
  gen.combinations = false;
  gen.safeties = false;
  gen.max_candidates = 400;
  gen.speed_factors = {1.35};
  gen.spins = {0.0};
  int best = -1;
  int tried = 0;
  for (const CandidateShot& cand : generate_shots(rules, s, gen)) {
    if (cand.kind != ShotKind::direct || cand.target != 1 || cand.pocket != pocket) continue;
    if (++tried > 3) break;
    int made = 0;
    for (int k = 0; k < samples; ++k) {
      Shoot sh = cand.shot;
      sh.strike = perturb(cand.shot.strike, noise, R,
                          mix_seed(0x706f7473ULL, static_cast<std::uint64_t>(k)));
      const Outcome o = rules.apply(s, Action{sh});
      made += o.ruling.fouls.empty() && o.state.snooker->score[0] > 0 ? 1 : 0;
    }
    best = std::max(best, made);
  }
  return best < 0 ? -1.0 : static_cast<double>(best) / samples;
}

void row(const Rules& rules, const char* name, Vec2 obj, int pocket, const NoiseModel& noise,
         int samples) {
  const double d2 = norm(rules.table().pockets[static_cast<std::size_t>(pocket)].centre - obj);
  std::printf("%-22s %5.2f", name, d2);
  for (const double cut : {0.0, 30.0}) {
    for (const double d1 : {0.15, 0.3, 0.6}) {
      const double p = pot_share(rules, obj, pocket, d1, cut, noise, samples);
      if (p < 0.0) {
        std::printf("      -");
      } else {
        std::printf("  %5.1f", 100.0 * p);
      }
    }
  }
  std::printf("\n");
  std::fflush(stdout);
}

int usage() {
  std::fprintf(stderr, "usage: snooker_pots [--noise SPEC] [--samples N]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string noise_spec = "tournament";
  int samples = 256;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (i + 1 >= argc) return usage();
    const std::string_view val = argv[++i];
    if (arg == "--noise") {
      noise_spec = std::string(val);
    } else if (arg == "--samples") {
      const auto r = std::from_chars(val.data(), val.data() + val.size(), samples);
      if (r.ec != std::errc() || r.ptr != val.data() + val.size() || samples < 1 ||
          samples > 100000) {
        std::fprintf(stderr, "snooker_pots: --samples takes a whole number from 1 to 100000\n");
        return 2;
      }
    } else {
      return usage();
    }
  }
  try {
    const Rules rules(snooker_config());
    const NoiseModel noise = parse_noise(noise_spec);
    const Table& t = rules.table();
    const SnookerMarks m = snooker_marks();
    const Vec2 top_corner{t.length, t.width};
    const Vec2 bottom_middle{0.5 * t.length, 0.0};
    const Vec2 bottom_corner{0.0, 0.0};
    std::printf("noise %s, %d plays a pot: %% potted, cue ball d1 m behind the ghost ball\n",
                noise_spec.c_str(), samples);
    std::printf("%-22s %5s  %-20s  %-20s\n", "pot", "d2 m", "straight d1 .15/.3/.6",
                "cut 30 d1 .15/.3/.6");
    row(rules, "black, top corner", m.black, nearest_pocket(t, top_corner), noise, samples);
    row(rules, "pink, top corner", m.pink, nearest_pocket(t, top_corner), noise, samples);
    row(rules, "blue, middle", m.blue, nearest_pocket(t, bottom_middle), noise, samples);
    row(rules, "yellow, bottom corner", m.yellow, nearest_pocket(t, bottom_corner), noise, samples);
    const int corner = nearest_pocket(t, top_corner);
    const Vec2 pc = t.pockets[static_cast<std::size_t>(corner)].centre;
    const Vec2 along = (m.black - pc) / norm(m.black - pc);
    for (const double d2 : {0.3, 0.6}) {
      char name[32];
      std::snprintf(name, sizeof name, "red %.1f m, top corner", d2);
      row(rules, name, pc + along * d2, corner, noise, samples);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snooker_pots: %s\n", e.what());
    return 1;
  }
  return 0;
}
