// The cell grid: its layout, and the cell of a point.
#include "physics/cell_grid.hpp"

#include <algorithm>
#include <cmath>

#include "physics/large_pages.hpp"

namespace breakshot::detail {

bool CellGrid::build(Vec2 lo, Vec2 hi, std::size_t n, double max_radius) {
  const Vec2 size = hi - lo;
  const double per_ball = std::sqrt(size.x * size.y / static_cast<double>(n));
  cell_size_ = std::max(2.0 * max_radius * 1.01, per_ball);
  const double nx = std::ceil(size.x / cell_size_);
  const double ny = std::ceil(size.y / cell_size_);
  // A very large table with tiny balls would want billions of cells;
  // then cells would not pay off and we check every pair.
  if (!(nx * ny <= 16.0 * static_cast<double>(n) + 64.0)) return false;
  used_ = true;
  origin_ = lo;
  nx_ = std::max<std::int32_t>(1, static_cast<std::int32_t>(nx));
  ny_ = std::max<std::int32_t>(1, static_cast<std::int32_t>(ny));
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  reserve_large(head_, cells);
  reserve_large(next_, n);
  reserve_large(prev_, n);
  reserve_large(ball_cell_, n);
  head_.assign(cells, -1);
  next_.assign(n, -1);
  prev_.assign(n, -1);
  ball_cell_.assign(n, -1);
  return true;
}

std::int32_t CellGrid::index(Vec2 p) const {
  auto clamp_axis = [&](double v, double o, std::int32_t count) {
    const double k = std::floor((v - o) / cell_size_);
    if (!(k >= 0.0)) return 0;
    if (k >= static_cast<double>(count - 1)) return count - 1;
    return static_cast<std::int32_t>(k);
  };
  return clamp_axis(p.y, origin_.y, ny_) * nx_ + clamp_axis(p.x, origin_.x, nx_);
}

}  // namespace breakshot::detail
