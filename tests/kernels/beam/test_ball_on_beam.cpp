// Ball-on-beam integrators: static equilibrium with residual flexibility, design order of the
// exact-step integrator, agreement with the Dormand–Prince reference (README B20–B28).
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "ball_on_beam_fixture.hpp"
#include "kernels/beam/dopri5_reference.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/beam/quadratic_hold_step.hpp"

using namespace rollspec::beam;

namespace {

// max over sensors and samples of |a - a_ref|, relative to max |a_ref|.
double relative_error(const BallOnBeamResult& a, const BallOnBeamResult& ref) {
  double e = 0.0, peak = 0.0;
  for (std::size_t s = 0; s < ref.sensor_acceleration.size(); ++s)
    for (std::size_t j = 0; j < ref.samples(); ++j) {
      e = std::max(e, std::abs(a.sensor_acceleration[s][j] - ref.sensor_acceleration[s][j]));
      peak = std::max(peak, std::abs(ref.sensor_acceleration[s][j]));
    }
  return e / peak;
}

double force_error(const BallOnBeamResult& a, const BallOnBeamResult& ref) {
  double e = 0.0, peak = 0.0;
  for (std::size_t j = 0; j < ref.samples(); ++j) {
    e = std::max(e, std::abs(a.contact_force[j] - ref.contact_force[j]));
    peak = std::max(peak, std::abs(ref.contact_force[j]));
  }
  return e / peak;
}

// The observed order of `run(s)` (a run at s substeps per sample of `sample_rate`) against ref as s doubles
// through `substeps`: each within 10 % of `order`.
template <class Run>
void check_order(const BallOnBeamResult& ref, const std::vector<int>& substeps, double sample_rate, double order,
                 const std::string& label, Run&& run) {
  std::vector<double> err;
  for (int s : substeps) {
    err.push_back(relative_error(run(s), ref));
    MESSAGE(label << "dt = " << 1.0 / (sample_rate * s) << " s: max rel. acceleration error " << err.back());
  }
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double slope = std::log2(err[i - 1] / err[i]);
    MESSAGE("observed order " << slope);
    CHECK(slope == doctest::Approx(order).epsilon(0.1));
  }
}

}  // namespace

TEST_CASE("static deflection under the ball: 16 modes + static correction within 0.05 % of P a^3 b^3 / (3 EI L^3)") {
  for (bool correction : {true, false}) {
    BeamProperties p;
    p.length = 0.4;  // clamped–clamped, no effective-length extension: the closed form applies directly
    for (double a_over_l : {0.1, 0.3, 0.5}) {
      BallOnBeamModel m{
          ModalBeam(p, {16, 0.0}, {0.02, {}}, correction), Ball{}, ContactLaw{}, Traverse{}, 20000.0, {0.2}};
      m.traverse = {a_over_l * p.length, a_over_l * p.length, 0.0, 0.01};  // at rest for 10 ms
      const ExactStepIntegrator integ(m, 2);
      const BallOnBeamResult r = integ.run(Realisation{});
      const double a = a_over_l * p.length, b = p.length - a, load = m.ball.mass * m.ball.gravity;
      const double exact =
          -load * a * a * a * b * b * b / (3.0 * m.beam.bending_stiffness() * p.length * p.length * p.length);
      double worst = 0.0;
      for (std::size_t j = 0; j < r.samples(); ++j) {
        worst = std::max(worst, std::abs(r.contact_deflection[j] / exact - 1.0));
        CHECK(r.contact_force[j] == doctest::Approx(load).epsilon(1e-9));
      }
      MESSAGE(std::string(correction ? "with" : "without")
              << " correction, a = " << a_over_l << " l: max rel. error " << worst);
      if (correction) CHECK(worst <= 5e-4);
      if (!correction && a_over_l == 0.1) CHECK(worst > 5e-4);  // shown not met without the correction
    }
  }
}

TEST_CASE("exact-step integrator converges at second order (Hertz, smooth roughness, no loss of contact)") {
  const BallOnBeamModel m = test::hertz_model(12, 0.02, 0.07, 10000.0);
  Realisation r;
  r.roughness = test::sine_roughness(0.39, 2e-5, {3e-8, 2e-8, 1e-8}, {4e-3, 1.3e-3, 0.7e-3});
  const BallOnBeamResult ref = ExactStepIntegrator(m, 512).run(r);
  CHECK(ref.loss_of_contact_share == 0.0);
  // 1.8 .. 2.2
  check_order(ref, {2, 4, 8, 16, 32}, 10000.0, 2.0, "", [&](int s) { return ExactStepIntegrator(m, s).run(r); });
}

TEST_CASE("exact-step integrator agrees with Dormand–Prince 5(4) on a nonlinear Hertz case") {
  BallOnBeamModel m = test::hertz_model(12, 0.02, 0.06, 20000.0);
  m.contact.rate = DampingRate::total;
  Realisation r;
  // Rough enough to stay strongly nonlinear: the compression swings by about half its static value.
  r.roughness = test::sine_roughness(0.39, 1e-5, {8e-8, 4e-8, 2e-8}, {3e-3, 1.1e-3, 0.5e-3});
  ReferenceTolerances tol;
  tol.rtol = 1e-11;
  tol.atol_displacement = 1e-17;
  const auto t0 = std::chrono::steady_clock::now();
  const BallOnBeamResult ref = simulate_dopri5(m, r, tol);
  const auto t1 = std::chrono::steady_clock::now();
  const BallOnBeamResult fast = ExactStepIntegrator(m, 64).run(r);  // dt = 0.78 us
  const auto t2 = std::chrono::steady_clock::now();
  double dmin = 1e9, dmax = -1e9;
  for (double d : ref.compression) dmin = std::min(dmin, d), dmax = std::max(dmax, d);
  const double ea = relative_error(fast, ref), ef = force_error(fast, ref);
  MESSAGE("compression range " << dmin << " .. " << dmax << " m; DOPRI5 steps " << ref.steps << " (+"
                               << ref.rejected_steps << " rejected), " << std::chrono::duration<double>(t1 - t0).count()
                               << " s; exact-step " << fast.steps << " steps, "
                               << std::chrono::duration<double>(t2 - t1).count() << " s");
  MESSAGE("max rel. acceleration error " << ea << ", max rel. force error " << ef);
  CHECK(dmax > 1.3 * dmin);
  CHECK(ea <= 1e-4);
  CHECK(ef <= 1e-4);
  // and it keeps converging to the reference (second order) at dt = 0.195 us
  const BallOnBeamResult finer = ExactStepIntegrator(m, 256).run(r);
  MESSAGE("256 substeps: max rel. acceleration error " << relative_error(finer, ref));
  CHECK(relative_error(finer, ref) <= 1e-5);
}

TEST_CASE("exact-step agrees with DOPRI5 for every contact law, and through loss of contact") {
  ReferenceTolerances tol;
  tol.rtol = 1e-11;
  tol.atol_displacement = 1e-17;
  Realisation r;
  r.roughness = test::sine_roughness(0.39, 1e-5, {6e-8, 3e-8}, {3e-3, 0.9e-3});
  // table and literal laws sampled from Hertz; the linearised law with a sinusoidal blocked force
  const ContactModel hertz(ContactLaw{});
  ContactLaw table, literal, lin;
  table.kind = ContactLawKind::table;
  literal.kind = ContactLawKind::literal_stiffness;
  for (int i = 0; i <= 60; ++i) {
    const double d = 1.5e-6 * i / 60.0;
    double p, k;
    hertz.elastic(d, p, k);
    table.compression.push_back(d), table.values.push_back(p);
    literal.compression.push_back(d), literal.values.push_back(k);
  }
  lin.kind = ContactLawKind::linearised;
  lin.k0 = 6.8e6;
  Realisation rl;
  rl.blocked_force.step = 1e-5;
  for (int i = 0; i <= 5000; ++i)
    rl.blocked_force.values.push_back(2.58 + 0.3 * std::sin(6.283185307179586 * 1700.0 * 1e-5 * i) +
                                      0.2 * std::sin(0.9 * i));
  const char* names[] = {"table", "literal", "linearised"};
  const ContactLaw* laws[] = {&table, &literal, &lin};
  for (int i = 0; i < 3; ++i) {
    BallOnBeamModel m = test::hertz_model(10, 0.1, 0.13, 20000.0);
    m.contact = *laws[i];
    m.contact.damping = 100.0;
    const Realisation& rr = i == 2 ? rl : r;
    const BallOnBeamResult ref = simulate_dopri5(m, rr, tol);
    const double e = relative_error(ExactStepIntegrator(m, 64).run(rr), ref);
    MESSAGE(std::string(names[i]) << " law: max rel. acceleration error vs DOPRI5 (dt = 0.78 us) " << e);
    CHECK(e <= 1e-4);
  }
  // Loss of contact (rough beam, damping-only law): the kinks cost accuracy, but both agree.
  BallOnBeamModel m = test::hertz_model(10, 0.1, 0.12, 20000.0);
  Realisation rough;
  rough.roughness = test::sine_roughness(0.39, 1e-5, {6e-7, 2e-7}, {2e-3, 0.7e-3});
  const BallOnBeamResult ref = simulate_dopri5(m, rough, tol);
  const BallOnBeamResult fast = ExactStepIntegrator(m, 64).run(rough);
  const double e = relative_error(fast, ref);
  MESSAGE("loss of contact: share " << fast.loss_of_contact_share << " (reference, by samples "
                                    << ref.loss_of_contact_share << "), max rel. acceleration error " << e);
  ExactStepOptions o;
  o.hold = ForceHold::quadratic;
  o.substeps = 64;
  const double eq = relative_error(ExactStepIntegrator(m, o).run(rough), ref);
  MESSAGE("loss of contact, quadratic hold: max rel. acceleration error " << eq);
  CHECK(eq <= 1e-2);
  CHECK(fast.loss_of_contact_share > 0.1);
  CHECK(std::abs(fast.loss_of_contact_share - ref.loss_of_contact_share) < 0.02);
  CHECK(e <= 1e-2);
}

TEST_CASE("quadratic force hold: equals the linear hold on a line, converges at third order") {
  // Collinear values: the parabola is the line, so both propagators agree.
  for (double w : {0.0, 300.0, 2.0e4}) {
    const auto l = rollspec::integrators::ExactOscillatorStep::make(w, 0.03, 1e-5);
    const auto q = QuadraticHoldStep::make(w, 0.03, 1e-5);
    const double fm = 0.3, f0 = 0.5, f1 = 0.7;  // on a line
    CHECK(q.bm * fm + q.b0 * f0 + q.b1 * f1 == doctest::Approx(l.b0 * f0 + l.b1 * f1).epsilon(1e-9));
    CHECK(q.cm * fm + q.c0 * f0 + q.c1 * f1 == doctest::Approx(l.c0 * f0 + l.c1 * f1).epsilon(1e-9));
    CHECK(q.a01 == doctest::Approx(l.a01).epsilon(1e-12));
  }
  const BallOnBeamModel m = test::hertz_model(12, 0.02, 0.07, 10000.0);
  Realisation r;
  r.roughness = test::sine_roughness(0.39, 2e-5, {3e-8, 2e-8, 1e-8}, {4e-3, 1.3e-3, 0.7e-3});
  ExactStepOptions o;
  o.hold = ForceHold::quadratic;
  o.substeps = 256;
  const BallOnBeamResult ref = ExactStepIntegrator(m, o).run(r);
  CHECK(relative_error(ExactStepIntegrator(m, 512).run(r), ref) < 1e-5);  // both holds converge to one answer
  // 2.7 .. 3.3
  check_order(ref, {2, 4, 8, 16}, 10000.0, 3.0, "quadratic hold, ", [&](int s) {
    o.substeps = s;
    return ExactStepIntegrator(m, o).run(r);
  });
}

TEST_CASE("exact-step run() (reordered step, B26a) agrees with run_reference() to rounding for every option") {
  // Shared by every case: 10 modes (padded to 12 lanes), a smooth two-wavelength roughness.
  Realisation r;
  r.roughness = test::sine_roughness(0.39, 1e-5, {6e-8, 3e-8}, {3e-3, 0.9e-3});
  Realisation rl;  // linearised law: a blocked force instead of the roughness
  rl.blocked_force.step = 1e-5;
  for (int i = 0; i <= 5000; ++i)
    rl.blocked_force.values.push_back(2.58 + 0.3 * std::sin(6.283185307179586 * 1700.0 * 1e-5 * i) +
                                      0.2 * std::sin(0.9 * i));
  struct Case {
    const char* name;
    ForceHold hold;
    bool table, total_rate, linearised, patch;
  };
  const Case cases[] = {
      {"linear hold", ForceHold::linear, true, false, false, false},
      {"quadratic hold", ForceHold::quadratic, true, false, false, false},
      {"quadratic hold, shapes on the fly", ForceHold::quadratic, false, false, false, false},
      {"total damper rate", ForceHold::quadratic, true, true, false, false},
      {"total damper rate, shapes on the fly", ForceHold::linear, false, true, false, false},
      {"linearised law", ForceHold::quadratic, true, false, true, false},
      {"contact patch (B38)", ForceHold::quadratic, true, false, false, true},
  };
  for (const Case& c : cases) {
    BallOnBeamModel m = test::hertz_model(10, 0.1, 0.13, 20000.0);
    if (c.total_rate) m.contact.rate = DampingRate::total;
    if (c.linearised) {
      m.contact.kind = ContactLawKind::linearised;
      m.contact.k0 = 6.8e6;
    }
    if (c.patch) m.patch_radius = 0.02;
    ExactStepOptions o;
    o.hold = c.hold;
    o.substeps = 4;
    if (!c.table) o.max_table_entries = 0;
    const ExactStepIntegrator integ(m, o);
    const Realisation& rr = c.linearised ? rl : r;
    BallOnBeamResult ref, fast;
    integ.run_reference(rr, ref);
    integ.run(rr, fast);
    const double e = relative_error(fast, ref), ef = force_error(fast, ref);
    MESSAGE(std::string(c.name) << ": max rel. difference run() vs run_reference(), acceleration " << e << ", force "
                                << ef);
    CHECK(e < 1e-10);
    CHECK(ef < 1e-12);
    CHECK(fast.loss_of_contact_share == ref.loss_of_contact_share);
  }
  // Through loss of contact the two still agree (the kinks do not amplify rounding).
  BallOnBeamModel m = test::hertz_model(10, 0.1, 0.12, 20000.0);
  Realisation rough;
  rough.roughness = test::sine_roughness(0.39, 1e-5, {6e-7, 2e-7}, {2e-3, 0.7e-3});
  ExactStepOptions o;
  o.hold = ForceHold::quadratic;
  const ExactStepIntegrator integ(m, o);
  BallOnBeamResult ref, fast;
  integ.run_reference(rough, ref);
  integ.run(rough, fast);
  CHECK(ref.loss_of_contact_share > 0.1);
  const double e = relative_error(fast, ref);
  MESSAGE("loss of contact: max rel. difference run() vs run_reference() " << e);
  CHECK(e < 1e-8);
  CHECK(fast.loss_of_contact_share == ref.loss_of_contact_share);
}
