// Uses the installed rollspec kernels (find_package(rollspec), rollspec::kernels) and checks two
// physics answers against their closed forms; exit 0 when both hold, 1 otherwise.
//
//   consumer [FACTOR]   FACTOR (default 1) scales the expected values: any FACTOR != 1 must fail,
//                       which shows the checks can fail.
//
// 1. Welch PSD (kernels/spectral) of x = A sin(2 pi f0 t) with f0 on a bin and a whole number of
//    periods per segment, periodic Hann window: the sine's power splits 4:1:1 over bins k0, k0 +- 1
//    (the Hann window's DFT is L/2 at 0 and -L/4 at +-1), so the one-sided density is
//    P(k0) = A^2 L / (3 fs), P(k0 +- 1) = A^2 L / (12 fs), 0 elsewhere, and sum P df = A^2 / 2 (Parseval).
// 2. Hertz contact (kernels/beam): a sphere of radius R on a flat, E* the effective modulus, load W:
//    contact radius a = (3 W R / (4 E*))^(1/3), approach delta = a^2 / R, stiffness dP/d delta = 2 E* a.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "kernels/beam/contact_law.hpp"
#include "kernels/spectral/welch.hpp"

namespace {

int failures = 0;

void check(const char* what, double got, double expected, double tolerance) {
  const double error = std::abs(got - expected) / std::abs(expected);
  const bool ok = error <= tolerance;
  std::printf("%-40s %.12g  expected %.12g  relative error %.2e  %s\n", what, got, expected, error, ok ? "ok" : "FAIL");
  if (!ok) ++failures;
}

}  // namespace

int main(int argc, char** argv) {
  const double factor = argc > 1 ? std::atof(argv[1]) : 1.0;
  const double pi = std::acos(-1.0);

  // 1. Welch PSD of a sine.
  namespace sp = rollspec::spectral;
  sp::WelchConfig config;
  config.sample_rate = 1024.0;  // Hz
  config.segment = 256;         // bin width 4 Hz
  config.overlap = 128;
  config.window = sp::Window::hann;
  const double amplitude = 2.0, f0 = 100.0;  // bin 25: 25 periods per segment
  const std::size_t n = 4096, k0 = 25;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = amplitude * std::sin(2.0 * pi * f0 * static_cast<double>(i) / config.sample_rate);
  const sp::WelchPlan plan(config);
  sp::WelchWorkspace workspace(config.segment);
  std::vector<double> psd(plan.n_freq());
  plan.psd(x.data(), n, psd.data(), workspace);
  const double L = static_cast<double>(config.segment), fs = config.sample_rate, a2 = amplitude * amplitude;
  check("welch: frequency of bin k0 (Hz)", plan.frequencies()[k0], factor * f0, 1e-12);
  check("welch: P(k0) (1/Hz, x unitless)", psd[k0], factor * a2 * L / (3.0 * fs), 1e-9);
  check("welch: P(k0 - 1)", psd[k0 - 1], factor * a2 * L / (12.0 * fs), 1e-9);
  check("welch: P(k0 + 1)", psd[k0 + 1], factor * a2 * L / (12.0 * fs), 1e-9);
  double power = 0.0, elsewhere = 0.0;
  for (std::size_t k = 0; k < psd.size(); ++k) {
    power += psd[k] * plan.frequency_step();
    if (k + 1 < k0 || k > k0 + 1) elsewhere = std::max(elsewhere, psd[k]);
  }
  check("welch: sum P df = A^2/2 (Parseval)", power, factor * a2 / 2.0, 1e-9);
  const bool leak_ok = elsewhere < 1e-12 * psd[k0];
  std::printf("%-40s %.3g  %s\n", "welch: largest P away from k0 +- 1", elsewhere, leak_ok ? "ok" : "FAIL");
  if (!leak_ok) ++failures;

  // 2. Hertz contact of a steel ball on a steel flat.
  namespace bm = rollspec::beam;
  bm::ContactLaw law;
  law.kind = bm::ContactLawKind::hertz;
  law.effective_modulus = 115.4e9;  // Pa
  law.radius = 0.01;                // m
  const bm::ContactModel model(law);
  const double load = 25.0;  // N
  const double delta = model.static_compression(load, 0.0);
  double force = 0.0, stiffness = 0.0;
  model.elastic(delta, force, stiffness);
  const double a = std::cbrt(3.0 * load * law.radius / (4.0 * law.effective_modulus));
  check("hertz: approach delta = a^2/R (m)", delta, factor * a * a / law.radius, 1e-12);
  check("hertz: P(delta) = W (N)", force, factor * load, 1e-12);
  check("hertz: k = 2 E* a (N/m)", stiffness, factor * 2.0 * law.effective_modulus * a, 1e-12);

  std::printf("%s\n", failures ? "consumer: FAILED" : "consumer: all checks passed");
  return failures ? 1 : 0;
}
