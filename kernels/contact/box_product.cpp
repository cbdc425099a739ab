#include "kernels/contact/box_product.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace rollspec::contact {

namespace {
// Smallest side of the ladder 2^k, 3·2^k, 5·2^k (k ≥ 3) that holds `need` cells, or `whole` if
// that side would not be smaller.
std::size_t box_side(std::size_t need, std::size_t whole) {
  std::size_t best = whole;
  for (std::size_t f : {std::size_t(8), std::size_t(12), std::size_t(20)}) {
    std::size_t side = f;
    while (side < need) side *= 2;
    best = std::min(best, side);
  }
  return best;
}
}  // namespace

BoxProduct::BoxProduct(HalfSpaceOperator& whole) : whole_(whole) {
  if (whole.boundary() != Boundary::Open) throw std::invalid_argument("BoxProduct: open boundary only");
}

void BoxProduct::set_cells(const std::vector<std::uint32_t>& cells) {
  const Grid& g = whole_.grid();
  cells_ = &cells;
  std::size_t x_lo = g.nx, x_hi = 0, y_lo = g.ny, y_hi = 0;
  for (const std::uint32_t i : cells) {
    const std::size_t ix = i % g.nx, iy = i / g.nx;
    x_lo = std::min(x_lo, ix);
    x_hi = std::max(x_hi, ix);
    y_lo = std::min(y_lo, iy);
    y_hi = std::max(y_hi, iy);
  }
  if (cells.empty()) x_lo = x_hi = y_lo = y_hi = 0;
  const std::size_t bx = box_side(x_hi - x_lo + 1, g.nx), by = box_side(y_hi - y_lo + 1, g.ny);
  x0_ = std::min(x_lo, g.nx - bx);
  y0_ = std::min(y_lo, g.ny - by);
  if (bx == g.nx && by == g.ny) {
    op_ = &whole_;
  } else {
    op_ = nullptr;
    for (const auto& b : boxes_)
      if (b->grid().nx == bx && b->grid().ny == by) op_ = b.get();
    if (!op_) {
      boxes_.push_back(std::make_unique<HalfSpaceOperator>(Grid{bx, by, g.dx, g.dy}, whole_.e_star()));
      op_ = boxes_.back().get();
    }
  }
  at_.resize(cells.size());
  for (std::size_t j = 0; j < cells.size(); ++j)
    at_[j] = static_cast<std::uint32_t>((cells[j] / g.nx - y0_) * bx + (cells[j] % g.nx - x0_));
  in_.assign(bx * by, 0.0);  // zero off the listed cells from now on (apply writes only those)
  out_.resize(bx * by);
}

void BoxProduct::apply(const double* v, double* out) {
  const std::vector<std::uint32_t>& cells = *cells_;
  const std::size_t m = cells.size();
  for (std::size_t j = 0; j < m; ++j) in_[at_[j]] = v[cells[j]];
  op_->apply(in_.data(), out_.data());
  for (std::size_t j = 0; j < m; ++j) out[cells[j]] = out_[at_[j]];
}

}  // namespace rollspec::contact
