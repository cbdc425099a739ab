#pragma once
// Ball-on-beam model (kernels/README.md (ball on beam): D-1, D-9, D-10, D-11; seed 001 Eq. 1–8, seed 002 Eq. 4–14):
// a rigid ball of mass m2 crosses the modal beam at constant speed v from x_start to x_end,
// pressed on by gravity; the point contact force F_c drives the modes and the ball.
//
//   q_n'' + 2 zeta_n w_n q_n' + w_n^2 q_n = -phi_n(xi) F_c / (rho A l_eff)     (D-9)
//   m2 w2'' = F_c - m2 g                                                        (seed 001 Eq. 4)
//   delta = w1(xi) + h(xi) - w2,  w1(xi) = sum phi_n(xi) q_n - R(xi) F_c        (D-1, B12)
//
// Plain data in (this header), plain time histories out (BallOnBeamResult). The realisation's
// random inputs come in as sampled arrays: roughness h(x) over the physical span (m) and, for
// the linearised law, the blocked force F0(t) (N, time from the start of the traverse).
// Integrators: exact_step_integrator.hpp (default), dopri5_reference.hpp (reference).
#include <cstddef>
#include <vector>

#include "kernels/beam/contact_law.hpp"
#include "kernels/beam/modal_beam.hpp"
#include "kernels/beam/uniform_samples.hpp"

namespace rollspec::beam {

struct Ball {
  double mass = 0.2631;   // kg (40 mm steel ball, rho = 7850)
  double gravity = 9.81;  // m/s^2
};

// Constant-speed traverse over physical positions [x_start, x_end] (m). speed = 0 keeps the ball
// still for `duration` seconds (static checks); otherwise duration = (x_end - x_start) / speed.
struct Traverse {
  double x_start = 0.0;
  double x_end = 0.0;
  double speed = 1.0;     // m/s
  double duration = 0.0;  // s, only used when speed == 0
};

struct BallOnBeamModel {
  ModalBeam beam;
  Ball ball;
  ContactLaw contact;
  Traverse traverse;
  double sample_rate = 25600.0;  // output rate, Hz
  std::vector<double> sensors;   // physical sensor positions, m
  // Contact-patch filter (README B38, exact-step integrator only): > 0 averages the roughness
  // over the instantaneous Hertz contact length 2a, a = sqrt(patch_radius * delta), with delta
  // from the start of each step (one step lag); 0 = point contact (seed 001 Eq. 7).
  double patch_radius = 0.0;  // m
};

// One realisation's sampled random inputs. An empty roughness means a smooth beam (h = 0); an
// empty blocked force means F0 = m2 g (linearised law only).
struct Realisation {
  UniformSamples roughness;      // h(x), m, over physical x
  UniformSamples blocked_force;  // F0(t), N
};

// Time histories at the output rate, sample j at t = j / sample_rate, j = 0..samples-1.
struct BallOnBeamResult {
  double sample_rate = 0.0;
  std::vector<std::vector<double>> sensor_acceleration;  // [sensor][j], m/s^2 (modal sum of q_n'' phi_n)
  std::vector<double> contact_force;                     // N
  std::vector<double> ball_acceleration;                 // m/s^2 (w2'')
  std::vector<double> compression;                       // delta, m (D-1)
  std::vector<double> contact_deflection;                // w1(xi) incl. -R F, m (up positive)
  std::vector<double> ball_displacement;                 // w2, m (up positive)
  std::vector<double> contact_position;                  // xi, m (physical)
  std::vector<unsigned char> loss_of_contact;            // 1 during loss of contact
  double loss_of_contact_share = 0.0;                    // share of integration steps (or samples, reference)
  long steps = 0;                                        // integration steps taken
  long rejected_steps = 0;                               // reference only
  std::size_t samples() const { return contact_force.size(); }
};

// Duration of the traverse, number of output samples (floor(T f_s) + 1).
double traverse_duration(const Traverse& traverse);
std::size_t output_samples(const BallOnBeamModel& model);

namespace detail {
// State at t = 0: static equilibrium under the ball's weight (README B22) and the contact force
// consistent with it. y = [q (N), q' (N), w2, w2'].
struct InitialState {
  std::vector<double> y;
  double force;
};
InitialState static_initial_state(const BallOnBeamModel& model, const ContactModel& contact, const Realisation& r);
// Inline: the exact-step integrator reads them once per step (a call would spill its registers).
inline void roughness_at(const Realisation& r, double x, double& h, double& dh) {
  if (r.roughness.empty()) {
    h = dh = 0.0;
    return;
  }
  r.roughness.evaluate(x, h, dh);
}
inline double blocked_force_at(const BallOnBeamModel& m, const Realisation& r, double t) {
  if (r.blocked_force.empty()) return m.ball.mass * m.ball.gravity;
  return r.blocked_force.value(t);
}
// The contact law's third argument at time t, position x: F0(t) (linearised), x (path, B46), else 0.
inline double law_argument(const BallOnBeamModel& m, const ContactModel& contact, const Realisation& r, double t,
                           double x) {
  if (contact.linearised()) return blocked_force_at(m, r, t);
  return contact.path() ? x : 0.0;
}
// Output arrays of `samples` entries, zeroed; clear = false keeps what a previous realisation left
// (for an integrator that writes every sample).
void resize_result(const BallOnBeamModel& model, std::size_t samples, BallOnBeamResult& out, bool clear = true);
}  // namespace detail

}  // namespace rollspec::beam
