#include "kernels/texture/profile_psd.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "kernels/spectral/welch.hpp"
#include "kernels/texture/statistics.hpp"

namespace rollspec::texture {

namespace {
constexpr std::size_t kMinSamples = 8;
constexpr double kSpacingTolerance = 1e-3;

// A length or variance in messages, six significant digits ("1.5625e-07 m", never "0.000000 m").
std::string g6(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

double checked_spacing(const Profile& p, std::size_t index) {
  const std::string who = "profile " + std::to_string(index);
  if (p.x.size() != p.z.size())
    throw std::invalid_argument(who + ": " + std::to_string(p.x.size()) + " positions but " +
                                std::to_string(p.z.size()) + " heights");
  if (p.z.size() < kMinSamples)
    throw std::invalid_argument(who + " has " + std::to_string(p.z.size()) + " samples; at least " +
                                std::to_string(kMinSamples) + " are needed");
  for (std::size_t i = 0; i < p.z.size(); ++i)
    if (!std::isfinite(p.x[i]) || !std::isfinite(p.z[i]))
      throw std::invalid_argument(who + ": sample " + std::to_string(i) + " is not finite");
  const double dx = (p.x.back() - p.x.front()) / static_cast<double>(p.x.size() - 1);
  if (!(dx > 0.0)) throw std::invalid_argument(who + ": positions must increase");
  for (std::size_t i = 1; i < p.x.size(); ++i) {
    const double d = p.x[i] - p.x[i - 1];
    if (std::abs(d / dx - 1.0) > kSpacingTolerance)
      throw std::invalid_argument(who + ": non-uniform spacing at sample " + std::to_string(i) + " (step " + g6(d) +
                                  " m, mean step " + g6(dx) + " m)");
  }
  return dx;
}

spectral::WelchConfig periodogram_config(std::size_t n, double dx) {
  spectral::WelchConfig cfg;
  cfg.sample_rate = 1.0 / dx;  // samples per metre: the PSD comes out per cycle/m
  cfg.segment = n;
  cfg.overlap = 0;
  cfg.window = spectral::Window::hann;
  cfg.detrend = spectral::Detrend::none;  // trend already removed (Eq. 15)
  return cfg;
}

// Eq. 16 with a plan made once per estimate; adds G_p to acc.
void add_periodogram(const spectral::WelchPlan& plan, spectral::WelchWorkspace& ws, const std::vector<double>& z,
                     std::vector<double>& acc) {
  std::vector<double> g(plan.n_freq());
  plan.psd(z.data(), z.size(), g.data(), ws);
  for (std::size_t j = 0; j < g.size(); ++j) acc[j] += g[j] / (2.0 * M_PI);  // per cycle/m -> per rad/m (Eq. 1)
}

// Eq. 42: the lowest bin whose octave the unresolved variance, as the scan's longest wave, leaks
// at most eps of the measured power into. Short profiles: at most N/2.
std::size_t first_resolved_bin(const EstimatedPsd& e, const ProfilePsdOptions& options) {
  const std::size_t top = e.psd.size() - 1, lowest = std::min(options.first_resolved_bin, top);
  if (!std::isfinite(options.resolved_leakage)) return lowest;
  const std::vector<double> leak = longest_wave_leakage(e.samples, e.spacing);
  std::vector<double> above(e.psd.size() + 1, 0.0);  // above[j] = sum_{i >= j} G_i dk
  for (std::size_t j = top + 1; j-- > 0;) above[j] = above[j + 1] + e.psd[j] * e.dk;
  for (std::size_t j = lowest; 2 * j <= top; ++j) {
    double leaked = 0.0, measured = 0.0;
    for (std::size_t i = j; i < 2 * j; ++i) {
      leaked += leak[i];
      measured += e.psd[i];
    }
    if (std::max(0.0, e.variance - above[j]) * leaked <= options.resolved_leakage * measured) return j;
  }
  return lowest;  // no octave clears it (a scan that is all form): the lowest bin, V_u says the rest
}

EstimatedPsd average(const std::vector<std::vector<double>>& rows, double dx, const ProfilePsdOptions& options) {
  EstimatedPsd out;
  if (options.first_resolved_bin < 2)
    throw std::invalid_argument("the first resolved bin must be >= 2 (bin 1 is the scan's longest wave), got " +
                                std::to_string(options.first_resolved_bin));
  out.samples = rows.front().size();
  out.spacing = dx;
  out.profiles = rows.size();
  out.dk = 2.0 * M_PI / (static_cast<double>(out.samples) * dx);
  out.psd.assign(out.samples / 2 + 1, 0.0);
  const spectral::WelchPlan plan(periodogram_config(out.samples, dx));
  spectral::WelchWorkspace ws(out.samples);
  std::vector<HeightStatistics> lengths;  // seed 001 takes its correlation lengths from the profiles (§3.1)
  double variance = 0.0;                  // sum of the profiles' variances (Eq. 44)
  for (std::vector<double> z : rows) {
    if (options.median_filter) median_filter3(z);
    add_periodogram(plan, ws, z, out.psd);
    double m = 0.0, v = 0.0;
    for (double h : z) m += h;
    m /= static_cast<double>(z.size());
    for (double h : z) v += (h - m) * (h - m);
    out.sigma += std::sqrt(v / static_cast<double>(z.size()));
    variance += v / static_cast<double>(z.size());
    lengths.push_back(line_statistics(z.data(), z.size(), dx));
  }
  out.sigma /= static_cast<double>(rows.size());
  out.correlation_length = mean_statistics(lengths).correlation_length_x;  // NaN only if no profile reaches 1/e
  for (double& g : out.psd) g /= static_cast<double>(rows.size());         // Eq. 17
  // The periodogram keeps its own level (Eq. 43): no rescaling to the variance, whose bulk on real
  // scans sits in the bins the window cannot resolve (Eq. 44 reports it apart). The DC bin holds the
  // windowed mean, no roughness.
  out.psd[0] = 0.0;
  out.variance = variance / static_cast<double>(rows.size());
  double held = 0.0;
  for (double g : out.psd) held += g * out.dk;
  if (!std::isfinite(held) || !std::isfinite(out.variance))
    throw std::invalid_argument("the profiles' variance overflows a double (" + g6(out.variance) +
                                " m^2, periodogram sum " + g6(held) + " m^2); heights must be far below 1e150 m");
  out.first_resolved = first_resolved_bin(out, options);
  out.wavenumber.resize(out.psd.size());
  for (std::size_t j = 0; j < out.psd.size(); ++j) out.wavenumber[j] = out.dk * static_cast<double>(j);
  return out;
}
}  // namespace

double EstimatedPsd::resolved_variance() const {
  double v = 0.0;
  for (std::size_t j = first_resolved; j < psd.size(); ++j) v += psd[j] * dk;
  return v;
}

double EstimatedPsd::unresolved_variance() const { return std::max(0.0, variance - resolved_variance()); }

TabulatedPsd estimated_psd_table(const EstimatedPsd& e, Extension extension, std::size_t first_bin) {
  if (first_bin < 1 || first_bin + 2 > e.psd.size())
    throw std::invalid_argument("estimated PSD table: first_bin must be >= 1 and leave at least 2 bins");
  std::vector<double> k(e.wavenumber.begin() + static_cast<std::ptrdiff_t>(first_bin), e.wavenumber.end());
  std::vector<double> g(e.psd.begin() + static_cast<std::ptrdiff_t>(first_bin), e.psd.end());
  return TabulatedPsd(std::move(k), std::move(g), extension);
}

void remove_linear_trend(std::vector<double>& z) {
  const std::size_t n = z.size();
  if (n < 2) return;
  const double xm = 0.5 * static_cast<double>(n - 1);
  double zm = 0.0, sxz = 0.0, sxx = 0.0;
  for (double v : z) zm += v;
  zm /= static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = static_cast<double>(i) - xm;
    sxz += xi * (z[i] - zm);
    sxx += xi * xi;
  }
  const double b = sxz / sxx;
  for (std::size_t i = 0; i < n; ++i) z[i] -= zm + b * (static_cast<double>(i) - xm);
}

void remove_quadratic_surface(Surface& map) {
  // Least squares on centred, scaled coordinates (u, v in [-1, 1]) for a well-conditioned 6x6 system.
  const double cx = 0.5 * static_cast<double>(map.nx - 1), cy = 0.5 * static_cast<double>(map.ny - 1);
  const double sx = std::max(cx, 1.0), sy = std::max(cy, 1.0);
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
  auto basis = [&](std::size_t ix, std::size_t iy) {
    const double u = (static_cast<double>(ix) - cx) / sx, v = (static_cast<double>(iy) - cy) / sy;
    Eigen::Matrix<double, 6, 1> f;
    f << 1.0, u, v, u * u, u * v, v * v;
    return f;
  };
  for (std::size_t iy = 0; iy < map.ny; ++iy)
    for (std::size_t ix = 0; ix < map.nx; ++ix) {
      const auto f = basis(ix, iy);
      a += f * f.transpose();
      b += f * map.at(ix, iy);
    }
  const Eigen::Matrix<double, 6, 1> c = a.ldlt().solve(b);
  for (std::size_t iy = 0; iy < map.ny; ++iy)
    for (std::size_t ix = 0; ix < map.nx; ++ix) map.at(ix, iy) -= basis(ix, iy).dot(c);
}

void median_filter3(std::vector<double>& z) {
  if (z.size() < 3) return;
  std::vector<double> out(z);
  for (std::size_t i = 1; i + 1 < z.size(); ++i) {
    const double a = z[i - 1], b = z[i], c = z[i + 1];
    out[i] = std::max(std::min(a, b), std::min(std::max(a, b), c));
  }
  z.swap(out);
}

std::vector<double> hann_periodogram(const std::vector<double>& z, double dx) {
  if (z.size() < kMinSamples) throw std::invalid_argument("periodogram needs at least 8 samples");
  const spectral::WelchPlan plan(periodogram_config(z.size(), dx));
  spectral::WelchWorkspace ws(z.size());
  std::vector<double> g(plan.n_freq(), 0.0);
  add_periodogram(plan, ws, z, g);
  return g;
}

std::vector<double> longest_wave_leakage(std::size_t n, double dx) {
  if (n < kMinSamples) throw std::invalid_argument("periodogram needs at least 8 samples");
  std::vector<double> c(n), s(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double phase = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    c[i] = std::sqrt(2.0) * std::cos(phase);  // unit variance
    s[i] = std::sqrt(2.0) * std::sin(phase);
  }
  remove_linear_trend(c);
  remove_linear_trend(s);
  std::vector<double> out = hann_periodogram(c, dx);
  const std::vector<double> ps = hann_periodogram(s, dx);
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = 0.5 * (out[j] + ps[j]);  // mean over the phase
  return out;
}

EstimatedPsd profile_psd(const std::vector<Profile>& profiles, const ProfilePsdOptions& options) {
  if (profiles.empty()) throw std::invalid_argument("a PSD from measured profiles needs at least 1 profile, got none");
  const double dx = checked_spacing(profiles.front(), 0);
  std::vector<std::vector<double>> rows;
  rows.reserve(profiles.size());
  for (std::size_t p = 0; p < profiles.size(); ++p) {
    const double dxp = checked_spacing(profiles[p], p);
    if (profiles[p].z.size() != profiles.front().z.size())
      throw std::invalid_argument("profile " + std::to_string(p) + " has " + std::to_string(profiles[p].z.size()) +
                                  " samples but profile 0 has " + std::to_string(profiles.front().z.size()) +
                                  "; periodograms are averaged on one grid");
    if (std::abs(dxp / dx - 1.0) > kSpacingTolerance)
      throw std::invalid_argument("profile " + std::to_string(p) + " has spacing " + g6(dxp) + " m but profile 0 has " +
                                  g6(dx) + " m");
    rows.push_back(profiles[p].z);
    remove_linear_trend(rows.back());  // Eq. 15, 1D
  }
  return average(rows, dx, options);
}

EstimatedPsd map_psd(const Surface& map, const ProfilePsdOptions& options) {
  if (map.ny < 2)
    throw std::invalid_argument("a height map needs at least 2 rows (profiles), got " + std::to_string(map.ny));
  if (map.nx < kMinSamples)
    throw std::invalid_argument("height map rows have " + std::to_string(map.nx) + " samples; at least 8 are needed");
  if (!(map.dx > 0.0) || !(map.dy > 0.0)) throw std::invalid_argument("height map spacings must be positive");
  if (map.heights.size() != map.nx * map.ny) throw std::invalid_argument("height map size does not match nx * ny");
  for (std::size_t i = 0; i < map.heights.size(); ++i)
    if (!std::isfinite(map.heights[i]))
      throw std::invalid_argument("height map sample " + std::to_string(i % map.nx) + ", row " +
                                  std::to_string(i / map.nx) + " is not finite");
  Surface m = map;
  remove_quadratic_surface(m);  // Eq. 15, 2D
  std::vector<std::vector<double>> rows(m.ny);
  for (std::size_t iy = 0; iy < m.ny; ++iy)
    rows[iy].assign(m.heights.begin() + static_cast<std::ptrdiff_t>(iy * m.nx),
                    m.heights.begin() + static_cast<std::ptrdiff_t>((iy + 1) * m.nx));
  return average(rows, m.dx, options);
}

}  // namespace rollspec::texture
