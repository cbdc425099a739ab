// Contact laws, monotone table, sampled inputs, implicit contact solve, loss of contact (README B13–B21).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "ball_on_beam_fixture.hpp"
#include "kernels/beam/contact_law.hpp"
#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/contact_solve.hpp"
#include "kernels/beam/dopri5_reference.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/beam/monotone_table.hpp"
#include "kernels/beam/uniform_samples.hpp"
#include "kernels/contact/hertz.hpp"

using namespace rollspec::beam;

TEST_CASE("monotone table: linear data exact, monotone without overshoot, derivative consistent") {
  const MonotoneTable lin({0.0, 1.0, 3.0, 3.5}, {1.0, 3.0, 7.0, 8.0});
  for (double x : {-1.0, 0.3, 2.2, 3.4, 5.0}) CHECK(lin(x) == doctest::Approx(1.0 + 2.0 * x).epsilon(1e-14));
  // Step-like data: a plain cubic spline overshoots; PCHIP must not.
  const MonotoneTable step({0.0, 1.0, 2.0, 3.0, 4.0}, {0.0, 0.0, 0.1, 1.0, 1.0});
  double prev = -1.0;
  for (int i = 0; i <= 400; ++i) {
    const double x = 0.01 * i, y = step(x);
    CHECK(y >= prev - 1e-15);
    CHECK(y >= 0.0);
    CHECK(y <= 1.0);
    prev = y;
    double v, d;
    step.evaluate(x + 0.0037, v, d);
    const double fd = (step(x + 0.0037 + 1e-7) - step(x + 0.0037 - 1e-7)) / 2e-7;
    CHECK(d == doctest::Approx(fd).epsilon(1e-6).scale(1.0));
  }
}

TEST_CASE("Hertz law: seed ball numbers (kernels/README.md (contact)) and a force table sampled from it") {
  ContactLaw law;  // E* = 115.4 GPa, R = 20 mm
  const ContactModel hertz(law);
  const double w = 2.58;
  const double delta = hertz.static_compression(w, 0.0);
  double p, k;
  hertz.elastic(delta, p, k);
  MESSAGE("seed ball: delta " << delta << " m, k " << k << " N/m");
  CHECK(delta == doctest::Approx(0.241e-6).epsilon(2e-3));
  CHECK(k == doctest::Approx(1.60e7).epsilon(3e-3));
  CHECK(p == doctest::Approx(w).epsilon(1e-12));
  // A 41-point table of the same law reproduces it (PCHIP error is O(dx^3) where smooth).
  ContactLaw tab;
  tab.kind = ContactLawKind::table;
  ContactLaw lit;
  lit.kind = ContactLawKind::literal_stiffness;
  for (int i = 0; i <= 40; ++i) {
    const double d = 1e-6 * i / 40.0;
    double pi, ki;
    hertz.elastic(d, pi, ki);
    tab.compression.push_back(d);
    tab.values.push_back(pi);
    lit.compression.push_back(d);
    lit.values.push_back(ki);  // tangent stiffness table k_c(delta), seed 001 Eq. 13
  }
  const ContactModel t(tab), l(lit);
  for (double d : {0.1e-6, 0.241e-6, 0.5e-6, 0.93e-6}) {
    double ph, kh, pt, kt, pl, kl;
    hertz.elastic(d, ph, kh);
    t.elastic(d, pt, kt);
    l.elastic(d, pl, kl);
    CHECK(pt == doctest::Approx(ph).epsilon(2e-3));
    CHECK(kt == doctest::Approx(kh).epsilon(2e-2));
    // kernels/README.md (contact) note on seed 001 Eq. 7: k_c(delta) delta overestimates the Hertz force by 1.5x.
    CHECK(pl / ph == doctest::Approx(1.5).epsilon(3e-3));
  }
  CHECK(t.static_compression(w, 0.0) == doctest::Approx(delta).epsilon(2e-3));
}

TEST_CASE("contact force: never pulls, loss of contact with damping only or zero force") {
  ContactLaw law;
  law.damping = 100.0;
  const ContactModel damping_only(law);
  CHECK(damping_only.evaluate(-1e-7, 0.01, 0.0).force == doctest::Approx(1.0));  // approaching: c delta_dot
  CHECK(damping_only.evaluate(-1e-7, 0.01, 0.0).contact == false);
  CHECK(damping_only.evaluate(-1e-7, -0.01, 0.0).force == 0.0);  // separating: never pulls
  CHECK(damping_only.evaluate(1e-8, -1.0, 0.0).force == 0.0);    // damper would pull
  law.loss = LossOfContact::zero_force;
  const ContactModel zero(law);
  CHECK(zero.evaluate(-1e-7, 0.01, 0.0).force == 0.0);
  // Implicit solve: the root satisfies F = law(delta_free - C F, rate_free - D F).
  const double c = 3e-8, d = 2e-6;
  for (double df : {-1e-7, 1e-8, 3e-7, 2e-6}) {
    const ContactSolution s = solve_contact_force(damping_only, df, 0.003, c, d, 0.0, 1.0, 2.58);
    const ContactForce f = damping_only.evaluate(df - c * s.force, 0.003 - d * s.force, 0.0);
    CHECK(s.force == doctest::Approx(f.force).epsilon(1e-12).scale(2.58));
    CHECK(s.force >= 0.0);
  }
  // Linearised (D-11): affine, solved in one Newton step; tension allowed only on request.
  ContactLaw lin;
  lin.kind = ContactLawKind::linearised;
  lin.k0 = 6.8e6;
  lin.d0 = 1e-7;
  const ContactModel lm(lin);
  const ContactSolution s = solve_contact_force(lm, 2e-7, 0.0, 1e-8, 0.0, 2.58, 0.0, 2.58);
  CHECK(s.force == doctest::Approx((2.58 + 6.8e6 * 3e-7) / (1.0 + 6.8e6 * 1e-8)).epsilon(1e-12));
  CHECK(lm.evaluate(-5e-7, 0.0, 0.0).force == 0.0);
  lin.allow_tension = true;
  CHECK(ContactModel(lin).evaluate(-5e-7, 0.0, 0.0).force == doctest::Approx(6.8e6 * -4e-7));
}

TEST_CASE("uniform samples: Catmull-Rom interpolation reproduces quadratics inside, linear data everywhere") {
  UniformSamples s;
  s.origin = 0.1;
  s.step = 0.01;
  for (int i = 0; i <= 50; ++i) {
    const double x = 0.1 + 0.01 * i;
    s.values.push_back(2.0 - 3.0 * x + 5.0 * x * x);
  }
  for (double x : {0.1237, 0.3011, 0.5822}) {
    double v, d;
    s.evaluate(x, v, d);
    CHECK(v == doctest::Approx(2.0 - 3.0 * x + 5.0 * x * x).epsilon(1e-13));
    CHECK(d == doctest::Approx(-3.0 + 10.0 * x).epsilon(1e-11));
  }
  CHECK_THROWS(s.value(0.0));
}

TEST_CASE("ball-on-beam: smooth beam stays in equilibrium; rough beam loses contact but never pulls") {
  // Smooth beam, linearised law with F0 = m2 g: nothing moves but the quasi-static deflection.
  BallOnBeamModel m = test::hertz_model(10, 0.05, 0.1, 10000.0);
  m.contact.kind = ContactLawKind::linearised;
  m.contact.k0 = 6.8e6;
  m.contact.damping = 100.0;
  const BallOnBeamResult quiet = ExactStepIntegrator(m, 2).run(Realisation{});
  const double w = m.ball.mass * m.ball.gravity;
  double dev = 0.0;
  for (std::size_t j = 0; j < quiet.samples(); ++j) dev = std::max(dev, std::abs(quiet.contact_force[j] / w - 1.0));
  MESSAGE("smooth beam, linearised law: max |F/W - 1| = " << dev);
  CHECK(dev <= 1e-3);  // no start-up transient (zero initial rates would give about 5e-3)
  CHECK(quiet.loss_of_contact_share == 0.0);
  // Rough beam, Hertz: 1 um roughness at 1 m/s makes the ball fly.
  BallOnBeamModel h = test::hertz_model(12, 0.05, 0.1, 20000.0);
  Realisation r;
  r.roughness = test::sine_roughness(0.39, 1e-5, {1e-6, 3e-7}, {2e-3, 0.7e-3});
  for (LossOfContact loss : {LossOfContact::damping_only, LossOfContact::zero_force}) {
    h.contact.loss = loss;
    const BallOnBeamResult res = ExactStepIntegrator(h, 8).run(r);
    MESSAGE("loss-of-contact share " << res.loss_of_contact_share);
    CHECK(res.loss_of_contact_share > 0.05);
    CHECK(res.loss_of_contact_share < 0.95);
    for (std::size_t j = 0; j < res.samples(); ++j) {
      CHECK(res.contact_force[j] >= 0.0);
      if (res.loss_of_contact[j]) {
        CHECK(res.compression[j] <= 0.0);
        if (loss == LossOfContact::zero_force) CHECK(res.contact_force[j] == 0.0);
      }
    }
  }
}

TEST_CASE("contact-patch filter: a sinusoid is scaled by sin(ka)/(ka)") {
  UniformSamples h;
  h.step = 1e-6;
  const double k = 6.283185307179586 / 0.4e-3;  // 0.4 mm wavelength
  for (int i = 0; i <= 4000; ++i) h.values.push_back(std::sin(k * h.step * i));
  const double a =
      rollspec::contact::hertz::contact_radius_at_approach(0.02, 0.241e-6);  // seed ball under its weight: a = 69 um
  CHECK(a == doctest::Approx(69.4e-6).epsilon(2e-3));
  const UniformSamples f = contact_patch_average(h, a);
  const double gain = std::sin(k * a) / (k * a);
  double worst = 0.0;
  for (int i = 200; i <= 3800; ++i) worst = std::max(worst, std::abs(f.values[i] - gain * h.values[i]));
  MESSAGE("gain " << gain << ", max deviation " << worst);
  CHECK(worst <= 1e-4);
  CHECK(contact_patch_average(h, 0.0).values[123] == h.values[123]);
}

TEST_CASE("instantaneous contact-patch filter in the integrator") {
  BallOnBeamModel m = test::hertz_model(12, 0.05, 0.09, 20000.0);
  const double a_w = rollspec::contact::hertz::contact_radius_at_approach(
      m.contact.radius, ContactModel(m.contact).static_compression(m.ball.mass * m.ball.gravity, 0.0));
  // Small roughness: the compression stays near its static value, so the instantaneous width is
  // close to a_W and the result close to a point contact on the roughness pre-averaged over a_W.
  Realisation r;
  r.roughness = test::sine_roughness(0.39, 2e-6, {1e-9, 1e-9}, {0.6e-3, 0.25e-3});
  Realisation pre;
  pre.roughness = contact_patch_average(r.roughness, a_w);
  BallOnBeamModel mp = m;
  mp.patch_radius = m.contact.radius;
  const BallOnBeamResult with_patch = ExactStepIntegrator(mp, 8).run(r);
  const BallOnBeamResult prefiltered = ExactStepIntegrator(m, 8).run(pre);
  const BallOnBeamResult point = ExactStepIntegrator(m, 8).run(r);
  double d = 0.0, peak = 0.0, peak_point = 0.0;
  for (std::size_t j = 0; j < point.samples(); ++j) {
    d = std::max(d, std::abs(with_patch.contact_force[j] - prefiltered.contact_force[j]));
    peak = std::max(peak, std::abs(prefiltered.contact_force[j] - m.ball.mass * m.ball.gravity));
    peak_point = std::max(peak_point, std::abs(point.contact_force[j] - m.ball.mass * m.ball.gravity));
  }
  MESSAGE("a_W = " << a_w << " m; dynamic force: point contact " << peak_point << " N, patch-filtered " << peak
                   << " N; instantaneous vs pre-filtered width: max difference " << d << " N");
  CHECK(peak < 0.7 * peak_point);  // short wavelengths are filtered (sin(ka)/(ka) = 0.91 and 0.56 here)
  CHECK(d <= 0.05 * peak);
  CHECK_THROWS(simulate_dopri5(mp, r));
}
