#pragma once
// The moving solver window of a ball slid along a strip (blocked_force.hpp BF-1, BF-5, BF-6): window
// placement, the undeformed gap on the window at each position, the confinement limit on the
// approach, and the warm-start shift. Shared by the blocked force (fixed approach) and the
// equivalent roughness (fixed load, equivalent_roughness.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "kernels/contact/geometry.hpp"
#include "kernels/contact/grid.hpp"

namespace rollspec::contact {

class PathWindow {
 public:
  // `window`: the solver grid (same dx, dy as `strip`, not larger); `heights`: strip.size() values
  // or empty (smooth); positions strictly increasing by whole cells dx; `caller` prefixes every
  // message ("blocked_force", ...). Throws std::invalid_argument on any inconsistency.
  PathWindow(const Grid& window, const Grid& strip, const std::vector<double>& heights, double radius, BallShape shape,
             const std::vector<double>& positions, double centre_y, std::string caller);

  std::size_t size() const { return positions_.size(); }
  // BF-5: the largest approach allowed at position k, and over all positions (with where).
  double limit(std::size_t k) const { return limit_[k]; }
  double max_approach(std::size_t* position) const;
  // Throws std::invalid_argument: approach d at position k exceeds BF-5 (message names both).
  [[noreturn]] void reject(std::size_t k, double d, const char* prefix = "") const;
  [[noreturn]] void fail(const std::string& what) const;
  // Undeformed gap s^(k) (BF-1) on the window at position k (thread-safe: no shared scratch).
  std::vector<double> gap(std::size_t k) const;
  // Shift of the ball relative to the window from position k−1 to k (σ_k of BF-6), and of the strip.
  std::ptrdiff_t ball_shift(std::size_t k) const { return shift_[k]; }
  std::ptrdiff_t strip_shift(std::size_t k) const { return -(start_[k] - start_[k - 1]); }
  // BF-6: field[ix, iy] ← field[ix − s, iy] on each window row, zero where ix − s leaves the window.
  void shift_field(std::vector<double>& field, std::ptrdiff_t s) const;

 private:
  double strip_gap(std::size_t ix, std::size_t iy, std::size_t k) const;
  void approach_limit(std::size_t k);

  Grid window_, strip_;
  const std::vector<double>& heights_;
  double radius_;
  BallShape shape_;
  std::vector<double> positions_;
  double centre_y_;
  std::string caller_;
  std::vector<std::ptrdiff_t> start_, shift_;
  std::size_t row0_ = 0;  // first strip row of the window
  std::vector<double> column_max_, row_max_, limit_;
  std::vector<const char*> limit_where_;
  double height_max_ = 0.0;
};

}  // namespace rollspec::contact
