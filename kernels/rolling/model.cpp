#include "kernels/rolling/model.hpp"

#include <cmath>
#include <stdexcept>

namespace rollspec::rolling {

BeamSection circular_section(double E, double nu, double rho, double outer_diameter, double inner_diameter) {
  if (!(outer_diameter > inner_diameter) || inner_diameter < 0.0)
    throw std::invalid_argument("circular_section: need outer_diameter > inner_diameter >= 0");
  const double pi = 3.14159265358979323846;
  const double ro = 0.5 * outer_diameter, ri = 0.5 * inner_diameter;
  const double A = pi * (ro * ro - ri * ri);
  const double I = pi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0;
  const double G = E / (2.0 * (1.0 + nu));
  const double m = ri / ro, m2 = (1.0 + m * m) * (1.0 + m * m);
  const double k = 6.0 * (1.0 + nu) * m2 / ((7.0 + 6.0 * nu) * m2 + (20.0 + 12.0 * nu) * m * m);
  BeamSection s;
  s.EA = E * A;
  s.GA2 = s.GA3 = k * G * A;
  s.GJ = G * 2.0 * I;  // circular: torsion constant = polar moment
  s.EI2 = s.EI3 = E * I;
  s.rhoA = rho * A;
  s.rhoJ1 = rho * 2.0 * I;
  s.rhoI2 = s.rhoI3 = rho * I;
  s.outer_radius = ro;
  return s;
}

int Model::add_node(const Eigen::Vector3d& x, const Eigen::Matrix3d& frame) {
  X.push_back(x);
  frames.push_back(frame);
  return static_cast<int>(X.size()) - 1;
}

std::vector<int> add_straight_beam(Model& model, const Eigen::Vector3d& a, const Eigen::Vector3d& b, int n_elements,
                                   int section, const Eigen::Vector3d& e2_hint) {
  if (n_elements < 1) throw std::invalid_argument("add_straight_beam: n_elements < 1");
  const Eigen::Vector3d e1 = (b - a).normalized();
  Eigen::Vector3d e2 = e2_hint - e2_hint.dot(e1) * e1;
  if (e2.norm() < 1e-8) throw std::invalid_argument("add_straight_beam: e2_hint parallel to beam");
  e2.normalize();
  Eigen::Matrix3d R;
  R.col(0) = e1;
  R.col(1) = e2;
  R.col(2) = e1.cross(e2);
  std::vector<int> ids;
  const int nn = 2 * n_elements + 1;
  for (int i = 0; i < nn; ++i) ids.push_back(model.add_node(a + (b - a) * (double(i) / (nn - 1)), R));
  for (int e = 0; e < n_elements; ++e)
    model.beams.push_back(BeamElement{{ids[2 * e], ids[2 * e + 1], ids[2 * e + 2]}, section});
  return ids;
}

}  // namespace rollspec::rolling
