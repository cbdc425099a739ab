#include "kernels/beam/path_contact_table.hpp"

#include "kernels/beam/bracketed_newton.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rollspec::beam {

namespace {
[[noreturn]] void fail(const char* what) { throw std::invalid_argument(std::string("PathContactTable: ") + what); }
}  // namespace

PathContactTable::PathContactTable(PathContactData data) : d_(std::move(data)) {
  const std::size_t nk = d_.position.size(), nj = d_.approach.size();
  if (nk == 0 || nj == 0) fail("no positions or approaches");
  if (d_.first_contact.size() != nk || d_.force.size() != nj * nk) fail("sizes do not match");
  if (!d_.rows.empty() && d_.rows.size() != nk) fail("rows: one count per position");
  for (std::size_t k = 1; k < nk; ++k)
    if (!(d_.position[k] > d_.position[k - 1])) fail("positions must increase");
  for (std::size_t j = 1; j < nj; ++j)
    if (!(d_.approach[j] > d_.approach[j - 1])) fail("approaches must increase");
  if (!d_.rows.empty() && !(d_.approach[0] > 0.0)) fail("ladder offsets must be > 0");
  for (std::size_t k = 0; k < nk; ++k) {
    if (!std::isfinite(d_.first_contact[k])) fail("first contact must be finite");
    const std::size_t rows = d_.rows.empty() ? nj : d_.rows[k];
    if (rows < 1 || rows > nj) fail("rows: between 1 and the number of approaches at every position");
    for (std::size_t j = 0; j < rows; ++j) {
      const double p = d_.force[j * nk + k];
      if (!(p >= 0.0) || !std::isfinite(p)) fail("forces must be finite, >= 0");
      if (j > 0 && p < d_.force[(j - 1) * nk + k]) fail("forces must be non-decreasing in the approach");
    }
  }
  // B45b needs k − 2 … k + 3 equally spaced about interval k (a thinned table's last interval is not).
  uniform_.assign(nk > 0 ? nk - 1 : 0, 0);
  for (std::size_t k = 2; d_.interpolation == PathInterpolation::cubic && k + 3 < nk; ++k) {
    const double h = d_.position[k + 1] - d_.position[k];
    bool same = true;
    for (std::size_t i = k - 2; i < k + 3; ++i)
      same = same && std::fabs((d_.position[i + 1] - d_.position[i]) - h) <= 1e-9 * h;
    uniform_[k] = same ? 1 : 0;
  }
  q_.resize(d_.force.size());
  for (std::size_t i = 0; i < q_.size(); ++i) q_[i] = std::cbrt(d_.force[i] * d_.force[i]);  // Q = P^{2/3}
}

double PathContactTable::top_approach(std::size_t k) const {
  if (d_.rows.empty()) return d_.approach.back();
  return d_.first_contact[k] + d_.approach[d_.rows[k] - 1];
}

void PathContactTable::at_position(std::size_t k, double delta, double& force, double& stiffness) const {
  force = stiffness = 0.0;
  const double dc = d_.first_contact[k];
  if (!(delta > dc)) return;
  const std::size_t nk = d_.position.size();
  const bool ladder = !d_.rows.empty();  // B43b: node j at δ_c + s_j
  const std::size_t nj = ladder ? d_.rows[k] : d_.approach.size();
  const double origin = ladder ? dc : 0.0;
  const auto begin = d_.approach.begin(), end = begin + static_cast<std::ptrdiff_t>(nj);
  // Nodes (B44): (δ_c, 0) and (δ_j, Q_j) for δ_j > δ_c. Find the segment [a, b] holding δ, or the
  // last one (continued beyond the last approach).
  const std::size_t j0 = ladder ? 0 : static_cast<std::size_t>(std::upper_bound(begin, end, dc) - begin);
  if (j0 == nj) return;                       // no tabulated approach above first contact: nothing known, no force
  std::size_t jb = static_cast<std::size_t>(  // first node above δ
      std::upper_bound(begin + static_cast<std::ptrdiff_t>(j0), end, delta - origin) - begin);
  if (jb == nj) jb = nj - 1;
  double da, qa;
  if (jb == j0) {
    da = dc;
    qa = 0.0;
  } else {
    da = origin + d_.approach[jb - 1];
    qa = q_[(jb - 1) * nk + k];
  }
  const double db = origin + d_.approach[jb], qb = q_[jb * nk + k];
  const double slope = (qb - qa) / (db - da);
  const double q = qa + (delta - da) * slope;
  if (!(q > 0.0)) return;
  const double r = std::sqrt(q);
  force = q * r;
  stiffness = 1.5 * r * slope;
}

void PathContactTable::locate(double xi, std::size_t& k, double& t) const {
  const std::vector<double>& x = d_.position;
  if (x.size() == 1 || xi <= x.front()) {
    k = 0;
    t = 0.0;
    return;
  }
  if (xi >= x.back()) {
    k = x.size() - 1;
    t = 0.0;
    return;
  }
  k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), xi) - x.begin()) - 1;
  t = (xi - x[k]) / (x[k + 1] - x[k]);
}

double keys_six_point(double s) {
  s = std::fabs(s);
  if (s < 1.0) return ((4.0 / 3.0) * s - 7.0 / 3.0) * s * s + 1.0;
  if (s < 2.0) return ((-7.0 / 12.0 * s + 3.0) * s - 59.0 / 12.0) * s + 2.5;
  if (s < 3.0) return ((1.0 / 12.0 * s - 2.0 / 3.0) * s + 7.0 / 4.0) * s - 1.5;
  return 0.0;
}

std::size_t PathContactTable::stencil(std::size_t k, double t, double* weight) const {
  if (t > 0.0 && k < uniform_.size() && uniform_[k]) {  // B45b
    for (int i = 0; i < 6; ++i) weight[i] = keys_six_point(t - static_cast<double>(i - 2));
    return 6;
  }
  weight[0] = 1.0 - t;  // B45
  weight[1] = t;
  return t > 0.0 ? 2 : 1;
}

void PathContactTable::evaluate(double delta, double xi, double& force, double& stiffness) const {
  std::size_t k;
  double t;
  locate(xi, k, t);
  double w[6];
  const std::size_t n = stencil(k, t, w), first = n == 6 ? k - 2 : k;
  force = stiffness = 0.0;  // the blend of B45 or B45b; no force where it is not positive (B45b)
  for (std::size_t i = 0; i < n; ++i) {
    double f, s;
    at_position(first + i, delta, f, s);
    force += w[i] * f;
    stiffness += w[i] * s;
  }
  if (!(force > 0.0)) force = stiffness = 0.0;
}

double PathContactTable::first_contact(double xi) const {
  std::size_t k;
  double t;
  locate(xi, k, t);
  double w[6];
  const std::size_t n = stencil(k, t, w);
  const std::size_t first = n == 6 ? k - 2 : k;
  double dc = d_.first_contact[first];
  for (std::size_t i = 1; i < n; ++i) dc = std::min(dc, d_.first_contact[first + i]);
  return dc;
}

bool PathContactTable::touches(double delta, double xi) const {
  if (d_.interpolation == PathInterpolation::linear) return delta > first_contact(xi);
  if (!(delta > first_contact(xi))) return false;
  double f, s;
  evaluate(delta, xi, f, s);
  return f > 0.0;
}

double PathContactTable::static_approach(double load, double xi) const {
  if (!(load > 0.0)) return first_contact(xi);
  std::size_t at;
  double t;
  locate(xi, at, t);
  double lo = first_contact(xi), hi = std::max(top_approach(at), t > 0.0 ? top_approach(at + 1) : -HUGE_VAL);
  double p, k;
  evaluate(hi, xi, p, k);
  for (int i = 0; p < load; ++i) {  // beyond the table: the continued last segment grows without bound
    if (i == 200 || !(k > 0.0)) throw std::runtime_error("PathContactTable: the path table cannot carry the load");
    lo = hi;
    hi += std::max(hi - first_contact(xi), 1e-9);
    evaluate(hi, xi, p, k);
  }
  const double first = first_contact(xi);
  return bracketed_newton(
      lo, hi, load, [&](double x, double& px, double& kx) { evaluate(x, xi, px, kx); },
      [first](double, double top) { return std::fabs(top - first); });
}

double PathContactTable::static_slope(double load, double xi, double width) const {
  const double lo = std::max(xi - 0.5 * width, d_.position.front()), hi = xi + 0.5 * width;
  if (!(hi > lo)) return 0.0;
  constexpr int n = 21;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = lo + (hi - lo) * i / (n - 1), y = static_approach(load, x);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

PathContactData thinned_rows(const PathContactData& d, std::size_t every) {
  if (every < 1) throw std::invalid_argument("thinned_rows: every must be >= 1");
  const std::size_t nk = d.position.size(), nj = d.approach.size();
  if (nj / every < 1) throw std::invalid_argument("thinned_rows: fewer approaches than every");
  PathContactData t{d.position, {}, d.first_contact, {}, {}, d.interpolation};
  for (std::size_t j = every - 1; j < nj; j += every) {
    t.approach.push_back(d.approach[j]);
    t.force.insert(t.force.end(), d.force.begin() + static_cast<std::ptrdiff_t>(j * nk),
                   d.force.begin() + static_cast<std::ptrdiff_t>((j + 1) * nk));
  }
  for (std::size_t r : d.rows) t.rows.push_back(r / every);  // a position with fewer rows than every: refused
  return t;
}

PathContactData thinned_positions(const PathContactData& d, std::size_t every) {
  if (every < 1) throw std::invalid_argument("thinned_positions: every must be >= 1");
  const std::size_t nk = d.position.size(), nj = d.approach.size();
  std::vector<std::size_t> keep;
  for (std::size_t k = 0; k < nk; k += every) keep.push_back(k);
  if (keep.back() != nk - 1) keep.push_back(nk - 1);  // the path's end stays covered
  PathContactData t{{}, d.approach, {}, {}, {}, d.interpolation};
  for (std::size_t k : keep) {
    t.position.push_back(d.position[k]);
    t.first_contact.push_back(d.first_contact[k]);
    if (!d.rows.empty()) t.rows.push_back(d.rows[k]);
  }
  for (std::size_t j = 0; j < nj; ++j)
    for (std::size_t k : keep) t.force.push_back(d.force[j * nk + k]);
  return t;
}

std::vector<double> path_static_approaches(const PathContactTable& table, double load) {
  std::vector<double> w;
  for (double xi : table.data().position) w.push_back(table.static_approach(load, xi));
  return w;
}

double path_table_static_approach(const std::vector<double>& static_approaches) {
  double s = 0.0;
  for (double w : static_approaches) s += w;
  return s / static_cast<double>(static_approaches.size());
}

double path_table_static_approach(const PathContactTable& table, double load) {
  return path_table_static_approach(path_static_approaches(table, load));
}

}  // namespace rollspec::beam
