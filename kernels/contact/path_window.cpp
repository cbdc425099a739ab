#include "kernels/contact/path_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rollspec::contact {

namespace {

using Index = std::ptrdiff_t;

bool same(double a, double b) { return std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b)); }

// z_ball(r) of README Eq. 5 (the same expressions as ball_gap).
double ball_height(double r2, double radius, BallShape shape) {
  if (shape == BallShape::Paraboloid) return r2 / (2.0 * radius);
  return r2 < radius * radius ? r2 / (radius + std::sqrt(radius * radius - r2)) : radius;
}

}  // namespace

void PathWindow::fail(const std::string& what) const { throw std::invalid_argument(caller_ + ": " + what); }

PathWindow::PathWindow(const Grid& window, const Grid& strip, const std::vector<double>& heights, double radius,
                       BallShape shape, const std::vector<double>& positions, double centre_y, std::string caller)
    : window_(window),
      strip_(strip),
      heights_(heights),
      radius_(radius),
      shape_(shape),
      positions_(positions),
      centre_y_(centre_y),
      caller_(std::move(caller)) {
  check_grid(strip);
  const Grid& win = window;
  if (!same(win.dx, strip.dx) || !same(win.dy, strip.dy)) fail("solver grid cells differ from the strip's");
  if (win.nx > strip.nx || win.ny > strip.ny) fail("solver grid is larger than the strip");
  if (!heights.empty() && heights.size() != strip.size()) fail("strip heights size != strip grid size");
  if (!(radius > 0.0) || !std::isfinite(radius)) fail("radius must be finite, > 0");
  if (!std::isfinite(centre_y)) fail("centre_y must be finite");
  if (positions.empty()) fail("no positions");
  for (double x : positions)
    if (!std::isfinite(x)) fail("positions must be finite");

  const Index nxs = static_cast<Index>(strip.nx), nxw = static_cast<Index>(win.nx);
  const Index j_max = nxs - nxw;
  // j_0 centres the window on x_0: strip column of x_0 is x_0/dx + (nx_s − 1)/2.
  const double centre_col =
      positions[0] / strip.dx + 0.5 * static_cast<double>(nxs - 1) - 0.5 * static_cast<double>(nxw - 1);
  if (!(std::fabs(centre_col) < 1e15)) fail("position 0 is far outside the strip");
  Index j_free = static_cast<Index>(std::llround(centre_col));
  start_.resize(positions.size());
  shift_.assign(positions.size(), 0);
  start_[0] = std::clamp<Index>(j_free, 0, j_max);
  for (std::size_t k = 1; k < positions.size(); ++k) {
    const double steps = (positions[k] - positions[k - 1]) / strip.dx;
    const double m = std::round(steps);
    if (!(m >= 1.0) || std::fabs(steps - m) > 1e-6) {
      std::ostringstream os;
      os << "position step " << k << " (x = " << positions[k - 1] << " -> " << positions[k]
         << " m) is not a positive whole number of cells dx = " << strip.dx << " m";
      fail(os.str());
    }
    j_free += static_cast<Index>(m);
    start_[k] = std::clamp<Index>(j_free, 0, j_max);
    shift_[k] = static_cast<Index>(m) - (start_[k] - start_[k - 1]);
  }
  // Window rows: fixed along the path, centred on y_c.
  const Index nys = static_cast<Index>(strip.ny), nyw = static_cast<Index>(win.ny);
  const double centre_row =
      centre_y / strip.dy + 0.5 * static_cast<double>(nys - 1) - 0.5 * static_cast<double>(nyw - 1);
  if (!(std::fabs(centre_row) < 1e15)) fail("centre_y is far outside the strip");
  row0_ = static_cast<std::size_t>(std::clamp<Index>(static_cast<Index>(std::llround(centre_row)), 0, nys - nyw));
  column_max_.assign(strip.nx, 0.0);
  row_max_.assign(strip.ny, 0.0);
  if (!heights.empty()) {
    std::fill(column_max_.begin(), column_max_.end(), -std::numeric_limits<double>::infinity());
    std::fill(row_max_.begin(), row_max_.end(), -std::numeric_limits<double>::infinity());
    for (std::size_t iy = 0; iy < strip.ny; ++iy)
      for (std::size_t ix = 0; ix < strip.nx; ++ix) {
        column_max_[ix] = std::max(column_max_[ix], heights[iy * strip.nx + ix]);
        row_max_[iy] = std::max(row_max_[iy], heights[iy * strip.nx + ix]);
      }
    height_max_ = *std::max_element(column_max_.begin(), column_max_.end());
  }
  limit_.resize(positions.size());
  limit_where_.resize(positions.size());
  for (std::size_t k = 0; k < positions.size(); ++k) approach_limit(k);
}

double PathWindow::max_approach(std::size_t* position) const {
  const auto it = std::min_element(limit_.begin(), limit_.end());
  *position = static_cast<std::size_t>(it - limit_.begin());
  return *it;
}

void PathWindow::reject(std::size_t k, double d, const char* prefix) const {
  std::ostringstream os;
  os.precision(9);
  os << prefix << "at position " << k << " (x = " << positions_[k] << " m) the ball's rigid interference at approach "
     << d << " m reaches " << limit_where_[k] << " (allowed there: approach <= " << limit_[k] << " m)";
  fail(os.str());
}

std::vector<double> PathWindow::gap(std::size_t k) const {
  const Grid& win = window_;
  const std::size_t nxw = win.nx, ny = win.ny;
  const std::size_t j = static_cast<std::size_t>(start_[k]);
  std::vector<double> window_heights(win.size());
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nxw; ++ix)
      window_heights[iy * nxw + ix] = heights_.empty() ? 0.0 : heights_[(row0_ + iy) * strip_.nx + j + ix];
  // Window coordinates = strip coordinates − (strip.x(j) − win.x(0), strip.y(row0) − win.y(0)).
  const double offset_x = strip_.x(j) - win.x(0);
  const double offset_y = strip_.y(row0_) - win.y(0);
  return ball_gap(win, radius_, window_heights, shape_, positions_[k] - offset_x, centre_y_ - offset_y);
}

void PathWindow::shift_field(std::vector<double>& field, std::ptrdiff_t s) const {
  if (s == 0) return;
  const std::size_t nxw = window_.nx, ny = window_.ny;
  const Index nx = static_cast<Index>(nxw);
  std::vector<double> shifted(field.size());
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (Index ix = 0; ix < nx; ++ix) {
      const Index src = ix - s;
      shifted[iy * nxw + static_cast<std::size_t>(ix)] =
          (src >= 0 && src < nx) ? field[iy * nxw + static_cast<std::size_t>(src)] : 0.0;
    }
  field.swap(shifted);
}

// Undeformed gap s_i (BF-1) of strip cell (ix, iy) at position k.
double PathWindow::strip_gap(std::size_t ix, std::size_t iy, std::size_t k) const {
  const double rx = strip_.x(ix) - positions_[k], ry = strip_.y(iy) - centre_y_;
  return ball_height(rx * rx + ry * ry, radius_, shape_) - (heights_.empty() ? 0.0 : heights_[iy * strip_.nx + ix]);
}

// BF-5 at position k: limit_[k] = min s_i over the strip's edge cells and the cells outside the
// window (an approach d ≤ limit_[k] leaves them without rigid interference).
void PathWindow::approach_limit(std::size_t k) {
  const std::size_t nxw = window_.nx, nyw = window_.ny, ny = strip_.ny, nxs = strip_.nx;
  const std::size_t j = static_cast<std::size_t>(start_[k]), i0 = row0_;
  double limit = std::numeric_limits<double>::infinity();
  const char* where = "nothing";
  auto consider = [&](double gap, const char* place) {
    if (gap < limit) {
      limit = gap;
      where = place;
    }
  };
  const char* outside = "strip cells outside the solver window (enlarge it)";
  // Strip edges inside the window.
  for (std::size_t ix = j; ix < j + nxw; ++ix) {
    if (i0 == 0) consider(strip_gap(ix, 0, k), "the strip's edge (first row)");
    if (i0 + nyw == ny) consider(strip_gap(ix, ny - 1, k), "the strip's edge (last row)");
  }
  for (std::size_t iy = i0; iy < i0 + nyw; ++iy) {
    if (j == 0) consider(strip_gap(0, iy, k), "the strip's edge (first column)");
    if (j + nxw == nxs) consider(strip_gap(nxs - 1, iy, k), "the strip's edge (last column)");
  }
  // Rows outside the window (window columns only; the columns loop below covers the rest),
  // nearest first on each side, screened like the columns.
  auto row = [&](std::size_t iy) {
    const double ry = strip_.y(iy) - centre_y_;
    const double z = ball_height(ry * ry, radius_, shape_);
    if (z - row_max_[iy] >= limit) return z - height_max_ >= limit;
    for (std::size_t ix = j; ix < j + nxw; ++ix)
      consider(strip_gap(ix, iy, k), iy == 0 || iy + 1 == ny ? "the strip's edge (first/last row)" : outside);
    return false;
  };
  for (std::size_t iy = i0; iy-- > 0;)
    if (row(iy) && strip_.y(iy) <= centre_y_) break;
  for (std::size_t iy = i0 + nyw; iy < ny; ++iy)
    if (row(iy) && strip_.y(iy) >= centre_y_) break;
  // Columns outside the window, nearest first on each side. A column is skipped when its bound
  // z_ball(|x − x_k|) − max_iy h cannot beat the limit; the side ends once the bound with the
  // strip's highest point cannot (z_ball grows with the distance).
  auto column = [&](std::size_t ix) {
    const double rx = strip_.x(ix) - positions_[k];
    const double z = ball_height(rx * rx, radius_, shape_);
    if (z - column_max_[ix] >= limit) return z - height_max_ >= limit;
    for (std::size_t iy = 0; iy < ny; ++iy)
      consider(strip_gap(ix, iy, k), ix == 0 || ix + 1 == nxs ? "the strip's edge (first/last column)" : outside);
    return false;
  };
  for (std::size_t ix = j; ix-- > 0;)
    if (column(ix) && strip_.x(ix) <= positions_[k]) break;
  for (std::size_t ix = j + nxw; ix < nxs; ++ix)
    if (column(ix) && strip_.x(ix) >= positions_[k]) break;
  limit_[k] = limit;
  limit_where_[k] = where;
}

}  // namespace rollspec::contact
