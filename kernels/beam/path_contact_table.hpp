#pragma once
// P(δ, ξ) of one rough strip, interpolated (README B42–B46; the table is built by
// kernels/contact/path_table.hpp): Q = P^{2/3} linear in δ between δ_c(ξ_k) and the tabulated
// approaches above it, the last segment continued beyond them (B44); P linear in ξ between
// positions, the end positions held outside (B45).
#include <cstddef>
#include <vector>

namespace rollspec::beam {

struct PathContactData {
  std::vector<double> position;       // ξ_k (m, path coordinate), N ≥ 1 values, increasing
  std::vector<double> approach;       // δ_j (m), J ≥ 1 values, increasing
  std::vector<double> first_contact;  // δ_c(ξ_k) (m), N values
  std::vector<double> force;          // P(δ_j, ξ_k) (N) at [j · N + k], non-decreasing in j, ≥ 0
};

class PathContactTable {
 public:
  PathContactTable() = default;
  // Throws std::invalid_argument on inconsistent sizes, non-increasing positions or approaches,
  // negative or decreasing forces.
  explicit PathContactTable(PathContactData data);

  bool empty() const { return d_.position.empty(); }
  const PathContactData& data() const { return d_; }

  // P(δ, ξ) and dP/dδ (B44, B45); zero at or below δ_c(ξ).
  void evaluate(double delta, double xi, double& force, double& stiffness) const;
  // δ_c(ξ) of B45: the force is positive exactly above it.
  double first_contact(double xi) const;
  // δ with P(δ, ξ) = load > 0 (B46 static start): bracketing Newton on the monotone P.
  double static_approach(double load, double xi) const;
  // P at the tabulated position k (B44).
  void at_position(std::size_t k, double delta, double& force, double& stiffness) const;

 private:
  // The position interval of ξ: k and weight t of k + 1 (t = 0 at the ends).
  void locate(double xi, std::size_t& k, double& t) const;
  PathContactData d_;
  std::vector<double> q_;  // P^{2/3}
};

// Mean over the tabulated positions of the static approach δ_W(ξ_k) (README, check against the
// static load).
double path_table_static_approach(const PathContactTable& table, double load);

}  // namespace rollspec::beam
