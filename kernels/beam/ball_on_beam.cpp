#include "kernels/beam/ball_on_beam.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/contact_solve.hpp"
#include "kernels/contact/hertz.hpp"

namespace rollspec::beam {

double traverse_duration(const Traverse& t) {
  if (t.speed > 0.0) {
    if (!(t.x_end > t.x_start)) throw std::invalid_argument("Traverse: x_end must exceed x_start");
    return (t.x_end - t.x_start) / t.speed;
  }
  if (t.speed == 0.0 && t.duration > 0.0) return t.duration;
  throw std::invalid_argument("Traverse: speed must be > 0, or 0 with a duration > 0");
}

std::size_t output_samples(const BallOnBeamModel& m) {
  if (!(m.sample_rate > 0.0)) throw std::invalid_argument("BallOnBeamModel: sample rate must be > 0");
  return static_cast<std::size_t>(std::floor(traverse_duration(m.traverse) * m.sample_rate + 1e-9)) + 1;
}

namespace detail {

InitialState static_initial_state(const BallOnBeamModel& m, const ContactModel& contact, const Realisation& r) {
  const ModalBeam& b = m.beam;
  const int n = b.modes();
  const double x0 = m.traverse.x_start, weight = m.ball.mass * m.ball.gravity;
  std::vector<double> phi(n), slope(n);
  b.shapes(x0, phi.data(), slope.data());
  InitialState s;
  s.y.assign(2 * n + 2, 0.0);
  // (B22): beam statically deflected by the weight, q_n = -phi_n(xi) W / (m w_n^2), moving with
  // the quasi-static rates q_n' = -phi_n'(xi) v W / (m w_n^2); the ball rides on the deflected,
  // rough beam: w2' = d/dt [w1(xi(t)) + h(xi(t))] at constant compression.
  const double v = m.traverse.speed;
  double w1 = 0.0, dw1 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double w = b.omega(i);
    const double c = w > 0.0 ? -weight / (b.modal_mass() * w * w) : 0.0;
    s.y[i] = phi[i] * c;
    s.y[n + i] = slope[i] * v * c;
    w1 += phi[i] * s.y[i];
    dw1 += slope[i] * s.y[i];
  }
  const double res = b.residual_flexibility(x0);
  w1 -= res * weight;
  double dres = 0.0;  // dR/dx by central differences (R is smooth inside the beam)
  if (b.static_correction() && v != 0.0) {
    const double e = 1e-5 * b.effective_length();
    const double lo = std::max(x0 - e, -b.offset()), hi = std::min(x0 + e, b.effective_length() - b.offset());
    if (hi > lo) dres = (b.residual_flexibility(hi) - b.residual_flexibility(lo)) / (hi - lo);
  }
  const double f0 = law_argument(m, contact, r, 0.0, x0);
  const double delta = contact.static_compression(weight, f0);
  double h, dh;
  roughness_at(r, x0, h, dh);
  if (m.patch_radius > 0.0 && !r.roughness.empty())  // (B38) at the static contact length
    PatchAverager(r.roughness).evaluate(x0, contact::hertz::contact_radius_at_approach(m.patch_radius, delta), h, dh);
  // Linearised law (D-11): roughness enters through F0 or, if given, through h as in D-1.
  s.y[2 * n] = w1 + h - delta;
  // The path law (B46) has no line: its strip enters through P(δ, ξ), and a ball that rides it at
  // constant load follows w1 − δ_W(ξ), so its rate carries −v dδ_W/dξ where the point laws' carries
  // v dh (B22). B45b: dδ_W/dξ fitted over [0, a/2] (PathContactTable::static_slope), since one
  // interval's chord changes with the step and rings the beam's first mode for the whole record;
  // B45: the first interval's chord, the point laws' rule.
  double dpath = 0.0;
  if (contact.path()) {
    const ContactLaw& law = contact.law();
    const std::vector<double>& xk = law.path->data().position;
    if (law.path_start_width > 0.0)
      dpath = -law.path->static_slope(weight, f0 - law.path_origin, law.path_start_width);
    else if (xk.size() > 1)
      dpath = -(contact.static_compression(weight, f0 + (xk[1] - xk[0])) - delta) / (xk[1] - xk[0]);
  }
  s.y[2 * n + 1] = v * (2.0 * dw1 - dres * weight + dh + dpath);
  // Contact force consistent with the state (the damper may see a convective rate at t = 0).
  // Damper rate of the initial state: relative velocity w1'(xi) - w2' (+ convective terms).
  double wd = 0.0;
  for (int i = 0; i < n; ++i) wd += phi[i] * s.y[n + i];
  double rate = wd - s.y[2 * n + 1];
  if (!contact.linearised() && contact.law().rate == DampingRate::total) rate += v * (dw1 + dh);
  s.force = solve_contact_force(contact, delta + res * weight, rate, res, 0.0, f0, weight, weight).force;
  return s;
}

void resize_result(const BallOnBeamModel& m, std::size_t ns, BallOnBeamResult& out, bool clear) {
  out.sample_rate = m.sample_rate;
  out.sensor_acceleration.resize(m.sensors.size());
  auto size = [&](auto& v) {
    if (clear)
      v.assign(ns, 0);
    else
      v.resize(ns);
  };
  for (auto& a : out.sensor_acceleration) size(a);
  size(out.contact_force);
  size(out.ball_acceleration);
  size(out.compression);
  size(out.contact_deflection);
  size(out.ball_displacement);
  size(out.contact_position);
  size(out.loss_of_contact);
  out.loss_of_contact_share = 0.0;
  out.steps = out.rejected_steps = 0;
}

}  // namespace detail
}  // namespace rollspec::beam
