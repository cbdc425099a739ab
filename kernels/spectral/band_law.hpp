#pragma once
// One realisation's band power x: its squared coefficient of variation c^2 = var x / (E x)^2 read from the
// variance s and skewness g1 of ln x through the generalised gamma law with those two moments (kernels/spectral/
// README.md D-26d). The lognormal law (g1 = 0: c^2 = e^s - 1) and every gamma law (g1 < 0: c^2 = 1/k) are members;
// the Welch band averages of a rolling record lie between them, lighter-tailed than the lognormal reading of s says.

namespace rollspec::spectral {

// c^2 of the generalised gamma law whose ln has variance s >= 0 and skewness g1 (Prentice 1974: ln x = mu + sigma w,
// w = ln(Q^2 G) / Q, G ~ gamma(1 / Q^2)). |g1| below 1e-3: the lognormal limit e^s - 1; |g1| is taken at most 1.99
// (ln of a gamma law is never skewed below -2); a right-skewed ln x whose law has no finite variance gives the
// lognormal reading (D-26a). Throws std::invalid_argument for s < 0 or a value that is not finite.
double band_cv2(double s, double g1);

// The skewness of ln G for G ~ gamma(k): psi''(k) / psi'(k)^{3/2}, from 0 (k -> inf) to -2 (k -> 0). For tests.
double log_gamma_skewness(double k);

}  // namespace rollspec::spectral
