// ExactStepIntegrator's step loop (README B26a): one body, compiled for baseline x86-64 and for
// AVX2 (no FMA, so both give the same bits).
#include <algorithm>
#include <cmath>

#include "kernels/beam/contact_solve.hpp"
#include "kernels/beam/exact_step_lanes.hpp"
#include "kernels/contact/hertz.hpp"

namespace rollspec::beam {

using detail::lane_sum;
using detail::Lanes;
using detail::load;
using detail::store;

namespace {
// sum phi x, sum phi y and sum slope x over the padded modes, in the loop's lanes and order.
__attribute__((always_inline)) inline void bracket_sums(const double* phi, const double* slope, const double* x,
                                                        const double* y, int np, double& xsum, double& ysum,
                                                        double& ssum) {
  Lanes sw = {0.0, 0.0, 0.0, 0.0}, sv = sw, ss = sw;
  for (int i = 0; i < np; i += 4) {
    Lanes pi, si, xi, yi;
    load(pi, phi + i), load(si, slope + i), load(xi, x + i), load(yi, y + i);
    sw += pi * xi;
    sv += pi * yi;
    ss += si * xi;
  }
  xsum = lane_sum(sw), ysum = lane_sum(sv), ssum = lane_sum(ss);
}

// sum a b over the padded modes (a sensor's acceleration), in the loop's lanes and order.
__attribute__((always_inline)) inline double lane_dot(const double* a, const double* b, int np) {
  Lanes s = {0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < np; i += 4) {
    Lanes ai, bi;
    load(ai, a + i), load(bi, b + i);
    s += ai * bi;
  }
  return lane_sum(s);
}
}  // namespace

void ExactStepIntegrator::steps(LoopState& st) const {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) {
    steps_avx2(st);
    return;
  }
#endif
  steps_plain(st);
}

__attribute__((always_inline)) inline void ExactStepIntegrator::steps_body(LoopState& st) const {
  const ModalBeam& b = model_.beam;
  const int np = padded_;
  const double m = b.modal_mass(), m2 = model_.ball.mass, g = model_.ball.gravity, v = model_.traverse.speed;
  const double weight = m2 * g, h = h_;
  const Realisation& r = *st.r;
  BallOnBeamResult& out = *st.out;
  const bool table = !phi_table_.empty();
  double* __restrict x = st.x.data();
  double* __restrict y = st.y.data();
  double* __restrict u = st.u.data();
  const double* __restrict zeta_omega2 = zeta_omega2_.data();
  const double* __restrict omega2 = omega2_.data();
  double f = st.f, f_prev = st.f_prev, delta_last = st.delta_last;
  // The ball (B24, B37) with 1/m2 in its coefficients, and, as for the modes (B26a), its free end
  // values w2f = wb + kw F_k, u2f = ub + ku F_k split into what is known before F_k and F_k's share.
  struct BallStep {
    double am, a0, a1, um, u0, u1;
  };
  auto scaled = [m2](const BallCoefficients& c) {
    return BallStep{c.am / m2, c.a0 / m2, c.a1 / m2, c.um / m2, c.u0 / m2, c.u1 / m2};
  };
  const BallStep ball_first = scaled(hold_ == ForceHold::quadratic ? ball_first_ : ball_), ball_next = scaled(ball_);
  const double c2 = g * h * h / 2.0, gh = g * h;
  double wb = st.w2 + st.u2 * h - c2 + ball_first.am * f_prev, ub = st.u2 - gh + ball_first.um * f_prev;
  double kw = ball_first.a0, ku = ball_first.u0;
  // Shapes and slopes at step position j: the tables, or a ring of three evaluated on the fly.
  auto phi_at = [&](long j) -> const double* {
    return table ? phi_table_.data() + j * np : st.ring.data() + (j % 3) * 2 * np;
  };
  auto slope_at = [&](long j) -> const double* {
    if (table) return total_rate_ ? slope_table_.data() + j * np : st.zeros.data();
    return st.ring.data() + ((j % 3) * 2 + 1) * np;
  };
  auto evaluate_shapes = [&](long j) {
    if (!table) b.shapes(position(j), st.ring.data() + (j % 3) * 2 * np, st.ring.data() + ((j % 3) * 2 + 1) * np);
  };
  evaluate_shapes(1);
  // The sums of the first step's bracket (then each step's, from the pass after its previous solve).
  double xsum = 0.0, ysum = 0.0, ssum = 0.0;
  bracket_sums(phi_at(1), slope_at(1), x, y, np, xsum, ysum, ssum);
  long lost = 0;
  int sub = 0;  // steps since the last output sample
  for (long k = 0; k < steps_; ++k) {
    // The first step of a quadratic hold has no previous value: it is linear.
    const bool first = hold_ == ForceHold::quadratic && k == 0;
    const ModeLanes& l = lanes_of_step(k);
    const BallStep& bk = k == 0 ? ball_first : ball_next;
    const long k1 = k + 1;
    const double* phi0 = phi_at(k);
    const double* phi1 = phi_at(k1);
    const double* slope1 = slope_at(k1);
    double fw, fv, fs;
    if (table) {
      fw = fold_w_[k];
      fv = fold_v_[k];
      fs = fold_s_[k];
    } else {
      fold(k, phi0, phi1, slope1, fw, fv, fs);
    }
    const double x1 = position(k1), t1 = static_cast<double>(k1) * h;
    double h1, dh1;
    if (st.averager)
      st.averager->evaluate(x1, contact::hertz::contact_radius_at_approach(model_.patch_radius, delta_last), h1, dh1);
    else
      detail::roughness_at(r, x1, h1, dh1);
    const double f0 = detail::law_argument(model_, contact_, r, t1, x1);
    double comp = comp_[k1], d = rate_comp_[k1], conv = conv_comp_[k1];
    if (first) compliance(phi1, slope1, residual_[k1], first_, ball_first_, comp, d, conv);
    // delta_free = wf + h - w2f and rate_free = vfree - u2f (+ v (sf + h'), B20), each as what is
    // known before F_k plus F_k's share: two operations between F_k and the contact solve.
    const double delta_base = (xsum + h1) - wb, delta_coef = fw - kw;
    double rate_base = ysum - ub, rate_coef = fv - ku;
    if (total_rate_) {  // (B20)
      rate_base += v * (ssum + dh1);
      rate_coef += v * fs;
      d += conv;
    }
    const ContactSolution cs = solve_contact_force(contact_, delta_base + delta_coef * f, rate_base + rate_coef * f,
                                                   comp, d, f0, 2.0 * f - f_prev, weight, tol_);
    const double f1 = cs.force;
    const double w2f = wb + kw * f, u2f = ub + ku * f;
    const bool record = ++sub == substeps_;
    const bool more = k1 < steps_;
    if (more) evaluate_shapes(k1 + 1);
    // One pass over the modes: this step's free part with its start force (B26a); at an output
    // step its end state q = qf + b1 g1 and q'' from (D-9) (B26); the next step's bracket and sums.
    const ModeLanes& ln = lanes_of_step(k1);
    const double* phi2 = more ? phi_at(k1 + 1) : st.zeros.data();
    const double* slope2 = more ? slope_at(k1 + 1) : st.zeros.data();
    const double s0 = -f / m, s1 = -f1 / m;
    Lanes sw = {0.0, 0.0, 0.0, 0.0}, sv = sw, ss = sw;
    for (int i = 0; i < np; i += 4) {
      Lanes p0, xi, yi, p, q;
      load(p0, phi0 + i), load(xi, x + i), load(yi, y + i), load(p, l.p.data() + i), load(q, l.q.data() + i);
      const Lanes g0 = p0 * s0;
      const Lanes qf = xi + p * g0, vf = yi + q * g0;
      if (record) {
        Lanes p1, b1, c1, zo, o2;
        load(p1, phi1 + i), load(b1, l.b1.data() + i), load(c1, l.c1.data() + i);
        load(zo, zeta_omega2 + i), load(o2, omega2 + i);
        const Lanes g1 = p1 * s1, qe = qf + b1 * g1, ve = vf + c1 * g1;
        store(u + i, g1 - zo * ve - o2 * qe);
      }
      Lanes a00, a01, bm, a10, a11, cm, p2;
      load(a00, ln.a00.data() + i), load(a01, ln.a01.data() + i), load(bm, ln.bm.data() + i);
      load(a10, ln.a10.data() + i), load(a11, ln.a11.data() + i), load(cm, ln.cm.data() + i);
      load(p2, phi2 + i);
      const Lanes xn = a00 * qf + a01 * vf + bm * g0, yn = a10 * qf + a11 * vf + cm * g0;
      store(x + i, xn);
      store(y + i, yn);
      sw += p2 * xn;
      sv += p2 * yn;
      if (total_rate_) {
        Lanes sl2;
        load(sl2, slope2 + i);
        ss += sl2 * xn;
      }
    }
    xsum = lane_sum(sw), ysum = lane_sum(sv), ssum = lane_sum(ss);
    // The next step's ball: w2f' = [w2f + u2f h - c2 + am' F_k] + F_{k+1} (a1 + u1 h + a0'),
    // u2f' = [u2f - g h + um' F_k] + F_{k+1} (u1 + u0').
    wb = w2f + u2f * h - c2 + ball_next.am * f;
    ub = u2f - gh + ball_next.um * f;
    kw = bk.a1 + bk.u1 * h + ball_next.a0;
    ku = bk.u1 + ball_next.u0;
    f_prev = f;
    f = f1;
    delta_last = cs.delta;
    if (!cs.contact) ++lost;
    if (record) {
      sub = 0;
      const std::size_t j = static_cast<std::size_t>(k1 / substeps_);
      for (std::size_t s = 0; s < model_.sensors.size(); ++s) {
        out.sensor_acceleration[s][j] = lane_dot(sensor_phi_.data() + s * np, u, np);
      }
      const double w2 = w2f + bk.a1 * f1;
      out.contact_force[j] = f1;
      out.ball_acceleration[j] = f1 / m2 - g;
      out.compression[j] = cs.delta;
      out.contact_deflection[j] = cs.delta - h1 + w2;
      out.ball_displacement[j] = w2;
      out.contact_position[j] = x1;
      out.loss_of_contact[j] = cs.contact ? 0 : 1;
    }
  }
  st.lost = lost;
}

void ExactStepIntegrator::steps_plain(LoopState& st) const { steps_body(st); }
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) void ExactStepIntegrator::steps_avx2(LoopState& st) const { steps_body(st); }
#endif

}  // namespace rollspec::beam
