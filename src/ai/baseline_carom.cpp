// The baseline player's three-cushion shots (baseline_carom.hpp): the
// simplest one-ball-first system shots, from the mirror construction,
// refined on the engine.
//
// A shot plays the cue ball into a first object ball F, from which it goes
// round three or four cushions to the second, S. The path after F comes
// from the mirror construction: the table for ball centres is the
// rectangle [R, L - R] x [R, W - R]; unfolded, the images of S are a
// lattice of reflected copies, and the image (i, j) (|i| reflections
// across the short cushions, |j| across the long ones) is reached by a
// straight line from the departure point after |i| + |j| cushions, as a
// frictionless ball without spin would go. For each image with |i| + |j|
// of 3 or 4 the player finds the contacts on F whose departure runs at
// it: a rolling cue ball leaves a contact with normal n (from the cue
// ball's centre to F's) along u - (5/7)(u.n) n, u its direction of travel
// (the tangent line, bent forward by its roll; the 30 degree rule's
// origin). The speed is the least that would bring the cue ball to S with
// some pace left, from rolling friction and a speed lost at each cushion.
//
// The candidates, easiest first (shortest path, cuts neither thin nor
// full), are then played on the engine with Rules::apply: the aim is
// turned a little either side of the geometric one, at two speeds, until
// a shot scores. Without a scoring shot in the budget the easiest
// candidate is played as the geometry gives it. The break plays the red
// (the rules want it first, directly). Deterministic: the seed is unused.
#include "baseline_carom.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "physics/detmath.hpp"
#include "geometry.hpp"

namespace breakshot::ai {

/// The centre of the image (i, j) of `p` in the unfolded table of ball
/// centres [lo.x, hi.x] x [lo.y, hi.y].
Vec2 carom_image(Vec2 p, Vec2 lo, Vec2 hi, int i, int j) {
  const auto coord = [](double v, double a, double b, int k) {
    const double span = b - a;
    const double off = (k % 2 == 0) ? v - a : b - v;
    return a + k * span + off;
  };
  return {coord(p.x, lo.x, hi.x, i), coord(p.y, lo.y, hi.y, j)};
}

/// The cue ball's departure direction (not normalised) from a contact
/// with normal n, travelling along u (both unit): the tangent line bent
/// forward by its roll.
Vec2 carom_departure(Vec2 u, Vec2 n) { return u - n * (5.0 / 7.0 * dot(u, n)); }

/// The contacts on F from which a cue ball at C departs toward `target`
/// (the angle of n from C's side), found where the departure's direction
/// crosses the wanted one.
std::vector<double> carom_contact_angles(Vec2 C, Vec2 F, Vec2 target, double R, int steps) {
  std::vector<double> out;
  const auto miss = [&](double a, double* along) {
    Vec2 n{0.0, 0.0};
    dm::sincos(a, n.y, n.x);
    const Vec2 G = F - n * (2.0 * R);
    const Vec2 cg = G - C;
    const double len = norm(cg);
    if (len < 1e-9) return std::nan("");
    const Vec2 u = cg / len;
    if (dot(u, n) < 0.08) return std::nan("");  // no hit, or a hair
    const Vec2 e = carom_departure(u, n);
    const Vec2 d = target - G;
    *along = dot(e, d);
    return cross(e, d);
  };
  double prev_a = 0.0;
  double prev = std::nan("");
  double prev_along = 0.0;
  for (int k = 0; k <= steps; ++k) {
    const double a = 2.0 * kPi * k / steps;
    double along = 0.0;
    const double m = miss(a, &along);
    if (std::isfinite(m) && std::isfinite(prev) && (m > 0.0) != (prev > 0.0) && along > 0.0 &&
        prev_along > 0.0) {
      double lo = prev_a;
      double hi = a;
      double flo = prev;
      for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (lo + hi);
        double al = 0.0;
        const double fm = miss(mid, &al);
        if (!std::isfinite(fm)) break;
        if ((fm > 0.0) == (flo > 0.0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      out.push_back(0.5 * (lo + hi));
    }
    prev_a = a;
    prev = m;
    prev_along = along;
  }
  return out;
}

namespace {

/// Simulations one decision may run at most.
constexpr int kBudget = 240;
/// Candidates refined on the engine at most.
constexpr int kCandidates = 10;
/// Speed kept per cushion (a rough figure for the default cushion law at
/// the angles these paths take).
constexpr double kCushionKeep = 0.8;
/// Pace the cue ball should still have at the second ball (m/s).
constexpr double kArrival = 0.5;
/// Cue ball speed per unit of cue speed, a centre hit of a carom ball with
/// the default cue (2 / (1 + m/M)); only for the speed estimate.
constexpr double kLaunch = 2.0 / (1.0 + 0.210 / 0.567);

struct Candidate {
  int first = -1;
  double phi = 0.0;    // degrees
  double speed = 0.0;  // cue speed, m/s
  double cost = 0.0;   // lower is easier
};

double phi_of(Vec2 d) { return dm::atan2(d.y, d.x) / kDeg; }

std::vector<Candidate> candidates(const Rules& rules, const GameState& state) {
  const Table& table = rules.table();
  const double R = rules.config().ball_radius;
  const int own = rules.cue_ball(state);
  const Vec2 C = state.position[static_cast<std::size_t>(own)];
  const Vec2 lo{R, R};
  const Vec2 hi{table.length - R, table.width - R};
  const std::vector<int> firsts = rules.targets(state);
  std::vector<int> objects;
  for (int b = 0; b < rules.ball_count(); ++b) {
    if (b != own) objects.push_back(b);
  }
  std::vector<Candidate> out;
  for (const int f : firsts) {
    const int s = objects[0] == f ? objects[1] : objects[0];
    const Vec2 F = state.position[static_cast<std::size_t>(f)];
    const Vec2 S = state.position[static_cast<std::size_t>(s)];
    for (int i = -4; i <= 4; ++i) {
      for (int j = -4; j <= 4; ++j) {
        const int rails = std::abs(i) + std::abs(j);
        if (rails < 3 || rails > 4) continue;
        const Vec2 target = carom_image(S, lo, hi, i, j);
        for (const double a : carom_contact_angles(C, F, target, R, 360)) {
          Vec2 n{0.0, 0.0};
          dm::sincos(a, n.y, n.x);
          const Vec2 G = F - n * (2.0 * R);
          if (G.x < lo.x || G.x > hi.x || G.y < lo.y || G.y > hi.y) continue;
          // The way to F must not meet the second ball.
          if (segment_distance(S, C, G) < 2.0 * R + kBallMargin) continue;
          const Vec2 u = (G - C) / norm(G - C);
          const double full = dot(u, n);  // 1: full ball, 0: a graze
          const Vec2 e = carom_departure(u, n);
          const double keep = norm(e);  // of the cue ball's speed
          const double l1 = norm(G - C);
          const double l2 = norm(target - G);
          double need = std::sqrt(kArrival * kArrival + 2.0 * kRollingFriction * kGravity * l2);
          for (int r = 0; r < rails; ++r) need /= kCushionKeep;
          const double at_contact = need / keep;
          // A centre hit slides, then rolls at 5/7 of its launch speed.
          const double launch =
              std::sqrt(at_contact * at_contact + 2.0 * kRollingFriction * kGravity * l1) /
              (5.0 / 7.0);
          const double cue = std::clamp(launch / kLaunch, 1.5, 8.0);
          Candidate c;
          c.first = f;
          c.phi = phi_of(G - C);
          c.speed = cue;
          // Shorter paths, fewer cushions and cuts near half-ball first.
          c.cost = l1 + l2 + 0.5 * (rails - 3) + 2.0 * std::abs(full - 0.5);
          out.push_back(c);
        }
      }
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; });
  return out;
}

}  // namespace

Shoot three_cushion_shot(const Rules& rules, const GameState& state) {
  const std::vector<Candidate> cands = candidates(rules, state);
  Shoot fallback;
  fallback.strike.speed = 3.0;
  if (cands.empty()) {
    // Nothing geometric: straight at the first legal ball.
    const int own = rules.cue_ball(state);
    const int f = rules.targets(state).front();
    fallback.strike.phi = phi_of(state.position[static_cast<std::size_t>(f)] -
                                 state.position[static_cast<std::size_t>(own)]);
    return fallback;
  }
  fallback.strike.phi = cands.front().phi;
  fallback.strike.speed = cands.front().speed;
  constexpr double kOffsets[] = {0.0,  0.4, -0.4, 0.8, -0.8, 1.2, -1.2, 1.6,
                                 -1.6, 2.0, -2.0, 2.5, -2.5, 3.0, -3.0};
  int runs = 0;
  const int n = std::min<int>(kCandidates, static_cast<int>(cands.size()));
  for (int k = 0; k < n && runs < kBudget; ++k) {
    const Candidate& c = cands[static_cast<std::size_t>(k)];
    for (const double scale : {1.0, 1.3}) {
      for (const double off : kOffsets) {
        if (runs >= kBudget) break;
        Shoot s;
        s.strike.phi = c.phi + off;
        s.strike.speed = std::min(c.speed * scale, 10.0);
        ++runs;
        const Outcome o = rules.apply(state, Action{s});
        if (o.ruling.carom && o.ruling.carom->point) return s;
      }
    }
  }
  return fallback;
}

}  // namespace breakshot::ai
