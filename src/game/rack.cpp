// Racks: the regulation starting positions of the object balls.
//
// The balls sit on a triangular lattice whose spacing is the ball diameter
// plus kLatticeGap, rows toward the foot rail (+x): row k lies k * s *
// sqrt(3)/2 behind the foot spot, its balls s apart and centred on the long
// axis. The apex ball is exactly on the foot spot; every other ball is then
// moved by a random vector shorter than kJitter (< kLatticeGap / 2), so
// that two balls are always more than 2R + kLatticeGap - 2 kJitter apart
// (never touching) and neighbours are at most 2R + kLatticeGap + 2 kJitter
// apart: a rack frozen with the tiny random gaps of a real one.
//
// Randomness comes from std::mt19937_64 seeded with `seed`, used through
// raw 64-bit draws only (no std::*_distribution, whose output is not
// specified across standard libraries) and plain arithmetic, so a seed
// gives the same rack everywhere. Draws, in order: the ball assignment
// (8-ball: the solid, the stripe and the corner that takes the solid, then
// a Fisher-Yates shuffle of the rest; 9-ball: the shuffle), then the
// displacement of each ball but the apex, in lattice order.
//
// Snooker: the same lattice and offsets for the 15 reds (all of one kind,
// so no assignment draws), the apex red on the pyramid spot just behind
// the pink (SnookerMarks::pyramid_apex) instead of the foot spot, rows
// toward the top cushion; the colours stand exactly on their spots.
#include "breakshot/rack.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "breakshot/carom.hpp"
#include "physics/detmath.hpp"
#include "breakshot/snooker.hpp"

namespace breakshot {

namespace {

constexpr double kLatticeGap = 0.2e-3;  ///< m, added to the lattice spacing
constexpr double kJitter = 0.09e-3;     ///< m, largest displacement of a ball

class Draws {
 public:
  explicit Draws(std::uint64_t seed) : rng_(seed) {}

  /// Uniform in [0, n), without modulo bias.
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t reject = (0 - n) % n;  // 2^64 mod n
    for (;;) {
      const std::uint64_t x = rng_();
      if (x >= reject) return x % n;
    }
  }

  /// Uniform in [-1, 1).
  double symmetric() {
    const double u = static_cast<double>(rng_() >> 11) * 0x1.0p-53;
    return 2.0 * u - 1.0;
  }

  /// Uniform in the unit disk, by rejection.
  Vec2 in_disk() {
    for (;;) {
      const double x = symmetric();
      const double y = symmetric();
      if (x * x + y * y < 1.0) return {x, y};
    }
  }

  template <class T>
  void shuffle(std::vector<T>& v) {
    for (std::size_t i = v.size(); i > 1; --i) {
      const auto j = static_cast<std::size_t>(below(i));
      std::swap(v[i - 1], v[j]);
    }
  }

 private:
  std::mt19937_64 rng_;
};

/// The lattice spots, row by row from the apex; row k has counts[k] balls,
/// listed toward +y.
std::vector<Vec2> lattice(Vec2 apex, double spacing, const std::vector<int>& counts) {
  std::vector<Vec2> spots;
  const double row = spacing * std::sqrt(3.0) * 0.5;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const int c = counts[k];
    for (int j = 0; j < c; ++j) {
      spots.push_back({apex.x + static_cast<double>(k) * row,
                       apex.y + (static_cast<double>(j) - 0.5 * static_cast<double>(c - 1)) * spacing});
    }
  }
  return spots;
}

/// The snooker rack: 15 reds in rows of 1-2-3-4-5 from the pyramid apex
/// (just behind the pink spot) toward the top cushion, red1 at the apex and
/// the rest row by row toward +y, each but the apex moved by the rack's
/// tiny random offset; then the six colours on their spots.
std::vector<RackedBall> snooker_rack(const Table& table, double radius, Draws& draws) {
  static_assert(kSnookerPyramidGap == kLatticeGap, "the apex gap is the lattice gap");
  const SnookerMarks m = snooker_marks();
  // The apex stands 2 kSnookerBallRadius + gap behind the pink; a ball of
  // another size keeps the same gap to the pink.
  const Vec2 apex{m.pink.x + 2.0 * radius + kSnookerPyramidGap, m.pink.y};
  std::vector<Vec2> spots = lattice(apex, 2.0 * radius + kLatticeGap, {1, 2, 3, 4, 5});
  for (std::size_t i = 1; i < spots.size(); ++i) spots[i] += draws.in_disk() * kJitter;
  std::vector<RackedBall> rack;
  for (std::size_t i = 0; i < spots.size(); ++i) {
    rack.push_back({"red" + std::to_string(i + 1), spots[i]});
  }
  rack.push_back({"yellow", m.yellow});
  rack.push_back({"green", m.green});
  rack.push_back({"brown", m.brown});
  rack.push_back({"blue", m.blue});
  rack.push_back({"pink", m.pink});
  rack.push_back({"black", m.black});
  for (const RackedBall& b : rack) {
    const Vec2 p = b.position;
    if (p.x < radius || p.x > table.length - radius || p.y < radius || p.y > table.width - radius) {
      throw std::invalid_argument("the rack does not fit on the table");
    }
  }
  return rack;
}

}  // namespace

std::vector<RackedBall> make_rack(const std::string& game, const Table& table, double radius,
                                  std::uint64_t seed) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("the ball radius must be positive and finite");
  }
  if (!(table.length > 0.0 && table.width > 0.0)) {
    throw std::invalid_argument("a rack needs a pool table");
  }
  const double spacing = 2.0 * radius + kLatticeGap;
  Draws draws(seed);

  // balls[i] is the number of the ball on lattice spot i.
  std::vector<Vec2> spots;
  std::vector<int> balls;
  if ((game == "eight_ball" || game == "nine_ball" || game == "ten_ball") &&
      (table.shape == TableShape::snooker || table.shape == TableShape::carom)) {
    throw std::invalid_argument("the " + game + " rack needs a pool table");
  }
  if (game == "three_cushion") {
    if (table.shape != TableShape::carom) {
      throw std::invalid_argument("the three_cushion rack needs the carom table");
    }
    // UMB's starting position: the red on the top spot, the opponent's
    // ball (yellow) on the bottom spot, the breaker's (white) on a starting
    // spot beside it. The rules leave the side to the breaker; the two are
    // mirror images, and the seed draws one.
    const CaromMarks m = carom_marks();
    const Vec2 white = m.starting_spots[static_cast<std::size_t>(draws.below(2))];
    for (const Vec2 p : {white, m.bottom_spot, m.top_spot}) {
      if (wall_clearance(table, p, radius) < 0.0) {
        throw std::invalid_argument("the rack does not fit on the table");
      }
    }
    if (norm(white - m.bottom_spot) < 2.0 * radius) {
      throw std::invalid_argument("the balls are too large for the starting spots");
    }
    return {{"white", white}, {"yellow", m.bottom_spot}, {"red", m.top_spot}};
  }
  if (game == "eight_ball") {
    // Rows of 1-2-3-4-5. Spot 4 is the middle of the third row, spots 10
    // and 14 the back corners.
    spots = lattice(table.foot_spot, spacing, {1, 2, 3, 4, 5});
    const int solid = 1 + static_cast<int>(draws.below(7));
    const int stripe = 9 + static_cast<int>(draws.below(7));
    const bool solid_first = draws.below(2) == 0;
    std::vector<int> rest;
    for (int n = 1; n <= 15; ++n) {
      if (n != 8 && n != solid && n != stripe) rest.push_back(n);
    }
    draws.shuffle(rest);
    balls.assign(15, 0);
    balls[4] = 8;
    balls[10] = solid_first ? solid : stripe;
    balls[14] = solid_first ? stripe : solid;
    std::size_t next = 0;
    for (int& b : balls) {
      if (b == 0) b = rest[next++];
    }
  } else if (game == "nine_ball" || game == "ten_ball") {
    // The rotation racks (WPA): 9-ball a diamond of 1-2-3-2-1, 10-ball a
    // triangle of 1-2-3-4; the 1 at the apex (spot 0), the game ball in
    // the middle of the third row (spot 4), the others at random.
    const bool nine = game == "nine_ball";
    const int game_ball = nine ? 9 : 10;
    spots = lattice(table.foot_spot, spacing,
                    nine ? std::vector<int>{1, 2, 3, 2, 1} : std::vector<int>{1, 2, 3, 4});
    std::vector<int> rest;
    for (int n = 2; n < game_ball; ++n) rest.push_back(n);
    draws.shuffle(rest);
    balls.assign(static_cast<std::size_t>(game_ball), 0);
    balls[0] = 1;
    balls[4] = game_ball;
    std::size_t next = 0;
    for (int& b : balls) {
      if (b == 0) b = rest[next++];
    }
  } else if (game == "snooker") {
    if (table.shape != TableShape::snooker) {
      throw std::invalid_argument("the snooker rack needs a snooker table");
    }
    return snooker_rack(table, radius, draws);
  } else {
    throw std::invalid_argument(
        "unknown game \"" + game +
        "\" (expected \"eight_ball\", \"nine_ball\", \"ten_ball\", \"snooker\" or "
        "\"three_cushion\")");
  }

  for (std::size_t i = 1; i < spots.size(); ++i) spots[i] += draws.in_disk() * kJitter;

  std::vector<RackedBall> rack;
  for (std::size_t i = 0; i < spots.size(); ++i) {
    const Vec2 p = spots[i];
    if (p.x < radius || p.x > table.length - radius || p.y < radius ||
        p.y > table.width - radius) {
      throw std::invalid_argument("the rack does not fit on the table");
    }
    rack.push_back({std::to_string(balls[i]), p});
  }
  std::sort(rack.begin(), rack.end(), [](const RackedBall& x, const RackedBall& y) {
    return std::stoi(x.id) < std::stoi(y.id);
  });
  return rack;
}

Vec2 snooker_break_off_spot() {
  const SnookerMarks m = snooker_marks();
  return {m.baulk_x, 0.5 * (m.brown.y + m.yellow.y)};
}

namespace {

/// The snooker break-off: the cue ball on its spot in the D, a level
/// centre-ball strike at `cue_speed` m/s that takes a quarter of the red at
/// the yellow-side end of the back row (red11) on its outer side.
Scenario snooker_break_scenario(const std::string& size, std::uint64_t seed, double cue_speed) {
  if (size != "12ft") {
    throw std::invalid_argument("unknown snooker table size \"" + size + "\" (expected \"12ft\")");
  }
  constexpr double kRadius = kSnookerBallRadius;
  constexpr double kMass = kSnookerBallMass;
  Scenario s;
  s.physics = default_physics(Model::pool);
  s.physics.ball_clusters = true;  // the break spreads the pack
  s.table = make_snooker_table();
  const double e = CushionParams{}.restitution;
  BallState cue;
  cue.position = snooker_break_off_spot();
  s.balls.push_back({"cue", kRadius, kMass, e});
  s.start.push_back(cue);
  Vec2 target;
  for (const RackedBall& b : make_rack("snooker", s.table, kRadius, seed)) {
    BallState st;
    st.position = b.position;
    if (b.id == "red11") target = b.position;
    s.balls.push_back({b.id, kRadius, kMass, e});
    s.start.push_back(st);
  }
  // Aim so that the cue ball's path passes 1.5 R from the red's centre on
  // its outer (smaller y) side: a quarter-ball hit.
  const Vec2 d = target - cue.position;
  const double dist = norm(d);
  const Vec2 u = d / dist;
  const double sin_b = 1.5 * kRadius / dist;
  const double cos_b = std::sqrt(1.0 - sin_b * sin_b);
  const Vec2 left{-u.y, u.x};
  const Vec2 aim = u * cos_b - left * sin_b;
  CueSpec strike_spec;
  strike_spec.ball = 0;
  strike_spec.strike.speed = cue_speed;
  strike_spec.strike.phi = dm::atan2(aim.y, aim.x) * (180.0 / 3.14159265358979323846);
  s.cue = strike_spec;
  s.until.rest = true;
  return s;
}

/// The three-cushion break: the UMB starting position from `seed` on the
/// carom table, carom balls, and a level centre-ball strike of the white
/// straight at the red (the break must hit the red first).
Scenario three_cushion_break_scenario(const std::string& size, std::uint64_t seed,
                                      double cue_speed) {
  if (size != "10ft") {
    throw std::invalid_argument("unknown carom table size \"" + size +
                                "\" (expected \"10ft\", the 2840 x 1420 mm match table)");
  }
  constexpr double kRadius = kCaromBallRadius;
  constexpr double kMass = kCaromBallMass;
  Scenario s;
  s.physics = default_physics(Model::pool);
  s.physics.ball_clusters = true;  // as every game's shots
  s.table = make_carom_table();
  const double e = CushionParams{}.restitution;
  Vec2 white;
  Vec2 red;
  for (const RackedBall& b : make_rack("three_cushion", s.table, kRadius, seed)) {
    BallState st;
    st.position = b.position;
    if (b.id == "white") white = b.position;
    if (b.id == "red") red = b.position;
    s.balls.push_back({b.id, kRadius, kMass, e});
    s.start.push_back(st);
  }
  const Vec2 d = red - white;
  CueSpec strike_spec;
  strike_spec.ball = 0;
  strike_spec.strike.speed = cue_speed;
  strike_spec.strike.phi = dm::atan2(d.y, d.x) * (180.0 / 3.14159265358979323846);
  s.cue = strike_spec;
  s.until.rest = true;
  return s;
}

}  // namespace

Scenario make_break_scenario(const std::string& game, const std::string& size,
                             std::uint64_t seed, double cue_speed) {
  if (game == "snooker") return snooker_break_scenario(size, seed, cue_speed);
  if (game == "three_cushion") return three_cushion_break_scenario(size, seed, cue_speed);
  constexpr double kRadius = kPoolBallRadius;
  constexpr double kMass = kPoolBallMass;
  Scenario s;
  s.physics = default_physics(Model::pool);
  s.physics.ball_clusters = true;  // the break spreads the rack
  s.table = make_pool_table(size);
  const double e = CushionParams{}.restitution;
  BallState cue;
  cue.position = s.table.head_spot;
  s.balls.push_back({"cue", kRadius, kMass, e});
  s.start.push_back(cue);
  for (const RackedBall& b : make_rack(game, s.table, kRadius, seed)) {
    BallState st;
    st.position = b.position;
    s.balls.push_back({b.id, kRadius, kMass, e});
    s.start.push_back(st);
  }
  CueSpec strike_spec;
  strike_spec.ball = 0;
  strike_spec.strike.speed = cue_speed;
  s.cue = strike_spec;
  s.until.rest = true;
  return s;
}

}  // namespace breakshot
