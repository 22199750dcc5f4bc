// Shot execution noise (include/breakshot/noise.hpp).
//
// The figures of the `tournament` model are those of the computational
// pool tournaments (FastFiz): 0.125 degrees on the aim phi, 0.1 degrees on
// the elevation theta, 0.075 m/s on the speed and 0.5 mm on each tip
// offset.
//
// Reproducibility: a seed must give the same strike on every platform, so
// nothing here comes from <random> (std::normal_distribution and the std::
// engines' seeding are implementation-defined) or from the maths library
// (std::log is not required to be correctly rounded, and libraries differ
// in the last bit). Draws come from SplitMix64; Gaussians from Marsaglia's
// polar method, which needs only a square root (correctly rounded in IEEE
// arithmetic) and a logarithm, dm::log (physics/detmath.hpp, built from
// +, -, *, / alone). With contraction off (-ffp-contract=off,
// CMakeLists.txt) every step is one IEEE operation and the result is the
// same bit for bit everywhere.
//
// The five parameters always take the first five of the deviates of a
// seed, in the order phi, theta, speed, a, b, whatever the sigmas: turning
// the noise of one parameter on or off does not change the others'.
#include "breakshot/game.hpp"
#include "breakshot/noise.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

#include "physics/detmath.hpp"

namespace breakshot {

namespace {

constexpr NoiseModel kTournament{0.125, 0.1, 0.075, 0.0005, 0.0005};

constexpr std::string_view kForms =
    "accepted forms: \"none\", \"tournament\", \"<k>x\" (k >= 0 times tournament, e.g. "
    "\"5x\", \"0.5x\"), \"custom:phi=..,theta=..,speed=..,a=..,b=..\" (any of the keys, "
    "degrees, m/s and metres, each >= 0)";

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("noise: " + what + "; " + std::string(kForms));
}

/// The whole of `text` as a finite, non-negative number; nullopt otherwise.
std::optional<double> non_negative(std::string_view text) {
  double v = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto r = std::from_chars(first, last, v, std::chars_format::general);
  if (text.empty() || r.ec != std::errc() || r.ptr != last) return std::nullopt;
  if (!std::isfinite(v) || v < 0.0) return std::nullopt;
  return v + 0.0;  // -0 becomes +0
}

NoiseModel scaled(double k) {
  return {k * kTournament.phi, k * kTournament.theta, k * kTournament.speed, k * kTournament.a,
          k * kTournament.b};
}

NoiseModel parse_custom(std::string_view body) {
  if (body.empty()) fail("\"custom:\" lists no parameter");
  NoiseModel m;
  std::array<bool, 5> seen{};
  constexpr std::array<std::string_view, 5> kKeys{"phi", "theta", "speed", "a", "b"};
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = body.find(',', start);
    const std::string_view item = body.substr(
        start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    if (item.empty()) fail("empty entry in \"custom:" + std::string(body) + "\"");
    const std::size_t eq = item.find('=');
    if (eq == std::string_view::npos) {
      fail("\"" + std::string(item) + "\" is not key=value");
    }
    const std::string_view key = item.substr(0, eq);
    const std::string_view value = item.substr(eq + 1);
    std::size_t k = 0;
    while (k < kKeys.size() && kKeys[k] != key) ++k;
    if (k == kKeys.size()) {
      fail("unknown key \"" + std::string(key) + "\" (keys: phi, theta, speed, a, b)");
    }
    if (seen[k]) fail("key \"" + std::string(key) + "\" given twice");
    seen[k] = true;
    const std::optional<double> v = non_negative(value);
    if (!v) {
      fail("the value of " + std::string(key) + ", \"" + std::string(value) +
           "\", is not a finite number >= 0");
    }
    double* const fields[] = {&m.phi, &m.theta, &m.speed, &m.a, &m.b};
    *fields[k] = *v;
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return m;
}

/// Shortest text that reads back as exactly v.
std::string number(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

// --- SplitMix64 (Steele, Lea and Flood 2014; Vigna's reference constants).

constexpr std::uint64_t kGamma = 0x9e3779b97f4a7c15ULL;

constexpr std::uint64_t finalize(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    state_ += kGamma;
    return finalize(state_);
  }
  /// Uniform in [-1, 1), on the grid of 2^-52.
  double symmetric() {
    const double u = static_cast<double>(next() >> 11) * 0x1.0p-53;
    return 2.0 * u - 1.0;
  }

 private:
  std::uint64_t state_;
};

/// Independent standard normal deviates, two per accepted pair
/// (Marsaglia and Bray 1964, the polar method).
class Gaussian {
 public:
  explicit Gaussian(std::uint64_t seed) : rng_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    for (;;) {
      const double u = rng_.symmetric();
      const double v = rng_.symmetric();
      const double s = u * u + v * v;
      if (s >= 1.0 || s == 0.0) continue;
      const double f = std::sqrt(-2.0 * dm::log(s) / s);
      spare_ = v * f;
      has_spare_ = true;
      return u * f;
    }
  }

 private:
  SplitMix64 rng_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace

NoiseModel parse_noise(std::string_view spec) {
  if (spec.empty()) fail("empty spec");
  if (spec == "none") return {};
  if (spec == "tournament") return kTournament;
  constexpr std::string_view kCustom = "custom:";
  if (spec.substr(0, kCustom.size()) == kCustom) return parse_custom(spec.substr(kCustom.size()));
  if (spec.back() == 'x') {
    const std::string_view k = spec.substr(0, spec.size() - 1);
    const std::optional<double> v = non_negative(k);
    if (!v) {
      fail("the factor \"" + std::string(k) + "\" of \"" + std::string(spec) +
           "\" is not a finite number >= 0");
    }
    return scaled(*v);
  }
  fail("unknown spec \"" + std::string(spec) + "\"");
}

std::string to_string(const NoiseModel& noise) {
  if (noise == NoiseModel{}) return "none";
  if (noise == kTournament) return "tournament";
  // A multiple of tournament reads best as one: dividing by 0.125, a
  // power of two, recovers the factor exactly.
  const double k = noise.phi / kTournament.phi;
  if (std::isfinite(k) && k > 0.0 && scaled(k) == noise) return number(k) + "x";
  return "custom:phi=" + number(noise.phi) + ",theta=" + number(noise.theta) +
         ",speed=" + number(noise.speed) + ",a=" + number(noise.a) + ",b=" + number(noise.b);
}

CueStrike perturb(const CueStrike& intended, const NoiseModel& noise, double ball_radius,
                  std::uint64_t seed) {
  if (!(ball_radius > 0.0) || !std::isfinite(ball_radius)) {
    throw std::invalid_argument("perturb: the ball radius must be positive and finite");
  }
  // Clamps keep every executed strike one that Rules::check accepts (the
  // game runners rely on it): speed in (0, 20] m/s, theta below 90
  // degrees, tip offsets on the ball. An offset at the edge of the ball
  // is a miscue all the same, as a wilder one would be.
  constexpr double kMinSpeed = 0.01;  // m/s: a stroke, however feeble
  constexpr double kMaxTheta = 89.0;  // degrees: strike() needs theta < 90
  constexpr double kMaxOffset = 1.0;  // radii
  Gaussian g(seed);
  const double z_phi = g.next();
  const double z_theta = g.next();
  const double z_speed = g.next();
  const double z_a = g.next();
  const double z_b = g.next();
  // A zero sigma leaves its parameter untouched, bit for bit (x + 0 would
  // turn -0 into +0, and the clamps would move values already outside).
  CueStrike s = intended;
  if (noise.phi != 0.0) s.phi += noise.phi * z_phi;
  if (noise.theta != 0.0) {
    s.theta = std::fmin(std::fmax(s.theta + noise.theta * z_theta, 0.0), kMaxTheta);
  }
  if (noise.speed != 0.0) {
    s.speed = std::fmin(std::fmax(s.speed + noise.speed * z_speed, kMinSpeed), kMaxCueSpeed);
  }
  if (noise.a != 0.0) {
    s.a = std::fmin(std::fmax(s.a + noise.a / ball_radius * z_a, -kMaxOffset), kMaxOffset);
  }
  if (noise.b != 0.0) {
    s.b = std::fmin(std::fmax(s.b + noise.b / ball_radius * z_b, -kMaxOffset), kMaxOffset);
  }
  return s;
}

std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b) {
  // Two SplitMix64 rounds: finalize is a bijection, so for either argument
  // fixed the map from the other is one-to-one, and swapping them changes
  // the result.
  return finalize(finalize(a + kGamma) + b + 2 * kGamma);
}

}  // namespace breakshot
