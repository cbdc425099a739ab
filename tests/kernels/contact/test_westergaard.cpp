// Westergaard: periodic sinusoid, 1D wave extruded on a 2D periodic grid, load control
// (Johnson, Contact Mechanics §13.2; kernels/README.md (contact) analytic checks).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "kernels/contact/contact_solver.hpp"

using namespace rollspec::contact;

namespace {
constexpr double kPi = 3.14159265358979323846;

struct Wave {
  double e_star = 115.4e9, lambda = 64e-6, amplitude = 0.1e-6;
  std::size_t nx = 64, ny = 4;
  double p_star() const { return kPi * e_star * amplitude / lambda; }  // full-contact amplitude
  Grid grid() const { return Grid{nx, ny, lambda / static_cast<double>(nx), lambda / static_cast<double>(nx)}; }
  double x(std::size_t ix) const { return static_cast<double>(ix) * lambda / static_cast<double>(nx); }
  // Rigid flat on the surface h = Δ cos(2πx/λ): gap s = −h, first contact at x = 0.
  std::vector<double> gap() const {
    std::vector<double> s(nx * ny);
    for (std::size_t iy = 0; iy < ny; ++iy)
      for (std::size_t ix = 0; ix < nx; ++ix) s[iy * nx + ix] = -amplitude * std::cos(2 * kPi * x(ix) / lambda);
    return s;
  }
};
}  // namespace

TEST_CASE("Westergaard full contact: p = p_mean + (pi E* Delta / lambda) cos(2 pi x / lambda)") {
  const Wave wave;
  ContactSolver solver(wave.grid(), wave.e_star, Boundary::Periodic);
  std::vector<double> p;
  SolverOptions opt;
  opt.tolerance = 1e-12;
  const double p_mean = 2.0 * wave.p_star();
  const ContactResult r = solver.solve_load(wave.gap(), p_mean, p, opt);
  REQUIRE(r.converged);
  double err = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double exact = p_mean + wave.p_star() * std::cos(2 * kPi * wave.x(i % wave.nx) / wave.lambda);
    err = std::max(err, std::fabs(p[i] - exact));
  }
  const double peak_err = r.max_pressure / (p_mean + wave.p_star()) - 1.0;
  MESSAGE("Westergaard full contact: peak rel err " << peak_err << ", max |p - exact| / p* " << err / wave.p_star()
                                                    << ", iterations " << r.iterations);
  CHECK(std::fabs(peak_err) < 3e-4);
  CHECK(err / wave.p_star() < 3e-4);
  CHECK(r.contact_cells == p.size());
}

namespace {
// Partial contact: returns the relative peak-pressure error; checks the contact width.
double partial_contact_peak_error(std::size_t points_per_wavelength, double ratio) {
  Wave wave;
  wave.nx = points_per_wavelength;
  ContactSolver solver(wave.grid(), wave.e_star, Boundary::Periodic);
  SolverOptions opt;
  opt.tolerance = 1e-12;
  {
    std::vector<double> p;
    const double p_mean = ratio * wave.p_star();
    const ContactResult r = solver.solve_load(wave.gap(), p_mean, p, opt);
    REQUIRE(r.converged);
    // Contact half-width a: sin²(πa/λ) = p_mean/p*; p(0) = 2 p_mean / sin(πa/λ).
    const double peak = 2.0 * std::sqrt(p_mean * wave.p_star());
    const double peak_err = r.max_pressure / peak - 1.0;
    const double half_width = wave.lambda / kPi * std::asin(std::sqrt(ratio));
    const double width_num = r.contact_area / (static_cast<double>(wave.ny) * wave.grid().dy);
    MESSAGE("Westergaard " << points_per_wavelength << " points/wavelength, p_mean/p* = " << ratio << ": peak rel err "
                           << peak_err << ", contact width " << width_num / (2 * half_width) - 1.0
                           << " rel, iterations " << r.iterations);
    // The contact set is resolved to one point at each edge.
    CHECK(std::fabs(width_num - 2 * half_width) <= 2 * wave.grid().dx);
    return peak_err;
  }
}
}  // namespace

TEST_CASE("Westergaard partial contact: peak 2 sqrt(p_mean p*)") {
  // Half the wavelength in contact, 64 points per wavelength.
  CHECK(std::fabs(partial_contact_peak_error(64, 0.5)) < 3e-4);
  // Narrower contact (0.30 λ): the error is larger at 64 points (measured 3.9e-4) and falls with
  // refinement; 3e-4 is met from 128 points per wavelength.
  const double e64 = partial_contact_peak_error(64, 0.2), e128 = partial_contact_peak_error(128, 0.2);
  CHECK(std::fabs(e128) < std::fabs(e64));
  CHECK(std::fabs(e128) < 3e-4);
}

TEST_CASE("periodic boundary refuses displacement control") {
  const Wave wave;
  ContactSolver solver(wave.grid(), wave.e_star, Boundary::Periodic);
  std::vector<double> p;
  CHECK_THROWS_AS(solver.solve(wave.gap(), 1e-7, p), std::invalid_argument);
  SolverOptions capped;
  capped.hardness = 1e9;
  CHECK_THROWS_AS(solver.solve_load(wave.gap(), 1e6, p, capped), std::invalid_argument);
}
