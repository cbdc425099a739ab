#include "kernels/beam/dopri5_reference.hpp"

#include <cmath>
#include <stdexcept>

#include "kernels/beam/contact_solve.hpp"
#include "kernels/beam/dopri5.hpp"

namespace rollspec::beam {

BallOnBeamResult simulate_dopri5(const BallOnBeamModel& model, const Realisation& r, const ReferenceTolerances& tol) {
  if (model.patch_radius > 0.0)
    throw std::invalid_argument("simulate_dopri5: the contact-patch filter is exact-step only");
  const ModalBeam& b = model.beam;
  const int n = b.modes();
  const ContactModel contact(model.contact);
  const double m = b.modal_mass(), m2 = model.ball.mass, g = model.ball.gravity, v = model.traverse.speed;
  const double weight = m2 * g;
  const bool total = !contact.linearised() && model.contact.rate == DampingRate::total;
  const std::size_t ns = output_samples(model);
  BallOnBeamResult out;
  detail::resize_result(model, ns, out);
  detail::InitialState init = detail::static_initial_state(model, contact, r);

  std::vector<double> phi(n), slope(n);
  double last_force = init.force;
  struct Contact {
    double force, delta, h;
    bool contact;
  };
  // Instantaneous contact force from the state (B21 with D = 0).
  auto contact_at = [&](double t, const double* y) {
    const double xi = model.traverse.x_start + v * t;
    b.shapes(xi, phi.data(), slope.data());
    double w = 0.0, wd = 0.0, ws = 0.0;
    for (int i = 0; i < n; ++i) {
      w += phi[i] * y[i];
      wd += phi[i] * y[n + i];
      ws += slope[i] * y[i];
    }
    double hx, dhx;
    detail::roughness_at(r, xi, hx, dhx);
    double rate = wd - y[2 * n + 1];
    if (total) rate += v * (ws + dhx);
    const double f0 = detail::law_argument(model, contact, r, t, xi);
    const ContactSolution cs =
        solve_contact_force(contact, w + hx - y[2 * n], rate, b.residual_flexibility(xi), 0.0, f0, last_force, weight);
    last_force = cs.force;
    return Contact{cs.force, cs.delta, hx, cs.contact};
  };
  auto rhs = [&](double t, const double* y, double* dy) {
    const Contact c = contact_at(t, y);
    for (int i = 0; i < n; ++i) {
      const double w = b.omega(i);
      dy[i] = y[n + i];
      dy[n + i] = -phi[i] * c.force / m - 2.0 * b.zeta(i) * w * y[n + i] - w * w * y[i];  // (D-9)
    }
    dy[2 * n] = y[2 * n + 1];
    dy[2 * n + 1] = c.force / m2 - g;  // seed 001 Eq. 4
  };
  std::vector<double> sensor_phi(model.sensors.size() * n);
  for (std::size_t s = 0; s < model.sensors.size(); ++s) b.shapes(model.sensors[s], sensor_phi.data() + s * n);
  long lost = 0;
  auto observe = [&](std::size_t j, double t, const double* y) {
    const Contact c = contact_at(t, y);
    for (std::size_t s = 0; s < model.sensors.size(); ++s) {
      double a = 0.0;
      for (int i = 0; i < n; ++i) {
        const double w = b.omega(i);
        a += sensor_phi[s * n + i] * (-phi[i] * c.force / m - 2.0 * b.zeta(i) * w * y[n + i] - w * w * y[i]);
      }
      out.sensor_acceleration[s][j] = a;
    }
    out.contact_force[j] = c.force;
    out.ball_acceleration[j] = c.force / m2 - g;
    out.compression[j] = c.delta;
    out.contact_deflection[j] = c.delta - c.h + y[2 * n];
    out.ball_displacement[j] = y[2 * n];
    out.contact_position[j] = model.traverse.x_start + v * t;
    out.loss_of_contact[j] = c.contact ? 0 : 1;
    if (!c.contact) ++lost;
  };
  std::vector<double> times(ns);
  for (std::size_t j = 0; j < ns; ++j) times[j] = static_cast<double>(j) / model.sample_rate;
  Dopri5Options opt;
  opt.rtol = tol.rtol;
  opt.max_step = tol.max_step;
  opt.atol.assign(2 * n + 2, tol.atol_displacement);
  const double wmax = b.omega(n - 1);
  for (int i = 0; i < n; ++i) opt.atol[n + i] = tol.atol_displacement * wmax;
  opt.atol[2 * n + 1] = tol.atol_displacement * wmax;
  const Dopri5Stats st = dopri5(rhs, init.y, 0.0, times, observe, opt);
  out.steps = st.accepted;
  out.rejected_steps = st.rejected;
  out.loss_of_contact_share = static_cast<double>(lost) / static_cast<double>(ns);
  return out;
}

}  // namespace rollspec::beam
