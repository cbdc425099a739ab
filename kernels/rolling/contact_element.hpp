// Rolling node-to-plane contact element (seed 000 Sec. 3; kernels/README.md D-13, D-14).
// The node is a rigid sphere of radius r; the plane is rigid. DOFs of the element are the
// node's incremental displacement and incremental Rodrigues parameters in the current
// step (updated Lagrangian, D-12). Penalty normal force, Coulomb stick/slip return
// mapping with a tangential penalty, friction moment (C - x_o) x f on the rotation DOFs
// through the pseudo-moment Xi^T m (seed 000 Eq. 5-6). Hand-derived consistent tangent:
// README Eq. R-20..R-27.
#pragma once

#include <Eigen/Dense>

namespace rollspec::rolling {

struct Plane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, toward the beam
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitY();
};
// Builds an orthonormal (t1, t2, n) frame from a point and a (not necessarily unit) normal.
Plane make_plane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal);

struct ContactLaw {
  double radius = 0.0;  // sphere radius r (section outer radius)
  double mu = 0.0;      // Coulomb coefficient
  double eps_n = 0.0;   // normal penalty (N/m)
  double eps_t = 0.0;   // tangential penalty (N/m)
  bool rolling = true;  // false: "no rolling" variant, r = 0 in the tangential gap and moment
};

// Committed (end of step) history of one contact.
struct ContactState {
  bool active = false;
  Eigen::Vector3d x_f = Eigen::Vector3d::Zero();     // fictitious initial contact point (D-13)
  Eigen::Vector3d g_st = Eigen::Vector3d::Zero();    // accumulated slip (seed 000 Eq. 13)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // contact normal x_f refers to (rough surfaces, R-63)
};

struct ContactEval {
  bool active = false;
  bool slip = false;
  double g_n = 0.0;                                    // normal gap (D-14), < 0 in contact
  double normal_force = 0.0;                           // magnitude of the normal force along n
  Eigen::Vector3d g_t = Eigen::Vector3d::Zero();       // elastic tangential gap (D-14)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     // total force on the node (normal + friction)
  Eigen::Vector3d friction = Eigen::Vector3d::Zero();  // friction part f
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();    // (C - x_o) x f, spatial
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     // C = x_o - r n
  ContactState next;                                   // state to commit if this iterate converges
  double dissipation = 0.0;                            // friction work of the step's slip increment
  double tangential_energy = 0.0;                      // |f_t|^2 / (2 eps_t) stored in the stick spring
  Eigen::Matrix<double, 6, 1> residual = Eigen::Matrix<double, 6, 1>::Zero();  // -[F; Xi^T M]
  Eigen::Matrix<double, 6, 6> tangent = Eigen::Matrix<double, 6, 6>::Zero();   // d residual / d[du; a]
};

// Normal force of a step: end-of-step penalty (R-22, Newmark) or the discrete gradient of the
// penalty potential V(g) = eps_n <-g>^2 / 2 between the step's end points, for which
// f_N . (x_{n+1} - x_n) = -(V(g_{n+1}) - V(g_n)) holds exactly.
enum class NormalForce { EndPoint, DiscreteGradient };

// x_start: node position at the start of the step; x: current iterate; alpha: incremental
// Rodrigues parameters of the node in this step. want_tangent = false: the tangent is left zero
// (residual-only assembly, R-44a), everything else the same bits.
ContactEval evaluate_contact(const Plane& plane, const ContactLaw& law, const ContactState& state,
                             const Eigen::Vector3d& x_start, const Eigen::Vector3d& x, const Eigen::Vector3d& alpha,
                             NormalForce normal_force = NormalForce::EndPoint, bool want_tangent = true);

// Discrete gradient of V(g) = eps_n <-g>^2 / 2 (README R-50): value D = (V(g1) - V(g0))/(g1 - g0)
// (V'(g_mid) when g1 = g0) and its derivative dD/dg1.
struct PenaltyGradient {
  double value = 0.0, derivative = 0.0;
};
PenaltyGradient penalty_discrete_gradient(double eps_n, double g0, double g1);

}  // namespace rollspec::rolling
