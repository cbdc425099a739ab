#include "kernels/spectral/band_noise_covariance.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

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
  cos_.resize(L);
  sin_.resize(L);
  for (std::size_t j = 0; j < L; ++j) {
    const double phase = 2.0 * M_PI * static_cast<double>(j) / static_cast<double>(L);
    cos_[j] = std::cos(phase);
    sin_[j] = std::sin(phase);
  }
  mean_re_.assign(nf, 0.0);
  mean_im_.assign(nf, 0.0);
  if (config.detrend == Detrend::constant)
    for (std::size_t k = 0; k < nf; ++k)
      for (std::size_t t = 0; t < L; ++t) {
        mean_re_[k] += window_[t] * cos_[(k * t) % L] / static_cast<double>(L);
        mean_im_[k] -= window_[t] * sin_[(k * t) % L] / static_cast<double>(L);
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

void BandNoiseCovariance::apply(std::size_t band, const double* x, double* q) const {
  const std::size_t L = config_.segment, step = L - config_.overlap;
  const BandWeights& w = weights_[band];
  const double inv = 1.0 / static_cast<double>(segments_);
  for (std::size_t t = 0; t < samples_; ++t) q[t] = 0.0;
  std::vector<double> seg(L);
  for (std::size_t s = 0; s < segments_; ++s) {
    const double* xs = x + s * step;
    for (std::size_t t = 0; t < L; ++t) seg[t] = 0.0;
    for (std::size_t i = 0; i < w.weight.size(); ++i) {
      const std::size_t k = w.first + i;
      // u_k(t) = w_t e^{-2 pi i k t / L} - W_k / L; y = sum_t x_t u_k(t).
      double y_re = 0.0, y_im = 0.0;
      for (std::size_t t = 0; t < L; ++t) {
        const std::size_t j = (k * t) % L;
        y_re += xs[t] * (window_[t] * cos_[j] - mean_re_[k]);
        y_im += xs[t] * (-window_[t] * sin_[j] - mean_im_[k]);
      }
      // a_k Re(conj(y) u_k(t)) = a_k (y_re u_re + y_im u_im).
      const double a = w.weight[i] * inv;
      for (std::size_t t = 0; t < L; ++t) {
        const std::size_t j = (k * t) % L;
        seg[t] += a * (y_re * (window_[t] * cos_[j] - mean_re_[k]) + y_im * (-window_[t] * sin_[j] - mean_im_[k]));
      }
    }
    for (std::size_t t = 0; t < L; ++t) q[s * step + t] += seg[t];
  }
}

std::vector<double> BandNoiseCovariance::gram(const double* x) const {
  const std::size_t p = bands();
  std::vector<double> q(p * samples_), g(p * p);
  for (std::size_t b = 0; b < p; ++b) apply(b, x, q.data() + b * samples_);
  for (std::size_t b = 0; b < p; ++b)
    for (std::size_t c = b; c < p; ++c) {
      double s = 0.0;
      for (std::size_t t = 0; t < samples_; ++t) s += q[b * samples_ + t] * q[c * samples_ + t];
      g[b * p + c] = g[c * p + b] = s;
    }
  return g;
}

std::vector<double> BandNoiseCovariance::covariance(const double* x, double sigma2) const {
  if (!(sigma2 >= 0.0) || !std::isfinite(sigma2))
    throw std::invalid_argument("band noise covariance: the noise variance must be finite and >= 0");
  std::vector<double> g = gram(x);
  for (std::size_t i = 0; i < g.size(); ++i) g[i] = 4.0 * sigma2 * g[i] - 2.0 * sigma2 * sigma2 * trace_product_[i];
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
