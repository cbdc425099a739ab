#include "kernels/contact/direct_product.hpp"

#include <stdexcept>

#include "kernels/contact/love_influence.hpp"

namespace rollspec::contact {

std::vector<double> direct_product(const Grid& grid, double e_star, const std::vector<double>& p) {
  check_grid(grid);
  if (p.size() != grid.size()) throw std::invalid_argument("direct_product: pressure size != grid size");
  std::vector<double> u(grid.size(), 0.0);
  for (std::size_t iy = 0; iy < grid.ny; ++iy)
    for (std::size_t ix = 0; ix < grid.nx; ++ix) {
      double sum = 0.0;
      for (std::size_t ky = 0; ky < grid.ny; ++ky)
        for (std::size_t kx = 0; kx < grid.nx; ++kx)
          sum += love_displacement(grid.x(ix) - grid.x(kx), grid.y(iy) - grid.y(ky), 0.5 * grid.dx, 0.5 * grid.dy,
                                   e_star) *
                 p[ky * grid.nx + kx];
      u[iy * grid.nx + ix] = sum;
    }
  return u;
}

}  // namespace rollspec::contact
