// The lab's ideal gas for the benchmarks (bench_events' BM_IdealGas and
// scaling's gas): n disks of radius 1 cm at area fraction 0.3 in a square
// box, on a jittered grid, each at 1 m/s in a random direction, from a
// fixed mt19937_64 seed. Not part of the library.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>

#include "breakshot/scenario.hpp"
#include "breakshot/table.hpp"

namespace breakshot::bench {

inline Scenario ideal_gas(long n, std::uint64_t seed) {
  const auto unit = [](std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; };
  const double r = 0.01;
  const double side = std::sqrt(static_cast<double>(n) * M_PI * r * r / 0.3);
  Scenario s;
  s.physics.model = Model::ideal;
  s.table = make_rectangle({0, 0}, {side, side});
  const long cols = static_cast<long>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double pitch = side / static_cast<double>(cols);
  const double slack = (pitch - 2 * r) / 2 * 0.9;
  std::mt19937_64 g(seed);
  s.balls.reserve(static_cast<std::size_t>(n));
  s.start.reserve(static_cast<std::size_t>(n));
  for (long k = 0; k < n; ++k) {
    BallSpec b{"g" + std::to_string(k), r, 0.01, 1.0};
    BallState st;
    st.position = {(static_cast<double>(k % cols) + 0.5) * pitch + slack * (2 * unit(g) - 1),
                   (static_cast<double>(k / cols) + 0.5) * pitch + slack * (2 * unit(g) - 1)};
    const double a = 2 * M_PI * unit(g);
    st.velocity = {std::cos(a), std::sin(a)};
    st.state = MotionState::moving;
    s.balls.push_back(b);
    s.start.push_back(st);
  }
  s.until.rest = false;
  s.until.time = 1e300;
  return s;
}

}  // namespace breakshot::bench
