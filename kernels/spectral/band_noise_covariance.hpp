#pragma once
// The logger noise's covariance between the band averages of one roll, given the roll's own signal
// (kernels/spectral/README.md D-33e). Each band average of the Welch density (D-15, D-17) is a quadratic form
// P_b(x) = x^T Q_b x in the roll's samples. For x = s + n, n white Gaussian of per-sample variance sigma^2,
//   cov(P_b, P_c | s) = 4 sigma^2 s^T Q_b Q_c s + 2 sigma^4 tr(Q_b Q_c),
// and since E[(Q_b x)^T (Q_c x) | s] = s^T Q_b Q_c s + sigma^2 tr(Q_b Q_c), the roll itself gives the unbiased
// estimate 4 sigma^2 (Q_b x)^T (Q_c x) - 2 sigma^4 tr(Q_b Q_c). D-33c b's 4 S N / nu is its expectation for a
// signal locally white over the band's bins; a coherent signal (a transient, bands narrower than a bin that share
// one) has another variance and a covariance between neighbouring bands, which this form keeps.
#include <cstddef>
#include <vector>

#include "kernels/spectral/band_dof.hpp"
#include "kernels/spectral/welch.hpp"

namespace rollspec::spectral {

class BandNoiseCovariance {
 public:
  // The Welch estimator, a roll's length in samples (>= the segment) and p bands [lower_b, upper_b] Hz, each with a
  // bin. Throws std::invalid_argument otherwise.
  BandNoiseCovariance(const WelchConfig& config, std::size_t samples, std::vector<double> lower,
                      std::vector<double> upper);
  std::size_t bands() const { return lower_.size(); }
  // tr Q_b: E P_b of unit white noise (so sigma^2 = N_b / tr Q_b for white noise of band level N_b).
  const std::vector<double>& trace() const { return trace_; }
  // tr(Q_b Q_c), p x p row-major: half the covariance of P_b and P_c for unit white noise.
  const std::vector<double>& trace_product() const { return trace_product_; }
  // (Q_b x)^T (Q_c x), p x p row-major, of one roll's samples x[0..samples). Q_b x = (1/N_B) sum_s sum_k a_k
  // Re(conj(y_{s,k}) u_k(t - s S)), y_{s,k} = sum_t x_{sS+t} u_k(t): one r2c FFT per segment, one c2r per band.
  std::vector<double> gram(const double* x) const;
  // The estimate of cov(P_b, P_c | s) from the roll x and the noise's per-sample variance in each band, sigma2[b]
  // >= 0 (N_b / tr Q_b; all equal for white noise): 4 s_b s_c (Q_b x)^T (Q_c x) - 2 s_b^2 s_c^2 tr(Q_b Q_c), s_b =
  // sqrt(sigma2[b]) (the noise white over each band pair's correlated bins).
  std::vector<double> covariance(const double* x, const std::vector<double>& sigma2) const;

 private:
  WelchConfig config_;
  std::size_t samples_ = 0, segments_ = 0;
  std::vector<double> lower_, upper_, window_;
  std::vector<BandWeights> weights_;       // a_k with the one-sided factor and the density's scale
  std::vector<double> lobe_re_, lobe_im_;  // W_k = sum_t w_t e^{-2 pi i k t / L}, k = 0..L/2 (0 without detrending)
  std::vector<double> trace_, trace_product_;
};

// Q_b x by polarisation of the plain estimator (WelchPlan, band_average): (P_b(x + e_t) - P_b(x - e_t)) / 4 for
// every sample t, exact for a quadratic form. For tests (O(samples^2 L)).
std::vector<double> band_form_reference(const WelchConfig& config, const double* x, std::size_t samples, double lower,
                                        double upper);

}  // namespace rollspec::spectral
