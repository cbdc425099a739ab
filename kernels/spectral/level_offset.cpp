#include "kernels/spectral/level_offset.hpp"

#include <Eigen/Dense>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rollspec::spectral {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// var c, nu and the interval from the weights' two quadratic forms.
LevelOffset finish(double estimate, double a_s, double a_t, double nu_s, double nu_t, double level) {
  LevelOffset o;
  o.estimate = estimate;
  o.variance = a_s + a_t;
  const double denominator = a_s * a_s / nu_s + (a_t > 0.0 ? a_t * a_t / nu_t : 0.0);
  o.dof = denominator > 0.0 ? o.variance * o.variance / denominator : nu_s;
  const double t = boost::math::quantile(boost::math::students_t(o.dof), 0.5 * (1.0 + level));
  o.lower = estimate - t * std::sqrt(o.variance);
  o.upper = estimate + t * std::sqrt(o.variance);
  return o;
}

}  // namespace

LevelOffset level_offset(const double* d, const double* v_s, const double* v_t, std::size_t p, double nu_s, double nu_t,
                         double level) {
  if (p == 0) throw std::invalid_argument("level offset: no bands");
  const auto n = static_cast<Eigen::Index>(p);
  const Eigen::MatrixXd vs = Eigen::Map<const RowMatrix>(v_s, n, n);
  const Eigen::MatrixXd vt =
      v_t ? Eigen::MatrixXd(Eigen::Map<const RowMatrix>(v_t, n, n)) : Eigen::MatrixXd::Zero(n, n);
  const Eigen::VectorXd diag = (vs + vt).diagonal();
  if (!(diag.minCoeff() > 0.0) || !diag.allFinite())
    throw std::invalid_argument("level offset: a band without a positive finite variance");
  const Eigen::VectorXd u = diag.cwiseInverse();
  const Eigen::VectorXd w = u / u.sum();
  return finish(w.dot(Eigen::Map<const Eigen::VectorXd>(d, n)), w.dot(vs * w), w.dot(vt * w), nu_s, nu_t, level);
}

LevelOffset level_offset_reference(const double* d, const double* v_s, const double* v_t, std::size_t p, double nu_s,
                                   double nu_t, double level) {
  double total = 0.0;
  std::vector<double> w(p);
  for (std::size_t i = 0; i < p; ++i) {
    w[i] = 1.0 / (v_s[i * p + i] + (v_t ? v_t[i * p + i] : 0.0));
    total += w[i];
  }
  double c = 0.0, a_s = 0.0, a_t = 0.0;
  for (std::size_t i = 0; i < p; ++i) c += w[i] / total * d[i];
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j) {
      a_s += w[i] / total * v_s[i * p + j] * w[j] / total;
      if (v_t) a_t += w[i] / total * v_t[i * p + j] * w[j] / total;
    }
  return finish(c, a_s, a_t, nu_s, nu_t, level);
}

}  // namespace rollspec::spectral
