#pragma once
// A rolling model's tangent at its initial state as the band-LU test and bench take it: every DOF free
// (equation i is DOF i), increments q_k = 1e-6 sin(0.7 k), one Newmark step of 2.5e-5 s from t = 0, assembled into
// the sparse pattern; and the band it spans. Header-only: bench/rolling/bench_band_lu.cpp includes it too.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/rolling/assembly.hpp"
#include "kernels/rolling/contact_set.hpp"

namespace rollspec::rolling::test {

struct InitialTangent {
  static constexpr double kStep = 2.5e-5;  // s
  const Model& model;
  std::vector<NodeState> nodes;
  BeamPoints points;
  int n;                 // equations: 6 per node
  std::vector<int> eq;   // the equation of each DOF
  Eigen::VectorXd q, r;  // the increments and the residual there
  SparseSink sparse;     // the tangent: sparse.A
  int kl = 0, ku = 0;    // its lower and upper bandwidths

  explicit InitialTangent(const Model& m)
      : model(m),
        nodes(initial_nodes(m)),
        points(make_beam_points(m)),
        n(6 * static_cast<int>(m.X.size())),
        eq(static_cast<std::size_t>(n)),
        q(n) {
    for (int i = 0; i < n; ++i) eq[static_cast<std::size_t>(i)] = i;
    for (int k = 0; k < n; ++k) q(k) = 1e-6 * std::sin(0.7 * k);
    ContactSet contacts(m, nodes);
    sparse.eq = &eq;
    sparse.neq = n;
    sparse.begin();
    assemble(state(), TimeRule(TimeRule::Kind::Newmark), contacts, q, kStep, kStep, false, r, &sparse);
    sparse.finish();
    for (int c = 0; c < n; ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(sparse.A, c); it; ++it) {
        kl = std::max(kl, static_cast<int>(it.row()) - c);
        ku = std::max(ku, c - static_cast<int>(it.row()));
      }
  }
  InitialTangent(const InitialTangent&) = delete;  // sparse.eq points at eq
  InitialTangent& operator=(const InitialTangent&) = delete;

  AssemblyState state() const { return {model, nodes, points, 0.0}; }
};

}  // namespace rollspec::rolling::test
