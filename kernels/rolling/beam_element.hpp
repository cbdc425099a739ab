// Geometrically exact 3D beam (Simo-Reissner; Pimenta's updated Lagrangian with incremental
// Rodrigues parameters, D-12), quadratic 3-node element. README Eq. R-10..R-16.
//   x(xi) = sum N_a x_a,  a(xi) = sum N_a a_a,  R(xi) = Q(a(xi)) R_n(xi)
//   Gamma = R^T x' - E1,  K = K_n + R_n^T Q^T Xi(a) a'        (material strains)
//   strain energy density  (1/2) Gamma.C_N Gamma + (1/2) K.C_M K
// Stiffness with 2-point Gauss (reduced) integration against shear/membrane locking;
// R_n, K_n are kept at the Gauss points and updated at the end of each step.
// Internal force and tangent are the exact gradient and Hessian of the energy: strains are
// bilinear in (x', a') and functions of a; their derivatives are written out analytically
// (README R-14a), the second-order jets in a and a Jet2<9> of the whole point energy
// are kept as the reference and the oracle.
#pragma once

#include <Eigen/Dense>
#include <array>

#include "kernels/rolling/model.hpp"

namespace rollspec::rolling {

void quadratic_shape(double xi, double N[3], double dN[3]);

struct BeamStiffPoint {
  double xi = 0.0, weight = 0.0, jac = 0.0;         // jac = ds/dxi of the reference line
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // committed rotation (step start)
  Eigen::Vector3d K = Eigen::Vector3d::Zero();      // committed material curvature
};

struct BeamStrain {
  Eigen::Vector3d Gamma = Eigen::Vector3d::Zero();  // material shear/axial strain
  Eigen::Vector3d K = Eigen::Vector3d::Zero();      // material curvature
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // current rotation at the point
};

// Strains at a stiffness point for current nodal positions x and incremental rotations a.
BeamStrain beam_point_strain(const BeamStiffPoint& p, const std::array<Eigen::Vector3d, 3>& x,
                             const std::array<Eigen::Vector3d, 3>& alpha);

// Strain energy per unit length at a stiffness point as a function of the point variables
// z = (x', a, a'), with gradient and Hessian (want_hess = false: the Hessian is left zero, the
// value and gradient are the same bits).
struct PointEnergy {
  double value = 0.0;
  Eigen::Matrix<double, 9, 1> grad = Eigen::Matrix<double, 9, 1>::Zero();
  Eigen::Matrix<double, 9, 9> hess = Eigen::Matrix<double, 9, 9>::Zero();
};
PointEnergy beam_point_energy(const BeamSection& s, const BeamStiffPoint& p, const Eigen::Matrix<double, 9, 1>& z,
                              bool want_hess = true);
// The same with second-order jets Jet2<3> of the six strain directions (README R-14), the
// reference the analytic path (R-14a) is tested against.
PointEnergy beam_point_energy_jet(const BeamSection& s, const BeamStiffPoint& p, const Eigen::Matrix<double, 9, 1>& z);
// Slow reference oracle of the same (one Jet2<9> evaluation), for tests.
PointEnergy beam_point_energy_reference(const BeamSection& s, const BeamStiffPoint& p,
                                        const Eigen::Matrix<double, 9, 1>& z);

struct BeamElementEval {
  Eigen::Matrix<double, 18, 1> force = Eigen::Matrix<double, 18, 1>::Zero();  // internal force
  Eigen::Matrix<double, 18, 18> tangent = Eigen::Matrix<double, 18, 18>::Zero();
  double energy = 0.0;
};

// Node order of the 18 DOFs: [u_0, a_0, u_1, a_1, u_2, a_2].
BeamElementEval beam_element_internal(const BeamSection& s, const std::array<BeamStiffPoint, 2>& gp,
                                      const std::array<Eigen::Vector3d, 3>& x,
                                      const std::array<Eigen::Vector3d, 3>& alpha, bool want_tangent);
// Plain reference of the same: B^T grad and B^T hess B with the Jet2<3> point path.
BeamElementEval beam_element_internal_reference(const BeamSection& s, const std::array<BeamStiffPoint, 2>& gp,
                                                const std::array<Eigen::Vector3d, 3>& x,
                                                const std::array<Eigen::Vector3d, 3>& alpha, bool want_tangent);

}  // namespace rollspec::rolling
