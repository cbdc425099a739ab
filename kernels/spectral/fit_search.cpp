#include "kernels/spectral/fit_search.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rollspec::spectral {

namespace {

std::vector<double> clamped(std::vector<double> x) {
  for (double& v : x) v = std::clamp(v, 0.0, 1.0);
  return x;
}

// a + c (b - a), clamped onto the box.
std::vector<double> along(const std::vector<double>& a, const std::vector<double>& b, double c) {
  std::vector<double> x(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) x[i] = a[i] + c * (b[i] - a[i]);
  return clamped(x);
}

}  // namespace

BoxMinimum box_minimum(const BoxObjective& f, const std::vector<double>& start, double step, double tolerance,
                       int max_evaluations) {
  const std::size_t n = start.size();
  BoxMinimum out;
  std::vector<std::vector<double>> p(n + 1, clamped(start));
  for (std::size_t i = 0; i < n; ++i)  // step inward from an edge
    p[i + 1][i] += p[i + 1][i] + step <= 1.0 ? step : -step;
  std::vector<double> v(n + 1);
  auto eval = [&](const std::vector<double>& x) { return ++out.evaluations, f(x); };
  for (std::size_t i = 0; i <= n; ++i) v[i] = eval(p[i]);
  std::vector<std::size_t> order(n + 1);
  while (true) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    const std::size_t best = order.front(), worst = order.back(), next = order[n > 0 ? n - 1 : 0];
    double edge = 0.0;
    for (std::size_t i = 0; i <= n; ++i)
      for (std::size_t k = 0; k < n; ++k) edge = std::max(edge, std::fabs(p[i][k] - p[best][k]));
    if ((edge < tolerance && v[worst] - v[best] < tolerance) || out.evaluations >= max_evaluations || n == 0) break;
    std::vector<double> centroid(n, 0.0);
    for (std::size_t i = 0; i <= n; ++i)
      if (i != worst)
        for (std::size_t k = 0; k < n; ++k) centroid[k] += p[i][k] / static_cast<double>(n);
    const auto r = along(centroid, p[worst], -1.0);
    const double fr = eval(r);
    if (fr < v[best]) {
      const auto e = along(centroid, p[worst], -2.0);
      const double fe = eval(e);
      if (fe < fr)
        p[worst] = e, v[worst] = fe;
      else
        p[worst] = r, v[worst] = fr;
    } else if (fr < v[next]) {
      p[worst] = r, v[worst] = fr;
    } else {
      const bool outside = fr < v[worst];
      const auto c = along(centroid, outside ? r : p[worst], 0.5);
      const double fc = eval(c);
      if (fc < (outside ? fr : v[worst])) {
        p[worst] = c, v[worst] = fc;
      } else {  // shrink towards the best point
        for (std::size_t i = 0; i <= n; ++i)
          if (i != best) p[i] = along(p[best], p[i], 0.5), v[i] = eval(p[i]);
      }
    }
  }
  const std::size_t best = static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
  out.x = p[best];
  out.value = v[best];
  return out;
}

BoxMinimum box_minimum_grid_reference(const BoxObjective& f, std::size_t n, int points) {
  BoxMinimum out;
  out.value = INFINITY;
  std::vector<int> idx(n, 0);
  std::vector<double> x(n);
  while (true) {
    for (std::size_t k = 0; k < n; ++k) x[k] = static_cast<double>(idx[k]) / (points - 1);
    const double v = f(x);
    ++out.evaluations;
    if (v < out.value) out.value = v, out.x = x;
    std::size_t k = 0;
    while (k < n && ++idx[k] == points) idx[k++] = 0;
    if (k == n) break;
  }
  return out;
}

ProfileContinuation::ProfileContinuation(BoxObjective f, std::size_t n, std::size_t j, double t0,
                                         const std::vector<double>& others0, double step, double tolerance,
                                         int max_evaluations)
    : f_(std::move(f)), n_(n), j_(j), step_(step), tolerance_(tolerance), max_evaluations_(max_evaluations) {
  solved_.emplace_back(t0, others0);
}

double ProfileContinuation::operator()(double t) {
  if (n_ == 1) return f_({t});
  std::size_t nearest = 0;
  for (std::size_t i = 1; i < solved_.size(); ++i)
    if (std::fabs(solved_[i].first - t) < std::fabs(solved_[nearest].first - t)) nearest = i;
  const BoxObjective g = [&](const std::vector<double>& o) {
    std::vector<double> u;
    for (std::size_t i = 0, k = 0; i < n_; ++i) u.push_back(i == j_ ? t : o[k++]);
    return f_(u);
  };
  const BoxMinimum m = box_minimum(g, solved_[nearest].second, step_, tolerance_, max_evaluations_);
  solved_.emplace_back(t, m.x);
  return m.value;
}

double profile_end(const std::function<double(double)>& profile, double t0, double f0, double end, double rise,
                   double tolerance, int* evaluations) {
  // h(t) = sqrt(profile - f0) - sqrt(rise) is linear in t for a Gaussian likelihood: regula falsi
  // (Illinois) on it then lands in a step or two; the bracket [inside, outside] keeps it safe.
  const double root = std::sqrt(rise);
  const auto h = [&](double t) {
    ++*evaluations;
    return std::sqrt(std::max(profile(t) - f0, 0.0)) - root;
  };
  double outside = end, h_out = h(end);
  if (h_out <= 0.0) return end;
  double inside = t0, h_in = -root;
  int side = 0;
  for (int i = 0; i < 100 && std::fabs(outside - inside) > tolerance; ++i) {
    const double t = outside - h_out * (outside - inside) / (h_out - h_in);
    const double ht = h(t);
    if (std::fabs(ht) < 1e-3 * root) return t;
    if (ht > 0.0) {
      outside = t, h_out = ht;
      if (side == 1) h_in *= 0.5;
      side = 1;
    } else {
      inside = t, h_in = ht;
      if (side == -1) h_out *= 0.5;
      side = -1;
    }
  }
  return 0.5 * (inside + outside);
}

std::vector<double> box_hessian(const BoxObjective& f, const std::vector<double>& x, double h, int* evaluations) {
  const std::size_t n = x.size();
  std::vector<double> c(x);
  for (double& v : c) v = std::clamp(v, h, 1.0 - h);  // the stencil stays inside the box
  auto at = [&](std::size_t i, double di, std::size_t j, double dj) {
    std::vector<double> y(c);
    y[i] += di;
    y[j] += dj;
    ++*evaluations;
    return f(y);
  };
  std::vector<double> hess(n * n);
  ++*evaluations;
  const double f0 = f(c);
  for (std::size_t i = 0; i < n; ++i) {
    hess[i * n + i] = (at(i, h, i, 0.0) - 2.0 * f0 + at(i, -h, i, 0.0)) / (h * h);
    for (std::size_t j = 0; j < i; ++j)
      hess[i * n + j] = hess[j * n + i] =
          (at(i, h, j, h) - at(i, h, j, -h) - at(i, -h, j, h) + at(i, -h, j, -h)) / (4.0 * h * h);
  }
  return hess;
}

std::vector<double> inverse_correlation(const std::vector<double>& h, std::size_t n) {
  // Gauss-Jordan without pivoting: a positive definite matrix needs none, and a non-positive pivot
  // says it is not positive definite.
  std::vector<double> a(h), inv(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) inv[i * n + i] = 1.0;
  for (std::size_t c = 0; c < n; ++c) {
    const double piv = a[c * n + c];
    if (!(piv > 0.0)) return {};
    for (std::size_t k = 0; k < n; ++k) a[c * n + k] /= piv, inv[c * n + k] /= piv;
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c) continue;
      const double m = a[r * n + c];
      for (std::size_t k = 0; k < n; ++k) a[r * n + k] -= m * a[c * n + k], inv[r * n + k] -= m * inv[c * n + k];
    }
  }
  std::vector<double> corr(n * n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) corr[i * n + j] = inv[i * n + j] / std::sqrt(inv[i * n + i] * inv[j * n + j]);
  return corr;
}

double fisher_combined_p(const std::vector<double>& p) {
  if (p.empty()) return 1.0;
  double half = 0.0;  // x / 2 = -sum ln p_i
  for (const double v : p) {
    if (!(v > 0.0)) return 0.0;
    half -= std::log(std::min(v, 1.0));
  }
  // P(chi2_2k >= x) = exp(-x/2) sum_{i<k} (x/2)^i / i!
  double term = std::exp(-half), sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    sum += term;
    term *= half / static_cast<double>(i + 1);
  }
  return std::min(sum, 1.0);
}

}  // namespace rollspec::spectral
