// Several planes and impact step control (README R-54): an oblique puck hits all four walls;
// the step limit near contact and the penetration cut are counted and bound what they promise;
// the energy terms of the multi-plane run are all reported per step.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "kernels/rolling/examples.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;

TEST_CASE("puck on an oblique path hits all four walls; step limit and penetration cut") {
  PuckParams p;
  p.half_width = 0.5;
  p.v0 = Vector3d(2.0, 0.0, 1.3);
  p.omega0 = 2.0;
  const double Tc = 2.0 * 3.141592653589793 * std::sqrt(p.mass / p.eps_n);
  RunOptions ro;
  ro.dt = 1e-3;
  ro.t_end = 1.5;

  SolverOptions plain;
  plain.force_tol = 1e-7;
  const History h0 = run(puck_model(p), plain, ro);
  REQUIRE(h0.completed);
  const std::vector<Impact> i0 = find_impacts(h0);
  std::set<int> walls;
  for (const Impact& im : i0) walls.insert(im.pair);
  CHECK(walls.size() == 4);  // floor-plane free run: x walls and z walls all detected
  CHECK(h0.substeps == h0.steps);
  CHECK(h0.limited_steps == 0);
  double worst0 = 0.0;
  for (const Impact& im : i0) worst0 = std::max(worst0, std::abs(im.energy_after / im.energy_before - 1.0));

  // step limit: dt <= T_c / 200 while a contact is closed or closing
  SolverOptions lim = plain;
  lim.impact_step_fraction = 1.0 / 200.0;
  const History h1 = run(puck_model(p), lim, ro);
  REQUIRE(h1.completed);
  const std::vector<Impact> i1 = find_impacts(h1);
  CHECK(i1.size() == i0.size());
  double worst1 = 0.0;
  for (const Impact& im : i1) worst1 = std::max(worst1, std::abs(im.energy_after / im.energy_before - 1.0));
  std::printf(
      "step limit T_c/200 = %.3e: substeps %d (output steps %d), limited %d; max |dE|/E per impact %.3e "
      "(no limit: %.3e, %zu impacts)\n",
      Tc / 200.0, h1.substeps, h1.steps, h1.limited_steps, worst1, worst0, i1.size());
  CHECK(h1.limited_steps > 0);
  CHECK(h1.substeps > h1.steps);
  CHECK(worst1 < 0.25 * worst0);

  // penetration cut: a new contact may not open deeper than 2e-4 m
  SolverOptions cut = plain;
  cut.max_new_penetration = 2e-4;
  cut.max_cuts = 12;
  Solver S(puck_model(p), cut);
  int pen_cuts = 0, substeps = 0;
  double worst_new = 0.0;
  for (int k = 1; k <= 1500; ++k) {
    const StepReport rep = S.advance(k * 1e-3);
    REQUIRE(rep.converged);
    pen_cuts += rep.penetration_cuts;
    substeps += rep.steps;
    worst_new = std::max(worst_new, rep.new_penetration);
    // energy terms of the multi-plane run, every step
    const Energies e = S.energies();
    CHECK(std::abs(e.kinetic - e.kinetic_translation - e.kinetic_rotation) <= 1e-12 * e.kinetic);
    const Vector3d w = S.nodes()[0].R * S.nodes()[0].W;
    CHECK(std::abs(e.kinetic_rotation - 0.5 * puck_axial_inertia(p) * w.y() * w.y()) <= 1e-9 * e.kinetic);
    double pen = 0.0;
    for (const ContactOutput& o : S.contacts()) pen += o.penalty;
    CHECK(std::abs(pen - e.penalty) <= 1e-12 * e.kinetic);
    CHECK(e.friction_work == 0.0);
    CHECK(e.external_work == 0.0);
  }
  std::printf("penetration cut 2e-4: %d cuts, %d sub-steps, deepest new contact %.3e m (no control: %.3e)\n", pen_cuts,
              substeps, worst_new, h0.new_penetration);
  CHECK(pen_cuts > 0);
  CHECK(worst_new <= 2e-4);
}
