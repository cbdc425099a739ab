#include "kernels/rolling/contact_set.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/rolling/assembly.hpp"

namespace rollspec::rolling {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

namespace {

// Gap of a node sphere at centre x with its normal, without history.
struct Gap {
  double g = 0.0;
  Vector3d normal = Vector3d::Zero();
  bool closed = false;  // the pair's own closing test at this gap
};

// Works and energies a pair's commit adds to.
struct Totals {
  Energies& acc;
  double& tangential;
};

}  // namespace

// One pair, either kind: evaluation at the iterate, gap at a position, commit of its history.
class ContactSet::Pair {
 public:
  Pair(int node_, double eps_n_, ContactOutput& out_) : node(node_), eps_n(eps_n_), out(out_) {}
  virtual ~Pair() = default;
  virtual Gap gap(const Vector3d& x) const = 0;
  virtual void assemble(const NodeState& n, const Vector3d& du, const Vector3d& alpha, double dt, const TimeRule& rule,
                        bool mass_matrix, VectorXd& R, Sink* K) = 0;
  virtual bool found() const { return true; }
  // Back to the state before the last assemble, so that assembling the same iterate again gives
  // the same bits (the closest-point search of a surface pair starts from its last point).
  virtual void rewind() {}
  // Everything of the commit but active, g_n and penalty, which the set writes for both kinds.
  virtual void commit(const Vector3d& du, const Vector3d& alpha, const TimeRule& rule, Totals& totals) = 0;

  // Closed at the end of the last evaluation, open at the step start (out holds the last commit).
  bool closes() const { return active && !out.active; }

  const int node;
  const double eps_n;
  ContactOutput& out;
  bool active = false;  // of the last evaluation
  double g_n = 0.0;
};

namespace {

// Rolling contact element on a plane (D-13, D-14; normal force per rule ).
class PlanePair final : public ContactSet::Pair {
 public:
  PlanePair(const Plane& plane, const ContactPair& cp, ContactOutput& out_, ContactState& state)
      : Pair(cp.node, cp.law.eps_n, out_), plane_(plane), law_(cp.law), state_(state) {}

  Gap gap(const Vector3d& x) const override {
    const double g = (x - plane_.point).dot(plane_.normal) - law_.radius;
    return {g, plane_.normal, g < 0.0};
  }

  void assemble(const NodeState& n, const Vector3d& du, const Vector3d& alpha, double, const TimeRule& rule,
                bool mass_matrix, VectorXd& R, Sink* K) override {
    ev_ = evaluate_contact(plane_, law_, state_, n.x, n.x + du, alpha, rule.normal_force());
    R.segment<6>(6 * node) += ev_.residual;
    add_block<6>(K, dofs6(node), mass_matrix ? Matrix6d::Zero() : ev_.tangent);
    active = ev_.active;
    g_n = ev_.g_n;
  }

  void commit(const Vector3d& du, const Vector3d& alpha, const TimeRule& rule, Totals& t) override {
    t.acc.friction_dissipation += ev_.dissipation;
    // work of friction force and moment on the node: trapezoidal, or the end-point
    // friction over the whole step
    const Vector3d fa = rule.friction_for_work(out.friction, ev_.friction);
    const Vector3d ma = rule.friction_for_work(out.moment, ev_.moment);
    t.acc.friction_work -= fa.dot(du) + ma.dot(alpha);
    if (ev_.active) {
      t.tangential += ev_.tangential_energy;
      state_ = ev_.next;
    } else {
      state_ = ContactState{};  // reset on separation
    }
    out.slip = ev_.slip;
    out.force = ev_.force;
    out.friction = ev_.friction;
    out.moment = ev_.moment;
    out.point = ev_.point;
  }

 private:
  const Plane& plane_;
  const ContactLaw& law_;
  ContactState& state_;
  ContactEval ev_;
};

// Rolling frictional contact with a rough surface (README R-63): the plane element (D-13, D-14)
// on the tangent plane at the closest point S(s*) with normal nu, so gap, normal force and the
// stick/slip return mapping are those of R-61 and seed 000 Eq. 8-16. The history is carried
// over to the turned plane: x_f += r (nu_old - nu) and g_st projected, so that pure rolling over
// a curved surface (centre step r alpha, contact point step r (alpha - dtheta)) leaves g_t = 0.
// The normal block of the tangent takes the exact curvature term of R-61; the friction blocks
// neglect the turning of the plane with x, which costs Newton iterations, not accuracy.
ContactEval rough_friction_contact(const SurfaceContactLaw& law, const SurfaceContactEval& sv,
                                   const ContactState& state, const Vector3d& x_start, const Vector3d& x,
                                   const Vector3d& alpha, bool want_tangent) {
  const Plane tangent_plane = make_plane(sv.point, sv.normal);
  const ContactLaw cl{law.radius, law.mu, law.eps_n, law.eps_t, law.rolling};
  ContactState carried = state;
  if (state.active) {
    carried.x_f += law.radius * (state.normal - sv.normal);
    carried.g_st -= carried.g_st.dot(sv.normal) * sv.normal;
  }
  ContactEval fe = evaluate_contact(tangent_plane, cl, carried, x_start, x, alpha, NormalForce::EndPoint, want_tangent);
  fe.next.normal = sv.normal;
  if (fe.active && want_tangent)
    fe.tangent.block<3, 3>(0, 0) += sv.tangent - law.eps_n * sv.normal * sv.normal.transpose();
  return fe;
}

// Closest-point penalty contact with a rough surface, end-point force in every rule; with
// friction the rolling element on the tangent plane; normal damper under Newmark.
class SurfacePair final : public ContactSet::Pair {
 public:
  SurfacePair(const HeightField& field, const SurfaceContactPair& sp, ContactOutput& out_, ContactState& state)
      : Pair(sp.node, sp.law.eps_n, out_), field_(field), law_(sp.law), state_(state) {}

  Gap gap(const Vector3d& x) const override {
    const SurfaceContactEval ev = evaluate_surface_contact(field_, law_, x);
    return {ev.g_n, ev.normal, ev.active};
  }

  void assemble(const NodeState& n, const Vector3d& du, const Vector3d& alpha, double dt, const TimeRule& rule,
                bool mass_matrix, VectorXd& R, Sink* K) override {
    had_start_ = has_start_;
    start_before_ = start_;
    start_sample_before_ = start_sample_;
    // K == nullptr: a residual-only pass (R-44a) needs no tangents
    const bool want_tangent = K != nullptr && !mass_matrix;
    ev_ = evaluate_surface_contact(field_, law_, n.x + du, has_start_ ? &start_ : nullptr,
                                   has_start_ ? &start_sample_ : nullptr, want_tangent);
    has_start_ = ev_.converged;  // the next evaluation starts from this closest point
    start_ = ev_.s;
    start_sample_ = ev_.sample;  // ... and its height sample
    active = ev_.active;
    g_n = ev_.g_n;
    if (law_.damping > 0.0 && !mass_matrix && rule.contact_dampers()) {
      // normal damper on the Newmark end velocity v1 = 2 du/dt - v_n
      Matrix3d Kd = Matrix3d::Zero();
      if (ev_.active) {
        const double gdot = ev_.normal.dot(2.0 / dt * du - n.v);
        const double fn = law_.eps_n * (-ev_.g_n);
        ev_.damping_force = -law_.damping * gdot;
        if (fn + ev_.damping_force < 0.0) {  // the contact never pulls: the normal force is zero
          ev_.damping_force = -fn;
          Kd = -law_.eps_n * ev_.normal * ev_.normal.transpose();
        } else {
          Kd = law_.damping * 2.0 / dt * ev_.normal * ev_.normal.transpose();
        }
        R.segment<3>(6 * node) -= ev_.damping_force * ev_.normal;
      }
      add_block<3>(K, dofs3(6 * node), Kd);
    }
    if (!(law_.mu > 0.0)) {
      R.segment<3>(6 * node) -= ev_.force;
      add_block<3>(K, dofs3(6 * node), mass_matrix ? Matrix3d::Zero() : ev_.tangent);
      return;
    }
    fe_ = rough_friction_contact(law_, ev_, state_, n.x, n.x + du, alpha, want_tangent);
    R.segment<6>(6 * node) += fe_.residual;
    add_block<6>(K, dofs6(node), mass_matrix ? Matrix6d::Zero() : fe_.tangent);
  }

  bool found() const override { return ev_.converged; }

  void rewind() override {
    has_start_ = had_start_;
    start_ = start_before_;
    start_sample_ = start_sample_before_;
  }

  void commit(const Vector3d& du, const Vector3d& alpha, const TimeRule&, Totals& t) override {
    if (law_.mu > 0.0) {  // friction: works and history as the plane pairs, trapezoidal
      t.acc.friction_dissipation += fe_.dissipation;
      t.acc.friction_work -=
          (0.5 * (out.friction + fe_.friction)).dot(du) + (0.5 * (out.moment + fe_.moment)).dot(alpha);
      state_ = fe_.active ? fe_.next : ContactState{};
      if (fe_.active) t.tangential += fe_.tangential_energy;
      out.slip = fe_.slip;
      out.friction = fe_.friction;
      out.moment = fe_.moment;
      out.force = fe_.force;
      out.point = fe_.point;
    } else {
      out.force = ev_.force;
      out.point = ev_.point;
    }
    const Vector3d damping = ev_.damping_force * ev_.normal;  // trapezoidal work of the damper
    t.acc.damping_work -= (0.5 * (out.damping + damping)).dot(du);
    out.damping = damping;
  }

 private:
  const HeightField& field_;
  const SurfaceContactLaw& law_;
  ContactState& state_;
  SurfaceContactEval ev_;
  ContactEval fe_;  // friction part (mu > 0)
  bool has_start_ = false;
  Eigen::Vector2d start_ = Eigen::Vector2d::Zero();  // last closest point found
  bool had_start_ = false;                           // has_start_ and start_ before the last assemble
  Eigen::Vector2d start_before_ = Eigen::Vector2d::Zero();
  HeightSample start_sample_, start_sample_before_;  // the field at start_ (and before the last assemble)
};

}  // namespace

ContactSet::ContactSet(const Model& m, const std::vector<NodeState>& nodes)
    : plane_out_(m.contacts.size()),
      surface_out_(m.surface_contacts.size()),
      plane_state_(m.contacts.size()),
      surface_state_(m.surface_contacts.size()) {
  for (std::size_t c = 0; c < m.contacts.size(); ++c)
    pairs_.push_back(std::make_unique<PlanePair>(m.planes[static_cast<std::size_t>(m.contacts[c].plane)], m.contacts[c],
                                                 plane_out_[c], plane_state_[c]));
  for (std::size_t c = 0; c < m.surface_contacts.size(); ++c)
    pairs_.push_back(std::make_unique<SurfacePair>(m.surfaces[static_cast<std::size_t>(m.surface_contacts[c].surface)],
                                                   m.surface_contacts[c], surface_out_[c], surface_state_[c]));
  for (const auto& p : pairs_) {  // initial penalty energy of pairs closed at t0
    const Gap gp = p->gap(nodes[static_cast<std::size_t>(p->node)].x);
    p->out.g_n = gp.g;
    if (gp.closed) {
      p->out.penalty = 0.5 * p->eps_n * gp.g * gp.g;
      penalty_ += p->out.penalty;
    }
  }
}

ContactSet::~ContactSet() = default;

void ContactSet::assemble(const std::vector<NodeState>& nodes, const VectorXd& q, double dt, const TimeRule& rule,
                          bool mass_matrix, VectorXd& R, Sink* K) {
  for (const auto& p : pairs_)
    p->assemble(nodes[static_cast<std::size_t>(p->node)], q.segment<3>(6 * p->node), q.segment<3>(6 * p->node + 3), dt,
                rule, mass_matrix, R, K);
}

void ContactSet::rewind() {
  for (const auto& p : pairs_) p->rewind();
}

bool ContactSet::closest_points_found() const {
  return std::all_of(pairs_.begin(), pairs_.end(), [](const auto& p) { return p->found(); });
}

bool ContactSet::closes_deeper_than(double depth) const {
  return std::any_of(pairs_.begin(), pairs_.end(), [&](const auto& p) { return p->closes() && -p->g_n > depth; });
}

double ContactSet::step_limit(const std::vector<NodeState>& nodes, const std::vector<double>& node_mass, double dt,
                              double fraction) const {
  double lim = dt;
  const double two_pi = 6.283185307179586;
  for (const auto& p : pairs_) {
    const std::size_t nd = static_cast<std::size_t>(p->node);
    if (!(node_mass[nd] > 0.0) || !(p->eps_n > 0.0)) continue;
    const Gap gp = p->gap(nodes[nd].x);
    // closed, or predicted to close within dt at the current normal velocity
    if (p->out.active || gp.g <= 0.0 || gp.g + dt * nodes[nd].v.dot(gp.normal) <= 0.0)
      lim = std::min(lim, fraction * two_pi * std::sqrt(node_mass[nd] / p->eps_n));
  }
  return lim;
}

void ContactSet::commit(const VectorXd& q, const TimeRule& rule, Energies& acc, double& new_penetration) {
  penalty_ = 0.0;
  tangential_ = 0.0;
  Totals totals{acc, tangential_};
  for (const auto& p : pairs_) {
    if (p->closes()) new_penetration = std::max(new_penetration, -p->g_n);
    p->commit(q.segment<3>(6 * p->node), q.segment<3>(6 * p->node + 3), rule, totals);
    p->out.active = p->active;
    p->out.g_n = p->g_n;
    p->out.penalty = p->active ? 0.5 * p->eps_n * p->g_n * p->g_n : 0.0;
    penalty_ += p->out.penalty;
  }
}

}  // namespace rollspec::rolling
