#pragma once
// P(δ, ξ) of one rough strip, interpolated (README B42–B46; the table is built by
// kernels/contact/path_table.hpp): Q = P^{2/3} linear in δ between δ_c(ξ_k) and the tabulated
// approaches above it, the last segment continued beyond them (B44); P linear in ξ between
// positions, the end positions held outside (B45). The approaches are either one set from the
// plane (B43) or each position's own ladder above its first contact (B43b).
#include <cstddef>
#include <vector>

namespace rollspec::beam {

// How P is carried between tabulated positions at one δ.
enum class PathInterpolation {
  linear,  // B45: two positions, weights 1 − t, t (in-band gain sinc²: −0.14 dB at a sixth of the node rate)
  cubic,   // B45b: Keys' six-point cubic convolution, exact for cubics, C¹ (−0.001 dB there)
};

struct PathContactData {
  std::vector<double> position;       // ξ_k (m, path coordinate), N ≥ 1 values, increasing
  std::vector<double> approach;       // δ_j (m), J ≥ 1 values, increasing
  std::vector<double> first_contact;  // δ_c(ξ_k) (m), N values
  std::vector<double> force;          // P(δ_j, ξ_k) (N) at [j · N + k], non-decreasing in j, ≥ 0
  // B43b: approach[j] is the offset s_j above δ_c(ξ_k), and position k holds rows[k] rows (the
  // force above them is not read). Empty: the approaches are from the plane, every row at every
  // position (B43).
  std::vector<std::size_t> rows;
  PathInterpolation interpolation = PathInterpolation::linear;
};

class PathContactTable {
 public:
  PathContactTable() = default;
  // Throws std::invalid_argument on inconsistent sizes, non-increasing positions or approaches,
  // negative or decreasing forces.
  explicit PathContactTable(PathContactData data);

  bool empty() const { return d_.position.empty(); }
  const PathContactData& data() const { return d_; }

  // P(δ, ξ) and dP/dδ (B44, B45 or B45b); zero at or below first_contact(ξ).
  void evaluate(double delta, double xi, double& force, double& stiffness) const;
  // B45: the approach above which the force is positive; B45b: the lowest first contact of the
  // positions whose columns are blended there (no force at or below it).
  double first_contact(double xi) const;
  // Contact at (δ, ξ): δ above first_contact(ξ) (B45), the blended force positive (B45b).
  bool touches(double delta, double xi) const;
  // δ with P(δ, ξ) = load > 0 (B46 static start): bracketing Newton on the monotone P.
  double static_approach(double load, double xi) const;
  // dδ_W/dξ at ξ (B46's start): the least-squares slope of static_approach(load, ·) at 21 points
  // over [ξ − width/2, ξ + width/2] (cut at the first position, the start: one-sided there), a derivative of the
  // path's part the positions resolve, whatever their spacing.
  double static_slope(double load, double xi, double width) const;
  // P at the tabulated position k (B44).
  void at_position(std::size_t k, double delta, double& force, double& stiffness) const;

 private:
  // The largest tabulated approach at position k.
  double top_approach(std::size_t k) const;
  // The position interval of ξ: k and weight t of k + 1 (t = 0 at the ends).
  void locate(double xi, std::size_t& k, double& t) const;
  // B45b's stencil at interval k (first position and count; linear where six equally spaced
  // positions k − 2 … k + 3 do not exist) and its weights for t.
  std::size_t stencil(std::size_t k, double t, double* weight) const;
  PathContactData d_;
  std::vector<double> q_;      // P^{2/3}
  std::vector<char> uniform_;  // B45b: interval k has six equally spaced positions about it
};

// Keys' six-point cubic convolution kernel W(s) (Keys 1981, Eq. 30; README B45b).
double keys_six_point(double s);

// The same table on every `every`-th approach row (rows every−1, 2·every−1, … of B43 or of each
// position's B43b ladder, each position keeping ⌊J_k / every⌋): the node spacing times `every`, no new
// solve. What the answer moves by on it shows whether the table's approaches are fine enough.
PathContactData thinned_rows(const PathContactData& d, std::size_t every);

// The same table on every `every`-th position (0, every, 2·every, …, and the last): the position
// spacing times `every`, no new solve. What the answer moves by on it shows whether the positions
// are close enough for the interpolation in ξ (B45, B45b).
PathContactData thinned_positions(const PathContactData& d, std::size_t every);

// The static approach δ_W(ξ_k) at each tabulated position (README, check against the static load).
std::vector<double> path_static_approaches(const PathContactTable& table, double load);

// Their mean over the positions (from them, or from the table).
double path_table_static_approach(const std::vector<double>& static_approaches);
double path_table_static_approach(const PathContactTable& table, double load);

}  // namespace rollspec::beam
