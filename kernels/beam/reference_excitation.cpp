// The excitation the linearised reference sees (README B13, B35a) and the Welch-weighted ball
// positions it averages receptances over (B34a); linear_reference.cpp combines them.
#include <algorithm>
#include <cmath>
#include <complex>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/linear_reference.hpp"
#include "kernels/spectral/welch_expectation.hpp"

namespace rollspec::beam {

double catmull_rom_gain(double tau, double theta) {
  // weights of y_{i-1}, y_i, y_{i+1}, y_{i+2} at fraction tau (Hermite basis, B13)
  const double t2 = tau * tau, t3 = t2 * tau;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + tau, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  const double c[4] = {-0.5 * h10, h00 - 0.5 * h11, h01 + 0.5 * h10, 0.5 * h11};
  std::complex<double> g = 0.0;
  for (int n = 0; n < 4; ++n) g += c[n] * std::polar(1.0, static_cast<double>(n - 1) * theta);
  return std::norm(g);
}

std::vector<double> reference_excitation(const ReferenceExcitation& e, const std::vector<double>& fine) {
  const double v = e.speed, dx = e.spacing, k_nyq = M_PI / dx;
  // Offset of the integration steps from the F0 samples (the same at every step when the samples
  // are one per step, the default); otherwise F0 is read at every fraction: mean gain over tau.
  const double dt_f0 = dx / v;
  const bool one_per_step = std::abs(dt_f0 / e.step - 1.0) < 1e-9;
  double tau = 0.0;
  if (one_per_step) {
    const double first = std::floor(e.x_start / dx);
    tau = (e.x_start - first * dx) / dx;
    tau -= std::floor(tau);
  }
  std::vector<double> exc(fine.size(), 0.0);
  for (std::size_t i = 1; i < fine.size(); ++i) {
    if (e.blocked_force) {
      exc[i] = e.time_psd(fine[i]);  // synthesised at the step, up to its Nyquist frequency
      continue;
    }
    const double k = 2.0 * M_PI * fine[i] / v;
    if (k > k_nyq) continue;  // harmonics above pi/dx are not synthesised
    const double patch = contact_patch_transfer(k, e.patch_half_width, dx);  // (B35a)
    const double theta = 2.0 * M_PI * fine[i] * dt_f0;
    double hold = 0.0;
    if (one_per_step) {
      hold = catmull_rom_gain(tau, theta);
    } else {
      for (int j = 0; j < 16; ++j) hold += catmull_rom_gain((j + 0.5) / 16.0, theta) / 16.0;
    }
    exc[i] = e.k0 * e.k0 * e.time_psd(fine[i]) * patch * patch * hold;
  }
  return exc;
}

PositionBlocks welch_position_blocks(const spectral::WelchPlan& plan, std::size_t n, std::size_t skip, double x_start,
                                     double v, double fs, std::size_t max_blocks) {
  // sample i of the analysed part weighs sum_segments w^2(i - segment start); the samples after
  // the last segment weigh nothing
  const auto tw = spectral::welch_time_weights(plan, n);
  const std::size_t blocks = std::min<std::size_t>(n, max_blocks), per = (n + blocks - 1) / blocks;
  PositionBlocks out;
  for (std::size_t b0 = 0; b0 < n; b0 += per) {
    const std::size_t b1 = std::min(n, b0 + per);
    double sw = 0.0, sx = 0.0;
    for (std::size_t i = b0; i < b1; ++i) {
      const double x = x_start + v * static_cast<double>(skip + i) / fs;
      sw += tw[i];
      sx += tw[i] * x;
    }
    out.edges.push_back(b0);
    out.position.push_back(sw > 0.0 ? sx / sw : x_start + v * static_cast<double>(skip + (b0 + b1) / 2) / fs);
    out.weight.push_back(sw);
  }
  out.edges.push_back(n);
  return out;
}

}  // namespace rollspec::beam
