// Frictionless contact of a node sphere with a rigid rough surface (plane + height field,
// README Sec. 10, R-61). The contact point is the closest point S(s*) of the interpolated
// surface to the sphere centre x (Newton on the stationarity of |x - S(s)|^2 / 2), the normal
// nu = (x - S)/|x - S|, the gap g = +-|x - S| - r (negative when x lies below the surface or
// within r of it). Penalty force eps_n <-g> nu and the exact tangent
// eps_n (nu nu^T + g d2g/dx2), d2g/dx2 = (I - S_s H^-1 S_s^T)/d.
#pragma once

#include <Eigen/Dense>

#include "kernels/rolling/height_field.hpp"

namespace rollspec::rolling {

struct SurfaceContactLaw {
  double radius = 0.0;
  double eps_n = 0.0;
  // Coulomb friction on the surface: mu > 0 runs the rolling contact element (D-13, D-14)
  // on the tangent plane at the closest point; mu = 0 keeps the frictionless law above.
  double mu = 0.0;
  double eps_t = 0.0;
  bool rolling = true;
  // Normal contact damper c_n (N s/m) on the gap rate nu . v while closed, Newmark only;
  // the total normal force never pulls.
  double damping = 0.0;
};

struct SurfaceContactEval {
  bool active = false;
  bool converged = true;  // closest-point Newton converged
  double g_n = 0.0;
  Eigen::Vector2d s = Eigen::Vector2d::Zero();        // tangent coordinates of the contact point
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();   // nu, surface toward the centre
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // S(s*)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    // on the node
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();  // d(-force)/dx
  double damping_force = 0.0;                         // c_n damper along nu (set by the solver, R-64)
  HeightSample sample;                                // the height field at s (for the next search from s)
};

// Closest point and gap for the centre x (Newton from the projection of x on the base plane, or
// from `start`, the last closest point of the same node, when it lies within 4 cells of it: the
// node moves far less than a cell between Newton iterates and steps, so the search converges in
// one or two iterations instead of three or four; the same point to the Newton tolerance).
// at_start: the height field's sample at *start when the caller has it (the last evaluation's
// `sample`), used when the search does start at *start: the same bits without sampling again.
// want_tangent = false: the tangent is left zero (residual-only assembly, R-44a).
SurfaceContactEval evaluate_surface_contact(const HeightField& f, const SurfaceContactLaw& law,
                                            const Eigen::Vector3d& x, const Eigen::Vector2d* start = nullptr,
                                            const HeightSample* at_start = nullptr, bool want_tangent = true);

}  // namespace rollspec::rolling
