// Shot generation's internals (generate_shots, include/breakshot/ai.hpp;
// the method: shot_generation.cpp). One Generator lists one state's
// candidates; its parts are files of their own:
//
//   shot_generation.cpp  the generator: lines of every kind, the cap on
//                        lines, the candidates in prior order
//   shot_lines.cpp       lines from geometry: direct pots, banks, kicks,
//                        combinations; speed estimates and priors
//   jump_lines.cpp       jump shots over the balls in the way (the
//                        flight's closed form)
//   aim_refinement.cpp   runs on the engine: a watched run measured, the
//                        aim corrected by secant steps
//   pot_candidates.cpp   a line's speed and spin variants played, judged
//                        and kept as candidates with their leave
//   safeties.cpp         safeties and one-rail kicks, ranked by what the
//                        opponent is left
//   judge.cpp            a noiseless play ruled by the game's own rules
//                        (judge.hpp)
//
// Internal: not installed.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "geometry.hpp"
#include "judge.hpp"
#include "physics/detmath.hpp"
#include "policy.hpp"

namespace breakshot::ai_detail::shot_gen {

using ai::Approach;
using ai::kDeg;
using ai::Layout;

// The largest cut angles, as their cosines correctly rounded (literals, so
// that no maths library is involved): 80 degrees for direct cuts (thinner
// ones are hopeless), 70 for banks, kicks and combinations, 60 for each
// contact of a combination.
inline constexpr double kMaxCutCos = 0.17364817766693041;
inline constexpr double kMaxBankCutCos = 0.34202014332566882;
inline constexpr double kMaxComboCutCos = 0.50000000000000011;
inline constexpr double kArrival = 0.5;      // m/s the target keeps at the pocket
inline constexpr double kMaxPotSpeed = 9.0;  // m/s: faster least speeds are not tried

inline Vec2 unit(Vec2 v) { return v / norm(v); }

inline Vec2 rotate(Vec2 v, double angle) {
  double s = 0.0;
  double c = 0.0;
  dm::sincos(angle, s, c);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

inline double phi_of(Vec2 v) { return dm::atan2(v.y, v.x) / kDeg; }

/// What a probe of a shot measured on the engine.
struct Probe {
  bool ok = false;       ///< the watched run happened and gives a measure
  double miss = 0.0;     ///< signed lateral miss at the aim point (m)
  bool reached = false;  ///< the watched ball got as far as the aim line
};

/// Which run of which ball a probe follows, and against what line.
struct Watch {
  int ball = -1;          ///< scenario index of the watched ball
  bool from_start = false;  ///< run starts at the strike (the cue ball)
  int pass_cushions = 0;  ///< cushion contacts the run goes through
  Vec2 aim;               ///< the run should pass through here...
  Vec2 dir;               ///< ...moving this way
};

/// One shot line before its speed and spin variants.
struct Line {
  ShotKind kind = ShotKind::direct;
  int first = -1;
  int target = -1;
  int pocket = -1;
  double phi = 0.0;                 ///< geometric aim, degrees
  double speed = 0.0;               ///< least cue speed estimate, m/s
  double room = 0.0;                ///< m of room at the pocket
  double geo_prior = 0.0;           ///< prior from geometry alone, for ordering
  double prior_scale = 1.0;         ///< what the slope cannot see (cushion, kicks)
  Watch watch;                      ///< the target's run into the pocket
  std::optional<Watch> pre;         ///< kicks: the cue ball's run off the rail first
  double theta = 0.0;               ///< jumps: the cue's elevation, degrees
  std::vector<double> jump_speeds;  ///< jumps: the cue speeds tried, m/s
};

/// The candidates of one state: made for one generate_shots call.
class Generator {
 public:
  Generator(const Rules& rules, const GameState& state, const ShotGenOptions& options);

  std::vector<CandidateShot> run();

 private:
  // Geometry (shot_lines.cpp)

  Vec2 pos(int b) const { return state_.position[static_cast<std::size_t>(b)]; }
  bool on(int b) const { return state_.on_table[static_cast<std::size_t>(b)] != 0; }

  bool balls_clear(const Layout& lay, Vec2 a, Vec2 b, int skip1, int skip2 = -1) const {
    return ai::balls_clear(lay, R_, a, b, skip1, skip2);
  }
  bool walls_clear(Vec2 a, Vec2 b) const { return ai::walls_clear(table_, R_, a, b); }

  bool fits(Vec2 p) const { return wall_clearance(table_, p, R_) >= 0.0; }

  std::optional<Approach> approach(const Layout& lay, Vec2 from, int pocket, int skip1,
                                   int skip2 = -1, bool at_rest = true) const {
    return ai::pocket_approach(table_, R_, lay, from, pocket, skip1, skip2, at_rest);
  }

  double slope_estimate(double d1, double d2, double cos_cut) const;
  static double prior_from(double room, double slope);
  double rail_line(int rail) const;
  Vec2 mirror(Vec2 p, int rail) const;
  std::optional<Vec2> bounce(Vec2 a, Vec2 p, int rail) const;

  // Speed estimates (shot_lines.cpp)

  static double start_speed(double end, double d);
  static double transfer(double cos_cut);
  double cue_speed_for(double ball_speed) const;

  // Shot lines (shot_lines.cpp, jump_lines.cpp)

  std::optional<Line> direct_line(int t, int pocket) const;
  std::optional<Line> bank_line(int t, int pocket, int rail) const;
  std::optional<Line> kick_line(int t, int pocket, int rail) const;
  /// A jump's flight per unit cue speed (flight()).
  struct Flight {
    double along = 0.0;  ///< m/s per m/s of cue speed
    double up = 0.0;     ///< m/s per m/s of cue speed
  };
  Flight flight(double theta) const;
  std::vector<Line> jump_lines(int t, int pocket) const;
  std::vector<int> combination_targets(int f) const;
  std::optional<Line> combination_line(int f, int t, int pocket) const;

  int index_of(int number) const { return index_[static_cast<std::size_t>(number)]; }

  // Runs on the engine and the aim's correction (aim_refinement.cpp)

  Simulation start(double phi, double speed, double b, double a = 0.0, double theta = 0.0) const;
  void recycle(Simulation&& sim) const;
  static Probe follow(Simulation& sim, const Watch& w);
  /// The result of correcting an aim: the aim, the run at that aim
  /// (stopped where its probe ended) and the slope found.
  struct Refined {
    double phi = 0.0;
    double slope = 0.0;  ///< m of miss per degree
    Probe probe;
    std::optional<Simulation> sim;
  };
  std::optional<Refined> refine(double phi0, double speed, double b, const Watch& w, double slope,
                                int iterations, double a = 0.0, double theta = 0.0) const;

  // Pots played and kept (pot_candidates.cpp)

  Shoot shot_of(const CueStrike& strike, int target, int pocket, bool safety) const;
  /// `sim`, a run of this state's shot scenario, ruled (judge.hpp).
  Judged judge(Simulation& sim, const Shoot& shot) const {
    return ai_detail::judge(rules_, state_, shot, sim, numbers_);
  }
  static bool pot_made(const Judged& j, const Line& l);
  void play_jump(const Line& l, std::vector<CandidateShot>& out) const;
  void add_pot(const Line& l, const Judged& j, const Shoot& shot, double prior,
               std::vector<CandidateShot>& out) const;
  void play_line(const Line& l, std::vector<CandidateShot>& out) const;
  double leave(const Judged& j) const;

  // Safeties (safeties.cpp)

  std::vector<int> opponent_targets(const GameState& next) const;
  double opponent_chance(const Judged& j) const;
  void add_safety(const CueStrike& s, int first, bool kick,
                  std::vector<CandidateShot>& found) const;
  void add_safeties(std::vector<CandidateShot>& out) const;

  const Rules& rules_;
  const GameState& state_;
  const ShotGenOptions& opt_;
  const Table& table_;
  double R_;
  double m_;
  const GamePolicy& policy_;  // the game's strategy (policy.hpp)
  bool colour_on_;  // snooker: a colour is on after a red
  LegalActions la_;
  std::vector<int> targets_;  // legal first balls that may be aimed at
  Layout layout_;
  double launch_ = 1.0;       // cue ball speed per unit cue speed, centre hit
  Scenario base_;             // the shot's scenario; the strike is set per run
  mutable Scenario run_;      // base_ with the strike of the last start()
  mutable std::vector<Simulation> spare_;  // runs done with, for start() to re-arm
  std::vector<int> numbers_;  // scenario index -> ball number
  std::vector<int> index_;    // ball number -> scenario index (-1: off the table)
  mutable long simulations_ = 0;
};

}  // namespace breakshot::ai_detail::shot_gen
