#pragma once
// Welch power spectral density, one-sided density (theory D-15):
//
//   P_k = c_k |X_k|^2 / (f_s sum_i w_i^2),   c_k = 1 at DC and Nyquist, 2 elsewhere,
//
// averaged over segments of length L with overlap O, each segment detrended (mean removed, as
// scipy.signal.welch's default detrend='constant') and windowed. The FFTW r2c plan is made once
// in the constructor; psd() is const and thread-safe when each thread passes its own workspace
// (FFTW's new-array execute interface on buffers from fftw_malloc, which share one alignment).
#include <cstddef>
#include <memory>
#include <vector>

#include "kernels/spectral/fftw_handles.hpp"
#include "kernels/spectral/window.hpp"

namespace rollspec::spectral {

enum class Detrend { none, constant };

struct WelchConfig {
  double sample_rate = 1.0;   // f_s, Hz
  std::size_t segment = 256;  // L, samples
  std::size_t overlap = 128;  // O < L, samples
  Window window = Window::hann;
  Detrend detrend = Detrend::constant;
};

// Per-thread scratch buffers for WelchPlan::psd (FFTW-aligned).
class WelchWorkspace {
 public:
  explicit WelchWorkspace(std::size_t segment) : segment_(segment), in_(segment), out_(segment / 2 + 1) {}
  double* in() { return in_.data(); }
  FftwComplex* out() { return out_.data(); }
  std::size_t segment() const { return segment_; }

 private:
  std::size_t segment_;
  RealBuffer in_;
  ComplexBuffer out_;  // segment/2+1 values
};

class WelchPlan {
 public:
  explicit WelchPlan(const WelchConfig& config);
  WelchPlan(const WelchPlan&) = delete;
  WelchPlan& operator=(const WelchPlan&) = delete;

  const WelchConfig& config() const { return config_; }
  std::size_t n_freq() const { return config_.segment / 2 + 1; }
  double frequency_step() const { return config_.sample_rate / static_cast<double>(config_.segment); }
  std::vector<double> frequencies() const;

  // Number of segments that fit in n samples (scipy's rule: (n - O) / (L - O)); 0 if n < L.
  std::size_t segments(std::size_t n) const;

  // One-sided PSD of x[0..n) into psd[0..n_freq). Throws std::invalid_argument if n < L.
  void psd(const double* x, std::size_t n, double* psd, WelchWorkspace& ws) const;

  // Equivalent chi-square degrees of freedom of one Welch estimate from n samples of a
  // Gaussian signal with a locally flat spectrum (theory D-16, Percival & Walden 1993 Eq. 292b):
  //   nu = 2 N_B / (1 + 2 sum_{m=1}^{N_B-1} (1 - m/N_B) rho(m)^2),
  //   rho(m) = sum_t w_t w_{t+mS} / sum_t w_t^2,  S = L - O.
  double equivalent_dof(std::size_t n) const;

  const std::vector<double>& window() const { return window_; }

 private:
  WelchConfig config_;
  std::vector<double> window_;
  double scale_;   // 1 / (f_s sum w^2)
  FftwPlan plan_;  // r2c, executed on a workspace's buffers
};

}  // namespace rollspec::spectral
