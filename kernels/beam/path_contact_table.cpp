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

void PathContactTable::evaluate(double delta, double xi, double& force, double& stiffness) const {
  std::size_t k;
  double t;
  locate(xi, k, t);
  at_position(k, delta, force, stiffness);
  if (t > 0.0) {  // B45
    double f1, k1;
    at_position(k + 1, delta, f1, k1);
    force = (1.0 - t) * force + t * f1;
    stiffness = (1.0 - t) * stiffness + t * k1;
  }
}

double PathContactTable::first_contact(double xi) const {
  std::size_t k;
  double t;
  locate(xi, k, t);
  return t > 0.0 ? std::min(d_.first_contact[k], d_.first_contact[k + 1]) : d_.first_contact[k];
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

PathContactData thinned_rows(const PathContactData& d, std::size_t every) {
  if (every < 1) throw std::invalid_argument("thinned_rows: every must be >= 1");
  const std::size_t nk = d.position.size(), nj = d.approach.size();
  if (nj / every < 1) throw std::invalid_argument("thinned_rows: fewer approaches than every");
  PathContactData t{d.position, {}, d.first_contact, {}, {}};
  for (std::size_t j = every - 1; j < nj; j += every) {
    t.approach.push_back(d.approach[j]);
    t.force.insert(t.force.end(), d.force.begin() + static_cast<std::ptrdiff_t>(j * nk),
                   d.force.begin() + static_cast<std::ptrdiff_t>((j + 1) * nk));
  }
  for (std::size_t r : d.rows) t.rows.push_back(r / every);  // a position with fewer rows than every: refused
  return t;
}

double path_table_static_approach(const PathContactTable& table, double load) {
  const std::vector<double>& x = table.data().position;
  double s = 0.0;
  for (double xi : x) s += table.static_approach(load, xi);
  return s / static_cast<double>(x.size());
}

}  // namespace rollspec::beam
