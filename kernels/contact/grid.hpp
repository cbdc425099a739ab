#pragma once
// Cell grid shared by every contact routine.
#include <cstddef>

namespace rollspec::contact {

// nx × ny square/rectangular cells of size dx × dy (m). Arrays on the grid are stored
// x-fastest: value of cell (ix, iy) at index iy*nx + ix. Cell (ix, iy) has its centre at
// x = (ix − (nx−1)/2)·dx, y = (iy − (ny−1)/2)·dy (the grid is centred on the origin).
struct Grid {
  std::size_t nx = 0;
  std::size_t ny = 0;
  double dx = 0.0;
  double dy = 0.0;

  std::size_t size() const { return nx * ny; }
  double cell_area() const { return dx * dy; }
  double x(std::size_t ix) const { return (static_cast<double>(ix) - 0.5 * static_cast<double>(nx - 1)) * dx; }
  double y(std::size_t iy) const { return (static_cast<double>(iy) - 0.5 * static_cast<double>(ny - 1)) * dy; }
};

// Throws std::invalid_argument unless nx, ny ≥ 1 and dx, dy > 0 are finite.
void check_grid(const Grid& grid);

}  // namespace rollspec::contact
