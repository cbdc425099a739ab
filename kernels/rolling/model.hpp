// Plain-data description of a rolling-beam model: nodes with 6 DOFs (displacement and
// incremental Rodrigues rotation, D-12), quadratic geometrically exact beam elements,
// rigid bodies on nodes, rigid planes with rolling contact nodes, gravity, nodal loads
// and imposed displacements with time series. No I/O; the engine builds these structs.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "kernels/rolling/contact_element.hpp"
#include "kernels/rolling/height_field.hpp"
#include "kernels/rolling/surface_contact.hpp"
#include "kernels/rolling/time_series.hpp"

namespace rollspec::rolling {

// Cross-section stiffness and inertia per unit length, in the section frame (e1 = axis).
struct BeamSection {
  double EA = 0.0, GA2 = 0.0, GA3 = 0.0;         // axial, shear (with shear coefficient)
  double GJ = 0.0, EI2 = 0.0, EI3 = 0.0;         // torsion, bending
  double rhoA = 0.0;                             // mass per length
  double rhoJ1 = 0.0, rhoI2 = 0.0, rhoI3 = 0.0;  // rotary inertia per length (polar, bending)
  double outer_radius = 0.0;                     // contact sphere radius of the section's nodes
};

// Solid (inner_diameter = 0) or tube circular section; Cowper's shear coefficient
// k = 6(1+nu)(1+m^2)^2 / ((7+6nu)(1+m^2)^2 + (20+12nu) m^2), m = inner/outer (README R-11).
BeamSection circular_section(double E, double nu, double rho, double outer_diameter, double inner_diameter = 0.0);

struct BeamElement {
  std::array<int, 3> nodes{};  // end, middle, end (xi = -1, 0, +1)
  int section = 0;
};

struct RigidBody {
  int node = 0;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the node, body (material) frame
};

struct ContactPair {
  int node = 0;
  int plane = 0;
  ContactLaw law;
};

// Frictionless node-sphere contact with a rough surface (Model::surfaces), README R-61.
struct SurfaceContactPair {
  int node = 0;
  int surface = 0;
  SurfaceContactLaw law;
};

struct NodalLoad {
  int node = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // spatial, fixed direction
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // spatial, fixed axis (pseudo-moment Xi^T m)
  TimeSeries series;
};

// dof 0..2: displacement component u_dof(t) = value * series(t) from the initial position.
// dof 3..5: rotation component held fixed (incremental Rodrigues component = 0); value ignored.
struct ImposedDof {
  int node = 0;
  int dof = 0;
  double value = 0.0;
  TimeSeries series;
};

struct Model {
  std::vector<Eigen::Vector3d> X;       // initial node positions
  std::vector<Eigen::Matrix3d> frames;  // initial node rotations (columns e1, e2, e3)
  std::vector<Eigen::Vector3d> v0;      // initial velocities (empty: zero)
  std::vector<Eigen::Vector3d> w0;      // initial spatial angular velocities (empty: zero)
  std::vector<BeamSection> sections;
  std::vector<BeamElement> beams;
  std::vector<RigidBody> bodies;
  std::vector<Plane> planes;
  std::vector<ContactPair> contacts;
  std::vector<HeightField> surfaces;  // rough rigid surfaces (plane + height field)
  std::vector<SurfaceContactPair> surface_contacts;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  TimeSeries gravity_series;
  std::vector<NodalLoad> loads;
  std::vector<ImposedDof> imposed;

  int add_node(const Eigen::Vector3d& x, const Eigen::Matrix3d& frame = Eigen::Matrix3d::Identity());
};

// Straight beam from a to b with n_elements quadratic elements (2 n + 1 equally spaced
// nodes); e1 along the beam, e2 from e2_hint. Returns the node ids in order.
std::vector<int> add_straight_beam(Model& model, const Eigen::Vector3d& a, const Eigen::Vector3d& b, int n_elements,
                                   int section, const Eigen::Vector3d& e2_hint = Eigen::Vector3d::UnitY());

}  // namespace rollspec::rolling
