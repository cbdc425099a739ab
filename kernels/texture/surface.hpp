#pragma once
// A height map z(x, y) on a regular grid: heights[iy * nx + ix] = z(ix dx, iy dy), metres.
// Row-major with x fastest, the layout of /surface/heights (count x ny x nx).
#include <cstddef>
#include <vector>

namespace rollspec::texture {

struct Surface {
  std::size_t nx = 0, ny = 0;
  double dx = 0.0, dy = 0.0;  // m
  std::vector<double> heights;

  Surface() = default;
  Surface(std::size_t nx_, std::size_t ny_, double dx_, double dy_)
      : nx(nx_), ny(ny_), dx(dx_), dy(dy_), heights(nx_ * ny_, 0.0) {}
  double& at(std::size_t ix, std::size_t iy) { return heights[iy * nx + ix]; }
  double at(std::size_t ix, std::size_t iy) const { return heights[iy * nx + ix]; }
};

}  // namespace rollspec::texture
