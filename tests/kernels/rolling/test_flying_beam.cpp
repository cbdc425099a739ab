// Seed 000 example 4.4 (flying beam, README R-56): a 10-element beam lying on the floor
// z = 0 is driven sideways by F_y at its centre into the wall x + y = 1000 (normal
// (-1, -1, 0)/sqrt 2); 42 contact pairs on two planes. Without friction the discrete energy
// balance must hold through the wall impact up to the penalty kinks.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "kernels/rolling/examples.hpp"
#include "run_options.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;
using rollspec::rolling::test::flying_beam_options;
using rollspec::rolling::test::run_options;

TEST_CASE("seed 000 example 4.4 without friction: beam hits the wall, energy balance" * doctest::test_suite("long")) {
  FlyingBeamParams p;
  p.mu = 0.0;
  const Model m = flying_beam_model(p);
  CHECK(m.planes.size() == 2);
  CHECK(m.contacts.size() == 42);
  const History h = run(m, flying_beam_options(), run_options(1e-3, 2.5));
  REQUIRE(h.completed);
  double kmax = 0.0, err = 0.0, zdev = 0.0, t_wall = -1.0, fwall = 0.0;
  for (std::size_t k = 0; k < h.time.size(); ++k) {
    const Energies& e = h.energy[k];
    kmax = std::max(kmax, e.kinetic);
    err = std::max(err, std::abs(e.balance_error()));
    for (std::size_t c = 0; c < 21; ++c) zdev = std::max(zdev, std::abs(h.position[k][c].z() - p.radius));
    for (std::size_t c = 21; c < 42; ++c)
      if (h.contact[k][c].active) {
        if (t_wall < 0.0) t_wall = h.time[k];
        fwall = std::max(fwall, h.contact[k][c].force.norm());
      }
  }
  const Energies& last = h.energy.back();
  std::printf(
      "flying beam mu = 0, dt = 1e-3, 2.5 s: wall hit at t = %.3f (max wall force %.1f N); max |balance error| "
      "%.3e J of max kinetic %.4e J (%.2e); final T %.1f U %.1f, W_ext %.1f; max |z - r| %.3e; steps %d, its %d\n",
      t_wall, fwall, err, kmax, err / kmax, last.kinetic, last.strain, last.external_work, zdev, h.steps,
      h.newton_iterations);
  CHECK(t_wall > 1.0);
  CHECK(fwall > 0.0);
  CHECK(err <= 1e-4 * kmax);
  CHECK(last.friction_work == 0.0);
  // frictionless floor: the beam stays on it (penetration of the static weight 6.4e-4 m)
  CHECK(zdev < 0.01 * p.radius);
}
