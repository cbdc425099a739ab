#include "kernels/texture/statistics.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernels/spectral/fftw_handles.hpp"

namespace rollspec::texture {

namespace {
struct Moments {
  double mean, rms, skew, kurt;
};
Moments moments(const double* h, std::size_t n) {
  if (n < 2) throw std::invalid_argument("statistics need at least 2 samples");
  double m = 0.0;
  for (std::size_t i = 0; i < n; ++i) m += h[i];
  m /= static_cast<double>(n);
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = h[i] - m, d2 = d * d;
    m2 += d2;
    m3 += d2 * d;
    m4 += d2 * d2;
  }
  const double inv = 1.0 / static_cast<double>(n);
  m2 *= inv;
  m3 *= inv;
  m4 *= inv;
  const double rq = std::sqrt(m2);
  return {m, rq, m2 > 0.0 ? m3 / (m2 * rq) : 0.0, m2 > 0.0 ? m4 / (m2 * m2) : 0.0};
}

// Autocovariance sums s(tau) = sum_i z_i z_{i+tau} for a batch of sequences (stride apart),
// accumulated over the batch, by FFT of length >= 2n (no wrap-around).
class AcfPlan {
 public:
  explicit AcfPlan(std::size_t n)
      : n_(n),
        m_(2 * n),
        in_(m_),
        spec_(m_ / 2 + 1),
        fwd_([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(m_), in_.data(), spec_.data(), FFTW_ESTIMATE); },
             "autocorrelation (r2c)"),
        bwd_([&] { return fftw_plan_dft_c2r_1d(static_cast<int>(m_), spec_.data(), in_.data(), FFTW_ESTIMATE); },
             "autocorrelation (c2r)") {}
  AcfPlan(const AcfPlan&) = delete;
  AcfPlan& operator=(const AcfPlan&) = delete;

  // Adds |Z|^2 of one sequence (n values at stride, minus mean) to acc (m/2+1 values).
  void add(const double* z, std::size_t stride, double mean, std::vector<double>& acc) {
    for (std::size_t i = 0; i < n_; ++i) in_[i] = z[i * stride] - mean;
    std::fill(in_.data() + n_, in_.data() + m_, 0.0);
    fftw_execute(fwd_.get());
    for (std::size_t k = 0; k < acc.size(); ++k) acc[k] += spec_[k][0] * spec_[k][0] + spec_[k][1] * spec_[k][1];
  }
  // rho(0..max_lag) from the accumulated power.
  std::vector<double> finish(const std::vector<double>& acc, std::size_t max_lag) {
    for (std::size_t k = 0; k < acc.size(); ++k) {
      spec_[k][0] = acc[k];
      spec_[k][1] = 0.0;
    }
    fftw_execute(bwd_.get());
    std::vector<double> rho(std::min(max_lag, n_ - 1) + 1);
    for (std::size_t t = 0; t < rho.size(); ++t) rho[t] = in_[t] / in_[0];
    return rho;
  }
  std::size_t spectrum_size() const { return m_ / 2 + 1; }

 private:
  std::size_t n_, m_;
  spectral::RealBuffer in_;
  spectral::ComplexBuffer spec_;
  spectral::FftwPlan fwd_, bwd_;  // after the buffers: destroyed before them
};
}  // namespace

std::vector<double> autocorrelation(const double* h, std::size_t n, std::size_t max_lag) {
  if (n < 2) throw std::invalid_argument("autocorrelation needs at least 2 samples");
  const Moments mo = moments(h, n);
  AcfPlan plan(n);
  std::vector<double> acc(plan.spectrum_size(), 0.0);
  plan.add(h, 1, mo.mean, acc);
  return plan.finish(acc, max_lag);
}

std::vector<double> autocorrelation_direct(const double* h, std::size_t n, std::size_t max_lag) {
  const Moments mo = moments(h, n);
  std::vector<double> r(std::min(max_lag, n - 1) + 1, 0.0);
  for (std::size_t t = 0; t < r.size(); ++t)
    for (std::size_t i = 0; i + t < n; ++i) r[t] += (h[i] - mo.mean) * (h[i + t] - mo.mean);
  const double r0 = r[0];
  for (double& v : r) v /= r0;
  return r;
}

std::vector<double> surface_autocorrelation(const Surface& s, int axis, std::size_t max_lag) {
  const Moments mo = moments(s.heights.data(), s.heights.size());
  const std::size_t len = axis == 0 ? s.nx : s.ny, count = axis == 0 ? s.ny : s.nx;
  const std::size_t stride = axis == 0 ? 1 : s.nx, step = axis == 0 ? s.nx : 1;
  AcfPlan plan(len);
  std::vector<double> acc(plan.spectrum_size(), 0.0);
  for (std::size_t c = 0; c < count; ++c) plan.add(s.heights.data() + c * step, stride, mo.mean, acc);
  return plan.finish(acc, max_lag);
}

double correlation_length_from_acf(const std::vector<double>& rho, double spacing) {
  const double target = std::exp(-1.0);
  for (std::size_t t = 1; t < rho.size(); ++t)
    if (rho[t] <= target) {
      const double frac = (rho[t - 1] - target) / (rho[t - 1] - rho[t]);  // linear between samples t-1, t
      return (static_cast<double>(t - 1) + frac) * spacing;
    }
  return std::numeric_limits<double>::quiet_NaN();
}

HeightStatistics line_statistics(const double* h, std::size_t n, double dx) {
  const Moments mo = moments(h, n);
  HeightStatistics st;
  st.mean = mo.mean;
  st.rms = mo.rms;
  st.skewness = mo.skew;
  st.kurtosis = mo.kurt;
  st.correlation_length_x = correlation_length_from_acf(autocorrelation(h, n, n - 1), dx);
  st.correlation_length_y = std::numeric_limits<double>::quiet_NaN();
  return st;
}

HeightStatistics surface_statistics(const Surface& s) {
  if (s.heights.size() != s.nx * s.ny || s.nx < 2 || s.ny < 2)
    throw std::invalid_argument("surface statistics: bad surface size");
  const Moments mo = moments(s.heights.data(), s.heights.size());
  HeightStatistics st;
  st.mean = mo.mean;
  st.rms = mo.rms;
  st.skewness = mo.skew;
  st.kurtosis = mo.kurt;
  st.correlation_length_x = correlation_length_from_acf(surface_autocorrelation(s, 0, s.nx - 1), s.dx);
  st.correlation_length_y = correlation_length_from_acf(surface_autocorrelation(s, 1, s.ny - 1), s.dy);
  return st;
}

HeightStatistics mean_statistics(const std::vector<HeightStatistics>& all) {
  if (all.empty()) throw std::invalid_argument("mean statistics of an empty ensemble");
  HeightStatistics m;
  double nx = 0.0, ny = 0.0;
  for (const HeightStatistics& s : all) {
    m.mean += s.mean;
    m.rms += s.rms;
    m.skewness += s.skewness;
    m.kurtosis += s.kurtosis;
    if (std::isfinite(s.correlation_length_x)) {
      m.correlation_length_x += s.correlation_length_x;
      nx += 1.0;
    }
    if (std::isfinite(s.correlation_length_y)) {
      m.correlation_length_y += s.correlation_length_y;
      ny += 1.0;
    }
  }
  const double n = static_cast<double>(all.size());
  m.mean /= n;
  m.rms /= n;
  m.skewness /= n;
  m.kurtosis /= n;
  m.correlation_length_x = nx > 0.0 ? m.correlation_length_x / nx : std::numeric_limits<double>::quiet_NaN();
  m.correlation_length_y = ny > 0.0 ? m.correlation_length_y / ny : std::numeric_limits<double>::quiet_NaN();
  return m;
}

HeightStatistics std_statistics(const std::vector<HeightStatistics>& all) {
  const HeightStatistics m = mean_statistics(all);
  const auto spread = [&](double HeightStatistics::*field) {
    double sum = 0.0, n = 0.0;
    for (const HeightStatistics& s : all)
      if (std::isfinite(s.*field)) {
        sum += (s.*field - m.*field) * (s.*field - m.*field);
        n += 1.0;
      }
    return n >= 2.0 ? std::sqrt(sum / (n - 1.0)) : std::numeric_limits<double>::quiet_NaN();
  };
  HeightStatistics d;
  d.mean = spread(&HeightStatistics::mean);
  d.rms = spread(&HeightStatistics::rms);
  d.skewness = spread(&HeightStatistics::skewness);
  d.kurtosis = spread(&HeightStatistics::kurtosis);
  d.correlation_length_x = spread(&HeightStatistics::correlation_length_x);
  d.correlation_length_y = spread(&HeightStatistics::correlation_length_y);
  return d;
}

std::vector<double> surface_periodogram(const Surface& s) {
  if (s.heights.size() != s.nx * s.ny || s.nx < 2 || s.ny < 2)
    throw std::invalid_argument("surface periodogram: bad surface size");
  const std::size_t nh = s.nx / 2 + 1;
  const spectral::RealBuffer in(s.nx * s.ny);
  const spectral::ComplexBuffer out(s.ny * nh);
  const spectral::FftwPlan plan(
      [&] {
        return fftw_plan_dft_r2c_2d(static_cast<int>(s.ny), static_cast<int>(s.nx), in.data(), out.data(),
                                    FFTW_ESTIMATE);
      },
      "surface periodogram (2D r2c)");
  const Moments mo = moments(s.heights.data(), s.heights.size());
  for (std::size_t i = 0; i < s.heights.size(); ++i) in[i] = s.heights[i] - mo.mean;
  fftw_execute(plan.get());
  const double scale = s.dx * s.dy / static_cast<double>(s.nx * s.ny);  // Eq. 25
  std::vector<double> c(s.ny * nh);
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = scale * (out[i][0] * out[i][0] + out[i][1] * out[i][1]);
  return c;
}

RadialPsd radially_averaged_psd(const Surface& s) {
  const std::vector<double> c = surface_periodogram(s);
  const std::size_t nh = s.nx / 2 + 1;
  const double dqx = 2.0 * M_PI / (static_cast<double>(s.nx) * s.dx),
               dqy = 2.0 * M_PI / (static_cast<double>(s.ny) * s.dy);
  RadialPsd r;
  r.dq = std::max(dqx, dqy);
  const double qmax = std::sqrt(std::pow(M_PI / s.dx, 2) + std::pow(M_PI / s.dy, 2));
  const auto nb = static_cast<std::size_t>(qmax / r.dq) + 2;
  std::vector<double> sum_c(nb, 0.0), sum_q(nb, 0.0), w(nb, 0.0);
  for (std::size_t iy = 0; iy < s.ny; ++iy) {
    const double qy =
        dqy * (iy <= s.ny / 2 ? static_cast<double>(iy) : static_cast<double>(iy) - static_cast<double>(s.ny));
    for (std::size_t ix = 0; ix < nh; ++ix) {
      // Modes 0 < ix < nx/2 stand for +q and -q (Hermitian pair): weight 2.
      const double weight = (ix == 0 || (s.nx % 2 == 0 && ix == nh - 1)) ? 1.0 : 2.0;
      const double q = std::hypot(dqx * static_cast<double>(ix), qy);
      const auto b = static_cast<std::size_t>(std::floor(q / r.dq + 0.5));
      if (b >= nb) continue;
      sum_c[b] += weight * c[iy * nh + ix];
      sum_q[b] += weight * q;
      w[b] += weight;
    }
  }
  for (std::size_t b = 1; b < nb; ++b)  // bin 0 holds only DC (zero after mean removal): skipped
    if (w[b] > 0.0) {
      r.q.push_back(sum_q[b] / w[b]);
      r.psd.push_back(sum_c[b] / w[b]);
      r.modes.push_back(w[b]);
    }
  return r;
}

}  // namespace rollspec::texture
