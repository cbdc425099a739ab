#include "kernels/beam/exact_step_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "kernels/beam/contact_patch_filter.hpp"
#include "kernels/beam/contact_solve.hpp"
#include "kernels/beam/exact_step_lanes.hpp"
#include "kernels/contact/hertz.hpp"

namespace rollspec::beam {

using detail::lane_dot3;

ExactStepIntegrator::ExactStepIntegrator(BallOnBeamModel model, const ExactStepOptions& o)
    : model_(std::move(model)),
      contact_(model_.contact),
      substeps_(o.substeps),
      hold_(o.hold),
      tol_(o.solver_tolerance) {
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
  ball_ =
      hold_ == ForceHold::linear ? ball_first_ : BallCoefficients{-h * h / 24.0, 5.0 * h * h / 12.0, h * h / 8.0,
                                                                  -h / 12.0,     2.0 * h / 3.0,      5.0 * h / 12.0};
  padded_ = (n + 3) / 4 * 4;
  const int np = padded_;
  lanes_[0] = lanes(hold_ == ForceHold::quadratic ? first_ : coef_, nullptr, np);
  lanes_[1] = lanes(coef_, hold_ == ForceHold::quadratic ? &first_ : &coef_, np);
  lanes_[2] = lanes(coef_, &coef_, np);
  zeta_omega2_.assign(np, 0.0);
  omega2_.assign(np, 0.0);
  for (int i = 0; i < n; ++i) {
    zeta_omega2_[i] = 2.0 * b.zeta(i) * b.omega(i);
    omega2_[i] = b.omega(i) * b.omega(i);
  }
  const bool table = static_cast<double>(steps_ + 1) * n <= static_cast<double>(o.max_table_entries);
  if (table) {  // slopes only when the damper sees the convective rate (B20)
    phi_table_.assign(static_cast<std::size_t>(steps_ + 1) * np, 0.0);
    if (total_rate_) slope_table_.assign(phi_table_.size(), 0.0);
  }
  comp_.resize(steps_ + 1);
  rate_comp_.resize(steps_ + 1);
  conv_comp_.resize(steps_ + 1);
  residual_.resize(steps_ + 1);
  // Positions are independent: the same bits on any thread count.
#pragma omp parallel
  {
    std::vector<double> phi(n), slope(n);
#pragma omp for schedule(static)
    for (long k = 0; k <= steps_; ++k) {
      const double x = position(k);
      b.shapes(x, phi.data(), slope.data());
      if (table) {
        std::copy(phi.begin(), phi.end(), phi_table_.begin() + k * np);
        if (total_rate_) std::copy(slope.begin(), slope.end(), slope_table_.begin() + k * np);
      }
      // (B12) from the shapes already at hand
      double modal = 0.0;
      for (int i = 0; i < n; ++i) modal += phi[i] * phi[i] / (m * b.omega(i) * b.omega(i));
      residual_[k] = b.static_correction() ? b.static_flexibility(x, x) - modal : 0.0;
      compliance(phi.data(), slope.data(), residual_[k], coef_, ball_, comp_[k], rate_comp_[k], conv_comp_[k]);
    }
  }
  if (table) {
    fold_w_.resize(steps_);
    fold_v_.resize(steps_);
    fold_s_.resize(steps_);
    const double* none = total_rate_ ? nullptr : phi_table_.data();  // fold_s unused then
    for (long k = 0; k < steps_; ++k)
      fold(k, phi_table_.data() + k * np, phi_table_.data() + (k + 1) * np,
           total_rate_ ? slope_table_.data() + (k + 1) * np : none, fold_w_[k], fold_v_[k], fold_s_[k]);
  }
  sensor_phi_.assign(model_.sensors.size() * np, 0.0);
  for (std::size_t s = 0; s < model_.sensors.size(); ++s) b.shapes(model_.sensors[s], sensor_phi_.data() + s * np);
}

ExactStepIntegrator::ModeLanes ExactStepIntegrator::lanes(const std::vector<Coefficients>& cur,
                                                          const std::vector<Coefficients>* prev, int np) {
  ModeLanes l;
  for (auto* v : {&l.a00, &l.a01, &l.a10, &l.a11, &l.bm, &l.cm, &l.b1, &l.c1, &l.p, &l.q}) v->assign(np, 0.0);
  for (std::size_t i = 0; i < cur.size(); ++i) {
    const Coefficients& c = cur[i];
    const double b1p = prev ? (*prev)[i].b1 : 0.0, c1p = prev ? (*prev)[i].c1 : 0.0;
    l.a00[i] = c.a00;
    l.a01[i] = c.a01;
    l.a10[i] = c.a10;
    l.a11[i] = c.a11;
    l.bm[i] = c.bm;
    l.cm[i] = c.cm;
    l.b1[i] = c.b1;
    l.c1[i] = c.c1;
    l.p[i] = c.a00 * b1p + c.a01 * c1p + c.b0;  // (B26a)
    l.q[i] = c.a10 * b1p + c.a11 * c1p + c.c0;
  }
  return l;
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
  if (!phi_table_.empty()) {
    phi = phi_table_.data() + k * padded_;
    slope = total_rate_ ? slope_table_.data() + k * padded_ : ss.data();  // ss stays zero otherwise
    return;
  }
  model_.beam.shapes(position(k), sp.data(), ss.data());
  phi = sp.data();
  slope = ss.data();
}

void ExactStepIntegrator::fold(long k, const double* phi0, const double* phi1, const double* slope1, double& fw,
                               double& fv, double& fs) const {
  const ModeLanes& l = lanes_of_step(k);
  const double m = model_.beam.modal_mass();
  fw = -lane_dot3(phi1, l.p.data(), phi0, padded_) / m;
  fv = -lane_dot3(phi1, l.q.data(), phi0, padded_) / m;
  fs = total_rate_ ? -lane_dot3(slope1, l.p.data(), phi0, padded_) / m : 0.0;
}

void ExactStepIntegrator::record_sample(BallOnBeamResult& out, std::size_t j, const SampleState& x) const {
  const ModalBeam& b = model_.beam;
  const int n = b.modes();
  const double m = b.modal_mass(), m2 = model_.ball.mass, g = model_.ball.gravity;
  for (std::size_t s = 0; s < model_.sensors.size(); ++s) {
    const double* ps = sensor_phi_.data() + s * padded_;
    double a = 0.0;
    for (int i = 0; i < n; ++i) {  // exact q_n'' from (D-9)
      const double w = b.omega(i);
      a += ps[i] * (-x.phi[i] * x.f / m - 2.0 * b.zeta(i) * w * x.dq[i] - w * w * x.q[i]);
    }
    out.sensor_acceleration[s][j] = a;
  }
  out.contact_force[j] = x.f;
  out.ball_acceleration[j] = x.f / m2 - g;
  out.compression[j] = x.delta;
  out.contact_deflection[j] = x.delta - x.hx + x.w2;
  out.ball_displacement[j] = x.w2;
  out.contact_position[j] = x.xi;
  out.loss_of_contact[j] = x.contact ? 0 : 1;
}

BallOnBeamResult ExactStepIntegrator::run(const Realisation& r) const {
  BallOnBeamResult out;
  run(r, out);
  return out;
}

void ExactStepIntegrator::run_reference(const Realisation& r, BallOnBeamResult& out) const {
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
    record_sample(out, j, {phi, q.data(), dq.data(), f, xi, delta, hx, w2, contact});
  };
  // (B38) instantaneous contact-patch average of the roughness, width from the last compression
  const bool patch = model_.patch_radius > 0.0 && !r.roughness.empty();
  std::unique_ptr<PatchAverager> averager;
  if (patch) averager = std::make_unique<PatchAverager>(r.roughness);
  {
    double h0, dh0, w1 = -residual_[0] * f;
    detail::roughness_at(r, model_.traverse.x_start, h0, dh0);
    if (patch)  // as in the initial state: the width under the weight
      averager->evaluate(
          model_.traverse.x_start,
          contact::hertz::contact_radius_at_approach(
              model_.patch_radius, contact_.static_compression(weight, detail::law_argument(model_, contact_, r, 0.0,
                                                                                            model_.traverse.x_start))),
          h0, dh0);
    for (int i = 0; i < n; ++i) w1 += phi[i] * q[i];
    const double delta = w1 + h0 - w2;
    record(
        0, model_.traverse.x_start, delta, h0,
        contact_.evaluate(delta, 0.0, detail::law_argument(model_, contact_, r, 0.0, model_.traverse.x_start)).contact);
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
      averager->evaluate(x1, contact::hertz::contact_radius_at_approach(model_.patch_radius, delta_last), h1, dh1);
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

void ExactStepIntegrator::run(const Realisation& r, BallOnBeamResult& out) const {
  const ModalBeam& b = model_.beam;
  const int n = b.modes(), np = padded_;
  const double m2 = model_.ball.mass, g = model_.ball.gravity;
  const double weight = m2 * g;
  detail::resize_result(model_, samples_, out, false);  // every sample is written below
  const detail::InitialState init = detail::static_initial_state(model_, contact_, r);
  LoopState st;
  for (auto* vec : {&st.x, &st.y, &st.u, &st.zeros}) vec->assign(np, 0.0);
  // The start state as a "free part" with no end force of a previous step (lanes_[0]: b1' = c1' = 0).
  const double* q0 = init.y.data();
  const double* dq0 = init.y.data() + n;
  st.w2 = init.y[2 * n];
  st.u2 = init.y[2 * n + 1];
  st.f = st.f_prev = init.force;
  st.r = &r;
  st.out = &out;
  const bool patch = model_.patch_radius > 0.0 && !r.roughness.empty();  // (B38)
  std::unique_ptr<PatchAverager> averager;
  if (patch) averager = std::make_unique<PatchAverager>(r.roughness);
  st.averager = averager.get();
  const double* phi = phi_table_.data();
  if (phi_table_.empty()) {
    st.ring.assign(6 * static_cast<std::size_t>(np), 0.0);
    b.shapes(model_.traverse.x_start, st.ring.data(), st.ring.data() + np);
    phi = st.ring.data();
  }
  {  // sample 0, as run_reference records it
    const double f = st.f;
    double h0, dh0, w1 = -residual_[0] * f;
    detail::roughness_at(r, model_.traverse.x_start, h0, dh0);
    const double f0 = detail::law_argument(model_, contact_, r, 0.0, model_.traverse.x_start);
    if (patch)  // as in the initial state: the width under the weight
      averager->evaluate(
          model_.traverse.x_start,
          contact::hertz::contact_radius_at_approach(model_.patch_radius, contact_.static_compression(weight, f0)), h0,
          dh0);
    for (int i = 0; i < n; ++i) w1 += phi[i] * q0[i];
    const double delta = w1 + h0 - st.w2;
    record_sample(
        out, 0,
        {phi, q0, dq0, f, model_.traverse.x_start, delta, h0, st.w2, contact_.evaluate(delta, 0.0, f0).contact});
    st.delta_last = delta;
  }
  // The first step's bracket (B26a) from the start state (gm = 0).
  const ModeLanes& l0 = lanes_[0];
  for (int i = 0; i < n; ++i) {
    st.x[i] = l0.a00[i] * q0[i] + l0.a01[i] * dq0[i] + l0.bm[i] * 0.0;
    st.y[i] = l0.a10[i] * q0[i] + l0.a11[i] * dq0[i] + l0.cm[i] * 0.0;
  }
  if (steps_ > 0) steps(st);
  out.steps = steps_;
  out.loss_of_contact_share = steps_ > 0 ? static_cast<double>(st.lost) / static_cast<double>(steps_) : 0.0;
}

}  // namespace rollspec::beam