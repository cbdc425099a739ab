#include "kernels/spectral/response_surface.hpp"

#include "kernels/spectral/gauss_jordan.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <utility>
#include <boost/math/special_functions/gamma.hpp>
#include <cmath>
#include <stdexcept>

namespace rollspec::spectral {

namespace {

using Matrix = Eigen::MatrixXd;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<double> scaled(const ResponseSurface& s, const std::vector<double>& u) {
  std::vector<double> x(s.keys);
  for (std::size_t i = 0; i < s.keys; ++i) x[i] = (u[i] - s.centre[i]) / s.half_width[i];
  return x;
}

// The design Phi (runs x terms) of the points u in the box; refuses a box of zero width.
Matrix design(const std::vector<double>& u, std::size_t keys, const std::vector<double>& centre,
              const std::vector<double>& half_width, std::size_t runs, std::size_t q) {
  if (centre.size() != keys || half_width.size() != keys || u.size() != runs * keys)
    throw std::invalid_argument("response surface: the points, centre and half widths disagree in size");
  for (const double w : half_width)
    if (!(w > 0.0) || !std::isfinite(w)) throw std::invalid_argument("response surface: a box of zero width");
  Matrix phi(static_cast<Eigen::Index>(runs), static_cast<Eigen::Index>(q));
  std::vector<double> x(keys), row(q);
  for (std::size_t j = 0; j < runs; ++j) {
    for (std::size_t i = 0; i < keys; ++i) x[i] = (u[j * keys + i] - centre[i]) / half_width[i];
    quadratic_basis(x.data(), keys, row.data());
    for (std::size_t k = 0; k < q; ++k) phi(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)) = row[k];
  }
  return phi;
}

ResponseSurface shell(std::size_t keys, std::size_t bands, std::size_t runs, const std::vector<double>& centre,
                      const std::vector<double>& half_width, const std::vector<double>& y) {
  ResponseSurface s;
  s.keys = keys, s.bands = bands, s.terms = quadratic_terms(keys), s.runs = runs;
  s.centre = centre, s.half_width = half_width;
  if (y.size() != runs * bands) throw std::invalid_argument("response surface: y is not runs x bands");
  if (runs < s.terms) throw std::invalid_argument("response surface: fewer runs than the quadratic's terms");
  return s;
}

void keep_residuals(ResponseSurface& s, const Matrix& phi, const std::vector<double>& y) {
  const auto runs = static_cast<Eigen::Index>(s.runs), bands = static_cast<Eigen::Index>(s.bands);
  const Matrix b = Eigen::Map<const RowMatrix>(s.coefficients.data(), static_cast<Eigen::Index>(s.terms), bands);
  const RowMatrix r = Eigen::Map<const RowMatrix>(y.data(), runs, bands) - phi * b;
  s.residuals.assign(r.data(), r.data() + r.size());
}

}  // namespace

std::size_t quadratic_terms(std::size_t keys) { return (keys + 1) * (keys + 2) / 2; }

void quadratic_basis(const double* x, std::size_t keys, double* phi) {
  std::size_t k = 0;
  phi[k++] = 1.0;
  for (std::size_t i = 0; i < keys; ++i) phi[k++] = x[i];
  for (std::size_t i = 0; i < keys; ++i)
    for (std::size_t m = i; m < keys; ++m) phi[k++] = x[i] * x[m];
}

ResponseSurface fit_response_surface(const std::vector<double>& u, const std::vector<double>& y, std::size_t keys,
                                     std::size_t bands, const std::vector<double>& centre,
                                     const std::vector<double>& half_width) {
  const std::size_t runs = keys ? u.size() / keys : 0;
  ResponseSurface s = shell(keys, bands, runs, centre, half_width, y);
  const Matrix phi = design(u, keys, centre, half_width, runs, s.terms);
  // Least squares by a column-pivoting QR of Phi (better conditioned than the normal equations); the
  // Gram inverse from R: (Phi^T Phi)^{-1} = P R^{-1} R^{-T} P^T.
  const Eigen::ColPivHouseholderQR<Matrix> qr(phi);
  if (qr.rank() < static_cast<Eigen::Index>(s.terms))
    throw std::invalid_argument("response surface: the design does not determine the quadratic");
  const Matrix b = qr.solve(
      Matrix(Eigen::Map<const RowMatrix>(y.data(), static_cast<Eigen::Index>(runs), static_cast<Eigen::Index>(bands))));
  const RowMatrix br = b;
  s.coefficients.assign(br.data(), br.data() + br.size());
  const auto q = static_cast<Eigen::Index>(s.terms);
  const Matrix r = qr.matrixR().topLeftCorner(q, q).template triangularView<Eigen::Upper>();
  const Matrix r_inv = r.template triangularView<Eigen::Upper>().solve(Matrix::Identity(q, q));
  const Matrix p = qr.colsPermutation();
  const RowMatrix g = p * r_inv * r_inv.transpose() * p.transpose();
  s.gram_inverse.assign(g.data(), g.data() + g.size());
  keep_residuals(s, phi, y);
  return s;
}

ResponseSurface fit_response_surface_reference(const std::vector<double>& u, const std::vector<double>& y,
                                               std::size_t keys, std::size_t bands, const std::vector<double>& centre,
                                               const std::vector<double>& half_width) {
  const std::size_t runs = keys ? u.size() / keys : 0;
  ResponseSurface s = shell(keys, bands, runs, centre, half_width, y);
  const std::size_t q = s.terms;
  const Matrix phi = design(u, keys, centre, half_width, runs, q);
  // Phi^T Phi summed plainly, then inverted by Gauss-Jordan with partial pivoting.
  std::vector<double> a(q * q), inv;
  for (std::size_t i = 0; i < q; ++i)
    for (std::size_t k = 0; k < q; ++k) {
      double sum = 0.0;
      for (std::size_t j = 0; j < runs; ++j)
        sum += phi(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) *
               phi(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k));
      a[i * q + k] = sum;
    }
  if (!gauss_jordan_inverse(std::move(a), q, inv))
    throw std::invalid_argument("response surface: the design does not determine the quadratic");
  s.gram_inverse = inv;
  s.coefficients.assign(q * bands, 0.0);
  for (std::size_t t = 0; t < q; ++t)
    for (std::size_t b = 0; b < bands; ++b)
      for (std::size_t k = 0; k < q; ++k)
        for (std::size_t j = 0; j < runs; ++j)
          s.coefficients[t * bands + b] +=
              inv[t * q + k] * phi(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)) * y[j * bands + b];
  keep_residuals(s, phi, y);
  return s;
}

std::vector<double> ResponseSurface::value(const std::vector<double>& u) const {
  const std::vector<double> x = scaled(*this, u);
  std::vector<double> phi(terms), mu(bands, 0.0);
  quadratic_basis(x.data(), keys, phi.data());
  for (std::size_t t = 0; t < terms; ++t)
    for (std::size_t b = 0; b < bands; ++b) mu[b] += phi[t] * coefficients[t * bands + b];
  return mu;
}

double ResponseSurface::leverage(const std::vector<double>& u) const {
  const std::vector<double> x = scaled(*this, u);
  std::vector<double> phi(terms);
  quadratic_basis(x.data(), keys, phi.data());
  double h = 0.0;
  for (std::size_t a = 0; a < terms; ++a)
    for (std::size_t c = 0; c < terms; ++c) h += phi[a] * gram_inverse[a * terms + c] * phi[c];
  return h;
}

std::vector<double> ResponseSurface::gradient(const std::vector<double>& u) const {
  // d phi / d x_i: 1 for x_i, x_m for x_i x_m (m != i), 2 x_i for x_i^2; then d x_i / d u_i = 1 / w_i.
  const std::vector<double> x = scaled(*this, u);
  std::vector<double> g(bands * keys, 0.0), dphi(terms);
  for (std::size_t i = 0; i < keys; ++i) {
    std::fill(dphi.begin(), dphi.end(), 0.0);
    dphi[1 + i] = 1.0;
    std::size_t k = 1 + keys;
    for (std::size_t a = 0; a < keys; ++a)
      for (std::size_t m = a; m < keys; ++m, ++k) {
        if (a == i) dphi[k] += x[m];
        if (m == i) dphi[k] += x[a];
      }
    for (std::size_t t = 0; t < terms; ++t)
      for (std::size_t b = 0; b < bands; ++b) g[b * keys + i] += dphi[t] * coefficients[t * bands + b] / half_width[i];
  }
  return g;
}

LackOfFit lack_of_fit(const ResponseSurface& s, const std::vector<double>& omega) {
  LackOfFit f;
  const auto p = static_cast<Eigen::Index>(s.bands);
  const Eigen::LLT<Matrix> llt(Matrix(Eigen::Map<const RowMatrix>(omega.data(), p, p)));
  if (llt.info() != Eigen::Success)
    throw std::invalid_argument("response surface: the runs' covariance is not positive definite");
  for (std::size_t j = 0; j < s.runs; ++j) {
    const Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(s.residuals.data() + j * s.bands, p);
    f.statistic += r.dot(llt.solve(r));
  }
  f.dof = static_cast<double>(s.bands) * (static_cast<double>(s.runs) - static_cast<double>(s.terms));
  f.p_value = f.dof > 0.0 ? boost::math::gamma_q(0.5 * f.dof, 0.5 * f.statistic) : 1.0;
  return f;
}

LackOfFit combined_lack_of_fit(const std::vector<LackOfFit>& parts) {
  LackOfFit f;
  for (const LackOfFit& x : parts) f.statistic += x.statistic, f.dof += x.dof;
  f.p_value = f.dof > 0.0 ? boost::math::gamma_q(0.5 * f.dof, 0.5 * f.statistic) : 1.0;
  return f;
}

}  // namespace rollspec::spectral
