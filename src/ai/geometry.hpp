// Path geometry shared by the computer players (internal): distances
// between straight paths and from a path to the table's walls, and the
// constants both players estimate with.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "breakshot/physics.hpp"
#include "breakshot/table.hpp"
#include "breakshot/vec.hpp"

namespace breakshot::ai {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The pool model's defaults (docs/physics.md), for the players' speed
// estimates only: their simulations use the scenario's own values.
inline constexpr double kGravity = default_physics(Model::pool).gravity;
inline constexpr double kSlidingFriction = default_physics(Model::pool).sliding_friction;
inline constexpr double kRollingFriction = default_physics(Model::pool).rolling_friction;
inline constexpr double kBallBallRestitution = default_physics(Model::pool).ball_ball_restitution;

/// True if the segments p0-p1 and q0-q1 cross at a point inside both.
bool segments_cross(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1);

/// Distance between the segments p0-p1 and q0-q1 (0 if they cross).
double segments_distance(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1);

/// Distance from the segment a-b to a wall piece; an arc counts as its
/// whole circle, which errs on the side of caution.
double wall_distance(const Wall& w, Vec2 a, Vec2 b);

/// Clearances a planned path keeps: beyond 2R from a ball, beyond R from a
/// cushion or jaw.
inline constexpr double kBallMargin = 0.001;  // m
inline constexpr double kWallMargin = 0.001;  // m

/// Where the balls are: a state's, or a layout left by a simulated shot
/// (by ball number; the cue ball is number 0 and is never an obstacle).
struct Layout {
  std::vector<Vec2> pos;
  std::vector<std::uint8_t> on;
};

/// True if a ball moving from a to b stays 2R (and kBallMargin) clear of
/// every object ball on `lay` except skip1 and skip2 (a ball behind a's
/// start is none).
bool balls_clear(const Layout& lay, double R, Vec2 a, Vec2 b, int skip1, int skip2 = -1);

/// The segment from a to b, for proving walls far from it at once: every
/// point of a wall that `beyond` accepts lies further than `reach` from
/// every point of the segment, by a margin far beyond rounding (1e-7 m),
/// so a test of the wall's distance against `reach` or less would pass.
class PathReach {
 public:
  PathReach(Vec2 a, Vec2 b, double reach);
  bool beyond(const Wall& w) const;

 private:
  Vec2 a_;
  Vec2 lo_, hi_;  // the segment's box grown by the reach
  Vec2 u_;        // unit direction from a to b (zero if a == b)
  double reach_;
};

/// True if a ball centre moving from a to b stays R (and kWallMargin)
/// clear of every cushion and jaw; an end already closer (a ball on a
/// rail, a bounce point) may keep its distance but not come closer.
bool walls_clear(const Table& table, double R, Vec2 a, Vec2 b);

/// A ball's path into a pocket: the point aimed at and its room.
struct Approach {
  Vec2 aim;             ///< aim point near the pocket centre
  Vec2 dir;             ///< unit direction of the final leg
  double length = 0.0;  ///< from the leg's start to the capture circle
  double room = 0.0;    ///< m the leg may move sideways before a jaw
};

/// Lines tried across a pocket's mouth by pocket_approach, and their
/// spacing in pocket radii: from -0.9 to +0.9 radii of the centre.
inline constexpr int kApproachLines = 13;
inline constexpr double kApproachStep = 0.15;

/// Rail runs: a ball at most kRailRunGap (m) off a rail is run along it
/// into the corner at its end, aimed to arrive kRailRunAim off the rail
/// (or its own gap when less), with kRailRunRoom of room.
inline constexpr double kRailRunGap = 0.08;
inline constexpr double kRailRunAim = 0.01;
inline constexpr double kRailRunRoom = 0.01;

/// The open path of a ball from `from` into pocket `pocket` that meets no
/// ball, cushion or jaw: of the line to the pocket's centre and lines 0.4
/// pocket radii to either side, the one with the most room (its distance
/// to the jaws); when all three are blocked, of the kApproachLines lines
/// aimed across the pocket's mouth, the middle of the widest run of open
/// ones (of equal runs, the one nearer the centre), with the larger of its
/// distance to the jaws and half the run's width as room. `skip1` and
/// `skip2` are balls not in the way (the moving ball). nullopt when every
/// line is blocked. For a ball `at_rest` (not a bank's second leg, which
/// starts on a cushion), a line is open only if the ball that strikes it
/// fits at its ghost ball's place, and when every line across the mouth is
/// blocked, a ball within kRailRunGap of a rail that ends in the corner
/// pocket is run along that rail (room kRailRunRoom).
std::optional<Approach> pocket_approach(const Table& table, double R, const Layout& lay,
                                        Vec2 from, int pocket, int skip1, int skip2 = -1,
                                        bool at_rest = true);

}  // namespace breakshot::ai
