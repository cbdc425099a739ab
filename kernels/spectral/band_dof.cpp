#include "kernels/spectral/band_dof.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "kernels/spectral/fftw_handles.hpp"

namespace rollspec::spectral {

namespace {

using Complex = std::complex<double>;

// e^{-2 pi i k t / L} with the phase reduced exactly (k t mod L) before it is scaled.
Complex unit(std::size_t k, std::size_t t, std::size_t L) {
  const double phase = 2.0 * M_PI * static_cast<double>((k * t) % L) / static_cast<double>(L);
  return {std::cos(phase), -std::sin(phase)};
}

// u_k(t) of D-33c a: the windowed Fourier kernel of bin k, less W_k / L where each segment's mean is removed.
std::vector<Complex> kernel(const std::vector<double>& w, std::size_t k, bool detrend) {
  const std::size_t L = w.size();
  std::vector<Complex> u(L);
  Complex total = 0.0;
  for (std::size_t t = 0; t < L; ++t) total += (u[t] = w[t] * unit(k, t, L));
  if (detrend)
    for (auto& x : u) x -= total / static_cast<double>(L);
  return u;
}

// |G_m(k, k')|^2 + |P_m(k, k')|^2 for the kernels u of k and v of k', segments `shift` = m S samples apart.
double pair_power(const std::vector<Complex>& u, const std::vector<Complex>& v, std::size_t shift) {
  Complex g = 0.0, p = 0.0;
  for (std::size_t t = shift; t < u.size(); ++t) {
    g += u[t] * std::conj(v[t - shift]);
    p += u[t] * v[t - shift];
  }
  return std::norm(g) + std::norm(p);
}

// The weights a_k: the band's bin weights times the one-sided factor (1 at DC and at an even L's Nyquist bin).
std::vector<double> one_sided(const BandWeights& b, std::size_t L) {
  std::vector<double> a(b.weight);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t k = b.first + i;
    a[i] *= (k == 0 || (L % 2 == 0 && k == L / 2)) ? 1.0 : 2.0;
  }
  return a;
}

// nu_b = 2 e^2 / var from e = E P_b per segment and the pair sums t[m] of the lags m S < L (D-33c a).
double dof_from_sums(std::size_t segments, double e, const std::vector<double>& t) {
  const double nb = static_cast<double>(segments);
  double var = nb * t[0];
  for (std::size_t m = 1; m < t.size() && m < segments; ++m) var += 2.0 * (nb - static_cast<double>(m)) * t[m];
  var /= nb * nb;
  return var > 0.0 ? 2.0 * e * e / var : 0.0;
}

}  // namespace

BandWeights band_weights(std::size_t n, double df, double lower, double upper) {
  if (!(upper > lower)) throw std::invalid_argument("band upper edge must exceed lower edge");
  BandWeights b;
  const auto k0 = static_cast<std::size_t>(std::max(0.0, std::floor(lower / df - 0.5)));
  for (std::size_t k = k0; k < n; ++k) {
    const double a = (static_cast<double>(k) - 0.5) * df, c = (static_cast<double>(k) + 0.5) * df;
    if (a >= upper) break;
    const double overlap = std::min(c, upper) - std::max(a, lower);
    if (!(overlap > 0.0)) continue;
    if (b.weight.empty()) b.first = k;
    b.weight.resize(k - b.first + 1, 0.0);
    b.weight.back() = overlap / (upper - lower);
  }
  return b;
}

BandDof::BandDof(const WelchConfig& config) : config_(config) {
  const WelchPlan plan(config);  // checks the configuration
  window_ = plan.window();
  const std::size_t L = config.segment, step = L - config.overlap, nf = L / 2 + 1;
  RealBuffer in(L);
  ComplexBuffer out(nf);
  const FftwPlan fft([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(L), in.data(), out.data(), FFTW_ESTIMATE); },
                     "band dof (r2c)");
  for (std::size_t m = 0; m * step < L; ++m) {  // R_m: the DFT of the window products of segments m apart
    for (std::size_t t = 0; t < L; ++t) in[t] = t >= m * step ? window_[t] * window_[t - m * step] : 0.0;
    fftw_execute_dft_r2c(fft.get(), in.data(), out.data());
    std::vector<double> r2(nf);
    for (std::size_t j = 0; j < nf; ++j) r2[j] = out[j][0] * out[j][0] + out[j][1] * out[j][1];
    r2_.push_back(std::move(r2));
  }
  lobe_.assign(nf, false);
  if (config.detrend == Detrend::constant) {  // W_k: the bins where the mean's removal changes the kernel
    for (std::size_t t = 0; t < L; ++t) in[t] = window_[t];
    fftw_execute_dft_r2c(fft.get(), in.data(), out.data());
    const double w0 = std::fabs(out[0][0]);
    for (std::size_t k = 0; k < nf; ++k) lobe_[k] = std::hypot(out[k][0], out[k][1]) > 1e-10 * w0;
  }
}

double BandDof::operator()(std::size_t samples, double lower, double upper) const {
  const std::size_t L = config_.segment, step = L - config_.overlap, nf = L / 2 + 1;
  const std::size_t segments = samples < L ? 0 : (samples - config_.overlap) / step;
  const BandWeights b = band_weights(nf, config_.sample_rate / static_cast<double>(L), lower, upper);
  if (segments == 0 || b.weight.empty()) return 0.0;
  const std::vector<double> a = one_sided(b, L);
  const std::size_t n = a.size();
  const auto r2 = [&](std::size_t m, std::size_t j) {  // |R_m(j)|^2 for any j >= 0 (R_m(-j) = conj R_m(j))
    j %= L;
    return r2_[m][j <= L / 2 ? j : L - j];
  };
  std::vector<std::vector<Complex>> u(n);  // direct kernels, only where a bin of the band is in the lobe
  bool any_lobe = false;
  for (std::size_t i = 0; i < n; ++i) any_lobe = any_lobe || lobe_[b.first + i];
  if (any_lobe)
    for (std::size_t i = 0; i < n; ++i) u[i] = kernel(window_, b.first + i, true);
  double e = 0.0;  // sum_k a_k G_0(k, k): R_0(0) = sum_t w_t^2 outside the lobe, sum_t |u_k(t)|^2 in it
  for (std::size_t i = 0; i < n; ++i) {
    double g = 0.0;
    if (lobe_[b.first + i])
      for (const Complex& x : u[i]) g += std::norm(x);
    else
      g = std::sqrt(r2(0, 0));
    e += a[i] * g;
  }
  std::vector<double> t(r2_.size(), 0.0);
  for (std::size_t m = 0; m < r2_.size(); ++m)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t k = b.first + i, kk = b.first + j;
        const double power =
            lobe_[k] || lobe_[kk] ? pair_power(u[i], u[j], m * step) : r2(m, k > kk ? k - kk : kk - k) + r2(m, k + kk);
        t[m] += a[i] * a[j] * power;
      }
  return dof_from_sums(segments, e, t);
}

double BandDof::mean_sum(double lower, double upper) const {
  const std::size_t L = config_.segment, nf = L / 2 + 1;
  const BandWeights b = band_weights(nf, config_.sample_rate / static_cast<double>(L), lower, upper);
  const std::vector<double> a = one_sided(b, L);
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    double g = std::sqrt(r2_[0][0]);  // R_0(0) = sum_t w_t^2 outside the lobe
    if (lobe_[b.first + i]) {
      g = 0.0;
      for (const Complex& x : kernel(window_, b.first + i, true)) g += std::norm(x);
    }
    e += a[i] * g;
  }
  return e;
}

double BandDof::pair_sum(std::size_t samples, double lower_b, double upper_b, double lower_c, double upper_c) const {
  const std::size_t L = config_.segment, step = L - config_.overlap, nf = L / 2 + 1;
  const std::size_t segments = samples < L ? 0 : (samples - config_.overlap) / step;
  const double df = config_.sample_rate / static_cast<double>(L);
  const BandWeights wb = band_weights(nf, df, lower_b, upper_b), wc = band_weights(nf, df, lower_c, upper_c);
  if (segments == 0 || wb.weight.empty() || wc.weight.empty()) return 0.0;
  const std::vector<double> ab = one_sided(wb, L), ac = one_sided(wc, L);
  const auto r2 = [&](std::size_t m, std::size_t j) {
    j %= L;
    return r2_[m][j <= L / 2 ? j : L - j];
  };
  const auto kernels = [&](const BandWeights& w, std::size_t n) {  // direct kernels of the band's lobe bins only
    std::vector<std::vector<Complex>> u(n);
    for (std::size_t i = 0; i < n; ++i)
      if (lobe_[w.first + i]) u[i] = kernel(window_, w.first + i, true);
    return u;
  };
  const auto ub = kernels(wb, ab.size()), uc = kernels(wc, ac.size());
  const double nb = static_cast<double>(segments);
  double total = 0.0;
  for (std::size_t m = 0; m < r2_.size() && m < segments; ++m) {
    // Lags +m and -m: |G_{-m}(k, k')| = |G_m(k', k)|, so the pair's two orders (equal outside the lobe).
    double t = 0.0;
    for (std::size_t i = 0; i < ab.size(); ++i)
      for (std::size_t j = 0; j < ac.size(); ++j) {
        const std::size_t k = wb.first + i, kk = wc.first + j;
        double power = 0.0;
        if (lobe_[k] || lobe_[kk]) {
          const auto& u = ub[i].empty() ? kernel(window_, k, true) : ub[i];
          const auto& v = uc[j].empty() ? kernel(window_, kk, true) : uc[j];
          power = pair_power(u, v, m * step) + (m > 0 ? pair_power(v, u, m * step) : 0.0);
        } else {
          power = (m > 0 ? 2.0 : 1.0) * (r2(m, k > kk ? k - kk : kk - k) + r2(m, k + kk));
        }
        t += ab[i] * ac[j] * power;
      }
    total += (nb - static_cast<double>(m)) * t;
  }
  return total / (nb * nb);
}

double band_dof_reference(const WelchConfig& config, std::size_t samples, double lower, double upper) {
  const WelchPlan plan(config);
  const std::size_t L = config.segment, step = L - config.overlap, segments = plan.segments(samples);
  const BandWeights b = band_weights(plan.n_freq(), plan.frequency_step(), lower, upper);
  if (segments == 0 || b.weight.empty()) return 0.0;
  const std::vector<double> a = one_sided(b, L);
  std::vector<std::vector<Complex>> u;
  for (std::size_t i = 0; i < a.size(); ++i)
    u.push_back(kernel(plan.window(), b.first + i, config.detrend == Detrend::constant));
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (const Complex& x : u[i]) e += a[i] * std::norm(x);
  std::vector<double> t;
  for (std::size_t m = 0; m * step < L; ++m) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < a.size(); ++j) s += a[i] * a[j] * pair_power(u[i], u[j], m * step);
    t.push_back(s);
  }
  return dof_from_sums(segments, e, t);
}

}  // namespace rollspec::spectral
