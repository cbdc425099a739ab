// Linear solvers of the rolling Newton step on a rolling tube's tangent (README R-44): band LU
// (partial pivoting) against Eigen's dense PartialPivLU and SparseLU (pattern analysed once), each
// factor + solve timed in the same run (median of repeated batches), and the band LU's plain loops over
// the whole band (factorize_reference, solve_reference) beside its profile-skipping ones. CSV on stdout.
//   usage: bench_band_lu [elements (default 4)] [batches (default 21)]
#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "tests/kernels/rolling/initial_tangent.hpp"  // the tangent test_band_lu.cpp checks
#include "kernels/rolling/assembly.hpp"
#include "kernels/rolling/band_lu.hpp"
#include "kernels/rolling/contact_set.hpp"

using namespace rollspec::rolling;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Steel tube 60 x 4 mm, 1 m, on a wavy grid with rolling friction and dampers at every node (the
// rolling-pipe study's model), at its initial state.
Model tube(int elements) {
  Model m;
  m.sections.push_back(circular_section(2.1e11, 0.3, 7850, 0.06, 0.052));
  const double r = 0.03;
  const std::vector<int> ids =
      add_straight_beam(m, Vector3d(0.0, -0.5, r - 2e-5), Vector3d(0.0, 0.5, r - 2e-5), elements, 0, Vector3d::UnitX());
  m.surfaces.push_back(
      grid_height_field(make_plane(Vector3d::Zero(), Vector3d::UnitZ()), {-0.1, 0.01, 60}, {-0.6, 0.01, 120},
                        [](double s1, double s2) { return 2e-5 * std::sin(40.0 * s1 + 30.0 * (s2 + 0.6)); }));
  for (int id : ids)
    m.surface_contacts.push_back(SurfaceContactPair{id, 0, SurfaceContactLaw{r, 5e6, 0.3, 1e6, true, 60.0}});
  m.v0.assign(m.X.size(), Vector3d(0.5, 0.0, 0.0));
  m.w0.assign(m.X.size(), Vector3d(0.0, 0.5 / r, 0.0));
  m.gravity = Vector3d(0, 0, -9.81);
  return m;
}

template <class F>
double median_us(int batches, int reps, F&& f) {
  std::vector<double> t;
  for (int b = 0; b < batches; ++b) {
    const double t0 = now();
    for (int r = 0; r < reps; ++r) f();
    t.push_back(1e6 * (now() - t0) / reps);
  }
  std::nth_element(t.begin(), t.begin() + batches / 2, t.end());
  return t[static_cast<std::size_t>(batches / 2)];
}
}  // namespace

int main(int argc, char** argv) {
  const int elements = argc > 1 ? std::atoi(argv[1]) : 4;
  const int batches = argc > 2 ? std::atoi(argv[2]) : 21;
  const Model m = tube(elements);
  const rollspec::rolling::test::InitialTangent tangent(m);
  const int n = tangent.n, kl = tangent.kl, ku = tangent.ku;
  const SparseSink& ss = tangent.sparse;
  const VectorXd& R = tangent.r;
  const Eigen::MatrixXd D = Eigen::MatrixXd(ss.A);
  const int reps = std::max(1, 20000 / n);
  BandLU band(n, kl, ku);
  VectorXd x(n);
  const double t_band = median_us(batches, reps, [&]() {
    band.set_zero();  // as BandSink::begin: the fill rows of the last factorisation are cleared
    for (int c = 0; c < n; ++c)
      for (int r = std::max(0, c - ku); r <= std::min(n - 1, c + kl); ++r) band.at(r, c) = D(r, c);
    band.factorize();
    x = -R;
    band.solve(x.data());
  });
  VectorXd xp(n);
  const double t_plain = median_us(batches, reps, [&]() {  // the loops over the whole band (reference)
    band.set_zero();
    for (int c = 0; c < n; ++c)
      for (int r = std::max(0, c - ku); r <= std::min(n - 1, c + kl); ++r) band.at(r, c) = D(r, c);
    band.factorize_reference();
    xp = -R;
    band.solve_reference(xp.data());
  });
  Eigen::PartialPivLU<Eigen::MatrixXd> dense(n);
  VectorXd xd(n);
  const double t_dense = median_us(batches, reps, [&]() {
    dense.compute(D);
    xd = dense.solve(-R);
  });
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> sparse;
  sparse.analyzePattern(ss.A);
  VectorXd xs(n);
  const double t_sparse = median_us(batches, reps, [&]() {
    sparse.factorize(ss.A);
    xs = sparse.solve(-R);
  });
  std::fprintf(stderr, "residuals: band %.2e dense %.2e sparse %.2e; |x| %.2e %.2e %.2e\n",
               (D * x + R).norm() / R.norm(), (D * xd + R).norm() / R.norm(), (D * xs + R).norm() / R.norm(), x.norm(),
               xd.norm(), xs.norm());
  std::printf(
      "n,kl,ku,nonzeros,band_us,band_plain_us,dense_us,sparse_us,band_over_dense,band_over_sparse,band_vs_dense_rel,"
      "band_vs_plain_identical\n");
  std::printf("%d,%d,%d,%ld,%.2f,%.2f,%.2f,%.2f,%.3f,%.3f,%.2e,%d\n", n, kl, ku, static_cast<long>(ss.A.nonZeros()),
              t_band, t_plain, t_dense, t_sparse, t_band / t_dense, t_band / t_sparse, (x - xd).norm() / xd.norm(),
              x == xp ? 1 : 0);
  return 0;
}
