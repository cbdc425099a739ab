#include "kernels/rolling/solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "kernels/rolling/assembly.hpp"
#include "kernels/rolling/contact_set.hpp"
#include "kernels/rolling/newton.hpp"
#include "kernels/rolling/rotation.hpp"
#include "kernels/rolling/time_rule.hpp"

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {

// Global DOF -> free equation (-1: imposed DOF), numbered in DOF order.
std::vector<int> equation_numbers(const Model& m, int& neq) {
  const int nn = static_cast<int>(m.X.size());
  std::vector<int> eq(6 * m.X.size(), 0);
  for (const ImposedDof& d : m.imposed) {
    if (d.node < 0 || d.node >= nn || d.dof < 0 || d.dof > 5) throw std::invalid_argument("Solver: bad imposed DOF");
    eq[static_cast<std::size_t>(6 * d.node + d.dof)] = -1;
  }
  neq = 0;
  for (int& e : eq)
    if (e == 0) e = neq++;
  return eq;
}

}  // namespace

struct Solver::Impl {
  Impl(const Model& m, const std::vector<NodeState>& nodes, const SolverOptions& o)
      : eq(equation_numbers(m, neq)),
        points(make_beam_points(m)),
        contacts(m, nodes),
        rule(TimeRule::from(o)),
        newton(eq, neq) {}
  int neq = 0;          // declared first: the initialiser of eq counts the free equations into it
  std::vector<int> eq;  // global DOF -> equation (-1: imposed)
  BeamPoints points;
  ContactSet contacts;
  TimeRule rule;  // chosen once (Sec. 5, 6a)
  NewtonDriver newton;
};

Solver::Solver(Model model, SolverOptions options, double t0) : model_(std::move(model)), opt_(options), t_(t0) {
  const Model& m = model_;
  if (m.frames.size() != m.X.size()) throw std::invalid_argument("Solver: frames.size() != X.size()");
  nodes_ = initial_nodes(m);
  impl_ = std::make_unique<Impl>(m, nodes_, opt_);
  const Impl& I = *impl_;
  if (opt_.integrator == Integrator::EnergyConsistent && !m.beams.empty())
    throw std::invalid_argument("Solver: the energy-consistent integrator supports rigid bodies only (no beams)");
  // lumped node masses: rigid bodies plus row sums of the consistent beam mass
  node_mass_.assign(m.X.size(), 0.0);
  for (const RigidBody& b : m.bodies) node_mass_[static_cast<std::size_t>(b.node)] += b.mass;
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const BeamSection& sec = m.sections[static_cast<std::size_t>(m.beams[e].section)];
    for (const MassPoint& p : I.points.mass[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      for (int k = 0; k < 3; ++k)
        node_mass_[static_cast<std::size_t>(m.beams[e].nodes[k])] += N[k] * p.weight * p.jac * sec.rhoA;
    }
  }
  reactions_.assign(m.imposed.size(), 0.0);
  if (opt_.analysis == Analysis::Dynamic && opt_.consistent_initial_acceleration) initial_acceleration();
  acc_.initial_balance = energies().balance();
}

Solver::~Solver() = default;

const std::vector<ContactOutput>& Solver::contacts() const { return impl_->contacts.plane_outputs(); }
const std::vector<ContactState>& Solver::contact_states() const { return impl_->contacts.plane_states(); }
const std::vector<ContactOutput>& Solver::surface_contacts() const { return impl_->contacts.surface_outputs(); }

double Solver::impact_step_limit(double dt) const {
  if (!(opt_.impact_step_fraction > 0.0)) return dt;
  return impl_->contacts.step_limit(nodes_, node_mass_, dt, opt_.impact_step_fraction);
}

// M a0 = -R(t0) with the current (zero-increment) state; imposed DOFs get zero
// acceleration, open contacts and unknown slip directions contribute no friction.
void Solver::initial_acceleration() {
  Impl& I = *impl_;
  if (I.neq == 0) return;  // fully imposed motion
  const int nn = static_cast<int>(model_.X.size());
  VectorXd R;
  SparseSink ms;
  ms.eq = &I.eq;
  ms.neq = I.neq;
  ms.begin();
  assemble(AssemblyState{model_, nodes_, I.points, t_}, TimeRule(TimeRule::Kind::QuasiStatic), I.contacts,
           VectorXd::Zero(6 * nn), t_, 1.0, true, R, &ms);
  ms.finish();
  VectorXd rf(I.neq);
  for (std::size_t i = 0; i < I.eq.size(); ++i)
    if (I.eq[i] >= 0) rf(I.eq[i]) = -R(static_cast<Eigen::Index>(i));
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(ms.A);
  if (lu.info() != Eigen::Success) return;  // massless DOFs: leave a0 = 0
  const VectorXd a0 = lu.solve(rf);
  VectorXd full = VectorXd::Zero(6 * nn);
  for (std::size_t i = 0; i < I.eq.size(); ++i)
    if (I.eq[i] >= 0) full(static_cast<Eigen::Index>(i)) = a0(I.eq[i]);
  for (int a = 0; a < nn; ++a) {
    nodes_[a].a = full.segment<3>(6 * a);
    nodes_[a].A = nodes_[a].R.transpose() * full.segment<3>(6 * a + 3);
  }
  for (std::size_t e = 0; e < model_.beams.size(); ++e)
    for (MassPoint& p : I.points.mass[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      Vector3d wd = Vector3d::Zero();
      for (int k = 0; k < 3; ++k) wd += N[k] * full.segment<3>(6 * model_.beams[e].nodes[k] + 3);
      p.A = p.R.transpose() * wd;
    }
}

void Solver::residual_and_tangent(const VectorXd& q, double t_next, double dt, VectorXd& r, Eigen::MatrixXd* K) {
  const int nn = static_cast<int>(model_.X.size());
  if (K) K->setZero(6 * nn, 6 * nn);
  DenseSink ds(K);
  assemble(AssemblyState{model_, nodes_, impl_->points, t_}, impl_->rule, impl_->contacts, q, t_next, dt, false, r,
           K ? &ds : nullptr);
}

// One step to t1: Newton on the increments (newton.cpp), the impact check, then the commit.
bool Solver::try_step(double t1, double dt, StepReport& rep, bool allow_penetration_cut) {
  Impl& I = *impl_;
  const Model& m = model_;
  VectorXd q = VectorXd::Zero(6 * static_cast<Eigen::Index>(m.X.size()));
  for (const ImposedDof& d : m.imposed) {
    const std::size_t a = static_cast<std::size_t>(d.node);
    q(6 * d.node + d.dof) = d.dof < 3 ? m.X[a](d.dof) + d.value * d.series(t1) - nodes_[a].x(d.dof) : 0.0;
  }
  const AssemblyState s{m, nodes_, I.points, t_};
  auto assemble_at = [&](const VectorXd& qi, VectorXd& Ri, Sink* K) {
    assemble(s, I.rule, I.contacts, qi, t1, dt, false, Ri, K);
    return I.contacts.closest_points_found();  // otherwise cut the step
  };
  VectorXd R;
  const NewtonDriver::Rewind rewind = [&]() { I.contacts.rewind(); };
  if (!I.newton.solve(opt_, assemble_at, q, R, rep, opt_.residual_only_checks ? rewind : nullptr)) return false;
  // impact control: reject a step that closes a contact too deep
  if (allow_penetration_cut && opt_.max_new_penetration > 0.0 &&
      I.contacts.closes_deeper_than(opt_.max_new_penetration)) {
    rep.penetration_cuts = 1;
    return false;
  }
  commit_step(q, R, t1, dt, rep);
  return true;
}

// State updates after convergence (README R-41): works, reactions, contact histories, beam
// Gauss points, node positions, rotations and rates (per the time rule).
void Solver::commit_step(const VectorXd& q, const VectorXd& R, double t1, double dt, StepReport& rep) {
  Impl& I = *impl_;
  const Model& m = model_;
  const int nn = static_cast<int>(m.X.size());
  const AssemblyState s{m, nodes_, I.points, t_};
  // external work: trapezoidal (Newmark, R-43) = exact work of the step-averaged loads
  const VectorXd f0 = external_loads(s, t_), f1 = external_loads(s, t1);
  for (int a = 0; a < nn; ++a) {
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
  I.contacts.commit(q, I.rule, acc_, rep.new_penetration);
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    std::array<Vector3d, 3> x, a;
    for (int k = 0; k < 3; ++k) {
      const int nd = m.beams[e].nodes[k];
      x[k] = nodes_[nd].x + q.segment<3>(6 * nd);
      a[k] = q.segment<3>(6 * nd + 3);
    }
    for (BeamStiffPoint& p : I.points.stiffness[e]) {
      const BeamStrain st = beam_point_strain(p, x, a);
      p.R = st.R;
      p.K = st.K;
    }
    for (MassPoint& p : I.points.mass[e]) {
      double N[3], dN[3];
      quadratic_shape(p.xi, N, dN);
      Vector3d ag = N[0] * a[0] + N[1] * a[1] + N[2] * a[2];
      I.rule.update_point_rates(p.R, dt, ag, p.W, p.A);
      p.R = rodrigues_q(ag) * p.R;
    }
  }
  for (int a = 0; a < nn; ++a) {
    NodeState& n = nodes_[a];
    const Vector3d du = q.segment<3>(6 * a), al = q.segment<3>(6 * a + 3);
    I.rule.update_rates(n, du, al, dt);
    n.x += du;
    n.R = rodrigues_q(al) * n.R;
  }
  t_ = t1;
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
  E.penalty = I.contacts.penalty_energy();
  E.tangential_elastic = I.contacts.tangential_energy();
  for (std::size_t e = 0; e < model_.beams.size(); ++e) {
    const BeamElement& be = model_.beams[e];
    const BeamSection& sec = model_.sections[static_cast<std::size_t>(be.section)];
    const Matrix3d Js = section_inertia(sec);
    std::array<Vector3d, 3> x, a;
    for (int k = 0; k < 3; ++k) {
      x[k] = nodes_[be.nodes[k]].x;
      a[k] = Vector3d::Zero();
    }
    E.strain += beam_element_internal(sec, I.points.stiffness[e], x, a, false).energy;
    for (const MassPoint& p : I.points.mass[e]) {
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

int Solver::pattern_analyses() const { return impl_->newton.pattern_analyses(); }
long Solver::residual_only_repeats() const { return impl_->newton.lazy_misses(); }

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
    for (const BeamStiffPoint& p : impl_->points.stiffness[e]) {
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
    for (auto* x : {&p, &v, &w, &acc, &wd}) x->reserve(rec.size());  // one allocation each
    R.reserve(rec.size());
    for (int a : rec) {
      const NodeState& n = S.nodes()[static_cast<std::size_t>(a)];
      p.push_back(n.x);
      v.push_back(n.v);
      w.push_back(n.R * n.W);
      acc.push_back(n.a);
      wd.push_back(n.R * n.A);
      R.push_back(n.R);
    }
    h.acceleration.push_back(std::move(acc));
    h.angular_acceleration.push_back(std::move(wd));
    h.position.push_back(std::move(p));
    h.velocity.push_back(std::move(v));
    h.angular_velocity.push_back(std::move(w));
    h.rotation.push_back(std::move(R));
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
