// Tables: the walls a ball can meet.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "breakshot/vec.hpp"

namespace breakshot {

/// The kinds of wall piece. Straight segments and the corners of a
/// polygon that point into the table exist now; round jaws and pocket
/// edges of the pool tables will be further kinds.
enum class WallKind : std::uint8_t {
  segment,  ///< straight wall from a to b; `normal` points into the table
  corner,   ///< a point (a reflex vertex) that a ball can hit
};

struct Wall {
  WallKind kind = WallKind::segment;
  Vec2 a;       ///< segment start, or the corner point
  Vec2 b;       ///< segment end (unused for a corner)
  Vec2 normal;  ///< unit normal into the table (segment only)
  std::string name;  ///< stable name used in events ("left", "edge3", ...)
};

/// A table: its outline (for drawing and containment) and its walls.
struct Table {
  std::string shape;          ///< "rectangle" or "polygon"
  std::vector<Vec2> outline;  ///< counter-clockwise boundary
  std::vector<Wall> walls;
  Vec2 min;  ///< bounding box
  Vec2 max;
};

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

/// Distance from p to the segment from a to b.
double segment_distance(Vec2 p, Vec2 a, Vec2 b);

/// True if p lies inside the outline (boundary counts as outside).
bool contains(const Table& table, Vec2 p);

}  // namespace breakshot
