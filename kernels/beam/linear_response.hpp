#pragma once
// Frequency-domain solution of the linearised ball-on-beam model (the Monte-Carlo check of the
// linear model), README Eq. (B31)–(B34). Receptances (displacement per unit contact force, sign
// convention "separation of ball and beam at the contact"):
//   beam    alpha_b(x, xi) = sum_n phi_n(x) phi_n(xi) / (m (w_n^2 - w^2 + 2 i zeta_n w_n w))
//           plus, at the contact, the residual flexibility R(xi) k0 / (k0 + i w c0): R is
//           quasi-static and the contact damper does not see its rate (B21), as in the time domain
//   ball    alpha_2 = -1 / (m2 w^2)
//   contact alpha_c = 1 / (k0 + i w c0)
// Roughness excitation (D-1 with F = k0 delta + i w c0 delta_dyn):  F = h / (alpha_c + alpha_b + alpha_2)  (B32)
// Blocked-force excitation (D-11):                          F = F0 / ((k0 + i w c0)(alpha_c + alpha_b + alpha_2))
// Sensor acceleration: A_s = w^2 alpha_b(x_s, xi) F (modal sum only, as in the time domain).  (B33)
// The ball's position is averaged out: E|A_s|^2 is the weighted mean over the given contact
// positions of |H(x_s, xi)|^2 times the excitation PSD in time (one-sided, D-2)            (B34)
// (quasi-stationary: valid when the ball moves slowly compared with the modal decay, Tf/tau << 1).
// The weights are the share of the estimate each position carries (for a Welch estimate the
// summed squared windows, B34a); none given: uniform.
#include <complex>
#include <vector>

#include "kernels/beam/modal_beam.hpp"

namespace rollspec::beam {

// roughness: h enters spring and damper, F = (k0 + i w c0) delta (a linearised table/Hertz law
//   whose damper sees the total rate, B20). The linearised law of the time integrator (D-11, B18)
//   with a roughness h puts h through k0 only: use blocked_force with G_F0 = k0^2 G_h for it.
enum class Excitation { roughness, blocked_force };

struct LinearResponse {
  std::vector<std::vector<double>> sensor_psd;  // [sensor][k], (m/s^2)^2/Hz
  std::vector<double> force_psd;                // [k], N^2/Hz (contact force)
};

// excitation_psd[k] at frequencies[k] (Hz): roughness in time, m^2/Hz, or blocked force, N^2/Hz.
// At f = 0 the responses are 0 (the free ball carries no static load in the dynamic part).
LinearResponse linear_response_psd(const ModalBeam& beam, double ball_mass, double k0, double c0,
                                   const std::vector<double>& contact_positions, const std::vector<double>& sensors,
                                   const std::vector<double>& frequencies, const std::vector<double>& excitation_psd,
                                   Excitation kind, const std::vector<double>& position_weights = {});

// Complex sensor accelerations per unit excitation amplitude at one contact position, H[s][k] =
// A_s / h or A_s / F0 (B32–B33), for cross-spectra between sensors: S_ss'(f) = H_s H_s'^* G(f).
// `modal` (optional): modal_receptances(beam, frequencies), shared by many contact positions; the
// result is the same to the last bit with or without it.
std::vector<std::vector<std::complex<double>>> linear_response_transfer(
    const ModalBeam& beam, double ball_mass, double k0, double c0, double contact_position,
    const std::vector<double>& sensors, const std::vector<double>& frequencies, Excitation kind,
    const std::vector<std::complex<double>>* modal = nullptr);

// Modal receptances 1 / (m (w_n^2 - w^2 + 2 i zeta_n w_n w)), frequency-major: [k * modes + n].
std::vector<std::complex<double>> modal_receptances(const ModalBeam& beam, const std::vector<double>& frequencies);

}  // namespace rollspec::beam
