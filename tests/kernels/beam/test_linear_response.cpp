// Frequency-domain solution of the linearised model (README B31–B34) against the time integrator.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "ball_on_beam_fixture.hpp"
#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/exact_step_integrator.hpp"
#include "kernels/beam/linear_response.hpp"
#include "kernels/texture/psd.hpp"

using namespace rollspec::beam;

namespace {
// Least-squares amplitude of a sinusoid at f (with offset) over samples [j0, end).
double amplitude(const std::vector<double>& y, double fs, double f, std::size_t j0) {
  double sc = 0, ss = 0, cc = 0, yc = 0, ys = 0, c1 = 0, s1 = 0, y1 = 0, n = 0;
  for (std::size_t j = j0; j < y.size(); ++j) {
    const double t = static_cast<double>(j) / fs, c = std::cos(6.283185307179586 * f * t),
                 s = std::sin(6.283185307179586 * f * t);
    cc += c * c, ss += s * s, sc += s * c, yc += y[j] * c, ys += y[j] * s, c1 += c, s1 += s, y1 += y[j], n += 1;
  }
  // Solve [cc sc c1; sc ss s1; c1 s1 n] [a b d] = [yc ys y1] by Cramer's rule.
  auto det3 = [](double a, double b, double c, double d, double e, double f_, double g, double h, double i) {
    return a * (e * i - f_ * h) - b * (d * i - f_ * g) + c * (d * h - e * g);
  };
  const double D = det3(cc, sc, c1, sc, ss, s1, c1, s1, n);
  const double a = det3(yc, sc, c1, ys, ss, s1, y1, s1, n) / D;
  const double b = det3(cc, yc, c1, sc, ys, s1, c1, y1, n) / D;
  return std::hypot(a, b);
}
}  // namespace

TEST_CASE("linear receptance model equals the steady state of the time integrator (ball at rest, sinusoidal F0)") {
  BallOnBeamModel m = test::hertz_model(10, 0.13, 0.13, 40000.0);
  m.beam = ModalBeam(test::rig_beam(), {10, 0.0}, {0.1, {}});
  m.contact.kind = ContactLawKind::linearised;
  m.contact.k0 = 6.8e6;
  m.contact.damping = 100.0;
  m.contact.allow_tension = true;
  m.traverse = {0.13, 0.13, 0.0, 0.25};
  const ExactStepIntegrator integ(m, 8);
  const double w = m.ball.mass * m.ball.gravity, a0 = 0.1;
  for (double f : {300.0, 1100.0, 2600.0}) {
    Realisation r;
    r.blocked_force.step = 1e-5;
    for (int i = 0; i <= 25001; ++i)
      r.blocked_force.values.push_back(w + a0 * std::sin(6.283185307179586 * f * 1e-5 * i));
    const BallOnBeamResult res = integ.run(r);
    const LinearResponse lr = linear_response_psd(m.beam, m.ball.mass, m.contact.k0, m.contact.damping, {0.13},
                                                  m.sensors, {f}, {1.0}, Excitation::blocked_force);
    const std::size_t j0 = res.samples() - 2000;  // last 50 ms
    const double fa = amplitude(res.contact_force, m.sample_rate, f, j0);
    MESSAGE(f << " Hz: force amplitude time " << fa << " vs frequency domain " << a0 * std::sqrt(lr.force_psd[0]));
    CHECK(fa == doctest::Approx(a0 * std::sqrt(lr.force_psd[0])).epsilon(5e-4));
    for (std::size_t s = 0; s < m.sensors.size(); ++s) {
      const double ta = amplitude(res.sensor_acceleration[s], m.sample_rate, f, j0);
      CHECK(ta == doctest::Approx(a0 * std::sqrt(lr.sensor_psd[s][0])).epsilon(5e-4));
    }
  }
}

TEST_CASE("roughness and blocked-force excitation are the same model with F0 = (k0 + i w c0) h") {
  const ModalBeam beam(test::rig_beam(), {12, 0.0}, {0.02, {}});
  const double k0 = 6.8e6, c0 = 100.0;
  std::vector<double> f, gh, gf;
  for (int k = 1; k <= 50; ++k) {
    f.push_back(100.0 * k);
    gh.push_back(1e-18 / k);
    const double w = 6.283185307179586 * f.back();
    gf.push_back(std::norm(std::complex<double>(k0, w * c0)) * gh.back());
  }
  const std::vector<double> xi = {0.05, 0.1, 0.2, 0.3}, sensors = {0.13, 0.26};
  const LinearResponse a = linear_response_psd(beam, 0.2631, k0, c0, xi, sensors, f, gh, Excitation::roughness);
  const LinearResponse b = linear_response_psd(beam, 0.2631, k0, c0, xi, sensors, f, gf, Excitation::blocked_force);
  for (std::size_t k = 0; k < f.size(); ++k) {
    CHECK(a.force_psd[k] == doctest::Approx(b.force_psd[k]).epsilon(1e-12));
    CHECK(a.sensor_psd[1][k] == doctest::Approx(b.sensor_psd[1][k]).epsilon(1e-12));
    CHECK(a.sensor_psd[0][k] > 0.0);
  }
}

TEST_CASE("weighted position average and complex transfer agree with single-position solutions") {
  const ModalBeam beam(test::rig_beam(), {12, 0.0}, {0.05, {}});
  const double k0 = 6.8e6, c0 = 100.0, m2 = 0.2631;
  const std::vector<double> f = {150.0, 700.0, 2500.0, 4400.0}, g = {1.0, 2.0, 0.5, 0.25};
  const std::vector<double> xi = {0.07, 0.15, 0.31}, wts = {1.0, 3.0, 0.0}, sensors = {0.065, 0.195};
  const LinearResponse avg = linear_response_psd(beam, m2, k0, c0, xi, sensors, f, g, Excitation::blocked_force, wts);
  std::vector<double> expect(f.size(), 0.0);
  for (std::size_t p = 0; p < xi.size(); ++p) {
    const LinearResponse one = linear_response_psd(beam, m2, k0, c0, {xi[p]}, sensors, f, g, Excitation::blocked_force);
    const auto H = linear_response_transfer(beam, m2, k0, c0, xi[p], sensors, f, Excitation::blocked_force);
    for (std::size_t k = 0; k < f.size(); ++k) {
      expect[k] += wts[p] / 4.0 * one.sensor_psd[1][k];
      CHECK(std::norm(H[0][k]) * g[k] == doctest::Approx(one.sensor_psd[0][k]).epsilon(1e-12));
      CHECK(std::norm(H[1][k]) * g[k] == doctest::Approx(one.sensor_psd[1][k]).epsilon(1e-12));
    }
    // Receptances computed once for many positions give the same transfer to the last bit.
    const auto modal = modal_receptances(beam, f);
    const auto Hm = linear_response_transfer(beam, m2, k0, c0, xi[p], sensors, f, Excitation::blocked_force, &modal);
    for (std::size_t s = 0; s < sensors.size(); ++s)
      for (std::size_t k = 0; k < f.size(); ++k) CHECK(Hm[s][k] == H[s][k]);
  }
  for (std::size_t k = 0; k < f.size(); ++k) CHECK(avg.sensor_psd[1][k] == doctest::Approx(expect[k]).epsilon(1e-12));
  CHECK_THROWS(linear_response_psd(beam, m2, k0, c0, xi, sensors, f, g, Excitation::blocked_force, {1.0, 2.0}));
}

TEST_CASE("contact_patch_transfer is what contact_patch_average does to a sampled sinusoid (B35a)") {
  const double dx = 1e-6, a = 69.4e-6;
  UniformSamples h{0.0, dx, {}};
  for (double k : {2.0e4, 1.3e5, 3.1e5, 9.0e5}) {
    h.values.assign(4001, 0.0);
    for (std::size_t i = 0; i < h.values.size(); ++i) h.values[i] = std::cos(k * dx * static_cast<double>(i) + 0.3);
    const UniformSamples out = contact_patch_average(h, a);
    const double t = contact_patch_transfer(k, a, dx);
    for (std::size_t i = 1000; i < 3000; i += 37)
      CHECK(out.values[i] == doctest::Approx(t * h.values[i]).scale(1.0).epsilon(1e-12));
    // The continuous filter times the linear interpolant's low-pass, to the aliases' O(dx / a).
    const double sinc = std::sin(k * a) / (k * a), lin = std::pow(std::sin(k * dx / 2) / (k * dx / 2), 2);
    MESSAGE("k = " << k << ": T = " << t << ", sin(ka)/(ka) = " << sinc << ", times sinc^2(k dx/2) = " << sinc * lin);
    CHECK(t == doctest::Approx(sinc * lin).scale(1.0).epsilon(dx / a));
  }
  CHECK(contact_patch_transfer(1e5, 0.0, dx) == 1.0);
}

TEST_CASE("a band-limited line drawn from interpolation_compensated has the continuous patch filter's power (B40a)") {
  // Seed 002 rig at 1 m/s, 4 substeps: dx = v / (f_s 4), a = 69 um, band limit k_b = pi f_s / v (B40).
  const double fs = 25600.0, v = 1.0, dx = v / (4.0 * fs), a = 69.4e-6, kb = M_PI * fs / v;
  rollspec::texture::Psd g;
  g.density = [](double k) { return 1e-19 * std::pow(k, -1.4); };
  const rollspec::texture::Psd limited = rollspec::texture::band_limited(g, kb);
  const rollspec::texture::Psd drawn = rollspec::texture::interpolation_compensated(limited, dx);
  CHECK(limited(1.01 * kb) == 0.0);
  CHECK(limited.support_max == kb);
  for (double f : {500.0, 2000.0, 5000.0, 9000.0, 12000.0}) {
    const double k = 2.0 * M_PI * f / v, t = contact_patch_transfer(k, a, dx), ka = std::sin(k * a) / (k * a);
    // Without the compensation the samples' filter loses sinc^4(k dx/2) of the power (0.07 dB at 5 kHz).
    const double lost = -10.0 * std::log10(t * t * limited(k) / (ka * ka * g(k)));
    const double kept = 10.0 * std::log10(t * t * drawn(k) / (ka * ka * g(k)));
    MESSAGE(f << " Hz: uncompensated " << -lost << " dB, compensated " << kept << " dB");
    CHECK(std::abs(kept) < 0.1 * lost + 1e-3);  // what remains is B35a's O(dx/a) aliases
  }
  CHECK_THROWS(rollspec::texture::interpolation_compensated(g, dx));  // not band-limited: gain up to 6 near pi/dx
}
