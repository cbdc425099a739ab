#pragma once
// A prescribed moving force on the modal beam (no ball), README Eq. (B29)–(B30): the modal
// machinery of the ball-on-beam integrator with the contact force given, for checks against
// closed forms.
//   moving_force_deflection: exact first-order-hold modal steps (B23), downward force F(t_k) at
//     x_start + v t_k, returns w1(x_p, t_k) (up positive, so a downward load gives w1 < 0).
//   fryba_moving_force: Frýba (1972, §1.3) closed-form series for a constant force P moving at v
//     over an undamped simply supported beam, deflection positive DOWN:
//     w = w0 sum_j [sin(j w t) - (alpha/j) sin(w_j t)] sin(j pi x / l) / (j^2 (j^2 - alpha^2)),
//     w0 = 2 P l^3 / (pi^4 EI), w = pi v / l, alpha = w / w_1, w_j = j^2 w_1.
#include <vector>

#include "kernels/beam/modal_beam.hpp"

namespace rollspec::beam {

// result[p][k] for positions p and step nodes k = 0..force.size()-1, t_k = k dt, starting at rest.
std::vector<std::vector<double>> moving_force_deflection(const ModalBeam& beam, double x_start, double speed,
                                                         const std::vector<double>& force, double dt,
                                                         const std::vector<double>& positions);

double fryba_moving_force(double length, double bending_stiffness, double mass_per_length, double force, double speed,
                          double x, double t, int terms);

}  // namespace rollspec::beam
