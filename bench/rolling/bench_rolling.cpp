// Wall time of seed 000 example 4.1 (disc, dt = 1e-3 to t = 6 s) and example 4.2
// (cantilever, quasi-static, 100 quadratic elements, load step 0.005 to t = 4), rolling and
// "no rolling". Prints CSV to stdout.
//   usage: bench_rolling [n_elements_4.2 (default 100)] [repeats_4.1 (default 5)] [dt_4.2 (default 0.005)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "kernels/rolling/examples.hpp"

using namespace rollspec::rolling;

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

int main(int argc, char** argv) {
  const int n_el = argc > 1 ? std::atoi(argv[1]) : 100;
  const int reps = argc > 2 ? std::atoi(argv[2]) : 5;
  const double dt42 = argc > 3 ? std::atof(argv[3]) : 0.005;
  std::printf("case,variant,elements,dt,t_end,steps,newton_iterations,cuts,wall_s,metric,value,reference\n");

  // ---- example 4.1 ----
  const DiscParams p;
  SolverOptions o;
  o.force_tol = 1e-4;
  o.disp_tol = 1e-13;
  RunOptions ro;
  ro.t_end = 6.0;
  ro.dt = 1e-3;
  double best = 1e300;
  History h;
  for (int r = 0; r < reps; ++r) {
    const double t0 = now();
    h = run(disc_model(p), o, ro);
    best = std::min(best, now() - t0);
  }
  const DiscSummary s = summarize_disc(p, h);
  const char* head = "4.1-disc,rolling,1,0.001,6";
  std::printf("%s,%d,%d,%d,%.4f,t_roll,%.5f,%.5f\n", head, h.steps, h.newton_iterations, h.cuts, best, s.t_roll,
              s.t_roll_exact);
  std::printf("%s,%d,%d,%d,%.4f,final_speed,%.5f,%.5f\n", head, h.steps, h.newton_iterations, h.cuts, best,
              s.final_speed, s.final_speed_exact);
  std::printf("%s,%d,%d,%d,%.4f,energy_loss,%.2f,%.2f\n", head, h.steps, h.newton_iterations, h.cuts, best,
              s.energy_loss, s.energy_loss_exact);
  std::printf("%s,%d,%d,%d,%.4f,friction_work,%.2f,%.2f\n", head, h.steps, h.newton_iterations, h.cuts, best,
              s.friction_work, s.energy_loss_exact);

  // ---- example 4.2 ----
  for (const bool rolling : {true, false}) {
    CantileverParams c;
    c.n_elements = n_el;
    c.rolling = rolling;
    const double t0 = now();
    const CantileverRun r = run_cantilever(c, 4.0, dt42, {2.0, 4.0});
    const double wall = now() - t0;
    const std::string hd = std::string("4.2-cantilever,") + (rolling ? "rolling" : "no-rolling") + "," +
                           std::to_string(n_el) + "," + std::to_string(dt42) + ",4";
    std::printf("%s,%d,%d,%d,%.3f,completed,%d,1\n", hd.c_str(), r.steps, r.newton_iterations, r.cuts, wall,
                r.completed ? 1 : 0);
    for (const CantileverSnapshot& sn : r.snapshots) {
      std::printf("%s,%d,%d,%d,%.3f,reaction_y_t%.0f,%.1f,\n", hd.c_str(), r.steps, r.newton_iterations, r.cuts, wall,
                  sn.time, sn.reaction_y);
      std::printf("%s,%d,%d,%d,%.3f,max_torsion_t%.0f,%.2f,\n", hd.c_str(), r.steps, r.newton_iterations, r.cuts, wall,
                  sn.time, sn.max_abs_torsion);
      std::printf("%s,%d,%d,%d,%.3f,tip_x_t%.0f,%.5f,\n", hd.c_str(), r.steps, r.newton_iterations, r.cuts, wall,
                  sn.time, sn.tip.x());
    }
    std::printf("%s,%d,%d,%d,%.3f,friction_dissipation,%.1f,\n", hd.c_str(), r.steps, r.newton_iterations, r.cuts, wall,
                r.friction_dissipation);
    std::printf("%s,%d,%d,%d,%.3f,friction_work,%.1f,\n", hd.c_str(), r.steps, r.newton_iterations, r.cuts, wall,
                r.friction_work);
  }
  return 0;
}
