// Timing of the event-time root finders on realistic input.
//
// The quartics are contact functions of two pool balls decelerating by
// rolling or sliding friction, f = |dp + dv t + da t^2 / 2|^2 - sigma^2,
// over the window until the first of them stops, as the simulator builds
// them. Each benchmark cycles through a fixed set of 4096 cases so that
// branch prediction cannot learn one input.
#include "breakshot/ball.hpp"
#include "physics/roots.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace {

constexpr double kSigma = 2.0 * breakshot::kPoolBallRadius;
constexpr std::size_t kCases = 4096;  // a power of two: cycle with a mask

struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double uniform() { return static_cast<double>(g() >> 11) * 0x1p-53; }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  double pow10(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
};

struct Quartic {
  double c[5];
  double t_max;
};

// As in tests/test_roots.cpp: `aimed` pairs pass within 1.5 sigma of each
// other at a random time (about 2/3 collide); the others are placed at
// random on the table (about 1% collide). `touching` pairs are aimed ones
// moved to just after a collision (in contact up to round-off, opening).
Quartic ball_pair(Rng& rng, bool aimed) {
  double v[2][2], a[2][2];
  double window = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2; ++i) {
    const bool moving = i == 0 || rng.uniform() < 0.7;
    const double speed = moving ? rng.pow10(-1.5, 0.8) : 0.0;
    const double angle = rng.uniform(0.0, 6.283185307179586);
    const double decel = rng.uniform() < 0.5 ? 0.0981 : 1.962;
    v[i][0] = speed * std::cos(angle);
    v[i][1] = speed * std::sin(angle);
    a[i][0] = moving ? -decel * std::cos(angle) : 0.0;
    a[i][1] = moving ? -decel * std::sin(angle) : 0.0;
    if (moving) window = std::min(window, speed / decel);
  }
  const double dv[2] = {v[1][0] - v[0][0], v[1][1] - v[0][1]};
  const double da[2] = {a[1][0] - a[0][0], a[1][1] - a[0][1]};
  double dp[2];
  if (aimed) {
    const double tau = rng.uniform(0.0, 1.2) * window;
    const double w[2] = {dv[0] + da[0] * tau, dv[1] + da[1] * tau};
    const double wn = std::hypot(w[0], w[1]);
    const double miss = rng.uniform(-1.5, 1.5) * kSigma;
    const double nx = wn > 0.0 ? -w[1] / wn : 1.0, ny = wn > 0.0 ? w[0] / wn : 0.0;
    dp[0] = miss * nx - dv[0] * tau - 0.5 * da[0] * tau * tau;
    dp[1] = miss * ny - dv[1] * tau - 0.5 * da[1] * tau * tau;
  } else {
    dp[0] = rng.uniform(-2.5, 2.5);
    dp[1] = rng.uniform(-1.25, 1.25);
  }
  Quartic q{};
  q.c[0] = dp[0] * dp[0] + dp[1] * dp[1] - kSigma * kSigma;
  q.c[1] = 2.0 * (dp[0] * dv[0] + dp[1] * dv[1]);
  q.c[2] = dv[0] * dv[0] + dv[1] * dv[1] + (dp[0] * da[0] + dp[1] * da[1]);
  q.c[3] = dv[0] * da[0] + dv[1] * da[1];
  q.c[4] = 0.25 * (da[0] * da[0] + da[1] * da[1]);
  q.t_max = window;
  return q;
}

enum class Mix { random, aimed, colliding, missing, touching };

std::vector<Quartic> quartics(Mix mix) {
  Rng rng(0xbe9c4000 + static_cast<std::uint64_t>(mix));
  std::vector<Quartic> out;
  while (out.size() < kCases) {
    Quartic q = ball_pair(rng, mix != Mix::random);
    if (mix == Mix::touching) {
      // Just after a collision: touching up to round-off and separating.
      q.c[0] = (rng.uniform() < 0.5 ? -1e-17 : 1e-17) * rng.uniform(0.0, 1.0);
      q.c[1] = std::fabs(q.c[1]);
    }
    const bool hit = breakshot::first_contact(q.c, 4, q.t_max) <= q.t_max;
    if ((mix == Mix::colliding && !hit) || (mix == Mix::missing && hit)) continue;
    out.push_back(q);
  }
  return out;
}

void run_quartics(benchmark::State& state, Mix mix) {
  const std::vector<Quartic> qs = quartics(mix);
  std::size_t i = 0;
  for (auto _ : state) {
    const Quartic& q = qs[i++ & (kCases - 1)];
    benchmark::DoNotOptimize(breakshot::first_contact(q.c, 4, q.t_max));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_FirstContactQuartic_RandomPairs(benchmark::State& s) { run_quartics(s, Mix::random); }
void BM_FirstContactQuartic_AimedPairs(benchmark::State& s) { run_quartics(s, Mix::aimed); }
void BM_FirstContactQuartic_Colliding(benchmark::State& s) { run_quartics(s, Mix::colliding); }
void BM_FirstContactQuartic_NearMisses(benchmark::State& s) { run_quartics(s, Mix::missing); }
void BM_FirstContactQuartic_Touching(benchmark::State& s) { run_quartics(s, Mix::touching); }
BENCHMARK(BM_FirstContactQuartic_RandomPairs);
BENCHMARK(BM_FirstContactQuartic_AimedPairs);
BENCHMARK(BM_FirstContactQuartic_Colliding);
BENCHMARK(BM_FirstContactQuartic_NearMisses);
BENCHMARK(BM_FirstContactQuartic_Touching);

// Degree 2: a decelerating ball reaching a cushion line or a grid cell
// edge, c0 = distance, c1 = -approach speed, c2 = deceleration / 2; all
// of them, or only those that get there.
void run_degree2(benchmark::State& state, bool reaching) {
  Rng rng(0xbe9c4100);
  struct Case {
    double c[3];
    double t_max;
  };
  std::vector<Case> cs;
  while (cs.size() < kCases) {
    Case k{};
    const double speed = rng.pow10(-1.5, 0.8), decel = rng.uniform() < 0.5 ? 0.0981 : 1.962;
    const double along = rng.uniform(-1.0, 1.0) * speed;  // velocity towards the line
    k.c[0] = rng.uniform(0.0, 1.0);
    k.c[1] = -along;
    k.c[2] = 0.5 * decel * along / speed;
    k.t_max = speed / decel;
    if (reaching && !(breakshot::first_contact(k.c, 2, k.t_max) <= k.t_max)) continue;
    cs.push_back(k);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& k = cs[i++ & (kCases - 1)];
    benchmark::DoNotOptimize(breakshot::first_contact(k.c, 2, k.t_max));
  }
  state.SetItemsProcessed(state.iterations());
}
void BM_FirstContactDegree2(benchmark::State& s) { run_degree2(s, false); }
void BM_FirstContactDegree2_Reaching(benchmark::State& s) { run_degree2(s, true); }
BENCHMARK(BM_FirstContactDegree2);
BENCHMARK(BM_FirstContactDegree2_Reaching);

// Ideal model: constant velocities, approaching pairs aimed to pass within
// 1.5 sigma (the simulator calls it only when dp.dv < 0).
void BM_FirstContactQuadratic(benchmark::State& state) {
  Rng rng(0xbe9c4200);
  struct Case {
    double c, b, a;
  };
  std::vector<Case> cs(kCases);
  for (Case& k : cs) {
    const double speed = rng.pow10(-2.0, 1.0), angle = rng.uniform(0.0, 6.283185307179586);
    const double dv[2] = {speed * std::cos(angle), speed * std::sin(angle)};
    const double tau = rng.pow10(-3.0, 1.0), miss = rng.uniform(-1.5, 1.5) * kSigma;
    const double dp[2] = {-dv[0] * tau - miss * std::sin(angle),
                          -dv[1] * tau + miss * std::cos(angle)};
    k.c = dp[0] * dp[0] + dp[1] * dp[1] - kSigma * kSigma;
    k.b = dp[0] * dv[0] + dp[1] * dv[1];
    k.a = dv[0] * dv[0] + dv[1] * dv[1];
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& k = cs[i++ & (kCases - 1)];
    benchmark::DoNotOptimize(breakshot::first_contact_quadratic(k.c, k.b, k.a));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FirstContactQuadratic);

void BM_SolveQuadratic(benchmark::State& state) {
  Rng rng(0xbe9c4300);
  struct Case {
    double a, b, c;
  };
  std::vector<Case> cs(kCases);
  for (Case& k : cs) {
    k.a = rng.uniform(-1.0, 1.0);
    k.b = rng.uniform(-1.0, 1.0);
    k.c = rng.uniform(-1.0, 1.0);
  }
  std::size_t i = 0;
  double roots[2];
  for (auto _ : state) {
    const Case& k = cs[i++ & (kCases - 1)];
    benchmark::DoNotOptimize(breakshot::solve_quadratic(k.a, k.b, k.c, roots));
    benchmark::DoNotOptimize(roots);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SolveQuadratic);

}  // namespace

BENCHMARK_MAIN();
