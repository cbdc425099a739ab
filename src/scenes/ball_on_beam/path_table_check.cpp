#include "src/scenes/ball_on_beam/path_table_check.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/spectral/welch.hpp"
#include "src/stiffness/study_strip.hpp"

namespace rollspec::scenes {

namespace {
// δ_W's Welch segment (positions): a quarter of the path to a power of two, at most this.
constexpr std::size_t kSegmentMax = 1024;
}  // namespace

double PathTableCheck::band_error_db(double lower, double upper, std::size_t first_bin) const {
  return stiffness::checked_band_error_db(residual, step, samples, psd_wavenumber, psd, lower, upper, first_bin);
}

PathTableCheck path_table_check(const beam::PathContactTable& table, double load,
                                const std::vector<double>& static_approach, const std::vector<double>& check_position,
                                const std::vector<double>& check_approach) {
  PathTableCheck c;
  const std::vector<double>& x = table.data().position;
  if (check_position.empty() || x.size() < 8) return c;
  for (std::size_t j = 0; j < check_position.size(); ++j)
    c.residual.push_back(check_approach[j] - table.static_approach(load, check_position[j]));
  // δ_W at the tabulated positions, on the table's own spacing (positions_every thins it).
  const std::vector<double>& w = static_approach;
  c.step = (x.back() - x.front()) / static_cast<double>(x.size() - 1);
  c.samples = w.size();
  std::size_t segment = 8;
  while (2 * segment <= std::min(kSegmentMax, w.size() / 4)) segment *= 2;
  spectral::WelchConfig wc;
  wc.sample_rate = 1.0 / c.step;
  wc.segment = segment;
  wc.overlap = segment / 2;
  const spectral::WelchPlan plan(wc);
  spectral::WelchWorkspace ws(wc.segment);
  std::vector<double> one(plan.n_freq());
  plan.psd(w.data(), w.size(), one.data(), ws);
  for (std::size_t k = 0; k < one.size(); ++k) {
    c.psd_wavenumber.push_back(2.0 * M_PI * plan.frequency_step() * static_cast<double>(k));
    c.psd.push_back(one[k] / (2.0 * M_PI));  // per rad/m (D-5)
  }
  return c;
}

}  // namespace rollspec::scenes
