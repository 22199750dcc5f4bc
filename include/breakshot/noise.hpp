// Shot execution noise: a seeded Gaussian perturbation of each shot
// parameter (the computational pool tournaments' model, docs/rules.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "breakshot/pool.hpp"

namespace breakshot {

/// Standard deviations of the executed shot around the intended one.
struct NoiseModel {
  double phi = 0.0;    ///< degrees
  double theta = 0.0;  ///< degrees
  double speed = 0.0;  ///< m/s
  double a = 0.0;      ///< m, tip offset across (converted to fractions of R)
  double b = 0.0;      ///< m, tip offset up
  bool operator==(const NoiseModel&) const = default;
};

/// `none`; `tournament` (0.125 deg on phi, 0.1 deg on theta, 0.075 m/s,
/// 0.5 mm on each tip offset; the computational pool tournaments' levels,
/// FastFiz); `<k>x` for k times tournament (e.g. `5x`, `0.5x`); or `custom:phi=..,theta=..,speed=..,a=..,b=..` (any subset,
/// the rest 0; offsets in metres). Throws std::invalid_argument naming
/// what is wrong otherwise.
NoiseModel parse_noise(std::string_view spec);
/// A spec that parse_noise reads back to the same model: `none`,
/// `tournament`, `<k>x` for exact multiples, else `custom:` with all five.
std::string to_string(const NoiseModel& noise);

/// The strike actually played: `intended` plus independent Gaussian
/// deviations drawn from `seed` (same seed, same result on every
/// platform: no <random>, no libm). The result is kept within what the
/// rules accept: speed in [0.01, kMaxCueSpeed] m/s, theta in [0, 89]
/// degrees, tip offsets (fractions of `ball_radius`) in [-1, 1]. Throws
/// std::invalid_argument for a ball_radius that is not positive and
/// finite.
CueStrike perturb(const CueStrike& intended, const NoiseModel& noise, double ball_radius,
                  std::uint64_t seed);

/// Deterministic 64-bit mixing (SplitMix64), for deriving seeds.
std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b);

}  // namespace breakshot
