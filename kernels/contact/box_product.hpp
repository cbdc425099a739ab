#pragma once
// The half-space product on a box of the grid (README Eq. 3c): C v for v non-zero only on a set of
// cells L and wanted only on L, by the DC-FFT of a grid just large enough to hold L's bounding box.
// C depends on the offset between cells only, so the box's product equals the whole grid's on L (to
// rounding). The box sides come from a ladder of FFT-friendly sizes (2^k, 3·2^k, 5·2^k cells; a
// padded side of 2^k points is about twice as fast as one of 9·2^k, e.g. 256 against 288); a side
// that would not be smaller than the grid's is the grid's.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "kernels/contact/half_space_operator.hpp"

namespace rollspec::contact {

class BoxProduct {
 public:
  // `whole`: the operator of the whole grid (open boundary), used when the box is the whole grid.
  explicit BoxProduct(HalfSpaceOperator& whole);

  // The cells L (indices of the whole grid, increasing): chooses the box (the list is kept by
  // reference and must outlive the following apply calls).
  void set_cells(const std::vector<std::uint32_t>& cells);
  // out[i] = Σ_k C_ik v[k] for i in L, the sum over k in L (v elsewhere is not read; out elsewhere not written).
  void apply(const double* v, double* out);
  // Source–target pairs of a direct sum that cost about one apply() (HalfSpaceOperator::fft_cost of the box).
  double fft_cost() const { return op_->fft_cost(); }
  std::size_t box_nx() const { return op_->grid().nx; }
  std::size_t box_ny() const { return op_->grid().ny; }

 private:
  HalfSpaceOperator& whole_;
  const std::vector<std::uint32_t>* cells_ = nullptr;
  std::size_t x0_ = 0, y0_ = 0;
  HalfSpaceOperator* op_ = nullptr;
  std::vector<std::unique_ptr<HalfSpaceOperator>> boxes_;  // made when first needed, kept
  std::vector<std::uint32_t> at_;                          // box index of each listed cell
  std::vector<double> in_, out_;
};

}  // namespace rollspec::contact
