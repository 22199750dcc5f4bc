// Shot execution noise (include/breakshot/noise.hpp): the spec language
// and its errors, to_string's round trip, seed mixing, and perturb's
// determinism, zero-noise identity, clamps and statistics. The statistics
// run over fixed seeds, so they are deterministic.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/noise.hpp"

namespace breakshot::test_noise {
namespace {

constexpr double kRadius = 0.028575;
constexpr NoiseModel kTournament{0.125, 0.1, 0.075, 0.0005, 0.0005};

CueStrike strike_of(double speed, double phi, double theta, double a, double b) {
  CueStrike s;
  s.speed = speed;
  s.phi = phi;
  s.theta = theta;
  s.a = a;
  s.b = b;
  return s;
}

bool same_bits(double x, double y) {
  return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
}

void expect_same_bits(const CueStrike& x, const CueStrike& y) {
  EXPECT_TRUE(same_bits(x.speed, y.speed)) << x.speed << " " << y.speed;
  EXPECT_TRUE(same_bits(x.phi, y.phi)) << x.phi << " " << y.phi;
  EXPECT_TRUE(same_bits(x.theta, y.theta)) << x.theta << " " << y.theta;
  EXPECT_TRUE(same_bits(x.a, y.a)) << x.a << " " << y.a;
  EXPECT_TRUE(same_bits(x.b, y.b)) << x.b << " " << y.b;
}

/// The message parse_noise throws for `spec` ("" if it does not throw).
std::string error_of(const std::string& spec) {
  try {
    parse_noise(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// ---------------------------------------------------------------------------
// Parsing.

TEST(NoiseParse, NamedModels) {
  EXPECT_EQ(parse_noise("none"), NoiseModel{});
  EXPECT_EQ(parse_noise("tournament"), kTournament);
}

TEST(NoiseParse, MultiplesOfTournament) {
  EXPECT_EQ(parse_noise("1x"), kTournament);
  EXPECT_EQ(parse_noise("0x"), NoiseModel{});
  const NoiseModel five = parse_noise("5x");
  EXPECT_EQ(five.phi, 5 * 0.125);
  EXPECT_EQ(five.theta, 5 * 0.1);
  EXPECT_EQ(five.speed, 5 * 0.075);
  EXPECT_EQ(five.a, 5 * 0.0005);
  EXPECT_EQ(five.b, 5 * 0.0005);
  const NoiseModel half = parse_noise("0.5x");
  EXPECT_EQ(half.phi, 0.0625);
  EXPECT_EQ(half.speed, 0.5 * 0.075);
  EXPECT_EQ(parse_noise("2.5e1x").phi, 25 * 0.125);
  EXPECT_EQ(parse_noise("-0x"), NoiseModel{});
  EXPECT_TRUE(same_bits(parse_noise("-0x").phi, 0.0));  // no negative zero sigmas
}

TEST(NoiseParse, CustomTakesAnySubsetInAnyOrder) {
  EXPECT_EQ(parse_noise("custom:phi=0.2"), (NoiseModel{0.2, 0, 0, 0, 0}));
  EXPECT_EQ(parse_noise("custom:speed=0.1,phi=0.3"), (NoiseModel{0.3, 0, 0.1, 0, 0}));
  EXPECT_EQ(parse_noise("custom:phi=1,theta=2,speed=3,a=0.004,b=5e-3"),
            (NoiseModel{1, 2, 3, 0.004, 0.005}));
  EXPECT_EQ(parse_noise("custom:b=0.001,a=0.002"), (NoiseModel{0, 0, 0, 0.002, 0.001}));
  EXPECT_EQ(parse_noise("custom:theta=0"), NoiseModel{});
}

TEST(NoiseParse, BadSpecsNameTheProblemAndListTheForms) {
  struct Case {
    std::string spec;
    std::string names;  // what the message must mention
  };
  const std::vector<Case> cases{
      {"", "empty"},
      {"None", "\"None\""},
      {"tournaments", "\"tournaments\""},
      {" none", "\" none\""},
      {"x", "factor \"\""},
      {"-1x", "\"-1\""},
      {"infx", "\"inf\""},
      {"nanx", "\"nan\""},
      {"1e999x", "\"1e999\""},
      {"2xx", "\"2x\""},
      {"0x10x", "\"0x10\""},
      {"5", "\"5\""},
      {"custom:", "no parameter"},
      {"custom:phi", "\"phi\" is not key=value"},
      {"custom:phi=", "value of phi"},
      {"custom:phi=0.1,", "empty entry"},
      {"custom:,phi=0.1", "empty entry"},
      {"custom:phi=0.1,,b=1", "empty entry"},
      {"custom:phi=0.1,phi=0.2", "\"phi\" given twice"},
      {"custom:spin=0.1", "unknown key \"spin\""},
      {"custom:Phi=0.1", "unknown key \"Phi\""},
      {"custom:phi=-0.1", "\"-0.1\""},
      {"custom:speed=inf", "\"inf\""},
      {"custom:a=nan", "\"nan\""},
      {"custom:b=1e400", "\"1e400\""},
      {"custom:theta=0.1deg", "\"0.1deg\""},
      {"custom:phi=0.1;theta=0.2", "\"0.1;theta=0.2\""},
      {"custom:phi = 0.1", "unknown key \"phi \""},
      {"custom:phi=+0.1", "\"+0.1\""},
  };
  for (const Case& c : cases) {
    const std::string msg = error_of(c.spec);
    ASSERT_FALSE(msg.empty()) << "accepted: \"" << c.spec << "\"";
    EXPECT_NE(msg.find(c.names), std::string::npos) << c.spec << " -> " << msg;
    EXPECT_NE(msg.find("accepted forms"), std::string::npos) << msg;
    EXPECT_NE(msg.find("tournament"), std::string::npos) << msg;
    EXPECT_NE(msg.find("custom:"), std::string::npos) << msg;
  }
}

TEST(NoiseParse, ToStringRoundTrips) {
  EXPECT_EQ(to_string(NoiseModel{}), "none");
  EXPECT_EQ(to_string(kTournament), "tournament");
  EXPECT_EQ(to_string(parse_noise("5x")), "5x");
  EXPECT_EQ(to_string(parse_noise("0.3x")), "0.3x");
  EXPECT_EQ(to_string(parse_noise("custom:phi=0.2")), "custom:phi=0.2,theta=0,speed=0,a=0,b=0");
  const std::vector<NoiseModel> models{
      {},
      kTournament,
      parse_noise("5x"),
      parse_noise("0.3x"),
      parse_noise("1e-3x"),
      {0.1 + 0.2, 0, 0, 0, 0},
      {0, 1.0 / 3.0, 0, 0, 0},
      {0, 0, 0.075, 0, 0},
      {1e-300, 2e300, 5e-324, 0.1, 7.0},
      {0.125, 0.1, 0.075, 0.0005, 0.0005000000000000001},
  };
  for (const NoiseModel& m : models) {
    const std::string text = to_string(m);
    const NoiseModel back = parse_noise(text);
    EXPECT_EQ(back, m) << text;
    EXPECT_TRUE(same_bits(back.phi, m.phi) && same_bits(back.theta, m.theta) &&
                same_bits(back.speed, m.speed) && same_bits(back.a, m.a) && same_bits(back.b, m.b))
        << text;
  }
}

// ---------------------------------------------------------------------------
// Seeds.

TEST(NoiseSeed, MixSeedIsDeterministicAndMixesBothArguments) {
  EXPECT_EQ(mix_seed(1, 2), mix_seed(1, 2));
  EXPECT_NE(mix_seed(1, 2), mix_seed(2, 1));
  std::set<std::uint64_t> seen;
  for (std::uint64_t a = 0; a < 100; ++a) {
    for (std::uint64_t b = 0; b < 100; ++b) seen.insert(mix_seed(a, b));
  }
  EXPECT_EQ(seen.size(), 10000u);
  // Neighbouring inputs give unrelated outputs: about half the bits flip.
  double flipped = 0.0;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    flipped += std::popcount(mix_seed(7, i) ^ mix_seed(7, i + 1));
    flipped += std::popcount(mix_seed(i, 7) ^ mix_seed(i + 1, 7));
  }
  EXPECT_NEAR(flipped / 2000.0, 32.0, 1.0);
}

// ---------------------------------------------------------------------------
// perturb.

TEST(NoisePerturb, ZeroNoiseLeavesTheStrikeBitIdentical) {
  const std::vector<CueStrike> strikes{
      strike_of(3.0, 37.25, 5.0, 0.1, -0.2),
      strike_of(0.001, -0.0, 0.0, -0.0, 0.0),  // below the speed clamp, negative zeros
      strike_of(12.0, 359.9, 89.5, 0.7, 0.9),  // theta above the clamp
  };
  for (const CueStrike& s : strikes) {
    for (std::uint64_t seed : {0ULL, 1ULL, 0xffffffffffffffffULL}) {
      expect_same_bits(perturb(s, NoiseModel{}, kRadius, seed), s);
    }
  }
}

TEST(NoisePerturb, ZeroSigmaParametersStayAndTheOthersDrawTheSameDeviates) {
  const CueStrike s = strike_of(3.0, 37.25, 5.0, 0.1, -0.2);
  const CueStrike all = perturb(s, parse_noise("tournament"), kRadius, 99);
  const CueStrike phi_only = perturb(s, parse_noise("custom:phi=0.125"), kRadius, 99);
  EXPECT_TRUE(same_bits(phi_only.phi, all.phi));  // the same deviate for phi either way
  EXPECT_NE(phi_only.phi, s.phi);
  EXPECT_TRUE(same_bits(phi_only.speed, s.speed));
  EXPECT_TRUE(same_bits(phi_only.theta, s.theta));
  EXPECT_TRUE(same_bits(phi_only.a, s.a));
  EXPECT_TRUE(same_bits(phi_only.b, s.b));
  const CueStrike b_only = perturb(s, parse_noise("custom:b=0.0005"), kRadius, 99);
  EXPECT_TRUE(same_bits(b_only.b, all.b));
  EXPECT_TRUE(same_bits(b_only.phi, s.phi));
}

TEST(NoisePerturb, SameSeedSameStrikeAndSeedsDiffer) {
  const CueStrike s = strike_of(2.0, 120.0, 10.0, 0.0, 0.0);
  const NoiseModel n = parse_noise("3x");
  std::set<double> phis;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const CueStrike x = perturb(s, n, kRadius, seed);
    expect_same_bits(x, perturb(s, n, kRadius, seed));
    phis.insert(x.phi);
  }
  EXPECT_EQ(phis.size(), 200u);
}

// The exact output for one seed: a change of generator, Gaussian or draw
// order shows up here (results must be the same on every platform).
TEST(NoisePerturb, PinnedOutputForOneSeed) {
  const CueStrike x =
      perturb(strike_of(2.0, 30.0, 10.0, 0.0, 0.0), parse_noise("tournament"), kRadius, 42);
  const CueStrike y =
      perturb(strike_of(2.0, 30.0, 10.0, 0.0, 0.0), parse_noise("tournament"), kRadius, 42);
  expect_same_bits(x, y);
  EXPECT_TRUE(same_bits(x.speed, 0x1.e7673fa58a9a2p+0)) << x.speed;
  EXPECT_TRUE(same_bits(x.phi, 0x1.e0fc6407428ep+4)) << x.phi;
  EXPECT_TRUE(same_bits(x.theta, 0x1.3dc77876736b6p+3)) << x.theta;
  EXPECT_TRUE(same_bits(x.a, -0x1.027650d2788abp-6)) << x.a;
  EXPECT_TRUE(same_bits(x.b, -0x1.5919079a4a966p-7)) << x.b;
  EXPECT_EQ(mix_seed(1, 2), 0xe2bbf3eb5675cf33ULL);
}

TEST(NoisePerturb, ClampsSpeedElevationAndOffsets) {
  const CueStrike s = strike_of(0.05, 0.0, 0.0, 0.0, 0.0);
  const NoiseModel n{0.0, 60.0, 2.0, 0.0, 0.0};
  int clamped_speed = 0;
  int theta_low = 0;
  int theta_high = 0;
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    const CueStrike x = perturb(s, n, kRadius, seed);
    EXPECT_GE(x.speed, 0.01);
    EXPECT_GE(x.theta, 0.0);
    EXPECT_LE(x.theta, 89.0);
    clamped_speed += x.speed == 0.01;
    theta_low += x.theta == 0.0;
    theta_high += x.theta == 89.0;
  }
  EXPECT_GT(clamped_speed, 800);  // about half
  EXPECT_GT(theta_low, 800);      // about half
  const CueStrike high = strike_of(3.0, 0.0, 88.0, 0.0, 0.0);
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    theta_high += perturb(high, n, kRadius, seed).theta == 89.0;
  }
  EXPECT_GT(theta_high, 800);
  // Wild noise: the speed stays within the rules' 20 m/s, the offsets on
  // the ball.
  const NoiseModel wild{1.0, 1.0, 30.0, 0.1, 0.1};
  int fastest = 0;
  int edge = 0;
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    const CueStrike x = perturb(strike_of(15.0, 0.0, 0.0, 0.5, -0.5), wild, kRadius, seed);
    EXPECT_GT(x.speed, 0.0);
    EXPECT_LE(x.speed, 20.0);
    EXPECT_LE(std::abs(x.a), 1.0);
    EXPECT_LE(std::abs(x.b), 1.0);
    fastest += x.speed == 20.0;
    edge += std::abs(x.a) == 1.0;
  }
  EXPECT_GT(fastest, 400);
  EXPECT_GT(edge, 400);
}

TEST(NoisePerturb, RejectsABadRadius) {
  const CueStrike s = strike_of(2.0, 0.0, 0.0, 0.0, 0.0);
  EXPECT_THROW(perturb(s, kTournament, 0.0, 1), std::invalid_argument);
  EXPECT_THROW(perturb(s, kTournament, -kRadius, 1), std::invalid_argument);
  EXPECT_THROW(perturb(s, kTournament, std::nan(""), 1), std::invalid_argument);
}

// Over 20,000 fixed seeds each parameter's deviation has the mean 0 and
// the standard deviation sigma (tip offsets in fractions of the radius),
// the deviations are uncorrelated, and 68.3 % of them lie within one
// sigma, as for a Gaussian. Intended values are far from the clamps.
TEST(NoisePerturb, DeviationsHaveTheModelsStatistics) {
  constexpr int kN = 20000;
  const CueStrike s = strike_of(3.0, 37.0, 20.0, 0.1, -0.1);
  const NoiseModel n{0.5, 1.0, 0.1, 0.001, 0.002};
  const double sigma[5] = {n.phi, n.theta, n.speed, n.a / kRadius, n.b / kRadius};
  std::vector<std::array<double, 5>> z(kN);
  for (int i = 0; i < kN; ++i) {
    const CueStrike x = perturb(s, n, kRadius, mix_seed(2024, static_cast<std::uint64_t>(i)));
    const double d[5] = {x.phi - s.phi, x.theta - s.theta, x.speed - s.speed, x.a - s.a, x.b - s.b};
    for (int k = 0; k < 5; ++k) {
      z[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = d[k] / sigma[k];
    }
  }
  const char* names[5] = {"phi", "theta", "speed", "a", "b"};
  for (std::size_t k = 0; k < 5; ++k) {
    double sum = 0.0;
    double sum2 = 0.0;
    int within = 0;
    for (const auto& row : z) {
      sum += row[k];
      sum2 += row[k] * row[k];
      within += std::abs(row[k]) < 1.0;
    }
    const double mean = sum / kN;
    const double sd = std::sqrt((sum2 - kN * mean * mean) / (kN - 1));
    // Standard errors: of the mean 1/sqrt(N) = 0.0071, of the standard
    // deviation 1/sqrt(2N) = 0.005, of the fraction 0.0033.
    EXPECT_NEAR(mean, 0.0, 4.0 / std::sqrt(double{kN})) << names[k];
    EXPECT_NEAR(sd, 1.0, 0.03) << names[k];
    EXPECT_NEAR(static_cast<double>(within) / kN, 0.6827, 0.013) << names[k];
    for (std::size_t l = k + 1; l < 5; ++l) {
      double c = 0.0;
      for (const auto& row : z) c += row[k] * row[l];
      EXPECT_NEAR(c / kN, 0.0, 4.0 / std::sqrt(double{kN})) << names[k] << "-" << names[l];
    }
  }
}

}  // namespace
}  // namespace breakshot::test_noise
