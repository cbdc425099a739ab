#include "kernels/beam/exact_step_integrator.hpp"

#include <cmath>
#include <stdexcept>

#include "kernels/beam/contact_solve.hpp"

namespace rollspec::beam {

ExactStepIntegrator::ExactStepIntegrator(BallOnBeamModel model, int substeps, double solver_tolerance,
                                         long max_table_entries)
    : model_(std::move(model)), contact_(model_.contact), substeps_(substeps), tol_(solver_tolerance) {
  if (substeps < 1) throw std::invalid_argument("ExactStepIntegrator: substeps must be >= 1");
  samples_ = output_samples(model_);
  steps_ = static_cast<long>(samples_ - 1) * substeps;
  h_ = 1.0 / (model_.sample_rate * substeps);
  total_rate_ = !contact_.linearised() && model_.contact.rate == DampingRate::total;
  const ModalBeam& b = model_.beam;
  const int n = b.modes();
  const double m = b.modal_mass(), m2 = model_.ball.mass;
  if (!(m2 > 0.0)) throw std::invalid_argument("ExactStepIntegrator: ball mass must be > 0");
  osc_.reserve(n);
  for (int i = 0; i < n; ++i) {
    osc_.push_back(integrators::ExactOscillatorStep::make(b.omega(i), b.zeta(i), h_));
    b1m_.push_back(osc_.back().b1 / m);
    c1m_.push_back(osc_.back().c1 / m);
  }
  const bool table = static_cast<double>(steps_ + 1) * n <= static_cast<double>(max_table_entries);
  if (table) {  // slopes only when the damper sees the convective rate (B20)
    phi_table_.resize(static_cast<std::size_t>(steps_ + 1) * n);
    if (total_rate_) slope_table_.resize(phi_table_.size());
  }
  comp_.resize(steps_ + 1);
  rate_comp_.resize(steps_ + 1);
  conv_comp_.resize(steps_ + 1);
  residual_.resize(steps_ + 1);
  std::vector<double> phi(n), slope(n);
  for (long k = 0; k <= steps_; ++k) {
    const double x = position(k);
    b.shapes(x, phi.data(), slope.data());
    if (table) {
      std::copy(phi.begin(), phi.end(), phi_table_.begin() + k * n);
      if (total_rate_) std::copy(slope.begin(), slope.end(), slope_table_.begin() + k * n);
    }
    // (B25): C = sum b1 phi^2 / m + h^2 / (6 m2) + R,  D = sum c1 phi^2 / m + h / (2 m2),
    //        convective part of D: v sum b1 phi phi' / m.
    double c = 0.0, d = 0.0, s = 0.0;
    for (int i = 0; i < n; ++i) {
      c += b1m_[i] * phi[i] * phi[i];
      d += c1m_[i] * phi[i] * phi[i];
      s += b1m_[i] * phi[i] * slope[i];
    }
    // (B12) from the shapes already at hand
    double modal = 0.0;
    for (int i = 0; i < n; ++i) modal += phi[i] * phi[i] / (m * b.omega(i) * b.omega(i));
    residual_[k] = b.static_correction() ? b.static_flexibility(x, x) - modal : 0.0;
    comp_[k] = c + h_ * h_ / (6.0 * m2) + residual_[k];
    rate_comp_[k] = d + h_ / (2.0 * m2);
    conv_comp_[k] = model_.traverse.speed * s;
  }
  sensor_phi_.resize(model_.sensors.size() * n);
  for (std::size_t s = 0; s < model_.sensors.size(); ++s) b.shapes(model_.sensors[s], sensor_phi_.data() + s * n);
}

double ExactStepIntegrator::position(long k) const {
  return model_.traverse.x_start + model_.traverse.speed * (static_cast<double>(k) * h_);
}

void ExactStepIntegrator::shapes_at(long k, const double*& phi, const double*& slope, std::vector<double>& sp,
                                    std::vector<double>& ss) const {
  const int n = model_.beam.modes();
  if (!phi_table_.empty()) {
    phi = phi_table_.data() + k * n;
    slope = total_rate_ ? slope_table_.data() + k * n : ss.data();  // ss stays zero otherwise
    return;
  }
  model_.beam.shapes(position(k), sp.data(), ss.data());
  phi = sp.data();
  slope = ss.data();
}

BallOnBeamResult ExactStepIntegrator::run(const Realisation& r) const {
  BallOnBeamResult out;
  run(r, out);
  return out;
}

void ExactStepIntegrator::run(const Realisation& r, BallOnBeamResult& out) const {
  const ModalBeam& b = model_.beam;
  const int n = b.modes();
  const double m = b.modal_mass(), m2 = model_.ball.mass, g = model_.ball.gravity, v = model_.traverse.speed;
  const double weight = m2 * g, h = h_;
  detail::resize_result(model_, samples_, out);
  detail::InitialState init = detail::static_initial_state(model_, contact_, r);
  std::vector<double> q(init.y.begin(), init.y.begin() + n), dq(init.y.begin() + n, init.y.begin() + 2 * n);
  double w2 = init.y[2 * n], u2 = init.y[2 * n + 1], f = init.force;
  std::vector<double> sp(n), ss(n), qf(n), vf(n);
  const double *phi = nullptr, *slope = nullptr;
  shapes_at(0, phi, slope, sp, ss);

  // Outputs at the current state (phi = shapes at the current position).
  auto record = [&](std::size_t j, double xi, double delta, double hx, bool contact) {
    for (std::size_t s = 0; s < model_.sensors.size(); ++s) {
      const double* ps = sensor_phi_.data() + s * n;
      double a = 0.0;
      for (int i = 0; i < n; ++i) {  // exact q_n'' from (D-9)
        const double w = b.omega(i);
        a += ps[i] * (-phi[i] * f / m - 2.0 * b.zeta(i) * w * dq[i] - w * w * q[i]);
      }
      out.sensor_acceleration[s][j] = a;
    }
    out.contact_force[j] = f;
    out.ball_acceleration[j] = f / m2 - g;
    out.compression[j] = delta;
    out.contact_deflection[j] = delta - hx + w2;
    out.ball_displacement[j] = w2;
    out.contact_position[j] = xi;
    out.loss_of_contact[j] = contact ? 0 : 1;
  };
  {
    double h0, dh0, w1 = -residual_[0] * f;
    detail::roughness_at(r, model_.traverse.x_start, h0, dh0);
    for (int i = 0; i < n; ++i) w1 += phi[i] * q[i];
    const double delta = w1 + h0 - w2;
    record(0, model_.traverse.x_start, delta, h0, contact_.evaluate(delta, 0.0, detail::blocked_force_at(model_, r, 0.0)).contact);
  }

  long lost = 0;
  double f_prev = f;  // force one step back, for the extrapolated Newton guess
  for (long k = 0; k < steps_; ++k) {
    // Free part of the step: start force only (B23), with the ramp's start coefficient.
    for (int i = 0; i < n; ++i) {
      const auto& o = osc_[i];
      const double g0 = -phi[i] * f / m;
      qf[i] = o.a00 * q[i] + o.a01 * dq[i] + o.b0 * g0;
      vf[i] = o.a10 * q[i] + o.a11 * dq[i] + o.c0 * g0;
    }
    const long k1 = k + 1;
    shapes_at(k1, phi, slope, sp, ss);
    double wf = 0.0, vfree = 0.0, sf = 0.0;
    for (int i = 0; i < n; ++i) {
      wf += phi[i] * qf[i];
      vfree += phi[i] * vf[i];
    }
    if (total_rate_)
      for (int i = 0; i < n; ++i) sf += slope[i] * qf[i];
    // Ball (B24): exact for a linear force; the F1 parts are in C and D.
    const double a0 = f / m2 - g;
    const double w2f = w2 + u2 * h + a0 * h * h / 2.0 - f * h * h / (6.0 * m2);
    const double u2f = u2 + a0 * h - f * h / (2.0 * m2);
    const double x1 = position(k1), t1 = static_cast<double>(k1) * h;
    double h1, dh1;
    detail::roughness_at(r, x1, h1, dh1);
    const double f0 = contact_.linearised() ? detail::blocked_force_at(model_, r, t1) : 0.0;
    double rate_free = vfree - u2f, d = rate_comp_[k1];
    if (total_rate_) {  // (B20)
      rate_free += v * (sf + dh1);
      d += conv_comp_[k1];
    }
    const ContactSolution cs =
        solve_contact_force(contact_, wf + h1 - w2f, rate_free, comp_[k1], d, f0, 2.0 * f - f_prev, weight, tol_);
    const double f1 = cs.force;
    for (int i = 0; i < n; ++i) {
      const double g1 = -phi[i] * f1 / m;
      q[i] = qf[i] + osc_[i].b1 * g1;
      dq[i] = vf[i] + osc_[i].c1 * g1;
    }
    w2 = w2f + f1 * h * h / (6.0 * m2);
    u2 = u2f + f1 * h / (2.0 * m2);
    f_prev = f;
    f = f1;
    if (!cs.contact) ++lost;
    if (k1 % substeps_ == 0) record(static_cast<std::size_t>(k1 / substeps_), x1, cs.delta, h1, cs.contact);
  }
  out.steps = steps_;
  out.loss_of_contact_share = steps_ > 0 ? static_cast<double>(lost) / static_cast<double>(steps_) : 0.0;
}

}  // namespace rollspec::beam
