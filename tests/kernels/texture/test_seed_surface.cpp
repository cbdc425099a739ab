// Seed line-sum surfaces (D-4; seed 001 Eq. 9-10): oracle, exact sigma, requested correlation lengths.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <random>

#include "kernels/texture/line_texture.hpp"
#include "kernels/texture/seed_surface.hpp"
#include "kernels/texture/self_affine_psd.hpp"
#include "kernels/texture/statistics.hpp"
#include "texture_test_helpers.hpp"

using namespace rollspec::texture;
using texture_test::uniforms;

namespace {
constexpr double kD = 1e-6;
SelfAffinePsd line_psd() {  // fine-grained lines: roll-off at 8 cells, cut off at pi/dx
  return SelfAffinePsd(SelfAffineSpec{0.8, 0.0, 2.0 * M_PI / (8.0 * kD), M_PI / kD, RmsTarget::height, 1e-6});
}
}  // namespace

TEST_CASE("seed surface: summed-area path equals the quadruple sum of Eq. 9 (oracle); sigma exact") {
  const SeedSurfaceSpec spec{20, 14, kD, 2 * kD, 5, 3, 0.4e-6};
  std::mt19937_64 rng(3);
  const auto d = uniforms(rng, (20 + 4) * (14 + 2)), g = uniforms(rng, (20 + 4) * (14 + 2));
  const Surface fast = seed_surface(spec, d, g), slow = seed_surface_direct(spec, d, g);
  for (std::size_t i = 0; i < fast.heights.size(); ++i)
    CHECK(fast.heights[i] == doctest::Approx(slow.heights[i]).epsilon(1e-10));
  const HeightStatistics st = surface_statistics(fast);
  CHECK(std::abs(st.rms / 0.4e-6 - 1.0) <= 1e-12);
  CHECK(std::abs(st.mean) <= 1e-12 * 0.4e-6);
  CHECK_THROWS_WITH_AS(seed_surface(spec, d, std::vector<double>(5)), doctest::Contains("must hold"),
                       std::invalid_argument);
}

TEST_CASE("seed surfaces: requested sigma exactly and requested orthotropic correlation lengths within 10 %") {
  SeedSurfaceRequest rq;
  rq.nx = 256;
  rq.ny = 256;
  rq.dx = kD;
  rq.dy = kD;
  rq.correlation_x = 12.0 * kD;
  rq.correlation_y = 6.0 * kD;
  rq.sigma = 0.3e-6;
  rq.max_box = 64;
  const SeedSurfaceGenerator gen(line_psd().to_psd(), rq);
  MESSAGE("box lengths n = " << gen.box().box_x << ", m = " << gen.box().box_y << "; Eq. 31 expects l_x = "
                             << gen.box().expected.x / kD << ", l_y = " << gen.box().expected.y / kD << " cells");
  std::mt19937_64 rng(31);
  const int count = 20;
  double lx = 0.0, ly = 0.0, worst_sigma = 0.0;
  for (int r = 0; r < count; ++r) {
    Surface s;
    gen.generate(uniforms(rng, gen.random_count()).data(), s);
    const HeightStatistics st = surface_statistics(s);
    worst_sigma = std::max(worst_sigma, std::abs(st.rms / rq.sigma - 1.0));
    lx += st.correlation_length_x / count;
    ly += st.correlation_length_y / count;
  }
  MESSAGE("sigma: worst relative error " << worst_sigma << "; measured l_x = " << lx / kD << ", l_y = " << ly / kD
                                         << " cells (requested 12, 6)");
  CHECK(worst_sigma <= 1e-12);
  CHECK(std::abs(lx / rq.correlation_x - 1.0) <= 0.10);
  CHECK(std::abs(ly / rq.correlation_y - 1.0) <= 0.10);
}

TEST_CASE("Eq. 31 with white lines reduces to the triangle: 1/e at n (1 - 1/e) lags") {
  // White lines: R(0) = 1, R(s) = 0 otherwise. Along x, the d part is a triangle of half-width n
  // (times m) and so is the g part: rho(tau) = 1 - tau / n.
  std::vector<double> r(200, 0.0);
  r[0] = 1.0;
  const SeedCorrelation c = seed_expected_correlation(r, r, 30, 10, 1.0, 1.0);
  CHECK(c.x == doctest::Approx(30.0 * (1.0 - std::exp(-1.0))).epsilon(1e-12));
  CHECK(c.y == doctest::Approx(10.0 * (1.0 - std::exp(-1.0))).epsilon(1e-12));
}
