// Not a benchmark of shots: the five cushion laws side by side, each at
// the defaults a scenario gives it (docs/physics.md, "Cushions"): how a
// rolling ball leaves the rail, and what one impact costs.
//
//   build/release/bench/cushion_laws [--rounds N]
//
// For each law: the rebound angle from the normal (degrees, right after
// the impact) of a ball rolling at 1 m/s into the rail at 30, 40 and 50
// degrees of incidence, its rebound speed over its incident speed
// straight in, and the time of one cushion_impact call (median of N
// rounds, default 5, each cycling 80 rolling impacts at 0-79 degrees and
// 0.5-2 m/s until 0.2 s have passed). The figures other than the times
// are the same on every run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "breakshot/pool.hpp"

using namespace breakshot;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kMass = 0.170;
constexpr double kR = 0.028575;

/// The law as a scenario with only table.cushion_model sets it.
CushionParams defaults(CushionModel m) {
  CushionParams p;
  p.model = m;
  p.cloth_friction = 0.2;  // physics.sliding_friction
  p.restitution = default_cushion_restitution(m);
  if (m == CushionModel::mathavan_2010) p.nose_height = kMathavanNoseHeight;
  return p;
}

struct Hit {
  Vec2 v;
  Vec3 w;
};

/// A ball rolling at `speed` into the rail whose inward normal is +y
/// (the rail along y = const above the ball), `inc` degrees off it.
Hit rolling(double speed, double inc) {
  const Vec2 v{speed * std::sin(inc * kDeg), -speed * std::cos(inc * kDeg)};
  return {v, {-v.y / kR, v.x / kR, 0.0}};
}

const Vec2 kNormal{0.0, 1.0};

double rebound_angle(const CushionParams& p, double inc) {
  const Hit h = rolling(1.0, inc);
  const CushionImpact r = cushion_impact(h.v, h.w, kNormal, kMass, kR, p);
  return std::atan2(r.velocity.x, r.velocity.y) / kDeg;
}

double straight_in(const CushionParams& p) {
  const Hit h = rolling(1.0, 0.0);
  return norm(cushion_impact(h.v, h.w, kNormal, kMass, kR, p).velocity);
}

/// Nanoseconds per impact, median over `rounds`.
double cost(const CushionParams& p, int rounds) {
  std::vector<Hit> hits;
  for (int k = 0; k < 80; ++k) hits.push_back(rolling(0.5 + 1.5 * (k % 7) / 6.0, k));
  std::vector<double> per;
  double sink = 0.0;
  for (int r = 0; r < rounds; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    long n = 0;
    double elapsed = 0.0;
    while (elapsed < 0.2) {
      for (const Hit& h : hits) sink += cushion_impact(h.v, h.w, kNormal, kMass, kR, p).velocity.y;
      n += static_cast<long>(hits.size());
      elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    per.push_back(elapsed / static_cast<double>(n) * 1e9);
  }
  std::sort(per.begin(), per.end());
  if (sink == 12345.678) std::printf(" ");  // keeps the loop's work
  return per[per.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 5;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rounds" && i + 1 < argc) {
      rounds = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "cushion_laws: usage: cushion_laws [--rounds N]\n");
      return 2;
    }
  }
  if (rounds < 1) {
    std::fprintf(stderr, "cushion_laws: --rounds must be at least 1\n");
    return 2;
  }
  std::printf("law                  e      angle at 30/40/50 deg   straight in   ns per impact\n");
  for (const CushionModel m : kCushionModels) {
    const CushionParams p = defaults(m);
    std::printf("%-19s  %.3f  %6.1f %6.1f %6.1f      %8.3f   %13.1f\n",
                std::string(cushion_model_name(m)).c_str(), p.restitution, rebound_angle(p, 30.0),
                rebound_angle(p, 40.0), rebound_angle(p, 50.0), straight_in(p), cost(p, rounds));
  }
  return 0;
}
