// Wall time of the impact examples of seed 000: 4.3 puck between walls (seed loads: 3 x 1e4 N
// along z and 3 x 5e3 N m about y, triangular pulse over 0.1 s; walls at +-1 m; dt = 1e-4,
// t = 0..10 s), mu = 0 and 0.4, Newmark and energy-consistent; 4.4 flying beam (10 elements,
// dt = 1e-3), mu = 0 and the seed's 0.8. Prints CSV to stdout.
//   usage: bench_rolling_impacts [t_end_4.3 (default 10)] [t_end_4.4 (default 20)]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/kernels/rolling/run_options.hpp"  // example 4.4's settings, as test_flying_beam.cpp runs it
#include "kernels/rolling/examples.hpp"

using namespace rollspec::rolling;

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

int main(int argc, char** argv) {
  const double t43 = argc > 1 ? std::atof(argv[1]) : 10.0;
  const double t44 = argc > 2 ? std::atof(argv[2]) : 20.0;
  std::printf("case,variant,dofs,dt,t_end,steps,substeps,newton_iterations,cuts,wall_s,metric,value\n");

  for (const double mu : {0.0, 0.4})
    for (const Integrator integ : {Integrator::Newmark, Integrator::EnergyConsistent}) {
      PuckParams p;
      p.mu = mu;
      p.force_peak = 3e4;
      p.moment_peak = 1.5e4;
      SolverOptions o;
      o.integrator = integ;
      o.force_tol = 1e-6;
      o.max_line_search = 8;
      RunOptions ro;
      ro.dt = 1e-4;
      ro.t_end = t43;
      const double t0 = now();
      const History h = run(puck_model(p), o, ro);
      const double wall = now() - t0;
      const std::vector<Impact> im = find_impacts(h);
      double pen = 0.0, worst = 0.0, bal = 0.0;
      for (const Impact& i : im) {
        pen = std::max(pen, i.max_penetration);
        worst = std::max(worst, std::abs(i.energy_after / i.energy_before - 1.0));
      }
      for (const Energies& e : h.energy) bal = std::max(bal, std::abs(e.balance_error()));
      char hd[160];
      std::snprintf(hd, sizeof hd, "4.3-puck,mu=%.1f %s,6,1e-4,%g,%d,%d,%d,%d,%.3f", mu,
                    integ == Integrator::Newmark ? "newmark" : "energy-consistent", t43, h.steps, h.substeps,
                    h.newton_iterations, h.cuts, wall);
      std::printf("%s,completed,%d\n", hd, h.completed ? 1 : 0);
      std::printf("%s,impacts,%zu\n", hd, im.size());
      std::printf("%s,max_penetration,%.4e\n", hd, pen);
      std::printf("%s,max_rel_energy_change_per_impact,%.3e\n", hd, worst);
      std::printf("%s,final_kinetic,%.3f\n", hd, h.energy.back().kinetic);
      std::printf("%s,external_work,%.3f\n", hd, h.energy.back().external_work);
      std::printf("%s,friction_work,%.3f\n", hd, h.energy.back().friction_work);
      std::printf("%s,max_abs_balance_error,%.3e\n", hd, bal);
    }

  for (const double mu : {0.0, 0.8}) {
    FlyingBeamParams p;
    p.mu = mu;
    const SolverOptions o = test::flying_beam_options();
    const RunOptions ro = test::run_options(1e-3, t44, 10);
    const Model m = flying_beam_model(p);
    const double t0 = now();
    const History h = run(m, o, ro);
    const double wall = now() - t0;
    double kmax = 0.0, bal = 0.0;
    for (const Energies& e : h.energy) {
      kmax = std::max(kmax, e.kinetic);
      bal = std::max(bal, std::abs(e.balance_error()));
    }
    char hd[160];
    std::snprintf(hd, sizeof hd, "4.4-flying-beam,mu=%.1f,%zu,1e-3,%g,%d,%d,%d,%d,%.3f", mu, 6 * m.X.size(), t44,
                  h.steps, h.substeps, h.newton_iterations, h.cuts, wall);
    std::printf("%s,completed,%d\n", hd, h.completed ? 1 : 0);
    std::printf("%s,max_kinetic,%.2f\n", hd, kmax);
    std::printf("%s,max_abs_balance_error,%.3e\n", hd, bal);
    std::printf("%s,friction_work,%.2f\n", hd, h.energy.back().friction_work);
    std::printf("%s,tip_A_final_x,%.2f\n", hd, h.position.back().front().x());
    std::printf("%s,tip_A_final_y,%.2f\n", hd, h.position.back().front().y());
    std::printf("%s,tip_B_final_x,%.2f\n", hd, h.position.back().back().x());
    std::printf("%s,tip_B_final_y,%.2f\n", hd, h.position.back().back().y());
  }
  return 0;
}
