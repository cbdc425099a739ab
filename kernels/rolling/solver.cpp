#include "kernels/rolling/solver.hpp"

#include <algorithm>
#include <limits>
#include <cmath>
#include <stdexcept>

#include "kernels/rolling/rotary_inertia.hpp"
#include "kernels/rolling/rotation.hpp"

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

enum class Mode { Static, Dynamic, Mass };

// Receives tangent entries by global DOF.
struct Sink {
  virtual ~Sink() = default;
  virtual void add(int i, int j, double v) = 0;
};

template <int M>
void add_block(Sink* s, const std::array<int, M>& dofs, const Eigen::Matrix<double, M, M>& K) {
  if (!s) return;
  for (int j = 0; j < M; ++j)
    for (int i = 0; i < M; ++i) s->add(dofs[i], dofs[j], K(i, j));
}

std::array<int, 3> dofs3(int first) { return {first, first + 1, first + 2}; }
std::array<int, 6> dofs6(int node) {
  return {6 * node, 6 * node + 1, 6 * node + 2, 6 * node + 3, 6 * node + 4, 6 * node + 5};
}

struct DenseSink : Sink {
  Eigen::MatrixXd* K;
  explicit DenseSink(Eigen::MatrixXd* k) : K(k) {}
  void add(int i, int j, double v) override { (*K)(i, j) += v; }
};

// Sparse assembly into a fixed pattern: the first pass records triplets and the slot of
// every entry in the compressed matrix; later passes add values straight into the slots
// (the assembly order is deterministic, so the pattern is analysed once).
struct SparseSink : Sink {
  const std::vector<int>* eq = nullptr;
  int neq = 0;
  bool recording = true;
  bool mismatch = false;
  bool new_pattern = false;
  std::vector<Eigen::Triplet<double>> trip;
  std::vector<int> slot, srow, scol;
  std::size_t k = 0;
  Eigen::SparseMatrix<double> A;

  void begin() {
    k = 0;
    mismatch = false;
    if (recording) {
      trip.clear();
    } else {
      std::fill(A.valuePtr(), A.valuePtr() + A.nonZeros(), 0.0);
    }
  }
  void add(int i, int j, double v) override {
    const int r = (*eq)[i], c = (*eq)[j];
    if (r < 0 || c < 0) return;
    if (recording) {
      trip.emplace_back(r, c, v);
      return;
    }
    if (k >= slot.size() || srow[k] != r || scol[k] != c) {
      mismatch = true;
      return;
    }
    A.valuePtr()[slot[k++]] += v;
  }
  void finish() {
    if (!recording) {
      if (k != slot.size()) mismatch = true;
      return;
    }
    A.resize(neq, neq);
    A.setFromTriplets(trip.begin(), trip.end());
    A.makeCompressed();
    slot.clear();
    srow.clear();
    scol.clear();
    for (const auto& t : trip) {
      const int c = t.col();
      const int* b = A.innerIndexPtr() + A.outerIndexPtr()[c];
      const int* e = A.innerIndexPtr() + A.outerIndexPtr()[c + 1];
      const int* p = std::lower_bound(b, e, t.row());
      slot.push_back(static_cast<int>(p - A.innerIndexPtr()));
      srow.push_back(t.row());
      scol.push_back(c);
    }
    recording = false;
    new_pattern = true;
  }
};

struct MassPoint {
  double xi = 0.0, weight = 0.0, jac = 0.0;
  Matrix3d R = Matrix3d::Identity();
  Vector3d W = Vector3d::Zero(), A = Vector3d::Zero();
};

Matrix3d section_inertia(const BeamSection& s) {
  return Eigen::Vector3d(s.rhoJ1, s.rhoI2, s.rhoI3).asDiagonal();
}

// Rolling frictional contact with a rough surface (README R-63): the plane element (D-13, D-14)
// on the tangent plane at the closest point S(s*) with normal nu, so gap, normal force and the
// stick/slip return mapping are those of R-61 and seed 000 Eq. 8-16. The history is carried
// over to the turned plane: x_f += r (nu_old - nu) and g_st projected, so that pure rolling over
// a curved surface (centre step r alpha, contact point step r (alpha - dtheta)) leaves g_t = 0.
// The normal block of the tangent takes the exact curvature term of R-61; the friction blocks
// neglect the turning of the plane with x, which costs Newton iterations, not accuracy.
ContactEval rough_friction_contact(const SurfaceContactLaw& law, const SurfaceContactEval& sv, const ContactState& state,
                                   const Vector3d& x_start, const Vector3d& x, const Vector3d& alpha) {
  const Plane tangent_plane = make_plane(sv.point, sv.normal);
  const ContactLaw cl{law.radius, law.mu, law.eps_n, law.eps_t, law.rolling};
  ContactState carried = state;
  if (state.active) {
    carried.x_f += law.radius * (state.normal - sv.normal);
    carried.g_st -= carried.g_st.dot(sv.normal) * sv.normal;
  }
  ContactEval fe = evaluate_contact(tangent_plane, cl, carried, x_start, x, alpha, NormalForce::EndPoint);
  fe.next.normal = sv.normal;
  if (fe.active) fe.tangent.block<3, 3>(0, 0) += sv.tangent - law.eps_n * sv.normal * sv.normal.transpose();
  return fe;
}

}  // namespace

struct Solver::Impl {
  int nn = 0;
  std::vector<int> eq;  // global DOF -> equation (-1: imposed)
  int neq = 0;
  std::vector<std::array<BeamStiffPoint, 2>> spts;
  std::vector<std::array<MassPoint, 3>> mpts;
  SparseSink sink;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  std::vector<ContactEval> cevals;
  std::vector<SurfaceContactEval> sevals;
  std::vector<ContactEval> sfevals;  // friction part of rough-surface pairs with mu > 0
  double penalty_energy = 0.0, tangential_energy = 0.0;
  int analyses = 0;  // SparseLU::analyzePattern calls

  void assemble(const Solver& S, const VectorXd& q, double t1, double dt, Mode mode, VectorXd& R,
                Sink* K, std::vector<ContactEval>* ce, std::vector<SurfaceContactEval>* se = nullptr,
                std::vector<ContactEval>* sfe = nullptr) const;
  VectorXd external(const Solver& S, double t) const;
};

// Residual R = f_int + f_inertia - f_ext - f_contact and its tangent dR/dq, q = [du, a] per
// node (README Eq. R-40).
void Solver::Impl::assemble(const Solver& S, const VectorXd& q, double t1, double dt, Mode mode,
                            VectorXd& R, Sink* K, std::vector<ContactEval>* ce,
                            std::vector<SurfaceContactEval>* se, std::vector<ContactEval>* sfe) const {
  const Model& m = S.model_;
  const auto& nodes = S.nodes_;
  R.setZero(6 * nn);
  // energy-consistent integrator: midpoint rule, loads averaged over the step
  const bool mid = mode == Mode::Dynamic && S.opt_.integrator == Integrator::EnergyConsistent;
  auto series = [&](const TimeSeries& ts) { return mid ? 0.5 * (ts(S.t_) + ts(t1)) : ts(t1); };
  const double gs = series(m.gravity_series);
  const Vector3d grav = gs * m.gravity;
  const double c2 = (mode == Mode::Dynamic) ? (mid ? 2.0 : 4.0) / (dt * dt) : 0.0;
  auto du = [&](int a) { return Vector3d(q.segment<3>(6 * a)); };
  auto al = [&](int a) { return Vector3d(q.segment<3>(6 * a + 3)); };
  // translational acceleration of node a: Newmark trapezoidal a_{n+1}, or the midpoint
  // mean acceleration (v_{n+1} - v_n)/dt = 2 (du - dt v_n)/dt^2
  auto acc = [&](int a) {
    return mid ? Vector3d(c2 * (du(a) - dt * nodes[a].v)) : Vector3d(c2 * (du(a) - dt * nodes[a].v) - nodes[a].a);
  };

  if (K) {  // every node's diagonal block is part of the pattern
    const Eigen::Matrix<double, 6, 6> Z = Eigen::Matrix<double, 6, 6>::Zero();
    for (int a = 0; a < nn; ++a) add_block<6>(K, dofs6(a), Z);
  }

  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const BeamElement& be = m.beams[e];
    const BeamSection& sec = m.sections[static_cast<std::size_t>(be.section)];
    std::array<Vector3d, 3> x, a;
    std::array<int, 18> dofs{};
    for (int k = 0; k < 3; ++k) {
      const int nd = be.nodes[k];
      x[k] = nodes[nd].x + du(nd);
      a[k] = al(nd);
      for (int i = 0; i < 6; ++i) dofs[6 * k + i] = 6 * nd + i;
    }
    // stiffness (reduced 2-point Gauss)
    const BeamElementEval ev = beam_element_internal(sec, spts[e], x, a, K && mode != Mode::Mass);
    for (int k = 0; k < 18; ++k) R(dofs[k]) += ev.force(k);
    Eigen::Matrix<double, 18, 18> Ke = Eigen::Matrix<double, 18, 18>::Zero();
    if (mode != Mode::Mass) Ke = ev.tangent;
    // mass, rotary inertia and gravity (3-point Gauss, exact for the consistent mass)
    const Matrix3d Js = section_inertia(sec);
    for (const MassPoint& p : mpts[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      const double w = p.weight * p.jac;
      for (int k = 0; k < 3; ++k) R.segment<3>(dofs[6 * k]) -= N[k] * w * sec.rhoA * grav;
      if (mode == Mode::Dynamic) {
        Vector3d ag = Vector3d::Zero(), ag_a = Vector3d::Zero();
        for (int k = 0; k < 3; ++k) {
          ag += N[k] * acc(be.nodes[k]);
          ag_a += N[k] * a[k];
        }
        const RotaryInertiaEval ri = rotary_inertia(Js, p.R, p.W, p.A, dt, ag_a);
        for (int k = 0; k < 3; ++k) {
          R.segment<3>(dofs[6 * k]) += N[k] * w * sec.rhoA * ag;
          R.segment<3>(dofs[6 * k + 3]) += N[k] * w * ri.residual;
          for (int l = 0; l < 3; ++l) {
            Ke.block<3, 3>(6 * k, 6 * l).diagonal().array() += N[k] * N[l] * w * sec.rhoA * c2;
            Ke.block<3, 3>(6 * k + 3, 6 * l + 3) += N[k] * N[l] * w * ri.tangent;
          }
        }
      } else if (mode == Mode::Mass) {
        const Vector3d gyro = p.R * p.W.cross(Js * p.W);
        const Matrix3d Jsp = p.R * Js * p.R.transpose();
        for (int k = 0; k < 3; ++k) {
          R.segment<3>(dofs[6 * k + 3]) += N[k] * w * gyro;
          for (int l = 0; l < 3; ++l) {
            Ke.block<3, 3>(6 * k, 6 * l).diagonal().array() += N[k] * N[l] * w * sec.rhoA;
            Ke.block<3, 3>(6 * k + 3, 6 * l + 3) += N[k] * N[l] * w * Jsp;
          }
        }
      }
    }
    add_block<18>(K, dofs, Ke);
  }

  for (const RigidBody& b : m.bodies) {
    const int nd = b.node;
    R.segment<3>(6 * nd) -= b.mass * grav;
    Eigen::Matrix<double, 6, 6> Kb = Eigen::Matrix<double, 6, 6>::Zero();
    if (mode == Mode::Dynamic) {
      const RotaryInertiaEval ri = mid ? rotary_inertia_midpoint(b.inertia, nodes[nd].R, nodes[nd].W, dt, al(nd))
                                       : rotary_inertia(b.inertia, nodes[nd].R, nodes[nd].W, nodes[nd].A, dt, al(nd));
      R.segment<3>(6 * nd) += b.mass * acc(nd);
      R.segment<3>(6 * nd + 3) += ri.residual;
      Kb.block<3, 3>(0, 0).diagonal().array() += b.mass * c2;
      Kb.block<3, 3>(3, 3) = ri.tangent;
    } else if (mode == Mode::Mass) {
      const NodeState& ns = nodes[nd];
      R.segment<3>(6 * nd + 3) += ns.R * ns.W.cross(b.inertia * ns.W);
      Kb.block<3, 3>(0, 0).diagonal().array() += b.mass;
      Kb.block<3, 3>(3, 3) = ns.R * b.inertia * ns.R.transpose();
    }
    add_block<6>(K, dofs6(nd), Kb);
  }

  for (const NodalLoad& L : m.loads) {
    const double s = series(L.series);
    const int nd = L.node;
    R.segment<3>(6 * nd) -= s * L.force;
    // pseudo-moment Xi^T m of a fixed-axis spatial moment and its load stiffness
    const Vector3d a = al(nd);
    R.segment<3>(6 * nd + 3) -= s * rodrigues_xi(a).transpose() * L.moment;
    const Matrix3d Kl = (mode == Mode::Mass) ? Matrix3d::Zero() : Matrix3d(-s * d_xi_transpose_m(a, L.moment));
    add_block<3>(K, dofs3(6 * nd + 3), Kl);
  }

  if (ce) ce->resize(m.contacts.size());
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    const ContactPair& cp = m.contacts[c];
    const int nd = cp.node;
    const ContactEval ev = evaluate_contact(m.planes[static_cast<std::size_t>(cp.plane)], cp.law,
                                            S.cstate_[c], nodes[nd].x, nodes[nd].x + du(nd), al(nd),
                                            mid ? NormalForce::DiscreteGradient : NormalForce::EndPoint);
    R.segment<6>(6 * nd) += ev.residual;
    add_block<6>(K, dofs6(nd), mode == Mode::Mass ? Eigen::Matrix<double, 6, 6>::Zero() : ev.tangent);
    if (ce) (*ce)[c] = ev;
  }

  // rough surfaces: closest-point penalty contact, end-point force; with friction the
  // rolling contact element on the tangent plane at the closest point
  if (se) se->resize(m.surface_contacts.size());
  if (sfe) sfe->resize(m.surface_contacts.size());
  for (std::size_t c = 0; c < m.surface_contacts.size(); ++c) {
    const SurfaceContactPair& sp = m.surface_contacts[c];
    const int nd = sp.node;
    SurfaceContactEval ev =
        evaluate_surface_contact(m.surfaces[static_cast<std::size_t>(sp.surface)], sp.law, nodes[nd].x + du(nd));
    if (sp.law.damping > 0.0 && mode == Mode::Dynamic && !mid) {
      // normal damper on the Newmark end velocity v1 = 2 du/dt - v_n
      Matrix3d Kd = Matrix3d::Zero();
      if (ev.active) {
        const double gdot = ev.normal.dot(2.0 / dt * du(nd) - nodes[nd].v);
        const double fn = sp.law.eps_n * (-ev.g_n);
        ev.damping_force = -sp.law.damping * gdot;
        if (fn + ev.damping_force < 0.0) {  // the contact never pulls: the normal force is zero
          ev.damping_force = -fn;
          Kd = -sp.law.eps_n * ev.normal * ev.normal.transpose();
        } else {
          Kd = sp.law.damping * 2.0 / dt * ev.normal * ev.normal.transpose();
        }
        R.segment<3>(6 * nd) -= ev.damping_force * ev.normal;
      }
      add_block<3>(K, dofs3(6 * nd), Kd);
    }
    if (se) (*se)[c] = ev;
    if (!(sp.law.mu > 0.0)) {
      R.segment<3>(6 * nd) -= ev.force;
      add_block<3>(K, dofs3(6 * nd), mode == Mode::Mass ? Matrix3d::Zero() : ev.tangent);
      continue;
    }
    const ContactEval fe = rough_friction_contact(sp.law, ev, S.sstate_[c], nodes[nd].x, nodes[nd].x + du(nd), al(nd));
    R.segment<6>(6 * nd) += fe.residual;
    add_block<6>(K, dofs6(nd), mode == Mode::Mass ? Eigen::Matrix<double, 6, 6>::Zero() : fe.tangent);
    if (sfe) (*sfe)[c] = fe;
  }
}

// External nodal forces and spatial moments at time t (gravity as consistent loads).
VectorXd Solver::Impl::external(const Solver& S, double t) const {
  const Model& m = S.model_;
  VectorXd f = VectorXd::Zero(6 * nn);
  const Vector3d grav = m.gravity_series(t) * m.gravity;
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const BeamSection& sec = m.sections[static_cast<std::size_t>(m.beams[e].section)];
    for (const MassPoint& p : mpts[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      for (int k = 0; k < 3; ++k) f.segment<3>(6 * m.beams[e].nodes[k]) += N[k] * p.weight * p.jac * sec.rhoA * grav;
    }
  }
  for (const RigidBody& b : m.bodies) f.segment<3>(6 * b.node) += b.mass * grav;
  for (const NodalLoad& L : m.loads) {
    f.segment<3>(6 * L.node) += L.series(t) * L.force;
    f.segment<3>(6 * L.node + 3) += L.series(t) * L.moment;
  }
  return f;
}

Solver::Solver(Model model, SolverOptions options, double t0)
    : impl_(std::make_unique<Impl>()), model_(std::move(model)), opt_(options), t_(t0) {
  Impl& I = *impl_;
  const Model& m = model_;
  I.nn = static_cast<int>(m.X.size());
  if (m.frames.size() != m.X.size()) throw std::invalid_argument("Solver: frames.size() != X.size()");
  nodes_.resize(m.X.size());
  for (std::size_t a = 0; a < m.X.size(); ++a) {
    nodes_[a].x = m.X[a];
    nodes_[a].R = m.frames[a];
    if (!m.v0.empty()) nodes_[a].v = m.v0[a];
    if (!m.w0.empty()) nodes_[a].W = m.frames[a].transpose() * m.w0[a];
  }
  I.eq.assign(6 * m.X.size(), 0);
  for (const ImposedDof& d : m.imposed) {
    if (d.node < 0 || d.node >= I.nn || d.dof < 0 || d.dof > 5) throw std::invalid_argument("Solver: bad imposed DOF");
    I.eq[static_cast<std::size_t>(6 * d.node + d.dof)] = -1;
  }
  for (int& e : I.eq)
    if (e == 0) e = I.neq++;
  I.sink.eq = &I.eq;
  I.sink.neq = I.neq;

  // Gauss points; the initial beam is straight: K_n = 0, frame from the tangent and the
  // first node's e2 (README R-15).
  const double gs = 1.0 / std::sqrt(3.0), gm = std::sqrt(0.6);
  for (const BeamElement& be : m.beams) {
    auto frame_at = [&](double xi, double& jac) {
      double N[3], dN[3];
      quadratic_shape(xi, N, dN);
      Vector3d Xp = Vector3d::Zero();
      for (int k = 0; k < 3; ++k) Xp += dN[k] * m.X[static_cast<std::size_t>(be.nodes[k])];
      jac = Xp.norm();
      const Vector3d e1 = Xp / jac;
      Vector3d e2 = m.frames[static_cast<std::size_t>(be.nodes[0])].col(1);
      e2 = (e2 - e2.dot(e1) * e1).normalized();
      Matrix3d Rf;
      Rf.col(0) = e1;
      Rf.col(1) = e2;
      Rf.col(2) = e1.cross(e2);
      return Rf;
    };
    std::array<BeamStiffPoint, 2> sp;
    for (int k = 0; k < 2; ++k) {
      sp[k].xi = k == 0 ? -gs : gs;
      sp[k].weight = 1.0;
      sp[k].R = frame_at(sp[k].xi, sp[k].jac);
    }
    I.spts.push_back(sp);
    std::array<MassPoint, 3> mp;
    const double xis[3] = {-gm, 0.0, gm}, ws[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    for (int k = 0; k < 3; ++k) {
      mp[k].xi = xis[k];
      mp[k].weight = ws[k];
      mp[k].R = frame_at(xis[k], mp[k].jac);
      if (!m.w0.empty()) {
        double N[3], dN[3];
        quadratic_shape(xis[k], N, dN);
        Vector3d w = Vector3d::Zero();
        for (int j = 0; j < 3; ++j) w += N[j] * m.w0[static_cast<std::size_t>(be.nodes[j])];
        mp[k].W = mp[k].R.transpose() * w;
      }
    }
    I.mpts.push_back(mp);
  }
  if (opt_.integrator == Integrator::EnergyConsistent && !m.beams.empty())
    throw std::invalid_argument("Solver: the energy-consistent integrator supports rigid bodies only (no beams)");
  // lumped node masses: rigid bodies plus row sums of the consistent beam mass
  node_mass_.assign(m.X.size(), 0.0);
  for (const RigidBody& b : m.bodies) node_mass_[static_cast<std::size_t>(b.node)] += b.mass;
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const BeamSection& sec = m.sections[static_cast<std::size_t>(m.beams[e].section)];
    for (const MassPoint& p : I.mpts[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      for (int k = 0; k < 3; ++k) node_mass_[static_cast<std::size_t>(m.beams[e].nodes[k])] += N[k] * p.weight * p.jac * sec.rhoA;
    }
  }
  cstate_.assign(m.contacts.size(), ContactState{});
  contact_out_.assign(m.contacts.size(), ContactOutput{});
  // initial penalty energy of contacts closed at t0 (forces follow in the first step)
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    const ContactPair& cp = m.contacts[c];
    const Plane& pl = m.planes[static_cast<std::size_t>(cp.plane)];
    const double g = (nodes_[static_cast<std::size_t>(cp.node)].x - pl.point).dot(pl.normal) - cp.law.radius;
    contact_out_[c].g_n = g;
    if (g < 0.0) {
      contact_out_[c].penalty = 0.5 * cp.law.eps_n * g * g;
      I.penalty_energy += contact_out_[c].penalty;
    }
  }
  surface_out_.assign(m.surface_contacts.size(), ContactOutput{});
  sstate_.assign(m.surface_contacts.size(), ContactState{});
  for (std::size_t c = 0; c < m.surface_contacts.size(); ++c) {
    const SurfaceContactPair& sp = m.surface_contacts[c];
    const SurfaceContactEval ev = evaluate_surface_contact(m.surfaces[static_cast<std::size_t>(sp.surface)], sp.law,
                                                           nodes_[static_cast<std::size_t>(sp.node)].x);
    surface_out_[c].g_n = ev.g_n;
    if (ev.active) {
      surface_out_[c].penalty = 0.5 * sp.law.eps_n * ev.g_n * ev.g_n;
      I.penalty_energy += surface_out_[c].penalty;
    }
  }
  reactions_.assign(m.imposed.size(), 0.0);
  if (opt_.analysis == Analysis::Dynamic && opt_.consistent_initial_acceleration) initial_acceleration();
  acc_.initial_balance = energies().balance();
}

double Solver::impact_step_limit(double dt) const {
  double lim = dt;
  if (!(opt_.impact_step_fraction > 0.0)) return lim;
  const double two_pi = 6.283185307179586;
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const ContactPair& cp = model_.contacts[c];
    const std::size_t nd = static_cast<std::size_t>(cp.node);
    if (!(node_mass_[nd] > 0.0) || !(cp.law.eps_n > 0.0)) continue;
    const Plane& pl = model_.planes[static_cast<std::size_t>(cp.plane)];
    const double g = (nodes_[nd].x - pl.point).dot(pl.normal) - cp.law.radius;
    const double gdot = nodes_[nd].v.dot(pl.normal);
    // closed, or predicted to close within dt at the current normal velocity
    if (cstate_[c].active || g <= 0.0 || g + dt * gdot <= 0.0)
      lim = std::min(lim, opt_.impact_step_fraction * two_pi * std::sqrt(node_mass_[nd] / cp.law.eps_n));
  }
  for (std::size_t c = 0; c < model_.surface_contacts.size(); ++c) {  // rough surfaces: gap and normal R-61
    const SurfaceContactPair& sp = model_.surface_contacts[c];
    const std::size_t nd = static_cast<std::size_t>(sp.node);
    if (!(node_mass_[nd] > 0.0) || !(sp.law.eps_n > 0.0)) continue;
    const SurfaceContactEval ev = evaluate_surface_contact(model_.surfaces[static_cast<std::size_t>(sp.surface)], sp.law, nodes_[nd].x);
    if (ev.g_n <= 0.0 || ev.g_n + dt * nodes_[nd].v.dot(ev.normal) <= 0.0)
      lim = std::min(lim, opt_.impact_step_fraction * two_pi * std::sqrt(node_mass_[nd] / sp.law.eps_n));
  }
  return lim;
}

Solver::~Solver() = default;

// M a0 = -R(t0) with the current (zero-increment) state; imposed DOFs get zero
// acceleration, open contacts and unknown slip directions contribute no friction.
void Solver::initial_acceleration() {
  Impl& I = *impl_;
  if (I.neq == 0) return;  // fully imposed motion
  VectorXd R;
  SparseSink ms;
  ms.eq = &I.eq;
  ms.neq = I.neq;
  ms.begin();
  I.assemble(*this, VectorXd::Zero(6 * I.nn), t_, 1.0, Mode::Mass, R, &ms, nullptr);
  ms.finish();
  VectorXd rf(I.neq);
  for (std::size_t i = 0; i < I.eq.size(); ++i)
    if (I.eq[i] >= 0) rf(I.eq[i]) = -R(static_cast<Eigen::Index>(i));
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(ms.A);
  if (lu.info() != Eigen::Success) return;  // massless DOFs: leave a0 = 0
  const VectorXd a0 = lu.solve(rf);
  VectorXd full = VectorXd::Zero(6 * I.nn);
  for (std::size_t i = 0; i < I.eq.size(); ++i)
    if (I.eq[i] >= 0) full(static_cast<Eigen::Index>(i)) = a0(I.eq[i]);
  for (int a = 0; a < I.nn; ++a) {
    nodes_[a].a = full.segment<3>(6 * a);
    nodes_[a].A = nodes_[a].R.transpose() * full.segment<3>(6 * a + 3);
  }
  for (std::size_t e = 0; e < model_.beams.size(); ++e)
    for (MassPoint& p : I.mpts[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      Vector3d wd = Vector3d::Zero();
      for (int k = 0; k < 3; ++k) wd += N[k] * full.segment<3>(6 * model_.beams[e].nodes[k] + 3);
      p.A = p.R.transpose() * wd;
    }
}

void Solver::residual_and_tangent(const VectorXd& q, double t_next, double dt, VectorXd& r, Eigen::MatrixXd* K) {
  const Mode mode = opt_.analysis == Analysis::Dynamic ? Mode::Dynamic : Mode::Static;
  if (K) K->setZero(6 * impl_->nn, 6 * impl_->nn);
  DenseSink ds(K);
  impl_->assemble(*this, q, t_next, dt, mode, r, K ? &ds : nullptr, nullptr);
}

bool Solver::try_step(double t1, double dt, StepReport& rep, bool allow_penetration_cut) {
  Impl& I = *impl_;
  const Model& m = model_;
  const Mode mode = opt_.analysis == Analysis::Dynamic ? Mode::Dynamic : Mode::Static;
  VectorXd q = VectorXd::Zero(6 * I.nn);
  for (const ImposedDof& d : m.imposed) {
    const std::size_t a = static_cast<std::size_t>(d.node);
    q(6 * d.node + d.dof) = d.dof < 3 ? m.X[a](d.dof) + d.value * d.series(t1) - nodes_[a].x(d.dof) : 0.0;
  }
  VectorXd R, rf(I.neq), dq;
  rep.residual_norms.clear();
  double last = std::numeric_limits<double>::infinity();
  VectorXd q_acc = q;
  double G0 = 0.0, step = 1.0, best_rn = std::numeric_limits<double>::infinity(), best_step = 1.0;
  int nback = 0, newton = 0;  // newton: Newton directions (line-search trials not counted)
  bool forced = false;
  for (int it = 0;; ++it) {
    I.sink.begin();
    I.assemble(*this, q, t1, dt, mode, R, &I.sink, &I.cevals, &I.sevals, &I.sfevals);
    I.sink.finish();
    if (I.sink.mismatch) {  // pattern changed (should not happen): record it again
      I.sink.recording = true;
      I.sink.begin();
      I.assemble(*this, q, t1, dt, mode, R, &I.sink, &I.cevals, &I.sevals, &I.sfevals);
      I.sink.finish();
    }
    for (const SurfaceContactEval& se : I.sevals)
      if (!se.converged) return false;  // closest point not found: cut the step
    for (std::size_t i = 0; i < I.eq.size(); ++i)
      if (I.eq[i] >= 0) rf(I.eq[i]) = R(static_cast<Eigen::Index>(i));
    const double rn = rf.norm();
    rep.residual_norms.push_back(rn);
    rep.iterations = it;
    // Backtracking line search on G(s) = dq . R(q_acc + s dq) (README R-42): a full
    // Newton step that overshoots (|G(1)| > 0.8 |G(0)|, e.g. across a stick/slip kink of the
    // friction law) is halved, up to max_line_search times; if no trial qualifies, the
    // trial with the smallest residual is taken.
    if (newton > 0 && opt_.max_line_search > 0 && !forced) {
      const double G = dq.dot(rf);
      const bool bad = !std::isfinite(rn) || std::abs(G) > 0.8 * std::abs(G0);
      if (std::isfinite(rn) && rn < best_rn) {
        best_rn = rn;
        best_step = step;
      }
      if (bad && (nback < opt_.max_line_search || best_step != step)) {
        if (nback < opt_.max_line_search) {
          ++nback;
          step *= 0.5;
        } else {
          step = best_step;  // exhausted: go back to the best trial and accept it
          forced = true;
        }
        for (std::size_t i = 0; i < I.eq.size(); ++i)
          if (I.eq[i] >= 0) q(static_cast<Eigen::Index>(i)) = q_acc(static_cast<Eigen::Index>(i)) + step * dq(I.eq[i]);
        last = step * dq.lpNorm<Eigen::Infinity>();
        continue;
      }
    }
    forced = false;
    if (!std::isfinite(rn)) return false;
    if (rn <= opt_.force_tol || (newton > 0 && last <= opt_.disp_tol)) break;
    if (newton >= opt_.max_iterations) return false;
    ++newton;
    if (I.sink.new_pattern) {
      I.lu.analyzePattern(I.sink.A);  // once (again only if the pattern ever changes)
      I.sink.new_pattern = false;
      ++I.analyses;
    }
    I.lu.factorize(I.sink.A);
    if (I.lu.info() != Eigen::Success) return false;
    dq = I.lu.solve(-rf);
    G0 = dq.dot(rf);
    q_acc = q;
    step = 1.0;
    nback = 0;
    best_rn = std::numeric_limits<double>::infinity();
    best_step = 1.0;
    for (std::size_t i = 0; i < I.eq.size(); ++i)
      if (I.eq[i] >= 0) q(static_cast<Eigen::Index>(i)) += dq(I.eq[i]);
    last = dq.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(last)) return false;
  }

  // ---- impact control: reject a step that opens a contact too deep (R-54) ----
  if (allow_penetration_cut && opt_.max_new_penetration > 0.0)
    for (std::size_t c = 0; c < m.contacts.size(); ++c)
      if (!cstate_[c].active && I.cevals[c].active && -I.cevals[c].g_n > opt_.max_new_penetration) {
        rep.penetration_cuts = 1;
        return false;
      }
  if (allow_penetration_cut && opt_.max_new_penetration > 0.0)
    for (std::size_t c = 0; c < m.surface_contacts.size(); ++c)
      if (!surface_out_[c].active && I.sevals[c].active && -I.sevals[c].g_n > opt_.max_new_penetration) {
        rep.penetration_cuts = 1;
        return false;
      }

  // ---- commit (README R-41) ----
  const bool mid = mode == Mode::Dynamic && opt_.integrator == Integrator::EnergyConsistent;
  // external work: trapezoidal (Newmark, R-43) = exact work of the step-averaged loads
  const VectorXd f0 = I.external(*this, t_), f1 = I.external(*this, t1);
  for (int a = 0; a < I.nn; ++a) {
    const Vector3d du = q.segment<3>(6 * a), al = q.segment<3>(6 * a + 3);
    // rotations: the Newmark energy identity pairs spatial moments with the Rodrigues
    // increment a (b.R^T m = a.m for b = R_n^T a), R-43
    acc_.external_work += 0.5 * (f0.segment<3>(6 * a) + f1.segment<3>(6 * a)).dot(du) +
                          0.5 * (f0.segment<3>(6 * a + 3) + f1.segment<3>(6 * a + 3)).dot(al);
  }
  for (std::size_t k = 0; k < m.imposed.size(); ++k) {
    const ImposedDof& d = m.imposed[k];
    const double reac = R(6 * d.node + d.dof);
    acc_.imposed_work += 0.5 * (reactions_[k] + reac) * q(6 * d.node + d.dof);
    reactions_[k] = reac;
  }
  I.penalty_energy = 0.0;
  I.tangential_energy = 0.0;
  for (std::size_t c = 0; c < m.contacts.size(); ++c) {
    const ContactEval& ev = I.cevals[c];
    if (ev.active && !cstate_[c].active) rep.new_penetration = std::max(rep.new_penetration, -ev.g_n);
    acc_.friction_dissipation += ev.dissipation;
    {  // trapezoidal work of friction force and moment on the node; midpoint: the
       // end-point friction acts over the whole step
      const int nd = m.contacts[c].node;
      const ContactOutput& prev = contact_out_[c];
      const Vector3d fa = mid ? ev.friction : Vector3d(0.5 * (prev.friction + ev.friction));
      const Vector3d ma = mid ? ev.moment : Vector3d(0.5 * (prev.moment + ev.moment));
      acc_.friction_work -= fa.dot(q.segment<3>(6 * nd)) + ma.dot(q.segment<3>(6 * nd + 3));
    }
    const double pen = ev.active ? 0.5 * m.contacts[c].law.eps_n * ev.g_n * ev.g_n : 0.0;
    if (ev.active) {
      I.penalty_energy += pen;
      I.tangential_energy += ev.tangential_energy;
      cstate_[c] = ev.next;
    } else {
      cstate_[c] = ContactState{};  // reset on separation
    }
    ContactOutput& o = contact_out_[c];
    o.active = ev.active;
    o.slip = ev.slip;
    o.g_n = ev.g_n;
    o.penalty = pen;
    o.force = ev.force;
    o.friction = ev.friction;
    o.moment = ev.moment;
    o.point = ev.point;
  }
  for (std::size_t c = 0; c < m.surface_contacts.size(); ++c) {
    const SurfaceContactEval& ev = I.sevals[c];
    ContactOutput& o = surface_out_[c];
    if (ev.active && !o.active) rep.new_penetration = std::max(rep.new_penetration, -ev.g_n);
    if (m.surface_contacts[c].law.mu > 0.0) {  // friction: works and history as the plane pairs
      const ContactEval& fe = I.sfevals[c];
      const int nd = m.surface_contacts[c].node;
      acc_.friction_dissipation += fe.dissipation;
      acc_.friction_work -= (0.5 * (o.friction + fe.friction)).dot(q.segment<3>(6 * nd)) +
                            (0.5 * (o.moment + fe.moment)).dot(q.segment<3>(6 * nd + 3));
      sstate_[c] = fe.active ? fe.next : ContactState{};
      if (fe.active) I.tangential_energy += fe.tangential_energy;
      o.slip = fe.slip;
      o.friction = fe.friction;
      o.moment = fe.moment;
      o.force = fe.force;
      o.point = fe.point;
    } else {
      o.force = ev.force;
      o.point = ev.point;
    }
    const Vector3d damping = ev.damping_force * ev.normal;  // trapezoidal work of the damper
    acc_.damping_work -= (0.5 * (o.damping + damping)).dot(q.segment<3>(6 * m.surface_contacts[c].node));
    o.damping = damping;
    o.active = ev.active;
    o.g_n = ev.g_n;
    o.penalty = ev.active ? 0.5 * m.surface_contacts[c].law.eps_n * ev.g_n * ev.g_n : 0.0;
    I.penalty_energy += o.penalty;
  }
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    std::array<Vector3d, 3> x, a;
    for (int k = 0; k < 3; ++k) {
      const int nd = m.beams[e].nodes[k];
      x[k] = nodes_[nd].x + q.segment<3>(6 * nd);
      a[k] = q.segment<3>(6 * nd + 3);
    }
    for (BeamStiffPoint& p : I.spts[e]) {
      const BeamStrain st = beam_point_strain(p, x, a);
      p.R = st.R;
      p.K = st.K;
    }
    for (MassPoint& p : I.mpts[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      Vector3d ag = N[0] * a[0] + N[1] * a[1] + N[2] * a[2];
      if (mode == Mode::Dynamic) rotary_newmark_update(p.R, dt, ag, p.W, p.A);
      p.R = rodrigues_q(ag) * p.R;
    }
  }
  for (int a = 0; a < I.nn; ++a) {
    NodeState& n = nodes_[a];
    const Vector3d du = q.segment<3>(6 * a), al = q.segment<3>(6 * a + 3);
    if (mid) {  // midpoint: v_{n+1} = 2 du/dt - v_n, a = mean acceleration of the step
      n.a = 2.0 / (dt * dt) * (du - dt * n.v);
      n.v = 2.0 / dt * du - n.v;
      rotary_midpoint_update(n.R, dt, al, n.W, n.A);
    } else if (mode == Mode::Dynamic) {
      const Vector3d a1 = 4.0 / (dt * dt) * (du - dt * n.v) - n.a;
      n.v += 0.5 * dt * (n.a + a1);
      n.a = a1;
      rotary_newmark_update(n.R, dt, al, n.W, n.A);
    }
    n.x += du;
    n.R = rodrigues_q(al) * n.R;
  }
  t_ = t1;
  return true;
}

StepReport Solver::advance(double t_target) {
  StepReport rep;
  const double h0 = t_target - t_;
  if (!(h0 > 0.0)) return rep;
  double h = h0;
  int ok_in_row = 0;
  while (t_ < t_target - 1e-12 * h0) {
    const double rest = t_target - t_;
    double dt = std::min(h, rest);
    if (opt_.impact_step_fraction > 0.0) {  // equal sub-steps no longer than the limit
      const double lim = impact_step_limit(dt);
      if (lim < dt) {
        dt = rest / std::ceil(rest / lim - 1e-9);
        dt = std::min(dt, lim * (1.0 + 1e-9));
        ++rep.limited_steps;
      }
    }
    StepReport sub;
    if (try_step(t_ + dt, dt, sub, rep.cuts < opt_.max_cuts)) {
      ++rep.steps;
      rep.new_penetration = std::max(rep.new_penetration, sub.new_penetration);
      rep.iterations += sub.iterations;
      rep.residual_norms = sub.residual_norms;
      if (++ok_in_row >= 2 && h < h0) {
        h = std::min(2.0 * h, h0);
        ok_in_row = 0;
      }
    } else {
      rep.iterations += sub.iterations;  // failed attempts count too
      rep.residual_norms = sub.residual_norms;
      rep.penetration_cuts += sub.penetration_cuts;
      if (++rep.cuts > opt_.max_cuts) return rep;
      h *= 0.5;
      ok_in_row = 0;
    }
  }
  rep.converged = true;
  return rep;
}

Energies Solver::energies() const {
  const Impl& I = *impl_;
  Energies E = acc_;
  E.penalty = I.penalty_energy;
  E.tangential_elastic = I.tangential_energy;
  for (std::size_t e = 0; e < model_.beams.size(); ++e) {
    const BeamElement& be = model_.beams[e];
    const BeamSection& sec = model_.sections[static_cast<std::size_t>(be.section)];
    const Matrix3d Js = section_inertia(sec);
    std::array<Vector3d, 3> x, a;
    for (int k = 0; k < 3; ++k) {
      x[k] = nodes_[be.nodes[k]].x;
      a[k] = Vector3d::Zero();
    }
    E.strain += beam_element_internal(sec, I.spts[e], x, a, false).energy;
    for (const MassPoint& p : I.mpts[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      Vector3d v = Vector3d::Zero();
      for (int k = 0; k < 3; ++k) v += N[k] * nodes_[be.nodes[k]].v;
      E.kinetic_translation += 0.5 * p.weight * p.jac * sec.rhoA * v.squaredNorm();
      E.kinetic_rotation += 0.5 * p.weight * p.jac * p.W.dot(Js * p.W);
    }
  }
  for (const RigidBody& b : model_.bodies) {
    const NodeState& n = nodes_[b.node];
    E.kinetic_translation += 0.5 * b.mass * n.v.squaredNorm();
    E.kinetic_rotation += 0.5 * n.W.dot(b.inertia * n.W);
  }
  E.kinetic = E.kinetic_translation + E.kinetic_rotation;
  return E;
}

int Solver::pattern_analyses() const { return impl_->analyses; }

std::vector<BeamResultant> Solver::beam_resultants() const {
  std::vector<BeamResultant> out;
  for (std::size_t e = 0; e < model_.beams.size(); ++e) {
    const BeamElement& be = model_.beams[e];
    const BeamSection& s = model_.sections[static_cast<std::size_t>(be.section)];
    std::array<Vector3d, 3> x, a;
    for (int k = 0; k < 3; ++k) {
      x[k] = nodes_[be.nodes[k]].x;
      a[k] = Vector3d::Zero();
    }
    for (const BeamStiffPoint& p : impl_->spts[e]) {
      const BeamStrain st = beam_point_strain(p, x, a);
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      BeamResultant r;
      r.element = static_cast<int>(e);
      for (int k = 0; k < 3; ++k) {
        r.position += N[k] * x[k];
        r.reference_position += N[k] * model_.X[static_cast<std::size_t>(be.nodes[k])];
      }
      r.force = Vector3d(s.EA * st.Gamma(0), s.GA2 * st.Gamma(1), s.GA3 * st.Gamma(2));
      r.moment = Vector3d(s.GJ * st.K(0), s.EI2 * st.K(1), s.EI3 * st.K(2));
      out.push_back(r);
    }
  }
  return out;
}

History run(const Model& model, const SolverOptions& options, const RunOptions& ro) {
  Solver S(model, options);
  History h;
  std::vector<int> rec = ro.record_nodes;
  if (rec.empty())
    for (int a = 0; a < static_cast<int>(model.X.size()); ++a) rec.push_back(a);
  auto record = [&]() {
    h.time.push_back(S.time());
    std::vector<Vector3d> p, v, w, acc, wd;
    std::vector<Matrix3d> R;
    for (int a : rec) {
      const NodeState& n = S.nodes()[static_cast<std::size_t>(a)];
      p.push_back(n.x);
      v.push_back(n.v);
      w.push_back(n.R * n.W);
      acc.push_back(n.a);
      wd.push_back(n.R * n.A);
      R.push_back(n.R);
    }
    h.acceleration.push_back(acc);
    h.angular_acceleration.push_back(wd);
    h.position.push_back(p);
    h.velocity.push_back(v);
    h.angular_velocity.push_back(w);
    h.rotation.push_back(R);
    h.contact.push_back(S.contacts());
    h.surface_contact.push_back(S.surface_contacts());
    if (ro.record_energies) h.energy.push_back(S.energies());
    h.reactions.push_back(S.reactions());
  };
  record();
  const long nsteps = std::lround(ro.t_end / ro.dt);
  for (long k = 1; k <= nsteps; ++k) {
    const StepReport rep = S.advance(double(k) * ro.dt);
    h.newton_iterations += rep.iterations;
    h.cuts += rep.cuts;
    h.substeps += rep.steps;
    h.limited_steps += rep.limited_steps;
    h.penetration_cuts += rep.penetration_cuts;
    h.new_penetration = std::max(h.new_penetration, rep.new_penetration);
    if (!rep.converged) {
      h.completed = false;
      h.failed_at = S.time();
      record();
      return h;
    }
    ++h.steps;
    if (k % ro.record_every == 0 || k == nsteps) record();
  }
  return h;
}

}  // namespace rollspec::rolling
