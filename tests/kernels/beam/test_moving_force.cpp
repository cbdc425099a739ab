// Moving constant force on a simply supported beam against Frýba's closed form (README B29–B30).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "kernels/beam/modal_beam.hpp"
#include "kernels/beam/moving_force.hpp"

using namespace rollspec::beam;

TEST_CASE("moving constant force on a simply supported beam matches Frýba's closed form") {
  BeamProperties p;
  p.support = Support::simply_supported;
  p.length = 0.4;
  const int modes = 30;
  const ModalBeam beam(p, {modes, 0.0}, {});  // undamped, as Frýba's series
  const double pi = 3.14159265358979323846, load = 100.0;
  const double l = p.length, ei = beam.bending_stiffness(), mu = beam.mass_per_length();
  for (double alpha : {0.1, 0.5, 1.3}) {  // speed parameter alpha = pi v / (l omega_1)
    const double v = alpha * beam.omega(0) * l / pi;
    const double dt = 2e-7;
    const long steps = static_cast<long>(std::floor(l / v / dt));
    const std::vector<double> force(static_cast<std::size_t>(steps + 1), load);
    const std::vector<double> xs = {0.25 * l, 0.5 * l, 0.8 * l};
    const auto w = moving_force_deflection(beam, 0.0, v, force, dt, xs);
    double worst = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i)
      for (long k = 0; k <= steps; k += 7) {
        const double ref = -fryba_moving_force(l, ei, mu, load, v, xs[i], static_cast<double>(k) * dt, modes);
        worst = std::max(worst, std::abs(w[i][k] - ref));
        peak = std::max(peak, std::abs(ref));
      }
    MESSAGE("alpha " << alpha << ": max |w - w_Fryba| / max |w_Fryba| = " << worst / peak
                     << ", peak midspan / static P l^3/(48 EI) = " << peak / (load * l * l * l / (48.0 * ei)));
    CHECK(worst <= 1e-6 * peak);
  }
  // A wrong modal mass or a wrong sign is caught: the dynamic peak differs from the static one.
  const double v = 0.5 * beam.omega(0) * l / pi;
  CHECK(std::abs(fryba_moving_force(l, ei, mu, load, v, 0.5 * l, 0.5 * l / v, 60) / (load * l * l * l / (48.0 * ei)) -
                 1.0) > 0.05);
}
