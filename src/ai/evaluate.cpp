// What a table is worth to the AI player (src/ai/evaluate.hpp).
//
// The geometric estimate of a pot follows the usual error propagation of
// the ghost-ball aim: an aim error e of the cue ball over its run d1 moves
// the contact sideways by d1 e, which turns the line of centres by
// d1 e / (2R cos cut), and the object ball misses the pocket centre by d2
// times that after its run d2. The shot goes in while the miss stays
// within the pocket's tolerance, which shrinks as the ball comes at the
// pocket from the side; with a Gaussian aim error the chance is
// erf(tol / (sqrt 2 sigma_miss)). A mild penalty for the total distance
// stands for speed and spin errors the formula leaves out. It is an
// estimate to rank tables by, quick enough to run after every sampled
// shot; how shots really go is left to the engine.
#include "evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "physics/detmath.hpp"
#include "geometry.hpp"
#include "policy.hpp"

namespace breakshot::ai_detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kMinSigmaDeg = 0.04;  // the floor of estimate_sigma
constexpr double kMaxCutCos = 0.17364817766693041;  // cos 80 degrees: thinner cuts are not counted

/// Unit direction from a pocket into the table: the bisector of a corner,
/// straight across for a side pocket.
Vec2 mouth_direction(const Table& t, Vec2 centre, bool* side) {
  const double sx = centre.x < t.length / 3.0 ? 1.0 : (centre.x > 2.0 * t.length / 3.0 ? -1.0 : 0.0);
  const double sy = centre.y < t.width / 2.0 ? 1.0 : -1.0;
  *side = sx == 0.0;
  const Vec2 d{sx, sy};
  return d / norm(d);
}

/// The value of a shot/break phase table to its shooter.
double shooter_side_value(const Rules& rules, const GameState& s, double sigma) {
  if (s.phase == Phase::break_shot) return 0.1;  // a fresh rack to break: a small edge
  double p = 0.0;
  if (!s.on_table[0] || s.ball_in_hand == BallInHand::anywhere) {
    p = kBallInHandP;
  } else if (s.ball_in_hand == BallInHand::kitchen) {
    p = std::max(kKitchenP, best_pot_estimate(rules, s, sigma));
  } else {
    p = best_pot_estimate(rules, s, sigma);
  }
  double v = shooter_value(p);
  // Progress toward the game ball where the rules count balls to go
  // (8-ball's groups): each ball counted against the opponent's.
  const Standing st = rules.standing(s);
  const auto to_go = [&](int who) { return std::max(0, st.balls_to_go[static_cast<std::size_t>(who)]); };
  if (st.balls_to_go[0] >= 0 || st.balls_to_go[1] >= 0) {
    v += kBallProgress * (to_go(1 - s.player) - to_go(s.player));
  }
  return std::clamp(v, -kOpenBound, kOpenBound);
}

}  // namespace

std::optional<Call> expected_pot(const std::vector<Call>& potted, int samples) {
  std::optional<Call> best;
  std::ptrdiff_t best_n = 0;
  for (const Call& c : potted) {
    const std::ptrdiff_t k = std::count(potted.begin(), potted.end(), c);
    if (k > best_n) {
      best_n = k;
      best = c;
    }
  }
  if (samples <= 0 || 2 * best_n < samples) return std::nullopt;
  return best;
}

void add_centred_aims(const Rules& rules, const GameState& state,
                      std::vector<CandidateShot>& cands, int threads) {
  const std::size_t n0 = cands.size();
  const std::vector<Shoot> centred = parallel_map<Shoot>(n0, threads, [&](std::size_t i) {
    return cands[i].target >= 0 ? centre_aim(rules, state, cands[i].shot) : cands[i].shot;
  });
  for (std::size_t i = 0; i < n0; ++i) {
    if (centred[i] == cands[i].shot) continue;
    CandidateShot c = cands[i];
    c.shot = centred[i];
    cands.push_back(c);
  }
}

Shoot centre_aim(const Rules& rules, const GameState& state, const Shoot& shot) {
  if (!shot.call) return shot;
  const auto makes = [&](double phi) {
    Shoot s = shot;
    s.strike.phi = phi;
    const Outcome o = rules.apply(state, Action{s});
    if (!o.ruling.call_made) return false;
    if (o.state.phase == Phase::game_over) return o.state.winner == state.player;
    return o.state.player == state.player;
  };
  const double phi0 = shot.strike.phi;
  if (!makes(phi0)) return shot;
  // The last aim that makes the pot on one side (dir +1 or -1).
  const auto edge = [&](double dir) {
    constexpr double kFirstStep = 0.04;  // degrees
    constexpr double kLastStep = 1.28;
    constexpr int kHalvings = 6;
    double good = phi0;
    double bad = phi0;
    bool found = false;
    for (double step = kFirstStep; step <= kLastStep + 1e-12; step *= 2.0) {
      const double x = phi0 + dir * step;
      if (!makes(x)) {
        bad = x;
        found = true;
        break;
      }
      good = x;
    }
    if (!found) return good;
    for (int k = 0; k < kHalvings; ++k) {
      const double mid = 0.5 * (good + bad);
      (makes(mid) ? good : bad) = mid;
    }
    return good;
  };
  const double lo = edge(-1.0);
  const double hi = edge(1.0);
  const double mid = 0.5 * (lo + hi);
  if (mid == phi0 || !makes(mid)) return shot;
  Shoot out = shot;
  out.strike.phi = mid;
  return out;
}

double estimate_sigma(const NoiseModel& noise) { return std::max(noise.phi, kMinSigmaDeg); }

int worker_count(int requested, std::size_t units) {
  int n = requested;
  if (n <= 0) n = static_cast<int>(std::thread::hardware_concurrency());
  n = std::max(n, 1);
  if (units < static_cast<std::size_t>(n)) n = static_cast<int>(std::max<std::size_t>(units, 1));
  return n;
}

EstimateConstants estimate_constants(const GamePhysics& physics) {
  return physics.spinning_friction == kLegacySpinningFriction ? kLegacySpinEstimateConstants
                                                              : EstimateConstants{};
}

double best_pot_estimate_from(const Rules& rules, const GameState& state, Vec2 cue,
                              bool kitchen_shot, double sigma_phi_deg, int* best_ball,
                              int* best_pocket) {
  return best_pot_estimate_from(rules, state, cue, kitchen_shot, sigma_phi_deg,
                                estimate_constants(rules.config().physics), best_ball,
                                best_pocket);
}

double best_pot_estimate_from(const Rules& rules, const GameState& state, Vec2 cue,
                              bool kitchen_shot, double sigma_phi_deg,
                              const EstimateConstants& constants, int* best_ball,
                              int* best_pocket) {
  if (state.phase != Phase::shot) return 0.0;
  const Table& table = rules.table();
  const double R = rules.config().ball_radius;
  const double e = sigma_phi_deg * kDeg;
  const double head = rules.head_string();
  const std::vector<int> targets = rules.legal_actions(state).targets;
  const ai::Layout lay{state.position, state.on_table};
  // Every pot's chance from the line to the pocket centre, with the cheap
  // checks; the costlier check that the object ball has an open line past
  // the cushions and jaws (as shot generation plans it) is made only for
  // the best until one passes.
  struct Pot {
    double p;
    int ball;
    int pocket;
    Vec2 ghost;
    double rank;  // p, or in snooker p times what the pot is worth
  };
  const bool snooker = game_policy(state.game).frame_scoring;
  const PocketConstants& c = snooker ? constants.snooker : constants.pool;
  std::vector<Pot> pots;
  for (const int t : targets) {
    const Vec2 b = state.position[static_cast<std::size_t>(t)];
    if (kitchen_shot && b.x <= head) continue;  // must first hit a ball beyond the head string
    for (std::size_t k = 0; k < table.pockets.size(); ++k) {
      const Pocket& pk = table.pockets[k];
      const Vec2 to = pk.centre - b;
      const double dist = norm(to);
      if (dist <= pk.radius) continue;
      const Vec2 u = to / dist;
      bool side = false;
      const Vec2 mouth = mouth_direction(table, pk.centre, &side);
      const double cos_alpha = -dot(u, mouth);
      if (cos_alpha < (side ? c.side_min_cos : c.corner_min_cos)) continue;
      const double tol = side ? c.side_tolerance * pk.radius * cos_alpha * std::sqrt(cos_alpha)
                              : c.corner_tolerance * pk.radius * cos_alpha;
      const double d2 = std::max(dist - pk.radius, 0.01);
      const Vec2 ghost = b - u * (2.0 * R);
      const Vec2 run = ghost - cue;
      const double d1 = norm(run);
      if (d1 < 1e-6) continue;
      const double cos_cut = dot(run / d1, u);
      if (cos_cut < kMaxCutCos) continue;
      if (!ai::balls_clear(lay, R, cue, ghost, t)) continue;
      const double miss = std::max(e * d1 * d2 / (2.0 * R * cos_cut), 1e-9);
      double p = dm::erf(tol / (std::sqrt(2.0) * miss));
      p /= 1.0 + c.distance_penalty * (d1 + d2);
      const double rank = snooker ? p * (rules.ball_value(t) + kSnookerCarry) : p;
      pots.push_back(Pot{p, t, static_cast<int>(k), ghost, rank});
    }
  }
  std::stable_sort(pots.begin(), pots.end(),
                   [](const Pot& x, const Pot& y) { return x.rank > y.rank; });
  for (const Pot& pot : pots) {
    const Vec2 b = state.position[static_cast<std::size_t>(pot.ball)];
    if (!disk_fits(table, pot.ghost, R)) continue;
    if (!ai::walls_clear(table, R, cue, pot.ghost)) continue;
    if (!ai::pocket_approach(table, R, lay, b, pot.pocket, pot.ball)) continue;
    if (best_ball) *best_ball = pot.ball;
    if (best_pocket) *best_pocket = pot.pocket;
    return pot.p;
  }
  return 0.0;
}

double best_pot_estimate(const Rules& rules, const GameState& state, double sigma_phi_deg) {
  return best_pot_estimate(rules, state, sigma_phi_deg,
                           estimate_constants(rules.config().physics));
}

double best_pot_estimate(const Rules& rules, const GameState& state, double sigma_phi_deg,
                         const EstimateConstants& constants) {
  if (!state.on_table[0]) return 0.0;
  return best_pot_estimate_from(rules, state, state.position[0], state.kitchen_shot,
                                sigma_phi_deg, constants);
}

double snooker_visit_points(const Rules& rules, const GameState& s, double sigma) {
  if (s.phase == Phase::game_over || s.phase == Phase::break_shot) return 0.0;
  int ball = -1;
  double p = 0.0;
  if (!s.on_table[0] || s.ball_in_hand != BallInHand::none) {
    p = kSnookerHandP;
    const std::vector<int> on = rules.balls_on(s);
    if (!on.empty()) ball = on.front();
  } else {
    p = best_pot_estimate_from(rules, s, s.position[0], false, sigma, &ball);
    if (ball < 0 && snookered(rules, s)) return -kSnookeredPoints;
  }
  if (ball <= 0) return 0.0;
  const double value = rules.ball_value(ball);
  const double after_pot = static_cast<double>(rules.standing(s).points_left) - value;
  return p * (value + std::min(kSnookerCarry, std::max(0.0, after_pot)));
}

bool snookered(const Rules& rules, const GameState& s) {
  if (!s.on_table[0]) return false;
  const double R = rules.config().ball_radius;
  const ai::Layout lay{s.position, s.on_table};
  const Vec2 cue = s.position[0];
  for (const int t : rules.balls_on(s)) {
    // A full contact, or a thin one on either side: the cue ball's centre
    // runs to the ball's centre, or to a point 2R from it across the line.
    const Vec2 b = s.position[static_cast<std::size_t>(t)];
    const Vec2 d = b - cue;
    const double len = norm(d);
    if (len < 1e-9) return false;
    const Vec2 side = Vec2{-d.y, d.x} / len * (2.0 * R * 0.98);
    for (const Vec2 to : {b - d / len * (2.0 * R), b - d / len * (2.0 * R) + side * 0.5,
                          b - d / len * (2.0 * R) - side * 0.5}) {
      if (ai::balls_clear(lay, R, cue, to, t) && ai::walls_clear(rules.table(), R, cue, to)) {
        return false;
      }
    }
  }
  return true;
}

namespace {
/// Snooker: the value of leading by `lead` with `left` points on the table.
double snooker_lead_value(double lead, double left) {
  const double spread = std::sqrt(kSnookerSpreadPerPoint * left + kSnookerSpreadBase);
  return (1.0 - kSnookerPointsWeight) * dm::erf(lead / (std::sqrt(2.0) * spread)) +
         kSnookerPointsWeight * std::clamp(lead / kSnookerPointsScale, -1.0, 1.0);
}
}  // namespace

double snooker_position_value(const Rules& rules, const GameState& after, int me, double sigma,
                              bool no_pot) {
  if (after.phase == Phase::game_over) {
    if (after.winner < 0) return 0.0;
    return after.winner == me ? 1.0 : -1.0;
  }
  const Standing st = rules.standing(after);
  const auto i_me = static_cast<std::size_t>(me);
  const double lead = static_cast<double>(st.score[i_me] - st.score[1 - i_me]);
  const double left = static_cast<double>(st.points_left);
  const auto value = [&](double lead_now) { return snooker_lead_value(lead_now, left); };
  const double e = no_pot ? 0.0 : snooker_visit_points(rules, after, sigma);
  const int shooter = after.player;
  if (after.phase == Phase::foul_choice) {
    // The chooser plays on, or has the offender play again, whichever
    // is worth more to the chooser.
    const double play = shooter == me ? value(lead + e) : value(lead - e);
    const double pass = shooter == me ? value(lead - e) : value(lead + e);
    return shooter == me ? std::max(play, pass) : std::min(play, pass);
  }
  return value(shooter == me ? lead + e : lead - e);
}

double position_value(const Rules& rules, const GameState& after, int me, double sigma) {
  if (game_policy(after.game).frame_scoring) {
    return snooker_position_value(rules, after, me, sigma, false);
  }
  const auto mine = [&](int who, double v) { return who == me ? v : -v; };
  switch (after.phase) {
    case Phase::game_over:
      if (after.winner < 0) return 0.0;
      return after.winner == me ? 1.0 : -1.0;
    case Phase::break_shot:
    case Phase::shot:
      return mine(after.player, shooter_side_value(rules, after, sigma));
    case Phase::push_out_choice: {
      // The chooser takes the better of shooting from here and making the
      // pusher shoot from here.
      GameState as_shot = after;
      as_shot.phase = Phase::shot;
      as_shot.ball_in_hand = BallInHand::none;
      const int chooser = after.player;
      as_shot.player = chooser;
      const double take = shooter_side_value(rules, as_shot, sigma);
      as_shot.player = 1 - chooser;
      const double pass = -shooter_side_value(rules, as_shot, sigma);
      return mine(chooser, std::max(take, pass));
    }
    case Phase::illegal_break_choice:
      // The incoming player picks the best of three: an edge to him.
      return mine(after.player, 0.2);
    case Phase::eight_on_break_choice:
      return mine(after.player, 0.3);
    case Phase::foul_choice:
      return 0.0;  // snooker's phase: valued above
  }
  return 0.0;
}

double sample_shot(const Rules& rules, const GameState& state, const Shoot& shot,
                   const NoiseModel& noise, std::uint64_t seed, double sigma,
                   GameState* after, Call* potted, ShotWorkspace* work) {
  Shoot played = shot;
  played.strike = perturb(shot.strike, noise, rules.config().ball_radius, seed);
  Outcome out = work ? rules.apply(state, played, *work) : rules.apply(state, played);
  const double v = position_value(rules, out.state, state.player, sigma);
  if (potted) {
    *potted = Call{};
    if (out.ruling.fouls.empty()) {
      for (std::size_t i = 0; i < out.facts.pocketed.size(); ++i) {
        if (out.facts.pocketed[i] > 0) {
          *potted = Call{out.facts.pocketed[i], out.facts.pocket_of[i]};
          break;
        }
      }
    }
  }
  if (after) *after = std::move(out.state);
  return v;
}

}  // namespace breakshot::ai_detail
