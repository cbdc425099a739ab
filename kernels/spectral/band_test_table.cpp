#include "kernels/spectral/band_test_table.hpp"

#include "kernels/spectral/covariance_shrinkage.hpp"

#include <Eigen/Dense>
#include <boost/math/special_functions/gamma.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rollspec::spectral {

namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Box-Muller: n standard normals from 2 ceil(n / 2) uniforms on (0, 1).
void standard_normals(const double* u, std::size_t n, double* z) {
  for (std::size_t i = 0; i < n; i += 2) {
    const double r = std::sqrt(-2.0 * std::log(u[i])), phi = 2.0 * M_PI * u[i + 1];
    z[i] = r * std::cos(phi);
    if (i + 1 < n) z[i + 1] = r * std::sin(phi);
  }
}

// G S G's diagonal scaling, d's offset and the noise's diagonal (D-26a, b, d; D-33c where `noise` is given), one
// band at a time as band_terms gives them.
void scaling(const Matrix& s, double K, double M, const BandNoise* noise, const double* cv2, Vector& g, Vector& offset,
             Vector& diagonal) {
  const auto p = s.rows();
  g.resize(p);
  offset.resize(p);
  diagonal.resize(p);
  for (Eigen::Index b = 0; b < p; ++b) {
    const BandTerms t = band_terms(s(b, b), K, M, 1.0, noise ? noise + b : nullptr, cv2 ? cv2 + b : nullptr);
    g(b) = t.g;
    offset(b) = t.offset;
    diagonal(b) = t.diagonal;
  }
}

// Sigma_T = U U^T over its positive eigenvalues (rank r = U's columns); refuses an asymmetric or
// indefinite matrix. Eigenvalues below 1e-12 of the largest are the jackknife's null space.
Matrix table_factor(const Matrix& t) {
  const double scale = t.cwiseAbs().maxCoeff();
  if (!std::isfinite(scale)) throw std::invalid_argument("band test: the table covariance is not finite");
  if (scale == 0.0) return Matrix(t.rows(), 0);
  if ((t - t.transpose()).cwiseAbs().maxCoeff() > 1e-10 * scale)
    throw std::invalid_argument("band test: the table covariance is not symmetric");
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(t);
  const Vector& lambda = eig.eigenvalues();
  const double top = lambda.maxCoeff();
  if (lambda.minCoeff() < -1e-9 * top)
    throw std::invalid_argument("band test: the table covariance is not positive semi-definite");
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    if (lambda(i) > 1e-12 * top) keep.push_back(i);
  Matrix u(t.rows(), static_cast<Eigen::Index>(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k)
    u.col(static_cast<Eigen::Index>(k)) = eig.eigenvectors().col(keep[k]) * std::sqrt(lambda(keep[k]));
  return u;
}

}  // namespace

std::vector<double> smoothed_variances(const std::vector<double>& v, std::size_t w, std::vector<std::size_t>* count) {
  const std::size_t p = v.size();
  std::vector<double> out(p);
  if (count) count->assign(p, 0);
  for (std::size_t b = 0; b < p; ++b) {
    const std::size_t lo = b >= w ? b - w : 0, hi = std::min(p, b + w + 1);
    double s = 0.0;
    for (std::size_t c = lo; c < hi; ++c) s += v[c];
    out[b] = s / static_cast<double>(hi - lo);
    if (count) (*count)[b] = hi - lo;
  }
  return out;
}

std::size_t bartlett_uniforms(std::size_t q) { return q + 2 * ((q * (q - 1) / 2 + 1) / 2); }

void bartlett_wishart(std::size_t q, double nu, const double* u, double* a) {
  Matrix l = Matrix::Zero(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q));
  std::vector<double> z(q * (q - 1) / 2);
  standard_normals(u + q, z.size(), z.data());
  std::size_t k = 0;
  for (std::size_t i = 0; i < q; ++i) {
    const double shape = 0.5 * (nu - static_cast<double>(i));
    l(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)) =
        std::sqrt(2.0 * boost::math::gamma_p_inv(shape, u[i]));
    for (std::size_t j = 0; j < i; ++j) l(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = z[k++];
  }
  Eigen::Map<RowMatrix>(a, static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q)) = l * l.transpose();
}

namespace {

// T^2 = d^T V^{-1} d, or of C^T d and C^T V C when C is given (D-27j); false when V is not positive definite.
bool statistic(const Matrix* c, const Vector& d, const Matrix& v, double& t2) {
  if (!c) {
    const Eigen::LLT<Matrix> llt(v);
    if (llt.info() != Eigen::Success) return false;
    t2 = llt.solve(d).dot(d);
    return true;
  }
  const Vector dc = c->transpose() * d;
  const Eigen::LLT<Matrix> llt(c->transpose() * v * *c);
  if (llt.info() != Eigen::Success) return false;
  t2 = llt.solve(dc).dot(dc);
  return true;
}

// D-26's F law of T^2 in p' = p - q dimensions after the projection C (D-27j).
BandTestResult projected_f_test(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                                std::uint64_t realisations, double records, const Matrix& c) {
  BandTestResult r;
  r.needed = p + kExtraRealisations;
  if (p == 0 || realisations < r.needed) return r;
  const auto n = static_cast<Eigen::Index>(p);
  std::vector<double> d, v;
  band_deviation(measured_log, mean, covariance, p, static_cast<double>(realisations), records, d, v);
  double t2 = 0.0;
  if (!statistic(&c, Eigen::Map<const Vector>(d.data(), n), Eigen::Map<const RowMatrix>(v.data(), n, n), t2))
    throw std::invalid_argument("band test: the band covariance is not positive definite");
  hotelling_f_law(r, t2, static_cast<double>(realisations - 1), static_cast<double>(c.cols()));
  return r;
}

BandTestResult table_test(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                          std::uint64_t realisations, double records, const TableTerm& table,
                          const DrawUniforms& uniform, std::size_t draws, const Matrix* c, const BandNoise* noise,
                          const double* cv2) {
  const auto untabled = [&] {
    return c ? projected_f_test(measured_log, mean, covariance, p, realisations, records, *c)
             : band_test(measured_log, mean, covariance, p, realisations, records, noise, cv2);
  };
  const bool tabled = table.factor > 0.0 && table.covariance != nullptr;
  // D-33f: the logger noise's terms are known far better than S, so T^2's law lies between chi^2_p's and
  // Hotelling's; the bootstrap draws it (the noise held at its estimates) where the F law is conservative.
  const bool noisy = !c && noise != nullptr &&
                     std::any_of(noise, noise + p, [](const BandNoise& b) { return b.measured + b.estimate > 0.0; });
  if (!(tabled || noisy) || draws == 0) return untabled();
  BandTestResult r;
  r.needed = p + kExtraRealisations;
  if (p == 0 || realisations < r.needed) return r;
  const auto n = static_cast<Eigen::Index>(p);
  const double K = static_cast<double>(realisations), nu = K - 1.0;
  const Matrix s = Eigen::Map<const RowMatrix>(covariance, n, n);
  const Matrix t_full = tabled ? Matrix(Eigen::Map<const RowMatrix>(table.covariance, n, n)) : Matrix::Zero(n, n);
  // Independent bands (D-31c): Sigma_T is its diagonal, each band's variance drawn alone. Else its
  // factor over the positive eigenvalues, drawn as one Wishart of its rank.
  Vector t_diag;
  Matrix u;
  std::size_t rank = 0;
  Vector raw;
  if (table.independent) {
    raw = t_full.diagonal();
    if (!raw.allFinite() || raw.minCoeff() < 0.0)
      throw std::invalid_argument("band test: a table variance is negative or not finite");
    t_diag = Eigen::Map<const Vector>(
        smoothed_variances(std::vector<double>(raw.data(), raw.data() + n), table.smooth).data(), n);
    rank = static_cast<std::size_t>((t_diag.array() > 0.0).count());
  } else {
    u = table_factor(t_full);
    rank = static_cast<std::size_t>(u.cols());
  }
  if (rank == 0 && !noisy) return untabled();
  if (rank > 0 &&
      (!(table.dof > (table.independent ? 0.0 : static_cast<double>(rank) - 1.0)) || !std::isfinite(table.dof)))
    throw std::invalid_argument("band test: the table term's degrees of freedom must exceed its rank - 1");
  if (!table.independent && !(table.shrinkage >= 0.0 && table.shrinkage <= 1.0))
    throw std::invalid_argument("band test: the table term's shrinkage must lie in [0, 1]");
  // D-31e: a full term's correlations shrunk toward its diagonal, here and in every draw.
  const auto shrunk = [&](Matrix t) {
    shrink_toward_diagonal(t.data(), p, table.shrinkage);  // symmetric: the storage order does not matter
    return t;
  };
  const Matrix t_used = table.independent ? Matrix(t_diag.asDiagonal()) : shrunk(u * u.transpose());

  // The observed T^2 with V = G S G + c Sigma_T (D-31a).
  std::vector<double> d, v;
  band_deviation(measured_log, mean, covariance, p, K, records, d, v, noise, cv2);
  Matrix vv = Eigen::Map<const RowMatrix>(v.data(), n, n);
  vv += table.factor * t_used;
  const Eigen::LLT<Matrix> llt(vv);
  double t2 = 0.0;
  if (llt.info() != Eigen::Success || !statistic(c, Eigen::Map<const Vector>(d.data(), n), vv, t2))
    throw std::invalid_argument("band test: the band covariance is not positive definite");

  // The bootstrap (D-31b): estimates drawn about the observed ones, d* from the law they give.
  const Eigen::LLT<Matrix> s_llt(s);
  if (s_llt.info() != Eigen::Success)
    throw std::invalid_argument("band test: the band covariance is not positive definite");
  const Matrix ls = s_llt.matrixL(), lv = llt.matrixL();
  Vector g, offset, diagonal, g_star, offset_star;
  scaling(s, K, records, noise, cv2, g, offset, diagonal);
  std::vector<double> cv2_star(cv2 ? p : 0);
  const std::size_t ns = bartlett_uniforms(p), nt = table.independent ? p : bartlett_uniforms(rank);
  std::vector<double> uni(ns + nt + 2 * ((p + 1) / 2)), a_s(p * p), a_t(rank * rank);
  std::size_t exceed = 0;
  for (std::size_t j = 0; j < draws; ++j) {
    uniform(j, uni.data(), uni.size());
    bartlett_wishart(p, nu, uni.data(), a_s.data());
    const Matrix s_star = ls * Eigen::Map<const RowMatrix>(a_s.data(), n, n) * ls.transpose() / nu;
    Matrix t_star = Matrix::Zero(n, n);  // no table: the noise's terms alone beside S*
    if (rank > 0 && table.independent) {
      std::vector<double> drawn(p);
      for (std::size_t b = 0; b < p; ++b)
        drawn[b] = raw(static_cast<Eigen::Index>(b)) * 2.0 * boost::math::gamma_p_inv(0.5 * table.dof, uni[ns + b]) /
                   table.dof;
      const std::vector<double> diag = smoothed_variances(drawn, table.smooth);
      t_star = Eigen::Map<const Vector>(diag.data(), n).asDiagonal();
    } else if (rank > 0) {
      bartlett_wishart(rank, table.dof, uni.data() + ns, a_t.data());
      const auto nr = static_cast<Eigen::Index>(rank);
      t_star = shrunk(u * Eigen::Map<const RowMatrix>(a_t.data(), nr, nr) * u.transpose() / table.dof);
    }
    for (std::size_t b = 0; b < cv2_star.size(); ++b) {  // D-26d's CV^2 moves with the drawn S*_bb
      const auto i = static_cast<Eigen::Index>(b);
      cv2_star[b] = s(i, i) > 0.0 ? cv2[b] * s_star(i, i) / s(i, i) : cv2[b];
    }
    scaling(s_star, K, records, noise, cv2 ? cv2_star.data() : nullptr, g_star, offset_star, diagonal);
    Matrix v_star = g_star.asDiagonal() * s_star * g_star.asDiagonal() + table.factor * t_star;
    if (noise) {  // D-33c: the noise's terms, held at their estimates (D-33e: with its covariance between bands)
      v_star.diagonal() += diagonal;
      for (std::size_t b = 0; b < p; ++b)
        if (noise[b].cross)
          for (std::size_t e = 0; e < p; ++e)
            if (e != b) v_star(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(e)) += noise[b].cross[e];
    }
    Vector z(n);
    standard_normals(uni.data() + ns + nt, p, z.data());
    const Vector d_star = lv * z + offset - offset_star;
    double t2_star = 0.0;
    // A draw whose covariance breaks down counts against the model: the p-value stays conservative.
    if (!statistic(c, d_star, v_star, t2_star) || t2_star >= t2) ++exceed;
  }
  const double pp = c ? static_cast<double>(c->cols()) : static_cast<double>(p);
  r.defined = true;
  r.t2 = t2;
  r.dof1 = pp;
  r.dof2 = nu - pp + 1.0;
  r.f = r.dof2 / (nu * pp) * t2;
  r.draws = draws;
  r.p_value = (1.0 + static_cast<double>(exceed)) / (1.0 + static_cast<double>(draws));
  return r;
}

}  // namespace

BandTestResult band_test_with_table(const double* measured_log, const double* mean, const double* covariance,
                                    std::size_t p, std::uint64_t realisations, double records, const TableTerm& table,
                                    const DrawUniforms& uniform, std::size_t draws, const BandNoise* noise,
                                    const double* cv2) {
  return table_test(measured_log, mean, covariance, p, realisations, records, table, uniform, draws, nullptr, noise,
                    cv2);
}

BandTestResult band_test_fitted(const double* measured_log, const double* mean, const double* covariance, std::size_t p,
                                std::uint64_t realisations, double records, const double* jacobian, std::size_t q,
                                const TableTerm& table, const DrawUniforms& uniform, std::size_t draws) {
  if (q == 0 || jacobian == nullptr)
    return table_test(measured_log, mean, covariance, p, realisations, records, table, uniform, draws, nullptr, nullptr,
                      nullptr);
  if (q >= p) throw std::invalid_argument("band test: as many fitted keys as bands leave nothing to test");
  const auto n = static_cast<Eigen::Index>(p), k = static_cast<Eigen::Index>(q);
  // C: the last p - q columns of Q in J = Q R (Householder), orthonormal and orthogonal to J's columns.
  const Matrix j = Eigen::Map<const RowMatrix>(jacobian, n, k);
  const Eigen::ColPivHouseholderQR<Matrix> qr(j);
  if (qr.rank() < k) throw std::invalid_argument("band test: the fitted keys' band-log derivatives are dependent");
  const Matrix full = qr.householderQ() * Matrix::Identity(n, n);
  const Matrix c = full.rightCols(n - k);
  return table_test(measured_log, mean, covariance, p, realisations, records, table, uniform, draws, &c, nullptr,
                    nullptr);
}

}  // namespace rollspec::spectral
