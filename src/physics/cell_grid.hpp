// The cell grid (DynamO's neighbour list): with many balls, each ball is
// filed in a uniform grid of square cells at least a ball diameter wide,
// so that it only looks for partners in the 3 x 3 cells around its own.
// Leaving a cell is an event of its own (predict_cell_crossing.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "breakshot/vec.hpp"

namespace breakshot::detail {

// Below this many balls every pair is checked; from it on a grid of cells
// keeps the per-event cost independent of the number of balls.
inline constexpr std::size_t kCellThreshold = 48;

// The neighbouring cell in each direction of a cell crossing: 0 = +x,
// 1 = -x, 2 = +y, 3 = -y.
inline constexpr std::int32_t kStepX[4] = {1, -1, 0, 0};
inline constexpr std::int32_t kStepY[4] = {0, 0, 1, -1};

class CellGrid {
 public:
  // Lays the grid over the table [lo, hi] for n balls whose largest
  // radius is max_radius: cells at least a ball diameter wide (with a
  // margin for round-off), so that two balls in contact are always in
  // neighbouring cells, and about one ball per cell otherwise. Returns
  // false, and stays unused, when the grid would not pay (a very large
  // table with tiny balls would want billions of cells). Balls are then
  // filed with link().
  bool build(Vec2 lo, Vec2 hi, std::size_t n, double max_radius);
  bool used() const { return used_; }
  /// Unused again, keeping the memory for the next build().
  void clear() { used_ = false; }

  double cell_size() const { return cell_size_; }
  Vec2 origin() const { return origin_; }
  std::int32_t nx() const { return nx_; }
  std::int32_t ny() const { return ny_; }

  // The cell holding point p (clamped to the grid).
  std::int32_t index(Vec2 p) const;
  // The cell ball i is filed in.
  std::int32_t cell_of(std::int32_t i) const { return ball_cell_[static_cast<std::size_t>(i)]; }
  // The balls of a cell: first(cell), then next(ball) until -1.
  std::int32_t first(std::int32_t cell) const { return head_[static_cast<std::size_t>(cell)]; }
  std::int32_t next(std::int32_t i) const { return next_[static_cast<std::size_t>(i)]; }

  // Files ball i in a cell; unlink takes it out of its cell.
  void link(std::int32_t i, std::int32_t cell) {
    const auto ui = static_cast<std::size_t>(i);
    const auto uc = static_cast<std::size_t>(cell);
    ball_cell_[ui] = cell;
    prev_[ui] = -1;
    next_[ui] = head_[uc];
    if (head_[uc] >= 0) prev_[static_cast<std::size_t>(head_[uc])] = i;
    head_[uc] = i;
  }
  void unlink(std::int32_t i) {
    const auto ui = static_cast<std::size_t>(i);
    const std::int32_t prev = prev_[ui];
    const std::int32_t next = next_[ui];
    if (prev >= 0) {
      next_[static_cast<std::size_t>(prev)] = next;
    } else {
      head_[static_cast<std::size_t>(ball_cell_[ui])] = next;
    }
    if (next >= 0) prev_[static_cast<std::size_t>(next)] = prev;
    ball_cell_[ui] = -1;
  }

 private:
  bool used_ = false;
  double cell_size_ = 0.0;
  Vec2 origin_;
  std::int32_t nx_ = 1;
  std::int32_t ny_ = 1;
  std::vector<std::int32_t> head_;  // first ball in each cell, or -1
  std::vector<std::int32_t> next_;  // next ball in the same cell
  std::vector<std::int32_t> prev_;
  std::vector<std::int32_t> ball_cell_;
};

}  // namespace breakshot::detail
