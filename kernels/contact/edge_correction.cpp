#include "kernels/contact/edge_correction.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace rollspec::contact {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

double cell_fraction_inside(double t, double nx, double ny, double dx, double dy) {
  // n·x over the cell is the sum of two uniform variables of half-widths α/2 ≥ β/2,
  // α = max(|nx| dx, |ny| dy), β = min(…): its distribution is a trapezoid (README Eq. 14).
  const double u = std::fabs(nx) * dx, v = std::fabs(ny) * dy;
  const double alpha = std::max(u, v), beta = std::min(u, v);
  const double h1 = 0.5 * (alpha + beta), h0 = 0.5 * (alpha - beta), s = std::fabs(t);
  double f;  // fraction on the side of the centre
  if (s >= h1)
    f = 1.0;
  else if (s > h0)
    f = 1.0 - (h1 - s) * (h1 - s) / (2.0 * alpha * beta);
  else
    f = 0.5 + s / alpha;
  return t >= 0.0 ? f : 1.0 - f;
}

EdgeCorrection edge_correction_reference(const Grid& grid, double e_star, double w, const std::vector<double>& p,
                                         const std::vector<double>& dp, const std::vector<double>& gap,
                                         const std::vector<double>& rate_u, double hardness) {
  const std::size_t nx = grid.nx, ny = grid.ny, n = grid.size();
  const double dx = grid.dx, dy = grid.dy, h = std::sqrt(dx * dy);
  EdgeCorrection out;
  // State: 1 elastic contact (0 < p < H), 0 open (p = 0), 2 plastic (p = H).
  std::vector<unsigned char> state(n);
  for (std::size_t i = 0; i < n; ++i) state[i] = p[i] <= 0.0 ? 0 : (p[i] < hardness ? 1 : 2);
  // Arrival approaches (README Eq. 13): T_lin (the cell's own switch, first order in the discrete
  // piecewise-linear fields) and T_edge (p² and g^{2/3} linear in the distance to a smooth edge;
  // a smooth arrival-time field whose gradient gives the edge normal and speed).
  std::vector<double> t_lin(n, kNaN), t_edge(n, kNaN);
  for (std::size_t i = 0; i < n; ++i) {
    if (state[i] == 1 && dp[i] > 0.0) {
      t_lin[i] = w - p[i] / dp[i];
      t_edge[i] = w - p[i] / (2.0 * dp[i]);
    } else if (state[i] == 0 && rate_u[i] < 1.0) {
      t_lin[i] = w + gap[i] / (1.0 - rate_u[i]);
      t_edge[i] = w + 1.5 * gap[i] / (1.0 - rate_u[i]);
    }
  }
  // ∇T_edge by central differences (one-sided where a neighbour has no arrival time).
  auto derivative = [&](std::size_t i, std::size_t j, std::size_t len, std::size_t stride, double step) {
    const bool lo = j > 0 && std::isfinite(t_edge[i - stride]);
    const bool hi = j + 1 < len && std::isfinite(t_edge[i + stride]);
    if (lo && hi) return (t_edge[i + stride] - t_edge[i - stride]) / (2.0 * step);
    if (hi) return (t_edge[i + stride] - t_edge[i]) / step;
    if (lo) return (t_edge[i] - t_edge[i - stride]) / step;
    return kNaN;
  };
  std::vector<double> gx(n, kNaN), gy(n, kNaN);
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const std::size_t i = iy * nx + ix;
      if (!std::isfinite(t_edge[i])) continue;
      gx[i] = derivative(i, ix, nx, 1, dx);
      gy[i] = derivative(i, iy, ny, nx, dy);
    }
  // Marginal stiffness per unit area of the edge near elastic cell i (README Eq. 15): the frozen
  // field is the flat-punch field, dp ≈ K/√(2π d) at depth d, and dk/dA = K²/E* along the edge,
  // so m_i = 2π d_i dp_i² / E* with d_i = (w − T_edge,i)/|∇T_edge|, taken 1.5–3.5 cells deep
  // (clear of the cell-scale layer at the edge, still in the √d regime).
  std::vector<double> m(n, kNaN);
  for (std::size_t i = 0; i < n; ++i) {
    if (state[i] != 1 || !std::isfinite(t_edge[i])) continue;
    const double g = std::hypot(gx[i], gy[i]);
    if (!(g > 0.0) || !std::isfinite(g)) continue;
    const double d = (w - t_edge[i]) / g;
    if (d >= 1.5 * h && d <= 3.5 * h) m[i] = 2.0 * kPi * d * dp[i] * dp[i] / e_star;
  }
  const long radius = 4;  // neighbourhood (cells) searched for m around a band cell
  double sum = 0.0;
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const std::size_t i = iy * nx + ix;
      if (state[i] == 2) continue;
      // Band: an elastic cell with an open 4-neighbour, or an open cell with an elastic one.
      const unsigned char other = state[i] == 1 ? 0 : 1;
      const bool band = (ix > 0 && state[i - 1] == other) || (ix + 1 < nx && state[i + 1] == other) ||
                        (iy > 0 && state[i - nx] == other) || (iy + 1 < ny && state[i + nx] == other);
      if (!band) continue;
      ++out.band_cells;
      const double g = std::hypot(gx[i], gy[i]);
      if (!std::isfinite(t_lin[i]) || !(g > 0.0) || !std::isfinite(g)) continue;
      // README Eq. 13: the edge lies δ = (w − T_lin)/|∇T_edge| beyond the centre, outward normal
      // n = −∇T_edge/|∇T_edge|; README Eq. 14: θ = fraction of the cell inside.
      const double delta = (w - t_lin[i]) / g;
      const double theta = cell_fraction_inside(delta, -gx[i] / g, -gy[i] / g, dx, dy);
      const double chi = state[i] == 1 ? 1.0 : 0.0;
      if (theta == chi) {
        ++out.used_cells;
        continue;
      }
      double msum = 0.0;
      int count = 0;
      const long x0 = static_cast<long>(ix), y0 = static_cast<long>(iy);
      for (long yy = std::max(0L, y0 - radius); yy <= std::min(static_cast<long>(ny) - 1, y0 + radius); ++yy)
        for (long xx = std::max(0L, x0 - radius); xx <= std::min(static_cast<long>(nx) - 1, x0 + radius); ++xx) {
          const double v = m[static_cast<std::size_t>(yy) * nx + static_cast<std::size_t>(xx)];
          if (std::isfinite(v)) {
            msum += v;
            ++count;
          }
        }
      if (count == 0) continue;
      ++out.used_cells;
      sum += (msum / count) * (theta - chi);
    }
  out.delta_k = grid.cell_area() * sum;
  return out;
}

// The same sums on the box of the elastic cells E grown by two cells (every cell the reference
// reads for a band cell: band cells lie within one cell of E, their gradients read one more; m is
// finite on E only). Cells in the same order, so the same bits as the reference.
EdgeCorrection edge_correction(const Grid& grid, double e_star, double w, const std::vector<double>& p,
                               const std::vector<double>& dp, const std::vector<double>& gap,
                               const std::vector<double>& rate_u, double hardness) {
  const std::size_t nx = grid.nx, ny = grid.ny;
  const double dx = grid.dx, dy = grid.dy, h = std::sqrt(dx * dy);
  EdgeCorrection out;
  std::size_t ex0 = nx, ex1 = 0, ey0 = ny, ey1 = 0;  // box of E
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const double v = p[iy * nx + ix];
      if (v > 0.0 && v < hardness) {
        ex0 = std::min(ex0, ix), ex1 = std::max(ex1, ix);
        ey0 = std::min(ey0, iy), ey1 = std::max(ey1, iy);
      }
    }
  if (ex0 > ex1) return out;  // no elastic cell: no band
  // R: E's box grown by two cells (clamped); local arrays over R, x-fastest.
  const std::size_t rx0 = ex0 >= 2 ? ex0 - 2 : 0, ry0 = ey0 >= 2 ? ey0 - 2 : 0;
  const std::size_t rx1 = std::min(nx - 1, ex1 + 2), ry1 = std::min(ny - 1, ey1 + 2);
  const std::size_t rw = rx1 - rx0 + 1, rh = ry1 - ry0 + 1, rn = rw * rh;
  const auto local = [&](std::size_t ix, std::size_t iy) { return (iy - ry0) * rw + (ix - rx0); };
  std::vector<unsigned char> state(rn);
  std::vector<double> t_lin(rn, kNaN), t_edge(rn, kNaN), gx(rn, kNaN), gy(rn, kNaN), m(rn, kNaN);
  for (std::size_t iy = ry0; iy <= ry1; ++iy)
    for (std::size_t ix = rx0; ix <= rx1; ++ix) {
      const std::size_t i = iy * nx + ix, l = local(ix, iy);
      state[l] = p[i] <= 0.0 ? 0 : (p[i] < hardness ? 1 : 2);
      if (state[l] == 1 && dp[i] > 0.0) {
        t_lin[l] = w - p[i] / dp[i];
        t_edge[l] = w - p[i] / (2.0 * dp[i]);
      } else if (state[l] == 0 && rate_u[i] < 1.0) {
        t_lin[l] = w + gap[i] / (1.0 - rate_u[i]);
        t_edge[l] = w + 1.5 * gap[i] / (1.0 - rate_u[i]);
      }
    }
  // Gradients on E's box grown by one cell (their neighbours lie in R or off the grid).
  const std::size_t gx0 = ex0 >= 1 ? ex0 - 1 : 0, gy0 = ey0 >= 1 ? ey0 - 1 : 0;
  const std::size_t gx1 = std::min(nx - 1, ex1 + 1), gy1 = std::min(ny - 1, ey1 + 1);
  auto derivative = [&](std::size_t l, std::size_t j, std::size_t len, std::size_t stride, double step) {
    const bool lo = j > 0 && std::isfinite(t_edge[l - stride]);
    const bool hi = j + 1 < len && std::isfinite(t_edge[l + stride]);
    if (lo && hi) return (t_edge[l + stride] - t_edge[l - stride]) / (2.0 * step);
    if (hi) return (t_edge[l + stride] - t_edge[l]) / step;
    if (lo) return (t_edge[l] - t_edge[l - stride]) / step;
    return kNaN;
  };
  for (std::size_t iy = gy0; iy <= gy1; ++iy)
    for (std::size_t ix = gx0; ix <= gx1; ++ix) {
      const std::size_t l = local(ix, iy);
      if (!std::isfinite(t_edge[l])) continue;
      gx[l] = derivative(l, ix, nx, 1, dx);
      gy[l] = derivative(l, iy, ny, rw, dy);
      // README Eq. 15 on the elastic cells (all in E's box).
      if (state[l] != 1) continue;
      const double g = std::hypot(gx[l], gy[l]);
      if (!(g > 0.0) || !std::isfinite(g)) continue;
      const double d = (w - t_edge[l]) / g;
      const std::size_t i = iy * nx + ix;
      if (d >= 1.5 * h && d <= 3.5 * h) m[l] = 2.0 * kPi * d * dp[i] * dp[i] / e_star;
    }
  const long radius = 4;  // as the reference
  double sum = 0.0;
  for (std::size_t iy = gy0; iy <= gy1; ++iy)
    for (std::size_t ix = gx0; ix <= gx1; ++ix) {
      const std::size_t l = local(ix, iy);
      if (state[l] == 2) continue;
      const unsigned char other = state[l] == 1 ? 0 : 1;
      const bool band = (ix > 0 && state[l - 1] == other) || (ix + 1 < nx && state[l + 1] == other) ||
                        (iy > 0 && state[l - rw] == other) || (iy + 1 < ny && state[l + rw] == other);
      if (!band) continue;
      ++out.band_cells;
      const double g = std::hypot(gx[l], gy[l]);
      if (!std::isfinite(t_lin[l]) || !(g > 0.0) || !std::isfinite(g)) continue;
      const double delta = (w - t_lin[l]) / g;
      const double theta = cell_fraction_inside(delta, -gx[l] / g, -gy[l] / g, dx, dy);
      const double chi = state[l] == 1 ? 1.0 : 0.0;
      if (theta == chi) {
        ++out.used_cells;
        continue;
      }
      double msum = 0.0;
      int count = 0;
      // m is finite on E's box only: the reference's window clipped to it, in the same order.
      const long x0 = static_cast<long>(ix), y0 = static_cast<long>(iy);
      const long xa = std::max(static_cast<long>(ex0), x0 - radius), xb = std::min(static_cast<long>(ex1), x0 + radius);
      const long ya = std::max(static_cast<long>(ey0), y0 - radius), yb = std::min(static_cast<long>(ey1), y0 + radius);
      for (long yy = ya; yy <= yb; ++yy)
        for (long xx = xa; xx <= xb; ++xx) {
          const double v = m[local(static_cast<std::size_t>(xx), static_cast<std::size_t>(yy))];
          if (std::isfinite(v)) {
            msum += v;
            ++count;
          }
        }
      if (count == 0) continue;
      ++out.used_cells;
      sum += (msum / count) * (theta - chi);
    }
  out.delta_k = grid.cell_area() * sum;
  return out;
}

}  // namespace rollspec::contact
