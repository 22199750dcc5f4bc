// Tables: the walls a ball can meet.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "breakshot/pool.hpp"
#include "breakshot/vec.hpp"

namespace breakshot {

/// The kinds of wall piece. Straight segments and the corners of a
/// polygon that point into the table exist now; round jaws and pocket
/// edges of the pool tables will be further kinds.
enum class WallKind : std::uint8_t {
  segment,  ///< straight wall from a to b; `normal` points into the table
  corner,   ///< a point (a reflex vertex) that a ball can hit
  arc,      ///< a convex round piece (a pocket jaw's tip): circle of
            ///< `radius` about `a`, hit from outside, only where the
            ///< direction from `a` to the contact lies between the unit
            ///< vectors `b` (start) and `normal` (end), counter-clockwise
};

struct Wall {
  WallKind kind = WallKind::segment;
  Vec2 a;       ///< segment start, or the corner point
  Vec2 b;       ///< segment end (unused for a corner)
  Vec2 normal;  ///< unit normal into the table (segment only)
  double radius = 0.0;  ///< arc only
  std::string name;  ///< stable name used in events ("left", "edge3", ...)
};

/// A pocket: a ball whose centre comes within `radius` of `centre` has
/// fallen in (the rule is documented in docs/physics.md).
struct Pocket {
  Vec2 centre;
  double radius = 0.0;
  std::string name;  ///< "top_left", "side_bottom", ...
};

/// The kinds of table. Scenario files name them in "table.shape".
enum class TableShape : std::uint8_t {
  rectangle,  ///< make_rectangle
  polygon,    ///< make_polygon
  pool,       ///< make_pool_table
  snooker,    ///< make_snooker_table (snooker.hpp)
  carom,      ///< make_carom_table (carom.hpp)
};

/// The name of a shape in scenario files: "rectangle", "polygon",
/// "pool", "snooker" or "carom".
std::string_view to_string(TableShape shape);

/// The shape named `name` (as to_string writes it); false, leaving `out`
/// alone, for any other text.
bool parse_table_shape(std::string_view name, TableShape& out);

/// A table: its outline (for drawing and containment) and its walls.
struct Table {
  TableShape shape = TableShape::rectangle;
  std::vector<Vec2> outline;  ///< counter-clockwise boundary
  std::vector<Wall> walls;
  std::vector<Pocket> pockets;  ///< pool and snooker tables only
  Vec2 min;  ///< bounding box of everything a ball centre can reach
  Vec2 max;
  // Pool and snooker tables: the playing surface is [0, length] x [0,
  // width]. The snooker table's head spot is the brown spot (the middle of
  // the baulk line) and its foot spot the pink (pyramid) spot.
  double length = 0.0;
  double width = 0.0;
  Vec2 head_spot;
  Vec2 foot_spot;
  /// The cushions' nose height and friction (pool model). The restitution
  /// used is each ball's wall_restitution.
  CushionParams cushion;
};

/// A regulation pocket billiards table (WPA): "7ft", "8ft" or "9ft".
/// Throws std::invalid_argument for another size. Geometry and names are
/// documented in docs/physics.md.
Table make_pool_table(const std::string& size);

/// Four walls named left, right, bottom and top. Requires min < max.
Table make_rectangle(Vec2 min, Vec2 max);

/// A closed simple polygon in either winding order. Walls are named
/// edge0 ... edgeN-1 (edge k runs from vertex k to vertex k+1 as given)
/// and the vertices that point into the table corner0 ... by vertex
/// index. Throws std::invalid_argument with a reason when the polygon
/// has fewer than 3 vertices, a repeated vertex, zero area or crosses
/// itself.
Table make_polygon(const std::vector<Vec2>& vertices);

/// Signed clearance of a disk of radius r centred at p: the smallest
/// distance from p to any wall minus r, negative if the disk crosses a
/// wall or if p lies outside the table.
double wall_clearance(const Table& table, Vec2 p, double r);

/// Whether that clearance is at least zero (the disk lies in the table,
/// touching no wall), answered sooner: the first wall closer than r ends
/// the search, and walls whose box is further than r are skipped.
bool disk_fits(const Table& table, Vec2 p, double r);

/// Distance from p to the segment from a to b.
double segment_distance(Vec2 p, Vec2 a, Vec2 b);

/// True if p lies inside the outline (boundary counts as outside).
bool contains(const Table& table, Vec2 p);

}  // namespace breakshot
