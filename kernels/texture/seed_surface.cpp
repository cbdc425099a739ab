#include "kernels/texture/seed_surface.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rollspec::texture {

namespace {
void validate(const SeedSurfaceSpec& s, const std::vector<double>& d, const std::vector<double>& g) {
  if (s.nx < 2 || s.ny < 2 || s.box_x < 1 || s.box_y < 1)
    throw std::invalid_argument("seed surface: needs nx, ny >= 2 and box lengths n, m >= 1");
  if (!(s.sigma > 0.0) || !std::isfinite(s.sigma))
    throw std::invalid_argument("seed surface: sigma must be positive and finite");
  const std::size_t lx = s.nx + s.box_x - 1, ly = s.ny + s.box_y - 1;
  if (d.size() != lx * ly || g.size() != lx * ly)
    throw std::invalid_argument(
        "seed surface: d and g must hold (nx + n - 1)(ny + m - 1) = " + std::to_string(lx * ly) + " samples (got " +
        std::to_string(d.size()) + ", " + std::to_string(g.size()) + ")");
}

void normalise(Surface& z, double sigma) {  // Eq. 30
  double mean = 0.0;
  for (double v : z.heights) mean += v;
  mean /= static_cast<double>(z.heights.size());
  double var = 0.0;
  for (double v : z.heights) var += (v - mean) * (v - mean);
  var /= static_cast<double>(z.heights.size());
  if (!(var > 0.0)) throw std::invalid_argument("seed surface: the line sum has zero variance (PSD zero on the grid?)");
  const double f = sigma / std::sqrt(var);
  for (double& v : z.heights) v = (v - mean) * f;
}

// rho(tau) -> first 1/e crossing by linear interpolation, in samples; NaN if none in range.
template <class F>
double crossing(F&& r, double r0, std::size_t max_tau) {
  const double target = std::exp(-1.0);
  double prev = 1.0;
  for (std::size_t t = 1; t <= max_tau; ++t) {
    const double rho = r(t) / r0;
    if (rho <= target) return static_cast<double>(t - 1) + (prev - target) / (prev - rho);
    prev = rho;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double lag(const std::vector<double>& r, long s) { return r[static_cast<std::size_t>(std::abs(s))]; }
}  // namespace

Surface seed_surface(const SeedSurfaceSpec& s, const std::vector<double>& d, const std::vector<double>& g) {
  validate(s, d, g);
  const std::size_t lx = s.nx + s.box_x - 1, ly = s.ny + s.box_y - 1;
  // Summed-area table of a(k, l) = d_kl + g_lk on (lx + 1) x (ly + 1), then box sums (Eq. 29).
  std::vector<double> sat((lx + 1) * (ly + 1), 0.0);
  for (std::size_t l = 0; l < ly; ++l)
    for (std::size_t k = 0; k < lx; ++k) {
      const double a = d[l * lx + k] + g[k * ly + l];
      sat[(l + 1) * (lx + 1) + k + 1] =
          a + sat[l * (lx + 1) + k + 1] + sat[(l + 1) * (lx + 1) + k] - sat[l * (lx + 1) + k];
    }
  Surface z(s.nx, s.ny, s.dx, s.dy);
  const std::size_t n = s.box_x, m = s.box_y, w = lx + 1;
  for (std::size_t j = 0; j < s.ny; ++j)
    for (std::size_t i = 0; i < s.nx; ++i)
      z.at(i, j) = 0.5 * (sat[(j + m) * w + i + n] - sat[j * w + i + n] - sat[(j + m) * w + i] + sat[j * w + i]);
  normalise(z, s.sigma);
  return z;
}

Surface seed_surface_direct(const SeedSurfaceSpec& s, const std::vector<double>& d, const std::vector<double>& g) {
  validate(s, d, g);
  const std::size_t lx = s.nx + s.box_x - 1, ly = s.ny + s.box_y - 1;
  Surface z(s.nx, s.ny, s.dx, s.dy);
  for (std::size_t i = 0; i < s.nx; ++i)
    for (std::size_t j = 0; j < s.ny; ++j) {
      double acc = 0.0;
      for (std::size_t k = i; k < i + s.box_x; ++k)
        for (std::size_t l = j; l < j + s.box_y; ++l) acc += (d[l * lx + k] + g[k * ly + l]) / 2.0;
      z.at(i, j) = acc;
    }
  normalise(z, s.sigma);
  return z;
}

std::vector<double> line_autocovariance(const LineTextureGenerator& lines, std::size_t max_lag) {
  const std::vector<double>& gj = lines.target_psd();
  const double dk = lines.fundamental(), dx = lines.spec().spacing;
  std::vector<double> r(max_lag + 1, 0.0);
  for (std::size_t s = 0; s <= max_lag; ++s)
    for (std::size_t j = 1; j < gj.size(); ++j)
      r[s] += gj[j] * dk * std::cos(dk * static_cast<double>(j) * dx * static_cast<double>(s));
  return r;
}

SeedCorrelation seed_expected_correlation(const std::vector<double>& rx, const std::vector<double>& ry, std::size_t n,
                                          std::size_t m, double dx, double dy) {
  const long ln = static_cast<long>(n), lm = static_cast<long>(m);
  if (rx.size() < n + 1 || ry.size() < m + 1) throw std::invalid_argument("seed correlation: autocovariance too short");
  double ax = 0.0, ay = 0.0;  // sum_{|s|<n} (n - |s|) R_x(s), same for y
  for (long s = -(ln - 1); s < ln; ++s) ax += static_cast<double>(ln - std::abs(s)) * lag(rx, s);
  for (long s = -(lm - 1); s < lm; ++s) ay += static_cast<double>(lm - std::abs(s)) * lag(ry, s);
  auto rzx = [&](std::size_t tau) {  // Eq. 31 along x (times 4)
    const long t = static_cast<long>(tau);
    double acc = 0.0;
    for (long s = -(ln - 1); s < ln; ++s) acc += static_cast<double>(ln - std::abs(s)) * lag(rx, t + s);
    return static_cast<double>(m) * acc + static_cast<double>(std::max(0L, ln - t)) * ay;
  };
  auto rzy = [&](std::size_t tau) {
    const long t = static_cast<long>(tau);
    double acc = 0.0;
    for (long s = -(lm - 1); s < lm; ++s) acc += static_cast<double>(lm - std::abs(s)) * lag(ry, t + s);
    return static_cast<double>(n) * acc + static_cast<double>(std::max(0L, lm - t)) * ax;
  };
  SeedCorrelation c;
  c.x = dx * crossing(rzx, rzx(0), rx.size() - n);
  c.y = dy * crossing(rzy, rzy(0), ry.size() - m);
  return c;
}

SeedBoxLengths seed_box_lengths(const std::vector<double>& rx, const std::vector<double>& ry, double dx, double dy,
                                double correlation_x, double correlation_y) {
  if (!(correlation_x > 0.0) || !(correlation_y > 0.0))
    throw std::invalid_argument("seed surface: correlation lengths must be positive");
  const std::size_t max_n = (rx.size() - 1) / 2, max_m = (ry.size() - 1) / 2;
  SeedBoxLengths b;
  auto miss = [](double got, double want) {
    return std::isnan(got) ? std::numeric_limits<double>::infinity() : std::abs(got - want);
  };
  for (int sweep = 0; sweep < 20; ++sweep) {  // coordinate descent: n and m interact only weakly
    const SeedBoxLengths before = b;
    // One box length along one axis, the other held: the 1/e length grows with it, so stop once past
    // the target.
    const auto search = [&](std::size_t max_len, double target, std::size_t& len, auto&& length_of) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t n = 1; n <= max_len; ++n) {
        const double got = length_of(n);
        const double e = miss(got, target);
        if (e < best) {
          best = e;
          len = n;
        } else if (got > target)
          break;
      }
    };
    search(max_n, correlation_x, b.box_x,
           [&](std::size_t n) { return seed_expected_correlation(rx, ry, n, b.box_y, dx, dy).x; });
    search(max_m, correlation_y, b.box_y,
           [&](std::size_t m) { return seed_expected_correlation(rx, ry, b.box_x, m, dx, dy).y; });
    if (b.box_x == before.box_x && b.box_y == before.box_y) break;
  }
  b.expected = seed_expected_correlation(rx, ry, b.box_x, b.box_y, dx, dy);
  return b;
}

SeedSurfaceGenerator::SeedSurfaceGenerator(const Psd& psd, const SeedSurfaceRequest& rq) {
  if (rq.nx < 2 || rq.ny < 2) throw std::invalid_argument("seed surface: nx, ny must be >= 2");
  const std::size_t max_box = rq.max_box ? rq.max_box : std::min(rq.nx, rq.ny);
  // One synthesis period per direction for every candidate n, m, so Eq. 31 uses the lines' exact R.
  LineTextureSpec sx{rq.nx + max_box - 1, rq.dx, 0, rq.amplitudes, rq.allow_truncation};
  LineTextureSpec sy{rq.ny + max_box - 1, rq.dy, 0, rq.amplitudes, rq.allow_truncation};
  sx.period = fast_even_length(2 * sx.samples);
  sy.period = fast_even_length(2 * sy.samples);
  const LineTextureGenerator probe_x(psd, sx), probe_y(psd, sy);
  // Eq. 30 scales the surface to sigma: a PSD with no power on the grid's harmonics has nothing to scale.
  if (!(probe_x.target_variance() > 0.0) || !(probe_y.target_variance() > 0.0))
    throw std::invalid_argument("seed surface: the PSD is zero at every wavenumber the grid holds (" +
                                std::to_string(probe_x.fundamental()) + " to " +
                                std::to_string(probe_x.fundamental() * static_cast<double>(probe_x.harmonics() - 1)) +
                                " rad/m); allowed: a grid spacing and size that reach the PSD's band");
  const std::vector<double> rx = line_autocovariance(probe_x, 2 * max_box + rq.nx);
  const std::vector<double> ry = line_autocovariance(probe_y, 2 * max_box + rq.ny);
  box_ = seed_box_lengths(rx, ry, rq.dx, rq.dy, rq.correlation_x, rq.correlation_y);
  spec_ = SeedSurfaceSpec{rq.nx, rq.ny, rq.dx, rq.dy, box_.box_x, box_.box_y, rq.sigma};
  sx.samples = rq.nx + box_.box_x - 1;
  sy.samples = rq.ny + box_.box_y - 1;
  along_x_ = std::make_unique<LineTextureGenerator>(psd, sx);
  along_y_ = std::make_unique<LineTextureGenerator>(psd, sy);
}

std::size_t SeedSurfaceGenerator::random_count() const {
  const std::size_t lx = spec_.nx + spec_.box_x - 1, ly = spec_.ny + spec_.box_y - 1;
  return 2 * (ly * along_x_->harmonics() + lx * along_y_->harmonics());
}

void SeedSurfaceGenerator::generate(const double* u, Surface& out) const {
  const std::size_t lx = spec_.nx + spec_.box_x - 1, ly = spec_.ny + spec_.box_y - 1;
  const std::size_t hx = along_x_->harmonics(), hy = along_y_->harmonics();
  std::vector<double> d(lx * ly), g(lx * ly);
  SynthesisScratch sx = along_x_->make_scratch(), sy = along_y_->make_scratch();
  for (std::size_t l = 0; l < ly; ++l, u += 2 * hx) along_x_->generate(u, u + hx, d.data() + l * lx, sx);
  for (std::size_t k = 0; k < lx; ++k, u += 2 * hy) along_y_->generate(u, u + hy, g.data() + k * ly, sy);
  out = seed_surface(spec_, d, g);
}

}  // namespace rollspec::texture
