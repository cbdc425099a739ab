// Seed 000 example 4.1 (disc sliding then rolling) and a cylinder on an incline, against
// the rigid-body analytic solutions (seed 000 Eq. 48-50).
#include <doctest/doctest.h>

#include <cmath>

#include "kernels/rolling/examples.hpp"

using namespace rollspec::rolling;

namespace {
SolverOptions disc_options() {
  SolverOptions o;
  o.analysis = Analysis::Dynamic;
  o.force_tol = 1e-4;  // N, forces are O(1e4)
  o.disp_tol = 1e-13;
  return o;
}
double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }
}  // namespace

TEST_CASE("seed 000 example 4.1: disc sliding then rolling (dt = 1e-3, t = 0..6 s)") {
  const DiscParams p;
  RunOptions ro;
  ro.t_end = 6.0;
  ro.dt = 1e-3;
  const History h = run(disc_model(p), disc_options(), ro);
  REQUIRE(h.completed);
  const DiscSummary s = summarize_disc(p, h);
  MESSAGE("t_roll " << s.t_roll << " (exact " << s.t_roll_exact << ", rel " << rel(s.t_roll, s.t_roll_exact) << ")");
  MESSAGE("final speed " << s.final_speed << " (exact " << s.final_speed_exact << ", rel "
                         << rel(s.final_speed, s.final_speed_exact) << "), r*omega " << p.radius * s.final_omega);
  MESSAGE("energy loss " << s.energy_loss << " dissipation " << s.dissipation << " (exact " << s.energy_loss_exact
                         << ", rel " << rel(s.energy_loss, s.energy_loss_exact) << ", "
                         << rel(s.dissipation, s.energy_loss_exact) << ")");
  MESSAGE("penetration " << s.penetration << " (exact " << s.penetration_exact << ", rel "
                         << rel(s.penetration, s.penetration_exact) << ")  newton its " << h.newton_iterations
                         << " cuts " << h.cuts);
  CHECK(s.t_roll_exact == doctest::Approx(3.1330).epsilon(1e-4));
  CHECK(s.final_speed_exact == doctest::Approx(10.039).epsilon(1e-4));
  CHECK(rel(s.t_roll, s.t_roll_exact) < 0.005);
  CHECK(rel(s.final_speed, s.final_speed_exact) < 0.003);
  // the undamped stick spring keeps the elastic stretch it had at the slip limit and
  // oscillates around the rolling state (seed 000 Sec. 4.1 remarks it); its mean rolls exactly
  MESSAGE("mean over the last second: v " << s.mean_speed << ", r w " << s.mean_roll_speed
                                          << "; friction work after t_roll " << s.slip_after_roll);
  CHECK(rel(s.mean_speed, s.final_speed_exact) < 0.003);
  CHECK(rel(s.mean_roll_speed, s.final_speed_exact) < 0.003);
  CHECK(s.slip_after_roll < 1e-4 * s.dissipation);  // sliding has stopped
  CHECK(rel(s.energy_loss, s.energy_loss_exact) < 0.005);
  CHECK(rel(s.dissipation, s.energy_loss_exact) < 0.005);
  MESSAGE("trapezoidal friction work (minus spring storage) " << s.friction_work << ", rel "
                                                              << rel(s.friction_work, s.energy_loss_exact));
  CHECK(rel(s.friction_work, s.energy_loss_exact) < 0.005);
  CHECK(rel(s.penetration, s.penetration_exact) < 0.02);
  // sliding all the way to t_roll (no early sticking), rolling after it
  const std::size_t k_half = static_cast<std::size_t>(std::lround(1.5 / ro.dt));
  CHECK(h.contact[k_half][0].slip);
  // while sliding: a = mu g, angular acceleration 2 mu g / r (seed 000 Eq. 48-49)
  CHECK(rel(h.acceleration[k_half][0].x(), p.mu * p.g) < 1e-6);
  CHECK(rel(h.angular_acceleration[k_half][0].z(), 2 * p.mu * p.g / p.radius) < 1e-6);
}

TEST_CASE("seed 000 example 4.1, no-rolling variant: the disc never rolls") {
  DiscParams p;
  p.rolling = false;
  RunOptions ro;
  ro.t_end = 1.0;
  ro.dt = 1e-3;
  const History h = run(disc_model(p), disc_options(), ro);
  REQUIRE(h.completed);
  // r = 0 in the gap and moment: the spin is not braked, the centre is decelerated by
  // kinetic friction against its own velocity: v = V0 - mu g t until it sticks (t = 0.96 s)
  const double v05 = h.velocity[500][0].x();
  MESSAGE("no rolling: v(0.5) " << v05 << " vs " << p.V0 - p.mu * p.g * 0.5 << ", w(1) "
                                << h.angular_velocity[1000][0].z());
  CHECK(rel(v05, p.V0 - p.mu * p.g * 0.5) < 0.003);
  CHECK(rel(h.angular_velocity[1000][0].z(), -p.omega0) < 1e-9);
}

TEST_CASE("cylinder on an incline: rolls for mu = 1.1 tan(theta)/3, slips for 0.9 tan(theta)/3") {
  for (const double f : {1.1, 0.9}) {
    InclineParams p;
    p.mu = f * std::tan(p.theta) / 3.0;
    RunOptions ro;
    ro.t_end = 1.5;
    ro.dt = 1e-3;
    const History h = run(incline_model(p), disc_options(), ro);
    REQUIRE(h.completed);
    int n_slip = 0, n_stick = 0, n_stick_after_ramp = 0;
    // least-squares slope of v_x(t) on [0.7, 1.5] s (after the 0.5 s gravity ramp)
    double st = 0, sv = 0, stt = 0, stv = 0, n = 0;
    for (std::size_t k = 0; k < h.time.size(); ++k) {
      const ContactOutput& c = h.contact[k][0];
      if (c.active) (c.slip ? n_slip : n_stick) += 1;
      if (h.time[k] > p.t_ramp && !c.slip) ++n_stick_after_ramp;
      if (h.time[k] < 0.7) continue;
      const double t = h.time[k], v = h.velocity[k][0].x();
      st += t;
      sv += v;
      stt += t * t;
      stv += t * v;
      n += 1;
    }
    const double acc = (n * stv - st * sv) / (n * stt - st * st);
    const double g = p.g, th = p.theta;
    MESSAGE("mu/(tan/3) = " << f << ": stick steps " << n_stick << ", slip steps " << n_slip << ", a = " << acc
                            << " (rolling 2/3 g sin = " << 2.0 / 3.0 * g * std::sin(th)
                            << ", sliding g(sin - mu cos) = " << g * (std::sin(th) - p.mu * std::cos(th)) << ")");
    if (f > 1.0) {
      CHECK(n_slip == 0);
      CHECK(rel(acc, 2.0 / 3.0 * g * std::sin(th)) < 0.005);
      // rolling without slip: v = r w
      const std::size_t e = h.time.size() - 1;
      CHECK(rel(-p.radius * h.angular_velocity[e][0].z(), h.velocity[e][0].x()) < 0.003);
    } else {
      CHECK(n_stick_after_ramp == 0);  // slides for the whole full-load window
      CHECK(rel(acc, g * (std::sin(th) - p.mu * std::cos(th))) < 0.005);
    }
  }
}
