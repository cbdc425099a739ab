// Frequency-domain reference of the linearised Monte-Carlo (kernels/beam/linear_reference, README
// B13, B34a-c, B35a; D-16, D-20) against what it must reduce to in simple cases.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "ball_on_beam_fixture.hpp"
#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/linear_reference.hpp"
#include "kernels/beam/linear_response.hpp"
#include "kernels/spectral/welch_expectation.hpp"

using namespace rollspec::beam;
using rollspec::spectral::WelchConfig;
using rollspec::spectral::WelchPlan;

namespace {
const double kPi = 3.141592653589793;

WelchConfig welch_config() {
  WelchConfig c;
  c.sample_rate = 2560.0;
  c.segment = 256;
  c.overlap = 128;
  return c;
}

// One ball position over the whole record of n samples, white blocked force S0.
LinearReferenceInput white_at_one_position(const ModalBeam& beam, const WelchPlan& welch, std::size_t n,
                                           std::vector<double> sensors, double S0) {
  LinearReferenceInput in;
  in.beam = &beam;
  in.ball_mass = 0.2631;
  in.damping = 100.0;
  in.sensors = std::move(sensors);
  in.welch = &welch;
  in.sample_rate = welch.config().sample_rate;
  in.excitation.time_psd = [S0](double) { return S0; };
  in.excitation.blocked_force = true;
  in.excitation.k0 = 6.8e6;
  in.excitation.speed = 1.0;
  in.excitation.spacing = 1.0 / (4.0 * in.sample_rate);
  in.excitation.x_start = 0.13;
  in.excitation.step = 1.0 / (4.0 * in.sample_rate);
  in.positions.edges = {0, n};
  in.positions.position = {0.13};
  in.positions.weight = {1.0};
  in.realisations = 5.0;
  return in;
}
}  // namespace

TEST_CASE("Catmull-Rom hold gain: a constant passes, samples are read exactly, Nyquist halfway vanishes (B13)") {
  for (double tau : {0.0, 0.25, 0.5, 0.9}) CHECK(catmull_rom_gain(tau, 0.0) == doctest::Approx(1.0).epsilon(1e-15));
  for (double theta : {0.3, 1.7, 3.0}) CHECK(catmull_rom_gain(0.0, theta) == 1.0);
  CHECK(catmull_rom_gain(0.5, kPi) < 1e-30);  // +-1 alternating: the midpoint interpolates to 0
  CHECK(catmull_rom_gain(0.5, 1.0) < 1.0);    // and the interpolation low-passes in between
}

TEST_CASE("reference excitation: k0^2 G T(k)^2 on the samples, nothing above pi/dx (B35a)") {
  ReferenceExcitation e;
  e.time_psd = [](double f) { return 1e-12 / (1.0 + f / 100.0); };
  e.k0 = 6.8e6;
  e.speed = 2.0;
  e.step = 1e-5;
  e.spacing = e.speed * e.step;  // one roughness sample per step, the ball starting on a sample
  e.patch_half_width = 1e-4;
  e.x_start = 50 * e.spacing;
  std::vector<double> f;
  for (int i = 0; i <= 80; ++i) f.push_back(1000.0 * i);  // to 80 kHz; pi/dx lies at v/(2 dx) = 50 kHz
  const std::vector<double> exc = reference_excitation(e, f);
  CHECK(exc[0] == 0.0);
  for (std::size_t i = 1; i < f.size(); ++i) {
    const double k = 2.0 * kPi * f[i] / e.speed, T = contact_patch_transfer(k, e.patch_half_width, e.spacing);
    if (f[i] > 0.5 / e.step) {
      CHECK(exc[i] == 0.0);
    } else {
      CHECK(exc[i] == doctest::Approx(e.k0 * e.k0 * e.time_psd(f[i]) * T * T).epsilon(1e-14));
    }
  }
  // two steps per sample: F0 read at fractions 0 and 1/2, the mean hold gain is below 1 and tends
  // to 1 at low frequency
  e.spacing = 2.0 * e.speed * e.step;
  const std::vector<double> coarse = reference_excitation(e, f);
  for (std::size_t i = 1; i < f.size() && f[i] <= 0.25 / e.step; ++i) {
    const double k = 2.0 * kPi * f[i] / e.speed, T = contact_patch_transfer(k, e.patch_half_width, e.spacing);
    const double hold = coarse[i] / (e.k0 * e.k0 * e.time_psd(f[i]) * T * T);
    CHECK(hold <= 1.0);
    if (f[i] <= 1000.0) CHECK(hold == doctest::Approx(1.0).epsilon(1e-3));
  }
}

TEST_CASE("linear reference: one position and white excitation give |H|^2 S0 and the stationary dof (D-16)") {
  const ModalBeam beam(test::rig_beam(), {10, 0.0}, {0.02, {}});
  const WelchPlan welch(welch_config());
  const std::size_t n = 2048;
  const double S0 = 3e-4;
  LinearReferenceInput in = white_at_one_position(beam, welch, n, {0.065, 0.26}, S0);
  std::size_t steps = 0;
  const LinearReference ref = linear_reference(in, [&steps] { ++steps; });
  CHECK(steps == linear_reference_steps(in));
  REQUIRE(ref.rows == 2);
  REQUIRE(ref.bins == welch.n_freq());
  const double dfine = welch.frequency_step() / static_cast<double>(in.refine);
  std::vector<double> fb;
  for (std::size_t k = 0; k < ref.bins; ++k) fb.push_back(dfine * static_cast<double>(k * in.refine));
  const auto H = linear_response_transfer(beam, in.ball_mass, in.excitation.k0, in.damping, 0.13, in.sensors, fb,
                                          Excitation::blocked_force);
  const double nu = in.realisations * welch.equivalent_dof(n);
  for (std::size_t s = 0; s < 2; ++s) {
    CHECK(ref.raw[s * ref.bins] == 0.0);
    for (std::size_t k = 1; k < ref.bins; ++k) {
      const std::size_t i = s * ref.bins + k;
      CHECK(ref.raw[i] == doctest::Approx(std::norm(H[s][k]) * S0).epsilon(1e-12));
      CHECK(ref.dof[i] == doctest::Approx(nu).epsilon(1e-10));
      CHECK(ref.mean_lower[i] < ref.psd[i]);
      CHECK(ref.mean_upper[i] > ref.psd[i]);
    }
  }
}

TEST_CASE("linear reference: the mean of two sensors at one place is that sensor, with no more dof (B34b)") {
  const ModalBeam beam(test::rig_beam(), {10, 0.0}, {0.02, {}});
  const WelchPlan welch(welch_config());
  const std::size_t n = 2048;
  LinearReferenceInput in = white_at_one_position(beam, welch, n, {0.2, 0.2}, 1e-4);
  in.sensor_mean = true;
  in.positions = welch_position_blocks(welch, n, 100, 0.1, 0.05, welch.config().sample_rate, 16);
  REQUIRE(in.positions.count() == 16);
  const LinearReference ref = linear_reference(in);
  REQUIRE(ref.rows == 3);
  const std::size_t nb = ref.bins;
  for (std::size_t k = 1; k < nb; ++k) {
    CHECK(ref.psd[2 * nb + k] == ref.psd[k]);
    CHECK(ref.raw[2 * nb + k] == ref.raw[nb + k]);
    CHECK(ref.dof[2 * nb + k] == doctest::Approx(ref.dof[k]).epsilon(1e-10));
    // the ball moves: fewer dof than a stationary record (B34b)
    CHECK(ref.dof[k] <= in.realisations * welch.equivalent_dof(n) * (1.0 + 1e-12));
  }
}

TEST_CASE(
    "linear reference equals the plain path: the modal PSD on the whole fine grid, then the direct Welch integral") {
  // Several weighted positions, modes above f_s/2 (the sparse grid there must follow them), a
  // blocked force that continues to the step's Nyquist frequency and aliases: the fast reference
  // against linear_response_psd + welch_expectation_direct on every fine frequency.
  for (int modes : {12, 3}) {  // modes above f_s/2 (every fine point computed there), none (sparse)
    const ModalBeam beam(test::rig_beam(), {modes, 0.0}, {0.02, {}});
    WelchConfig c = welch_config();
    c.segment = 64;
    c.overlap = 32;
    const WelchPlan welch(c);
    const std::size_t n = 1024;
    LinearReferenceInput in = white_at_one_position(beam, welch, n, {0.065, 0.195, 0.26}, 1.0);
    in.sensor_mean = true;
    in.excitation.time_psd = [](double f) { return 1e-4 / (1.0 + std::pow(f / 700.0, 2)); };
    in.positions.edges = {0, 300, 700, n};
    in.positions.position = {0.11, 0.16, 0.23};
    in.positions.weight = {1.0, 2.5, 0.7};
    REQUIRE((beam.frequency(beam.modes() - 1) > 0.5 * c.sample_rate) == (modes == 12));
    const LinearReference ref = linear_reference(in);
    const std::size_t half = in.refine * (welch.n_freq() - 1), nfine = 4 * half + 1;
    std::vector<double> fine(nfine);
    for (std::size_t j = 0; j < nfine; ++j)
      fine[j] = welch.frequency_step() / static_cast<double>(in.refine) * static_cast<double>(j);
    const auto exc = reference_excitation(in.excitation, fine);
    const auto plain = linear_response_psd(beam, in.ball_mass, in.excitation.k0, in.damping, in.positions.position,
                                           in.sensors, fine, exc, Excitation::blocked_force, in.positions.weight);
    std::vector<std::vector<double>> rows = plain.sensor_psd;
    std::vector<double> mean(nfine, 0.0);
    for (const auto& r : rows)
      for (std::size_t j = 0; j < nfine; ++j) mean[j] += r[j] / 3.0;
    rows.push_back(mean);
    REQUIRE(ref.rows == 4);
    double worst = 0.0;
    for (std::size_t r = 0; r < 4; ++r) {
      const auto expect = rollspec::spectral::welch_expectation_direct(welch, rows[r], in.refine);
      for (std::size_t k = 1; k < ref.bins; ++k) {
        CHECK(std::abs(ref.raw[r * ref.bins + k] / rows[r][k * in.refine] - 1.0) < 1e-12);
        worst = std::max(worst, std::abs(ref.psd[r * ref.bins + k] / expect[k] - 1.0));
      }
    }
    // Dense above f_s/2 where modes lie there: the plain sum to rounding; else interpolated between
    // one point per Welch bin, which rounds off anti-resonances of the aliased part.
    CHECK(worst < (modes == 12 ? 1e-12 : 1e-2));
  }
}

TEST_CASE("linear reference, fast path: the plain path's raw PSD to the bit, its expected PSD and dof to rounding") {
  // Many weighted blocks along the rig beam, five sensors and their mean, modes above f_s/2 and not:
  // the fast path sums the products with the Welch weights before smoothing them (B34b) and runs the
  // modal sums over ranges of frequencies; the plain path smooths every block's products.
  for (int modes : {12, 4}) {
    const ModalBeam beam(test::rig_beam(), {modes, 0.0}, {0.02, {}});
    const WelchPlan welch(welch_config());
    const std::size_t n = 1500;
    LinearReferenceInput in = white_at_one_position(beam, welch, n, {0.065, 0.13, 0.195, 0.26, 0.325}, 1.0);
    in.sensor_mean = true;
    in.excitation.time_psd = [](double f) { return 1e-4 / (1.0 + std::pow(f / 500.0, 2)); };
    in.positions = welch_position_blocks(welch, n, 50, 0.05, 0.2, welch.config().sample_rate, 37);
    REQUIRE(in.positions.count() == 37);
    REQUIRE(in.positions.weight.back() == 0.0);  // samples after the last segment weigh nothing
    const LinearReference fast = linear_reference(in), plain = linear_reference_plain(in);
    REQUIRE(fast.rows == 6);
    REQUIRE(plain.rows == 6);
    double worst_psd = 0.0, worst_dof = 0.0;
    for (std::size_t i = 0; i < fast.psd.size(); ++i) {
      CHECK(fast.raw[i] == plain.raw[i]);
      if (i % fast.bins == 0) continue;
      worst_psd = std::max(worst_psd, std::abs(fast.psd[i] / plain.psd[i] - 1.0));
      worst_dof = std::max(worst_dof, std::abs(fast.dof[i] / plain.dof[i] - 1.0));
    }
    CHECK(worst_psd < 1e-12);
    CHECK(worst_dof < 1e-10);
    // the ball moves along a beam with nodes: the dof differ from bin to bin and stay below stationary
    CHECK(*std::max_element(fast.dof.begin(), fast.dof.end()) <= in.realisations * 6 * welch.equivalent_dof(n));
  }
}
