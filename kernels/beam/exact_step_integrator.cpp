#include "kernels/beam/exact_step_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/contact_solve.hpp"

namespace rollspec::beam {

ExactStepIntegrator::ExactStepIntegrator(BallOnBeamModel model, const ExactStepOptions& o)
    : model_(std::move(model)), contact_(model_.contact), substeps_(o.substeps), hold_(o.hold), tol_(o.solver_tolerance) {
  if (o.substeps < 1) throw std::invalid_argument("ExactStepIntegrator: substeps must be >= 1");
  samples_ = output_samples(model_);
  steps_ = static_cast<long>(samples_ - 1) * substeps_;
  h_ = 1.0 / (model_.sample_rate * substeps_);
  total_rate_ = !contact_.linearised() && model_.contact.rate == DampingRate::total;
  const ModalBeam& b = model_.beam;
  const int n = b.modes();
  const double m = b.modal_mass(), m2 = model_.ball.mass, h = h_;
  if (!(m2 > 0.0)) throw std::invalid_argument("ExactStepIntegrator: ball mass must be > 0");
  for (int i = 0; i < n; ++i) {
    const auto f = integrators::ExactOscillatorStep::make(b.omega(i), b.zeta(i), h);  // (B23)
    first_.push_back({f.a00, f.a01, f.a10, f.a11, 0.0, f.b0, f.b1, 0.0, f.c0, f.c1});
    if (hold_ == ForceHold::quadratic) {
      const auto q = QuadraticHoldStep::make(b.omega(i), b.zeta(i), h);  // (B36)
      coef_.push_back({q.a00, q.a01, q.a10, q.a11, q.bm, q.b0, q.b1, q.cm, q.c0, q.c1});
    }
  }
  if (hold_ == ForceHold::linear) coef_ = first_;
  // (B24) linear force over the step; (B37) the parabola through F_m, F_0, F_1.
  ball_first_ = {0.0, h * h / 3.0, h * h / 6.0, 0.0, h / 2.0, h / 2.0};
  ball_ = hold_ == ForceHold::linear ? ball_first_
                                     : BallCoefficients{-h * h / 24.0, 5.0 * h * h / 12.0, h * h / 8.0, -h / 12.0,
                                                        2.0 * h / 3.0, 5.0 * h / 12.0};
  const bool table = static_cast<double>(steps_ + 1) * n <= static_cast<double>(o.max_table_entries);
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
    // (B12) from the shapes already at hand
    double modal = 0.0;
    for (int i = 0; i < n; ++i) modal += phi[i] * phi[i] / (m * b.omega(i) * b.omega(i));
    residual_[k] = b.static_correction() ? b.static_flexibility(x, x) - modal : 0.0;
    compliance(phi.data(), slope.data(), residual_[k], coef_, ball_, comp_[k], rate_comp_[k], conv_comp_[k]);
  }
  sensor_phi_.resize(model_.sensors.size() * n);
  for (std::size_t s = 0; s < model_.sensors.size(); ++s) b.shapes(model_.sensors[s], sensor_phi_.data() + s * n);
}

// (B25): C = sum b1 phi^2 / m + a1 / m2 + R,  D = sum c1 phi^2 / m + u1 / m2,
//        convective part of D: v sum b1 phi phi' / m.
void ExactStepIntegrator::compliance(const double* phi, const double* slope, double residual,
                                     const std::vector<Coefficients>& c, const BallCoefficients& bc, double& comp,
                                     double& rate, double& conv) const {
  const double m = model_.beam.modal_mass(), m2 = model_.ball.mass;
  double cs = 0.0, ds = 0.0, ss = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    cs += c[i].b1 * phi[i] * phi[i];
    ds += c[i].c1 * phi[i] * phi[i];
    ss += c[i].b1 * phi[i] * slope[i];
  }
  comp = cs / m + bc.a1 / m2 + residual;
  rate = ds / m + bc.u1 / m2;
  conv = model_.traverse.speed * ss / m;
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
  // (B38) instantaneous contact-patch average of the roughness, width from the last compression
  const bool patch = model_.patch_radius > 0.0 && !r.roughness.empty();
  std::unique_ptr<PatchAverager> averager;
  if (patch) averager = std::make_unique<PatchAverager>(r.roughness);
  {
    double h0, dh0, w1 = -residual_[0] * f;
    detail::roughness_at(r, model_.traverse.x_start, h0, dh0);
    if (patch)  // as in the initial state: the width under the weight
      averager->evaluate(model_.traverse.x_start,
                         std::sqrt(model_.patch_radius * std::max(contact_.static_compression(weight, detail::law_argument(model_, contact_, r, 0.0, model_.traverse.x_start)), 0.0)),
                         h0, dh0);
    for (int i = 0; i < n; ++i) w1 += phi[i] * q[i];
    const double delta = w1 + h0 - w2;
    record(0, model_.traverse.x_start, delta, h0, contact_.evaluate(delta, 0.0, detail::law_argument(model_, contact_, r, 0.0, model_.traverse.x_start)).contact);
  }

  double delta_last = out.compression[0];
  long lost = 0;
  double f_prev = f;  // force one step back: Newton guess and the quadratic hold
  std::vector<double> g0(n), gm(n, 0.0);
  for (long k = 0; k < steps_; ++k) {
    // The first step of a quadratic hold has no previous value: it is linear.
    const bool first = hold_ == ForceHold::quadratic && k == 0;
    const std::vector<Coefficients>& co = first ? first_ : coef_;
    const BallCoefficients& bc = first ? ball_first_ : ball_;
    // Free part of the step: previous and start forces only (B23, B36).
    for (int i = 0; i < n; ++i) {
      const Coefficients& o = co[i];
      g0[i] = -phi[i] * f / m;
      qf[i] = o.a00 * q[i] + o.a01 * dq[i] + o.bm * gm[i] + o.b0 * g0[i];
      vf[i] = o.a10 * q[i] + o.a11 * dq[i] + o.cm * gm[i] + o.c0 * g0[i];
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
    // Ball (B24, B37): exact for the held force; the F1 parts are in C and D.
    const double w2f = w2 + u2 * h - g * h * h / 2.0 + (bc.am * f_prev + bc.a0 * f) / m2;
    const double u2f = u2 - g * h + (bc.um * f_prev + bc.u0 * f) / m2;
    const double x1 = position(k1), t1 = static_cast<double>(k1) * h;
    double h1, dh1;
    if (patch)
      averager->evaluate(x1, std::sqrt(model_.patch_radius * std::max(delta_last, 0.0)), h1, dh1);
    else
      detail::roughness_at(r, x1, h1, dh1);
    const double f0 = detail::law_argument(model_, contact_, r, t1, x1);
    double comp = comp_[k1], d = rate_comp_[k1], conv = conv_comp_[k1];
    if (first) compliance(phi, slope, residual_[k1], first_, ball_first_, comp, d, conv);
    double rate_free = vfree - u2f;
    if (total_rate_) {  // (B20)
      rate_free += v * (sf + dh1);
      d += conv;
    }
    const ContactSolution cs =
        solve_contact_force(contact_, wf + h1 - w2f, rate_free, comp, d, f0, 2.0 * f - f_prev, weight, tol_);
    const double f1 = cs.force;
    for (int i = 0; i < n; ++i) {
      const double g1 = -phi[i] * f1 / m;
      q[i] = qf[i] + co[i].b1 * g1;
      dq[i] = vf[i] + co[i].c1 * g1;
    }
    w2 = w2f + bc.a1 * f1 / m2;
    u2 = u2f + bc.u1 * f1 / m2;
    f_prev = f;
    f = f1;
    gm.swap(g0);
    delta_last = cs.delta;
    if (!cs.contact) ++lost;
    if (k1 % substeps_ == 0) record(static_cast<std::size_t>(k1 / substeps_), x1, cs.delta, h1, cs.contact);
  }
  out.steps = steps_;
  out.loss_of_contact_share = steps_ > 0 ? static_cast<double>(lost) / static_cast<double>(steps_) : 0.0;
}

}  // namespace rollspec::beam
