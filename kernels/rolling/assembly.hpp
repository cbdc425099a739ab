// Residual and tangent assembly of the rolling Solver (README Sec. 6, R-40): the receivers of
// tangent entries (dense, or sparse into a pattern recorded once), the beam Gauss points, and the
// assembly of beams, inertia, loads and contacts for increments q = [du, alpha] per node.
// Internal to kernels/rolling (the Solver and its tests).
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "kernels/rolling/band_lu.hpp"
#include "kernels/rolling/beam_element.hpp"
#include "kernels/rolling/model.hpp"
#include "kernels/rolling/solver.hpp"
#include "kernels/rolling/time_rule.hpp"

namespace rollspec::rolling {

class ContactSet;

// Receives tangent entries by global DOF.
struct Sink {
  virtual ~Sink() = default;
  virtual void add(int i, int j, double v) = 0;
  // An m x m block K (column-major) at the DOFs, entry by entry in the order (j, then i) of add();
  // one virtual call per block for the sinks that override it.
  virtual void add_dense(const int* dofs, int m, const double* K) {
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) add(dofs[i], dofs[j], K[i + m * j]);
  }
  // Whether the assembly's all-zero pattern blocks (every node's diagonal block) are to be added;
  // a sink over storage that holds every entry anyway skips them (adding zeros changes no bit).
  virtual bool wants_pattern_blocks() const { return true; }
};

template <int M>
void add_block(Sink* s, const std::array<int, M>& dofs, const Eigen::Matrix<double, M, M>& K) {
  if (s) s->add_dense(dofs.data(), M, K.data());
}

inline std::array<int, 3> dofs3(int first) { return {first, first + 1, first + 2}; }
inline std::array<int, 6> dofs6(int node) {
  return {6 * node, 6 * node + 1, 6 * node + 2, 6 * node + 3, 6 * node + 4, 6 * node + 5};
}

// Adds into a dense matrix over all 6 DOFs per node.
struct DenseSink : Sink {
  Eigen::MatrixXd* K;
  explicit DenseSink(Eigen::MatrixXd* k) : K(k) {}
  void add(int i, int j, double v) override { (*K)(i, j) += v; }
};

// Sparse assembly into a fixed pattern over the free equations (eq[dof] >= 0): the first pass
// records triplets and the slot of every entry in the compressed matrix; later passes add values
// straight into the slots (the assembly order is deterministic, so the pattern is analysed once).
struct SparseSink : Sink {
  const std::vector<int>* eq = nullptr;
  int neq = 0;
  bool recording = true;
  bool mismatch = false;     // a replay did not follow the recorded order: record again
  bool new_pattern = false;  // set by a recording pass, for the factorisation to analyse
  std::vector<Eigen::Triplet<double>> trip;
  std::vector<int> slot, srow, scol;
  std::size_t k = 0;
  Eigen::SparseMatrix<double> A;

  void begin();
  void add(int i, int j, double v) override;
  void finish();
};

// Assembly straight into the band storage of a BandLU over the free equations (eq[dof] >= 0), in
// the same order as SparseSink: each entry receives the same sums. An entry outside the band
// sets mismatch (the pattern changed: record it again).
struct BandSink : Sink {
  const std::vector<int>* eq = nullptr;
  BandLU* lu = nullptr;
  bool mismatch = false;

  void begin() {
    lu->set_zero();
    mismatch = false;
  }
  void add(int i, int j, double v) override {
    const int r = (*eq)[static_cast<std::size_t>(i)], c = (*eq)[static_cast<std::size_t>(j)];
    if (r < 0 || c < 0) return;
    if (!lu->in_band(r, c)) {
      mismatch = true;
      return;
    }
    lu->at(r, c) += v;
  }
  void add_dense(const int* dofs, int m, const double* K) override;
  bool wants_pattern_blocks() const override { return false; }
};

// Beam mass point (3-point Gauss): committed rotation and body-frame rates.
struct MassPoint {
  double xi = 0.0, weight = 0.0, jac = 0.0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d W = Eigen::Vector3d::Zero(), A = Eigen::Vector3d::Zero();
};

// Stiffness (2-point, reduced) and mass (3-point) Gauss points of every beam element.
struct BeamPoints {
  std::vector<std::array<BeamStiffPoint, 2>> stiffness;
  std::vector<std::array<MassPoint, 3>> mass;
};
// The initial beam is straight: K_n = 0, frame from the tangent and the first node's e2;
// mass points take the initial angular velocity model.w0.
BeamPoints make_beam_points(const Model& model);

// Nodes at the model's initial state (positions, frames, v0, body-frame W from w0).
std::vector<NodeState> initial_nodes(const Model& model);

Eigen::Matrix3d section_inertia(const BeamSection& s);

// What the assembly reads: the model and the committed state at the step start t0.
struct AssemblyState {
  const Model& model;
  const std::vector<NodeState>& nodes;
  const BeamPoints& points;
  double t0 = 0.0;
};

// Residual R = f_int + f_inertia - f_ext - f_contact and its tangent dR/dq into K (when not null)
// for the increments q over [t0, t1]. mass_matrix: K receives the mass matrix and R the
// gyroscopic terms instead, for the initial acceleration (Sec. 5; pass the quasi-static rule).
// The contact pairs keep their evaluations for the commit.
void assemble(const AssemblyState& s, const TimeRule& rule, ContactSet& contacts, const Eigen::VectorXd& q, double t1,
              double dt, bool mass_matrix, Eigen::VectorXd& R, Sink* K);

// External nodal forces and spatial moments at time t (gravity as consistent loads).
Eigen::VectorXd external_loads(const AssemblyState& s, double t);

}  // namespace rollspec::rolling
