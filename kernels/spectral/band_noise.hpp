#pragma once
// Logger noise in the bands that stay in a comparison (kernels/spectral/README.md D-33c b). One roll's measured
// band power is X = P_s + P_n + C: the signal's, the noise's (mean N, variance 2 N^2 / nu for the band's dof nu of
// D-33c a) and the cross term C = sum_k a_k 2 Re(y_s conj y_n) (mean 0; variance 4 S N / nu for a signal that is
// locally white over the bins the window and the overlapping segments correlate). With the model's mean band
// power m for S and a = m / (m + N), the measured mean of the rolls has expectation m + N, and against (m + N)^2
// its noise and cross terms have the variance (2 N^2 + 4 m N) / (nu_M (m + N)^2) = 2 (1 - a^2) / nu_M, nu_M the
// dof of the rolls' mean (M^2 / sum_r 1/nu_r). The quiet recording's estimate N^ adds 2 (1 - a)^2 / nu_N to
// ln(m + N^). The signal's own log variance enters ln(S + N) times a^2 (d ln(S + N) / d ln S = a).
namespace rollspec::spectral {

struct BandNoise {
  double shift = 0.0;         // ln(1 + N / m): the expected measured band over the model's own
  double signal_share = 1.0;  // a^2
  double measured = 0.0;      // ln(1 + 2 (1 - a^2) / nu_M): the measured mean's log variance from the noise
  double estimate = 0.0;      // ln(1 + 2 (1 - a)^2 / nu_N): ln(m + N^)'s log variance from N^'s own error
  // D-33e: this band's row of the measured mean's noise log covariance with the p tested bands (its own entry
  // unused: `measured` holds it), from the rolls' own signal; null: D-33c's bands independent.
  const double* cross = nullptr;
};

// model_power m > 0 and noise_power N >= 0 (band averages, one unit); measured_dof nu_M and noise_dof nu_N > 0, or
// 0 where unknown (that term is then 0). Throws std::invalid_argument otherwise.
BandNoise band_noise(double model_power, double noise_power, double measured_dof, double noise_dof);

}  // namespace rollspec::spectral
