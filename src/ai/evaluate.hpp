// Internals of the AI player (src/ai/ai_player.cpp): what a table is
// worth, shots played out under noise, and the deterministic parallel
// map the sampling runs on. Not part of the public API.
//
// Values are from the deciding player's side, in [-1, 1]: 1 a won game,
// -1 a lost one. Between shots a table is worth about what its shooter's
// best pot promises (position_value), so a successful shot is worth the
// next shot it leaves and a miss the negative of the opponent's.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "breakshot/ai.hpp"
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"

namespace breakshot::ai_detail {

/// Value of being the shooter with a best pot of estimated success p in
/// [0, 1]: kShooterBase + kShooterGain p. With nothing on (p = 0) the
/// shooter still plays a safety and loses little, so the base is only a
/// little below 0; a sure pot with a good table is worth most of a rack.
inline constexpr double kShooterBase = -0.1;
inline constexpr double kShooterGain = 0.85;
/// What p a shooter with the cue ball in hand anywhere is given: nearly
/// any table has an easy pot from some place. Behind the head string less.
inline constexpr double kBallInHandP = 0.9;
inline constexpr double kKitchenP = 0.55;
/// 8-ball: each ball of the shooter's group still up, counted against
/// the opponent's, moves the value by this much (progress toward the 8).
inline constexpr double kBallProgress = 0.06;
/// Values short of a decided game stay within this bound, so a win or a
/// loss always dominates.
inline constexpr double kOpenBound = 0.95;

/// Snooker (docs/ai.md, "Snooker"): a table is worth, mostly, the chance
/// of winning the frame from its score, read as a normal law: the lead
/// plus the points the shooter's visit promises (for the side to shoot)
/// over a spread of sqrt(kSnookerSpreadPerPoint x points left +
/// kSnookerSpreadBase) points; and for kSnookerPointsWeight of it, that
/// margin over kSnookerPointsScale points, so that a frame all but won
/// or lost still ranks shots by the points they promise. A visit
/// promises p (value of the ball + the smaller of kSnookerCarry and the
/// points left after it) for its best pot p; with the cue ball in hand,
/// p is kSnookerHandP.
inline constexpr double kSnookerCarry = 4.0;
inline constexpr double kSnookerSpreadPerPoint = 9.0;
inline constexpr double kSnookerSpreadBase = 16.0;
inline constexpr double kSnookerHandP = 0.6;
inline constexpr double kSnookerPointsWeight = 0.25;
inline constexpr double kSnookerPointsScale = 147.0;
/// Snooker: what a visit that begins snookered (no ball on can be hit
/// directly, full or thin) is worth: the escape risks a foul of at least 4.
inline constexpr double kSnookeredPoints = 3.0;

/// Snooker: the player to act in `s` cannot hit any ball on in a straight
/// line (full, or half a ball either side of full).
bool snookered(const Rules& rules, const GameState& s);

/// Snooker: the points the player to act in `s` may expect from the
/// visit it begins (0 on the break-off).
double snooker_visit_points(const Rules& rules, const GameState& s, double sigma_phi_deg);

/// Snooker's position_value; `no_pot` values the table as if the shooter
/// had no pot (it plays safe).
double snooker_position_value(const Rules& rules, const GameState& after, int me,
                              double sigma_phi_deg, bool no_pot);

/// The shooter's value for a best pot p (above).
inline double shooter_value(double p) { return kShooterBase + kShooterGain * p; }

/// The pot estimate's constants for one kind of table, fitted against
/// the engine by bench/ai_estimate_fit (docs/ai.md, "The estimate,
/// checked against the engine"). A corner pocket takes a ball whose centre
/// comes within corner_tolerance pocket radii of the centre line, times
/// cos(alpha) for a ball coming at alpha to the pocket's bisector, and
/// none beyond cos(alpha) = corner_min_cos; a side pocket side_tolerance
/// radii times cos(alpha)^1.5 (its facings turn balls away faster as the
/// angle grows), none beyond side_min_cos. The chance is divided by 1 +
/// distance_penalty per metre of the cue ball's and the object ball's
/// runs, for the speed and spin errors the aim leaves out.
struct PocketConstants {
  double corner_tolerance;
  double side_tolerance;
  double corner_min_cos;
  double side_min_cos;
  double distance_penalty;
};

/// The estimate's constants: the pool tables' and the snooker table's
/// (rounded jaws and tighter mouths); the defaults are the AI's on the
/// default physics. The pool ones are fitted under tournament noise on the
/// tables of 160 recorded games of 8- and 9-ball between the champion and
/// the baseline. The snooker ones are the earlier fit's: fitted the same
/// way on 18 frames, the estimate reads the engine better with
/// {0.48, 0.57, 0.87, 0.6, 0.055} but the champion's breaks from open
/// tables were shorter with them (docs/ai.md, "The estimate on a snooker
/// table").
struct EstimateConstants {
  PocketConstants pool{0.66, 0.46, 0.5, 0.47, 0.04};
  PocketConstants snooker{0.38, 0.38, 0.5, 0.47, 0.04};
};

/// The constants the AI used while side spin decayed with FastFiz's
/// spinning friction (kLegacySpinningFriction), fitted on breakshot 0.1's
/// physics. A physics with that spinning friction (the legacy physics, and
/// the default of the time before the measured one) keeps them, so that
/// the games played on it are played again as they were.
inline constexpr EstimateConstants kLegacySpinEstimateConstants{
    {0.78, 0.715, 0.5, 0.47, 0.04}, {0.38, 0.38, 0.5, 0.47, 0.04}};

/// The constants the AI uses on `physics`: kLegacySpinEstimateConstants
/// for the legacy spinning friction, EstimateConstants{} otherwise.
EstimateConstants estimate_constants(const GamePhysics& physics);

/// Geometric estimate in [0, 1] of the best pot the player to act in
/// `state` (phase shot, cue ball on the table) has: ghost-ball aim at
/// each legal ball and pocket with open paths (the object ball's line
/// past the cushions and jaws checked as shot generation plans it),
/// succeeding when the aim error (sigma `sigma_phi_deg`, carried through
/// the cut to the object ball) keeps the object ball within the pocket's
/// tolerance; fitted to sampled play (docs/ai.md). Tens of microseconds;
/// it sees no throw, kisses or speed, which is what the sampling is for.
double best_pot_estimate(const Rules& rules, const GameState& state, double sigma_phi_deg);

/// The same with other constants than the AI's (estimate_constants of
/// the rules' physics), for fitting them.
double best_pot_estimate(const Rules& rules, const GameState& state, double sigma_phi_deg,
                         const EstimateConstants& constants);

/// The same with the cue ball at `cue` instead (for choosing placements):
/// `kitchen_shot` as the rules would set it after the placement. The pot
/// it rates is stored in *best_ball and *best_pocket when given (left
/// alone when there is none).
double best_pot_estimate_from(const Rules& rules, const GameState& state, Vec2 cue,
                              bool kitchen_shot, double sigma_phi_deg, int* best_ball = nullptr,
                              int* best_pocket = nullptr);

/// The same with other constants than the AI's, for fitting them.
double best_pot_estimate_from(const Rules& rules, const GameState& state, Vec2 cue,
                              bool kitchen_shot, double sigma_phi_deg,
                              const EstimateConstants& constants, int* best_ball = nullptr,
                              int* best_pocket = nullptr);

/// What `after` (the table after an action, any phase) is worth to player
/// `me`: 1 or -1 for a decided game (0 a draw), else the shooter's value
/// (with the cue ball in hand valued by kBallInHandP or kKitchenP), its
/// negative when the opponent shoots, and a pessimistic reading of the
/// decisions the rules may hand the opponent.
double position_value(const Rules& rules, const GameState& after, int me,
                      double sigma_phi_deg);

/// Plays `shot` from `state` with the strike perturbed by `noise` under
/// `seed`, and returns position_value of the result for the shooter. The
/// resulting state is stored in *after when given, and in *potted the
/// first object ball pocketed and its pocket when the shot was no foul
/// (ball -1 otherwise).
/// With `work`, the shot is played in that thread's workspace
/// (Rules::apply), re-armed instead of made anew; the value is the same.
double sample_shot(const Rules& rules, const GameState& state, const Shoot& shot,
                   const NoiseModel& noise, std::uint64_t seed, double sigma_phi_deg,
                   GameState* after = nullptr, Call* potted = nullptr,
                   ShotWorkspace* work = nullptr);

/// The ball and pocket that at least half of `samples` noisy plays of a
/// shot pocketed (`potted`: one entry per play that pocketed an object
/// ball without a foul, its first such ball), if any: the pot the player
/// can be said to expect from the shot. Ties go to the first seen.
std::optional<Call> expected_pot(const std::vector<Call>& potted, int samples);

/// `shot` (a called pot) with its aim moved to the middle of the range of
/// aims (phi, all else fixed) around its own for which the noiseless play
/// from `state` makes the call and keeps the turn (or wins): each edge is
/// found by steps that double from 0.04 degrees (to at most 1.28), then
/// six halvings, to within about 0.01 degrees. A Gaussian aim error then
/// has the most room on both sides. The shot is returned unchanged when
/// its own aim does not make the pot, or has no call. Deterministic;
/// about 25 plays.
Shoot centre_aim(const Rules& rules, const GameState& state, const Shoot& shot);

/// The aim noise (degrees) used for geometric estimates: the model's phi
/// noise, with a floor so that even a noiseless player ranks easy shots
/// above hard ones.
double estimate_sigma(const NoiseModel& noise);

/// Threads to use: `requested`, or all cores for 0, never more than `units`.
int worker_count(int requested, std::size_t units);

/// Calls fn(i, scratch) for i in [0, n) on `threads` threads and returns
/// the results in index order; each worker has a Scratch of its own (made
/// at the start of the call) that its units may keep memory in. Each unit
/// must be a pure function of its index (its seed derived from the index,
/// never from the thread that runs it, nor from what a scratch holds), so
/// the result is the same for any thread count. The first exception a
/// unit throws is rethrown here.
template <class T, class Scratch, class Fn>
std::vector<T> parallel_map_with(std::size_t n, int threads, Fn&& fn) {
  const int workers = worker_count(threads, n);
  std::vector<Scratch> scratch(static_cast<std::size_t>(std::max(workers, 1)));
  std::vector<T> out(n);
  if (workers <= 1) {
    for (std::size_t i = 0; i < n; ++i) out[i] = fn(i, scratch[0]);
    return out;
  }
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(workers));
  const auto work = [&](std::size_t w) {
    try {
      for (std::size_t i = next.fetch_add(1); i < n; i = next.fetch_add(1)) {
        out[i] = fn(i, scratch[w]);
      }
    } catch (...) {
      errors[w] = std::current_exception();
      next.store(n);  // the others stop taking units
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(workers - 1));
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, static_cast<std::size_t>(w));
  work(0);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return out;
}

/// parallel_map_with without a scratch: fn(i).
template <class T, class Fn>
std::vector<T> parallel_map(std::size_t n, int threads, Fn&& fn) {
  struct None {};
  return parallel_map_with<T, None>(n, threads, [&fn](std::size_t i, None&) { return fn(i); });
}

/// parallel_map_with a ShotWorkspace per worker (Rules::apply re-arms its
/// simulation from unit to unit): fn(i, workspace).
template <class T, class Fn>
std::vector<T> parallel_map_ws(std::size_t n, int threads, Fn&& fn) {
  return parallel_map_with<T, ShotWorkspace>(n, threads, std::forward<Fn>(fn));
}

/// Appends, after the candidates in `cands`, each pot (target >= 0)
/// again with its aim centred (centre_aim) where that moves it; the
/// centring runs on `threads` threads and the order is the candidates'.
void add_centred_aims(const Rules& rules, const GameState& state,
                      std::vector<CandidateShot>& cands, int threads);

}  // namespace breakshot::ai_detail
