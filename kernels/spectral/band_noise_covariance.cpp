#include "kernels/spectral/band_noise_covariance.hpp"

#include <fftw3.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "kernels/spectral/fftw_handles.hpp"
#include "kernels/spectral/third_octave_bands.hpp"

namespace rollspec::spectral {

BandNoiseCovariance::BandNoiseCovariance(const WelchConfig& config, std::size_t samples, std::vector<double> lower,
                                         std::vector<double> upper)
    : config_(config), samples_(samples), lower_(std::move(lower)), upper_(std::move(upper)) {
  const WelchPlan plan(config);  // checks the configuration
  const std::size_t L = config.segment, nf = L / 2 + 1;
  segments_ = plan.segments(samples);
  if (segments_ == 0) throw std::invalid_argument("band noise covariance: a roll shorter than one segment");
  if (lower_.size() != upper_.size() || lower_.empty())
    throw std::invalid_argument("band noise covariance: needs as many lower as upper band edges, at least one");
  window_ = plan.window();
  double w2 = 0.0;
  for (double w : window_) w2 += w * w;
  lobe_re_.assign(nf, 0.0);
  lobe_im_.assign(nf, 0.0);
  if (config.detrend == Detrend::constant) {  // W_k: the window's DFT
    RealBuffer in(L);
    ComplexBuffer out(nf);
    const FftwPlan fft([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(L), in.data(), out.data(), FFTW_ESTIMATE); },
                       "band noise covariance (window)");
    for (std::size_t t = 0; t < L; ++t) in[t] = window_[t];
    fftw_execute_dft_r2c(fft.get(), in.data(), out.data());
    for (std::size_t k = 0; k < nf; ++k) {
      lobe_re_[k] = out[k][0];
      lobe_im_[k] = out[k][1];
    }
  }
  const double scale = 1.0 / (config.sample_rate * w2);  // D-15's density scale
  const BandDof dof(config);
  const std::size_t p = lower_.size();
  for (std::size_t b = 0; b < p; ++b) {
    BandWeights w = band_weights(nf, plan.frequency_step(), lower_[b], upper_[b]);
    if (w.weight.empty()) throw std::invalid_argument("band noise covariance: a band without a bin");
    for (std::size_t i = 0; i < w.weight.size(); ++i) {
      const std::size_t k = w.first + i;
      w.weight[i] *= ((k == 0 || (L % 2 == 0 && k == L / 2)) ? 1.0 : 2.0) * scale;
    }
    weights_.push_back(std::move(w));
    trace_.push_back(scale * dof.mean_sum(lower_[b], upper_[b]));
  }
  trace_product_.assign(p * p, 0.0);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = b; c < p; ++c)  // cov(P_b, P_c) = 2 tr(Q_b Q_c) for unit Gaussian samples
      trace_product_[b * p + c] = trace_product_[c * p + b] =
          0.5 * scale * scale * dof.pair_sum(samples, lower_[b], upper_[b], lower_[c], upper_[c]);
}

std::vector<double> BandNoiseCovariance::gram(const double* x) const {
  const std::size_t L = config_.segment, step = L - config_.overlap, nf = L / 2 + 1, p = bands();
  RealBuffer real(L);
  ComplexBuffer spectrum(nf), half(nf);
  const FftwPlan forward(
      [&] { return fftw_plan_dft_r2c_1d(static_cast<int>(L), real.data(), spectrum.data(), FFTW_ESTIMATE); },
      "band noise covariance (r2c)");
  const FftwPlan inverse(
      [&] { return fftw_plan_dft_c2r_1d(static_cast<int>(L), half.data(), real.data(), FFTW_ESTIMATE); },
      "band noise covariance (c2r)");
  std::vector<double> q(p * samples_, 0.0), g(p * p);
  const double inv = 1.0 / static_cast<double>(segments_);
  for (std::size_t s = 0; s < segments_; ++s) {
    const double* xs = x + s * step;
    double mean = 0.0;
    for (std::size_t t = 0; t < L; ++t) mean += xs[t] / static_cast<double>(L);
    for (std::size_t t = 0; t < L; ++t) real[t] = window_[t] * xs[t];
    fftw_execute_dft_r2c(forward.get(), real.data(), spectrum.data());
    for (std::size_t k = 0; k < nf; ++k) {  // y_k = sum_t x_t (w_t e^{-2 pi i k t / L} - W_k / L)
      spectrum[k][0] -= mean * lobe_re_[k];
      spectrum[k][1] -= mean * lobe_im_[k];
    }
    for (std::size_t b = 0; b < p; ++b) {
      // sum_k a_k Re(conj(y_k) u_k(t)) = w_t Re(sum_k a_k y_k e^{2 pi i k t / L}) - Re(sum_k a_k conj(y_k) W_k) / L;
      // c2r sums D_0 + 2 Re sum_{0<k<L/2} D_k e^{..} + D_{L/2} (-1)^t: D_k = a_k y_k / 2 inside, a_k Re y_k at the
      // ends.
      const BandWeights& w = weights_[b];
      for (std::size_t k = 0; k < nf; ++k) half[k][0] = half[k][1] = 0.0;
      double lobe = 0.0;
      for (std::size_t i = 0; i < w.weight.size(); ++i) {
        const std::size_t k = w.first + i;
        const double a = w.weight[i] * inv, end = (k == 0 || (L % 2 == 0 && k == L / 2)) ? 1.0 : 0.5;
        half[k][0] = a * end * spectrum[k][0];
        half[k][1] = end == 1.0 ? 0.0 : a * end * spectrum[k][1];
        lobe += a * (spectrum[k][0] * lobe_re_[k] + spectrum[k][1] * lobe_im_[k]);
      }
      fftw_execute_dft_c2r(inverse.get(), half.data(), real.data());
      double* qb = q.data() + b * samples_ + s * step;
      for (std::size_t t = 0; t < L; ++t) qb[t] += window_[t] * real[t] - lobe / static_cast<double>(L);
    }
  }
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = b; c < p; ++c) {
      double sum = 0.0;
      for (std::size_t t = 0; t < samples_; ++t) sum += q[b * samples_ + t] * q[c * samples_ + t];
      g[b * p + c] = g[c * p + b] = sum;
    }
  return g;
}

std::vector<double> BandNoiseCovariance::covariance(const double* x, const std::vector<double>& sigma2) const {
  const std::size_t p = bands();
  if (sigma2.size() != p) throw std::invalid_argument("band noise covariance: one noise variance per band");
  for (double v : sigma2)
    if (!(v >= 0.0) || !std::isfinite(v))
      throw std::invalid_argument("band noise covariance: the noise variance must be finite and >= 0");
  std::vector<double> g = gram(x);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = 0; c < p; ++c) {
      const double sc = std::sqrt(sigma2[b] * sigma2[c]);
      g[b * p + c] = 4.0 * sc * g[b * p + c] - 2.0 * sc * sc * trace_product_[b * p + c];
    }
  return g;
}

std::vector<double> band_form_reference(const WelchConfig& config, const double* x, std::size_t samples, double lower,
                                        double upper) {
  const WelchPlan plan(config);
  WelchWorkspace ws(config.segment);
  std::vector<double> y(x, x + samples), p(plan.n_freq()), q(samples);
  const auto band = [&] {
    plan.psd(y.data(), samples, p.data(), ws);
    return band_average(p.data(), p.size(), plan.frequency_step(), lower, upper);
  };
  for (std::size_t t = 0; t < samples; ++t) {
    y[t] = x[t] + 1.0;
    const double up = band();
    y[t] = x[t] - 1.0;
    const double down = band();
    y[t] = x[t];
    q[t] = (up - down) / 4.0;
  }
  return q;
}

}  // namespace rollspec::spectral
