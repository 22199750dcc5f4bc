// The layouts and shots of bench_pool's BM_RandomShot15, shared with
// export_random_shots (the Python benchmark bench/python_shots.py plays
// the same shots): 15 object balls at random places on a 9 ft table, a
// cue ball and a random strike (speed 1-6 m/s, any direction, tip offsets
// up to 0.3 R), from a fixed mt19937_64 seed. Not part of the library.
#pragma once

#include <cstddef>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "breakshot/physics.hpp"
#include "breakshot/pool.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/table.hpp"

namespace breakshot::bench {

inline constexpr double kR = kPoolBallRadius;

inline double unit(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }

inline Scenario pool_scene() {
  Scenario s;
  s.physics = default_physics(Model::pool);
  s.table = make_pool_table("9ft");
  s.until.rest = true;
  return s;
}

inline void add_ball(Scenario& s, const std::string& id, Vec2 p) {
  s.balls.push_back({id, kR, kPoolBallMass, CushionParams{}.restitution});
  BallState st;
  st.position = p;
  s.start.push_back(st);
}

/// `count` scenes, each with its cue strike on ball 0 ("cue"); object
/// balls are "1" ... "15".
inline std::vector<Scenario> random_shots(std::size_t count) {
  std::mt19937_64 g(2026);
  std::vector<Scenario> out;
  while (out.size() < count) {
    Scenario s = pool_scene();
    const double L = s.table.length, W = s.table.width;
    for (int k = 0; k < 16 * 50 && s.balls.size() < 16; ++k) {
      const Vec2 p{kR + (L - 2 * kR) * unit(g), kR + (W - 2 * kR) * unit(g)};
      bool free = wall_clearance(s.table, p, kR) > 1e-4;
      for (const BallState& b : s.start) free = free && norm(b.position - p) > 2 * kR + 1e-4;
      if (free) add_ball(s, s.balls.empty() ? "cue" : std::to_string(s.balls.size()), p);
    }
    CueSpec cue;
    cue.ball = 0;
    cue.strike.speed = 1.0 + 5.0 * unit(g);
    cue.strike.phi = 360.0 * unit(g);
    cue.strike.a = 0.6 * unit(g) - 0.3;
    cue.strike.b = 0.6 * unit(g) - 0.3;
    s.cue = cue;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace breakshot::bench
